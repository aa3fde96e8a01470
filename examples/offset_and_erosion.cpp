// Example: offset and erosion of a mesh by a ball, with points.
//   example_offset_and_erosion [MESH.off] [r] [d]     (r, d: fractions of the bbox diagonal)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL_pmsum/point_offset.h>

#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  Mesh P;
  if (!PMP::IO::read_polygon_mesh(argc > 1 ? argv[1] : CGAL_PMSUM_DATA_DIR "/elephant.off", P)) return 1;
  const CGAL::Bbox_3 b = PMP::bbox(P);
  const double diag = std::sqrt(std::pow(b.xmax() - b.xmin(), 2) + std::pow(b.ymax() - b.ymin(), 2) +
                                std::pow(b.zmax() - b.zmin(), 2));
  const double r = (argc > 2 ? std::atof(argv[2]) : 0.02) * diag, d = (argc > 3 ? std::atof(argv[3]) : 0.01) * diag;

  Mesh ball;
  const double inner = CGAL::make_icosphere(r, 0.02, ball); // polygonal ball, 2% error
  std::vector<K::Point_3> offset, erosion;
  CGAL::point_offset(P, ball, d, std::back_inserter(offset));
  CGAL::point_erosion(P, ball, d, std::back_inserter(erosion));
  std::cout << "offset:  " << offset.size() << " points at distance in [" << inner << ", " << r << "] outside\n"
            << "erosion: " << erosion.size() << " points at distance in [" << inner << ", " << r << "] inside\n";
  return 0;
}
