// A consumer of CGAL_pmsum: the sum of two unit cubes is the cube [0, 2]^3; every point must
// lie on its boundary (a coordinate 0 or 2, all in [0, 2]) and cover it within d (every corner
// of the sum has a point closer than d). Exit code 0 when both hold.
#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <cmath>
#include <iostream>
#include <iterator>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main()
{
  Mesh cube;
  CGAL::make_hexahedron(K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(1, 1, 0), K::Point_3(0, 1, 0),
                        K::Point_3(0, 1, 1), K::Point_3(0, 0, 1), K::Point_3(1, 0, 1), K::Point_3(1, 1, 1), cube);
  CGAL::Polygon_mesh_processing::triangulate_faces(cube);
  const double d = 0.25;
  std::vector<K::Point_3> points;
  CGAL::point_minkowski_sum(cube, cube, d, std::back_inserter(points));
  std::size_t off = 0;
  for (const auto& p : points) {
    bool on_face = false, inside = true;
    for (int c = 0; c < 3; ++c) {
      on_face |= (p[c] == 0 || p[c] == 2);
      inside &= (p[c] >= 0 && p[c] <= 2);
    }
    off += !(on_face && inside);
  }
  std::size_t uncovered = 0;
  for (int i = 0; i < 8; ++i) {
    const K::Point_3 corner(2 * (i & 1), 2 * ((i >> 1) & 1), 2 * ((i >> 2) & 1));
    double nearest = HUGE_VAL;
    for (const auto& p : points) nearest = (std::min)(nearest, std::sqrt(CGAL::squared_distance(p, corner)));
    uncovered += !(nearest < d);
  }
  std::cout << points.size() << " points, " << off << " off the boundary, " << uncovered << " corners uncovered\n";
  return (!points.empty() && off == 0 && uncovered == 0) ? 0 : 1;
}
