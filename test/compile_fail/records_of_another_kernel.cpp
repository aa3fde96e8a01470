#include "common.h"

int main()
{
  Mesh P, Q;
  // P's kernel is Epick: records of Epeck cannot be written
  std::vector<CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, EK>> out;
  CGAL::point_minkowski_sum(P, Q, 0.1, std::back_inserter(out));
}
