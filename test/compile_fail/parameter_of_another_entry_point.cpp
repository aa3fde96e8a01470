#include "common.h"

#include <CGAL_pmsum/point_sweep.h>

int main()
{
  Mesh P;
  const std::vector<IK::Point_3> path = {IK::Point_3(0, 0, 0), IK::Point_3(1, 0, 0)};
  std::vector<IK::Point_3> out;
  // roadmap_neighbors is the planner's: the sweep would ignore it
  CGAL::point_sweep(P, path, 0.1, std::back_inserter(out), CGAL::parameters::roadmap_neighbors(3));
}
