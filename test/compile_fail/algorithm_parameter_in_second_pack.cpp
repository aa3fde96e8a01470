#include "common.h"

int main()
{
  Mesh P, Q;
  std::vector<IK::Point_3> out;
  // use_cd_filter is the algorithm's: it belongs in the first pack
  CGAL::point_minkowski_sum(P, Q, 0.1, std::back_inserter(out), CGAL::parameters::default_values(),
                            CGAL::parameters::use_cd_filter(false));
}
