// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_minkowski_sum_coarse_to_fine(): the points of point_minkowski_sum() for several
// covering distances, coarse to fine, each level reusing the work of the coarser ones.

#ifndef CGAL_PMSUM_POINT_MINKOWSKI_SUM_COARSE_TO_FINE_H
#define CGAL_PMSUM_POINT_MINKOWSKI_SUM_COARSE_TO_FINE_H

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <vector>

namespace CGAL {

/// \ingroup PkgPointMinkowskiSumSum
/// Computes point_minkowski_sum() for the covering distances `ds[0] > ds[1] > ...`, coarse
/// to fine, and calls `level_output(k, statistics, records)` once level `k` is complete,
/// with its `CGAL::Pmsum::Statistics` and a `std::vector` of its
/// `CGAL::Pmsum::Minkowski_sum_boundary_point` records.
///
/// What does not depend on the covering distance is computed once: the input stage, the
/// normal filter, the collision filter's trees and the octree filter's interior
/// certificate. Each level samples P and Q with resolutions that are multiples of the
/// coarser level's (at least the resolutions a single run would use, so each level keeps
/// the guarantees of point_minkowski_sum()): every candidate of the coarser level is a
/// candidate again, and its decision, boundary point or not, is reused without a collision
/// test. Every level is exact and covers the boundary within its `ds[k]`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`, as for
///         point_minkowski_sum()
/// \tparam PolygonMeshP, PolygonMeshQ models of `FaceListGraph`, as for point_minkowski_sum()
/// \tparam LevelOutput a callable as `level_output(std::size_t k, const CGAL::Pmsum::Statistics& s,
///         std::vector<R>&& records)`, with `R` the record type
///         `CGAL::Pmsum::Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, GeomTraits>`
///         (`GeomTraits`: the geometric traits of `P`)
/// \tparam NamedParametersP, NamedParametersQ sequences of named parameters, as for
///         point_minkowski_sum()
///
/// \param P the first mesh
/// \param Q the second mesh
/// \param ds covering distances, each > 0, strictly decreasing
/// \param level_output called once per level, in the order of `ds`, with the level's index,
///        statistics and records
/// \param np_p named parameters of `P` and of the algorithm, as for point_minkowski_sum();
///        `statistics` receives the last level's.
/// \param np_q named parameters of `Q`, as for point_minkowski_sum()
///
/// \pre `ds` is non-empty and strictly decreasing; the other preconditions of
///      point_minkowski_sum(). Violations throw `CGAL::Pmsum::Invalid_input` before
///      `level_output` is called.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMeshP, class PolygonMeshQ, class LevelOutput,
          class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersQ = parameters::Default_named_parameters>
void point_minkowski_sum_coarse_to_fine(const PolygonMeshP& P, const PolygonMeshQ& Q, const std::vector<double>& ds,
                                        LevelOutput&& level_output,
                                        const NamedParametersP& np_p = parameters::default_values(),
                                        const NamedParametersQ& np_q = parameters::default_values())
{
  namespace in = Pmsum::internal;
  static_assert(!in::has_any_parameter<NamedParametersP, Pmsum::internal_np::roadmap_neighbors_t,
                                       Pmsum::internal_np::mesh_statistics_t>(),
                "CGAL_pmsum: roadmap_neighbors and mesh_statistics are not parameters of point_minkowski_sum_coarse_to_fine()");
  CGAL_precondition(!ds.empty());
  if (ds.empty()) throw Pmsum::Invalid_input("no covering distance given");
  for (std::size_t k = 0; k < ds.size(); ++k) {
    in::check_covering_distance(ds[k]);
    CGAL_precondition(k == 0 || ds[k] < ds[k - 1]);
    if (k > 0 && !(ds[k] < ds[k - 1])) throw Pmsum::Invalid_input("covering distances must decrease");
  }
  Pmsum::Statistics local_stats;
  const in::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(P, Q, ds[0], np_p,
                                                                                            np_q, local_stats);
  using Record = typename decltype(sum)::Record;
  in::Clock::time_point start = sum.start;
  in::Pipeline<ConcurrencyTag> pipeline(sum.mp, sum.mq, sum.options, /*coarse_to_fine=*/true);
  for (std::size_t k = 0; k < ds.size(); ++k) {
    std::vector<Record> records;
    auto out = std::back_inserter(records);
    sum.stats = Pmsum::Statistics();
    pipeline.run_level(ds[k], sum.stats, sum.make_emit(out), start);
    level_output(k, static_cast<const Pmsum::Statistics&>(sum.stats), std::move(records));
    start = in::Clock::now();
  }
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_MINKOWSKI_SUM_COARSE_TO_FINE_H
