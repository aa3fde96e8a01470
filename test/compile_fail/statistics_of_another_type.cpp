#include "common.h"

int main()
{
  Mesh P, Q;
  std::vector<IK::Point_3> out;
  int statistics = 0;
  CGAL::point_minkowski_sum(P, Q, 0.1, std::back_inserter(out), CGAL::parameters::statistics(statistics));
}
