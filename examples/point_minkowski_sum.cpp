// Example: points on the boundary of knot1 + tetrahedron, and of the contact space -P + Q,
// with their provenance.
//
//   example_point_minkowski_sum [P.off] [Q.off] [d]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <iostream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  const std::string fp = argc > 1 ? argv[1] : CGAL_PMSUM_DATA_DIR "/knot1.off";
  const std::string fq = argc > 2 ? argv[2] : CGAL_PMSUM_DATA_DIR "/tetrahedron.off";
  const double d = argc > 3 ? std::atof(argv[3]) : 0.05;
  Mesh P, Q;
  if (!PMP::IO::read_polygon_mesh(fp, P) || !PMP::IO::read_polygon_mesh(fq, Q)) {
    std::cerr << "cannot read the meshes\n";
    return 1;
  }
  // CGAL's tetrahedron.off is oriented inward; the algorithm wants outward solids.
  for (Mesh* m : {&P, &Q})
    if (CGAL::is_closed(*m) && !PMP::does_bound_a_volume(*m)) PMP::orient_to_bound_a_volume(*m);

  try {
    // 1. Just the points.
    std::vector<K::Point_3> points;
    CGAL::point_minkowski_sum(P, Q, d, std::back_inserter(points));
    std::cout << points.size() << " points on the boundary of P + Q\n";

    // 2. Records: point, outward normal, and where it came from; statistics.
    std::vector<CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, K>> records;
    CGAL::Pmsum::Statistics stats;
    CGAL::point_minkowski_sum(P, Q, d, std::back_inserter(records),
                              CGAL::parameters::negate_first_mesh(true).statistics(stats));
    std::cout << records.size() << " points on the boundary of -P + Q (contact space), from "
              << stats.candidates << " candidates and " << stats.cd_queries << " exact collision tests\n";
    const auto& r = records.front();
    const char* kind[] = {"vertex", "edge", "face"};
    std::cout << "first point " << r.point << ", normal " << r.normal << ", from a " << kind[r.origin_p.dimension]
              << " of P and a " << kind[r.origin_q.dimension] << " of Q\n";
  } catch (const CGAL::Pmsum::Invalid_input& e) {
    std::cerr << "invalid input: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
