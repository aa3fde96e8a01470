// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_minkowski_sum(): points covering the boundary of the Minkowski sum of two
// triangle meshes (J.-M. Lien, "Covering Minkowski sum boundary using points with
// applications", CAGD 2008), every point exactly on the boundary.
//
// Pipeline (one header per stage in internal/; pipeline.h wires them):
//   mesh_data.h      input checks, flat exact copy of P (or -P) and Q
//   sampling.h       d/2-coverings of every vertex, edge and facet, with origins
//   normal_filter.h  feature pairs whose sums can be on the boundary, and their directions
//   candidates.h     the candidates p + q of the kept pairs, in canonical order
//   octree_filter.h  octree cells of candidates certified inside the sum
//   decision.h       each candidate: reused, certified inner, covered by the net, or CD-tested
//   cd_filter.h      exact collision test of (-P + x) against Q, symbolically perturbed
//                    (its predicates: perturbed_predicates.h, shared with swept_cd.h)
//   covering_net.h   the output: a (d/2, d)-net of the boundary candidates
//   parallel.h       waves of feature pairs decided in parallel, committed in canonical order
//   sum_input.h      the input stage: named parameters read, meshes copied and checked
//   sum_output.h     the output function: points, or records with normal and provenance

#ifndef CGAL_PMSUM_POINT_MINKOWSKI_SUM_H
#define CGAL_PMSUM_POINT_MINKOWSKI_SUM_H

#include <CGAL_pmsum/Minkowski_sum_boundary_point.h>
#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/version.h>
#include <CGAL_pmsum/internal/pipeline.h>
#include <CGAL_pmsum/internal/sum_input.h>
#include <CGAL_pmsum/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cmath>
#include <functional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/// \ingroup PkgPointMinkowskiSumSum
/// Computes points that cover the boundary of the Minkowski sum `P + Q` (or `-P + Q`).
///
/// Every output point lies exactly on the boundary (decided with exact predicates and a
/// symbolic perturbation, no tolerance), and the output is a `d`-covering of the boundary:
/// every boundary point has an output point closer than `d`. By default it is a
/// (d/2, d)-net: no two lattice points of the output (records not `on_trim_curve`)
/// are closer than `d/2` (up to a margin of a few hundred
/// units in the last place of the largest coordinate), and candidates closer than `d/2` to an
/// output point are never CD-tested; `use_covering_net(false)` gives every boundary candidate
/// instead (the paper's output, many times larger). The samples of P and Q are
/// `d/2`-coverings, which leaves room for the boundary's concave creases, where the
/// paper's Theorem 2 alone would not guarantee `d`; points on the trim curves of the
/// convolution facets cover the passages of the sum narrower than the sample spacing, and
/// points of the islands (visible pieces of a facet strictly inside one lattice cell, e.g. a
/// tiny void) cover those (user manual, §4); `pmsum validate` measures coverage.
///
/// Closed components of a mesh are solids; components with borders are surfaces.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (TBB: link with
///         `CGAL::TBB_support`). The output is the same, in the same order, either way.
/// \tparam PolygonMeshP, PolygonMeshQ models of `FaceListGraph` (e.g. `Surface_mesh`, `Polyhedron_3`)
/// \tparam NamedParametersP, NamedParametersQ named parameter packs (`CGAL::parameters::...`)
/// \tparam OutputIterator receives `Point_3` of the geometric traits, or, if it accepts them,
///         `CGAL::Pmsum::Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, GeomTraits>`
///
/// \param P the first mesh
/// \param Q the second mesh
/// \param d covering distance, > 0
/// \param out where the points (or records) go
/// \param np_p named parameters for P and for the algorithm: `vertex_point_map`,
///        `geom_traits`, `use_normal_filter` (true), `use_cd_filter` (true), `use_octree_filter` (true),
///        `use_covering_net` (true), `use_trim_points` (true), `search_islands` (true),
///        `negate_first_mesh` (false), `callback` (a `std::function<bool(double)>` called with
///        the fraction done; returning false throws `CGAL::Pmsum::Operation_cancelled`),
///        `statistics` (a `CGAL::Pmsum::Statistics&` to fill), `maximum_number_of_candidates`,
///        `treat_as_surface` (false: closed components of P are solids), `check_overlaps` (true), `merge_flat_regions` (true),
///        `communicator` (a `CGAL::Pmsum::Communicator*`, nullptr: one process; with ranks,
///        every rank calls this with the same input and returns the same output).
/// \param np_q named parameters for Q: `vertex_point_map`, `treat_as_surface`
///        (an algorithm parameter here is a compile-time error).
/// \returns the output iterator past the last point written
///
/// \pre `d > 0` and finite
/// \pre P and Q are non-empty triangle meshes without degenerate faces, with finite
///      coordinates exactly representable as `double`; closed components are oriented outward
///      and do not overlap each other (touching and nesting are fine).
/// \pre with `check_overlaps(false)`: closed components known not to cross themselves or each other (not checked).
/// Violations throw `CGAL::Pmsum::Invalid_input`; nothing is written to `out` then.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMeshP, class PolygonMeshQ,
          class OutputIterator, class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersQ = parameters::Default_named_parameters>
OutputIterator point_minkowski_sum(const PolygonMeshP& P, const PolygonMeshQ& Q, double d, OutputIterator out,
                                   const NamedParametersP& np_p = parameters::default_values(),
                                   const NamedParametersQ& np_q = parameters::default_values())
{
  static_assert(!Pmsum::internal::has_any_parameter<NamedParametersP, Pmsum::internal_np::roadmap_neighbors_t,
                                                    Pmsum::internal_np::mesh_statistics_t>(),
                "CGAL_pmsum: roadmap_neighbors and mesh_statistics are not parameters of point_minkowski_sum()");
  Pmsum::Statistics local_stats;
  const Pmsum::internal::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(
    P, Q, d, np_p, np_q, local_stats);
  Pmsum::internal::run_pipeline<ConcurrencyTag>(sum.mp, sum.mq, d, sum.options, sum.stats, sum.make_emit(out),
                                                sum.start);
  return out;
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_MINKOWSKI_SUM_H
