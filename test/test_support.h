// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Runs point_minkowski_sum on test shapes and checks its output against a Reference.

#ifndef CGAL_PMSUM_TEST_SUPPORT_H
#define CGAL_PMSUM_TEST_SUPPORT_H

#include "reference.h"

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Surface_mesh.h>

#include <string>
#include <vector>

namespace pmsum_test {

using Mesh = CGAL::Surface_mesh<IK::Point_3>;
using Record = CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, IK>;

struct Result
{
  std::vector<Record> records;
  std::vector<IK::Point_3> points;
  std::vector<EK::Point_3> exact;
  CGAL::Pmsum::Statistics stats;
};

/// `np` must start with a CGAL_pmsum parameter (they chain `statistics`).
template <class NP = decltype(CGAL::parameters::use_normal_filter(true))>
Result run(const Soup& P, const Soup& Q, double d, const NP& np = CGAL::parameters::use_normal_filter(true))
{
  const Mesh mp = to_mesh<Mesh>(P), mq = to_mesh<Mesh>(Q);
  Result r;
  CGAL::point_minkowski_sum(mp, mq, d, std::back_inserter(r.records), np.statistics(r.stats));
  for (const Record& rec : r.records) {
    r.points.push_back(rec.point);
    r.exact.push_back(CGAL::Pmsum::exact_point<EK>(rec, get(CGAL::vertex_point, mp), get(CGAL::vertex_point, mq)));
  }
  return r;
}

/// Number of output points not exactly on the reference boundary.
inline std::size_t exactness_failures(const Result& r, const Reference& ref)
{
  std::size_t bad = 0;
  for (const auto& x : r.exact) bad += !ref.on_boundary(x);
  return bad;
}

} // namespace pmsum_test

#endif // CGAL_PMSUM_TEST_SUPPORT_H
