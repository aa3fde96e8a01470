// Example: penetration depth of a translated robot P into an obstacle Q.
//   example_penetration_depth [P.off] [Q.off] [d] then lines "x y z" on standard input
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL_pmsum/Penetration_depth.h>

#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  Mesh P, Q;
  if (!PMP::IO::read_polygon_mesh(argc > 1 ? argv[1] : CGAL_PMSUM_DATA_DIR "/star.off", P) ||
      !PMP::IO::read_polygon_mesh(argc > 2 ? argv[2] : CGAL_PMSUM_DATA_DIR "/cross.off", Q))
    return 1;
  for (Mesh* m : {&P, &Q}) PMP::orient_to_bound_a_volume(*m);
  const double d = argc > 3 ? std::atof(argv[3]) : 0.01;

  // Built once: points covering the contact space, and a kd-tree.
  auto pd = CGAL::Penetration_depth<Mesh, Mesh>::make(P, Q, d);
  std::cerr << pd.number_of_contact_points() << " contact points; enter translations x y z\n";
  double x, y, z;
  while (std::cin >> x >> y >> z) {
    const auto r = pd.query(K::Point_3(x, y, z));
    if (r.overlapping)
      std::cout << "overlap: depth " << r.depth << " (within " << d << "), move by " << r.depth * r.direction << "\n";
    else
      std::cout << "no overlap\n";
  }
  return 0;
}
