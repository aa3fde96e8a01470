// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs point_minkowski_sum on test shapes and checks its output against a Reference.

#ifndef CGAL_PMSUM_TEST_SUPPORT_H
#define CGAL_PMSUM_TEST_SUPPORT_H

#include "reference.h"

#include <CGAL_pmsum/measure_boundary_coverage.h>
#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Surface_mesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace pmsum_shapes {

using Mesh = CGAL::Surface_mesh<IK::Point_3>;
using Record = CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, IK>;

/// Is the record a trim-curve point (between lattice samples)?
inline bool is_trim_point(const Record& r) { return r.on_trim_curve; }

/// The points of the records that are lattice sums (not trim points).
inline std::vector<IK::Point_3> lattice_points(const std::vector<Record>& records)
{
  std::vector<IK::Point_3> r;
  for (const Record& x : records)
    if (!is_trim_point(x)) r.push_back(x.point);
  return r;
}

inline std::vector<IK::Point_3> all_points(const std::vector<Record>& records)
{
  std::vector<IK::Point_3> r;
  for (const Record& x : records) r.push_back(x.point);
  return r;
}

struct Result
{
  std::vector<Record> records;
  std::vector<IK::Point_3> points;
  std::vector<EK::Point_3> exact;
  CGAL::Pmsum::Statistics stats;
};

/// `np` must start with a CGAL_pmsum parameter (they chain `statistics`).
/// P (negated) and Q as the CD filter of their sum takes them.
inline std::pair<CGAL::Pmsum::internal::Mesh_data, CGAL::Pmsum::internal::Mesh_data> cd_operands(const Soup& ps,
                                                                                              const Soup& qs)
{
  using namespace CGAL::Pmsum::internal;
  const Mesh pm = to_mesh<Mesh>(ps), qm = to_mesh<Mesh>(qs);
  Mesh_descriptors<Mesh> dp, dq;
  return {make_mesh_data(pm, get(CGAL::vertex_point, pm), true, false, "P", dp),
          make_mesh_data(qm, get(CGAL::vertex_point, qm), false, false, "Q", dq)};
}

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

/// Runs P + Q twice, with the default net and with every boundary candidate
/// (use_covering_net(false)), with the parameters `np` (a CGAL_pmsum parameter first); checks
/// both for exactness and coverage against `ref`, and the net against the candidates.
/// Returns {net, all}.
template <class NP = decltype(CGAL::parameters::use_normal_filter(true))>
std::pair<Result, Result> check_net_and_all(const Soup& P, const Soup& Q, double d, const Reference& ref,
                                            const NP& np = CGAL::parameters::use_normal_filter(true));

/// The smallest distance between two of the lattice points of `records` inside convolution
/// facets (vertex + face, edge + edge: one outward normal, the record's) that do not face each
/// other (normals at most 120 degrees apart): the covering net keeps facing points, the two
/// walls of a passage, closer than d/2. (A point on a crease has the normals of its pair's
/// cone, which a record does not give.)
inline double spacing_of_unfacing(const std::vector<Record>& records, double reach)
{
  std::vector<const Record*> r;
  for (const Record& x : records)
    if (!is_trim_point(x) && x.origin_p.dimension + x.origin_q.dimension == 2) r.push_back(&x);
  std::sort(r.begin(), r.end(), [](const Record* a, const Record* b) { return a->point.x() < b->point.x(); });
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t j = i + 1; j < r.size() && r[j]->point.x() - r[i]->point.x() < (std::min)(best, reach); ++j)
      if (!(r[i]->normal * r[j]->normal < -0.5))
        best = (std::min)(best, std::sqrt(CGAL::squared_distance(r[i]->point, r[j]->point)));
  return best;
}

/// The default output `net` against every boundary candidate `all` (use_covering_net(false)):
/// its lattice points are boundary candidates, no two that do not face each other closer than
/// d/2 (up to the rounding margin), and every boundary candidate is closer than d/2 to one of
/// its points. (Trim points are not lattice sums, and may be closer to other points.)
inline void check_covering_net(const std::vector<Record>& net_records, const std::vector<Record>& all_records, double d)
{
  const std::vector<IK::Point_3> net = lattice_points(net_records), all = lattice_points(all_records);
  INFO("net " << net.size() << " lattice points (of " << net_records.size() << ") and " << all.size()
              << " boundary candidates");
  REQUIRE(!net.empty());
  std::set<std::tuple<double, double, double>> candidates;
  for (const auto& p : all) candidates.insert({p.x(), p.y(), p.z()});
  std::size_t outside = 0;
  for (const auto& p : net) outside += candidates.count({p.x(), p.y(), p.z()}) == 0;
  CHECK(outside == 0);
  const double spacing = spacing_of_unfacing(net_records, d);
  INFO("minimum spacing of points that do not face each other " << spacing / d << " d");
  CHECK(spacing >= d / 2 * (1 - 1e-9));
  const double cover = coverage_distance(all, all_points(net_records));
  INFO("boundary candidates within " << cover / d << " d of the net");
  CHECK(cover < d / 2);
}

template <class NP>
std::pair<Result, Result> check_net_and_all(const Soup& P, const Soup& Q, double d, const Reference& ref, const NP& np)
{
  const auto samples = ref.boundary_samples(d / 8);
  std::pair<Result, Result> r{run(P, Q, d, np.use_covering_net(true)), run(P, Q, d, np.use_covering_net(false))};
  for (const Result* x : {&r.first, &r.second}) {
    INFO((x == &r.first ? "net: " : "all candidates: ") << x->points.size() << " points, candidates " << x->stats.candidates);
    REQUIRE(!x->points.empty());
    CHECK(exactness_failures(*x, ref) == 0);
    const double cover = coverage_distance(samples, x->points);
    INFO("coverage " << cover / d << " d");
    CHECK(cover < d);
  }
  check_covering_net(r.first.records, r.second.records, d);
  return r;
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_TEST_SUPPORT_H
