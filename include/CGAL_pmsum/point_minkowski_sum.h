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
//   and this file    named parameters, the input stage, and the output records

#ifndef CGAL_PMSUM_POINT_MINKOWSKI_SUM_H
#define CGAL_PMSUM_POINT_MINKOWSKI_SUM_H

#include <CGAL_pmsum/Minkowski_sum_boundary_point.h>
#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/version.h>
#include <CGAL_pmsum/internal/mesh_data.h>
#include <CGAL_pmsum/internal/pipeline.h>
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
namespace Pmsum {
namespace internal {

/// Does `*out = r` compile? Then the output iterator receives records, else points.
template <class OutputIterator, class Record, class = void>
struct Accepts_record : std::false_type {};
template <class OutputIterator, class Record>
struct Accepts_record<OutputIterator, Record,
                      std::void_t<decltype(*std::declval<OutputIterator&>() = std::declval<const Record&>())>>
  : std::true_type {};

/// Fills the public Mesh_feature of a sample s, or of side `side`'s part of the trim point of
/// `trim` (s: that side's sample of its first corner).
template <class PolygonMesh>
Mesh_feature<PolygonMesh> to_mesh_feature(const Sample& s, const Mesh_descriptors<PolygonMesh>& desc,
                                          const Trim* trim = nullptr, int side = 0)
{
  Mesh_feature<PolygonMesh> f;
  const Feature o = trim ? (side == 0 ? trim->origin_p : trim->origin_q) : s.origin;
  f.dimension = o.dimension;
  if (f.dimension == 0) f.vertex = desc.vertices[o.index];
  else if (f.dimension == 1) f.halfedge = desc.edges[o.index];
  else f.face = desc.faces[o.index];
  for (int i = 0; i < 3; ++i) {
    f.vertices[i] = desc.vertices[s.vertices[i]];
    f.weights[i] = s.weights[i];
  }
  f.denominator = s.denominator;
  if (trim) f.rational_weights = trim_weights(s, *trim, side);
  return f;
}

/// The input stage of a sum: the named parameters read, P (or -P) and Q copied and checked.
/// make_emit(out) gives the pipeline's emit function writing records (or points) to out.
template <class PolygonMeshP, class PolygonMeshQ, class NamedParametersP, class NamedParametersQ>
struct Prepared_sum
{
  using GT = typename GetGeomTraits<PolygonMeshP, NamedParametersP>::type;
  using Record = Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, GT>;
  using FT = typename GT::FT;

  Prepared_sum(const PolygonMeshP& P, const PolygonMeshQ& Q, double d, const NamedParametersP& np_p,
               const NamedParametersQ& np_q, Statistics& local_stats)
    : stats(*parameters::choose_parameter(parameters::get_parameter(np_p, internal_np::statistics), &local_stats))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const auto vpm_p = choose_parameter(get_parameter(np_p, CGAL::internal_np::vertex_point),
                                        get_const_property_map(CGAL::vertex_point, P));
    const auto vpm_q = choose_parameter(get_parameter(np_q, CGAL::internal_np::vertex_point),
                                        get_const_property_map(CGAL::vertex_point, Q));
    options.use_normal_filter = choose_parameter(get_parameter(np_p, internal_np::use_normal_filter), true);
    options.use_cd_filter = choose_parameter(get_parameter(np_p, internal_np::use_cd_filter), true);
    options.use_octree_filter = choose_parameter(get_parameter(np_p, internal_np::use_octree_filter), true);
    options.use_covering_net = choose_parameter(get_parameter(np_p, internal_np::use_covering_net), true);
    options.use_trim_points = choose_parameter(get_parameter(np_p, internal_np::use_trim_points), true);
    options.search_islands = choose_parameter(get_parameter(np_p, internal_np::search_islands), true);
    options.max_candidates =
      choose_parameter(get_parameter(np_p, internal_np::maximum_number_of_candidates), std::size_t(-1));
    options.callback =
      choose_parameter(get_parameter(np_p, CGAL::internal_np::callback), std::function<bool(double)>());
    negate_p = choose_parameter(get_parameter(np_p, internal_np::negate_first_mesh), false);
    stats = Statistics();

    check_covering_distance(d);
    start = Clock::now();
    const bool check_overlaps = choose_parameter(get_parameter(np_p, internal_np::check_overlaps), true);
    mp = make_mesh_data(P, vpm_p, negate_p, choose_parameter(get_parameter(np_p, internal_np::treat_as_surface), false),
                        "P", desc_p, check_overlaps);
    mq = make_mesh_data(Q, vpm_q, false, choose_parameter(get_parameter(np_q, internal_np::treat_as_surface), false),
                        "Q", desc_q, check_overlaps);
  }

  /// emit(p, q, direction, trim) for the pipeline: writes a Record, or a Point_3 if `out` takes no
  /// records, to out.
  template <class OutputIterator>
  auto make_emit(OutputIterator& out) const
  {
    return [this, &out](const Sample& sp, const Sample& sq, const Direction& direction, const Trim* trim) {
      const typename GT::Point_3 x(sum_coordinate<FT>(mp, mq, sp, sq, trim, 0), sum_coordinate<FT>(mp, mq, sp, sq, trim, 1),
                                   sum_coordinate<FT>(mp, mq, sp, sq, trim, 2));
      if constexpr (Accepts_record<OutputIterator, Record>::value) {
        const auto n = direction.template vector<double>(mp, mq);
        const double len = std::sqrt(dot(n, n));
        Record r{x, typename GT::Vector_3(n[0] / len, n[1] / len, n[2] / len),
                 to_mesh_feature(sp, desc_p, trim, 0), to_mesh_feature(sq, desc_q, trim, 1),
                 negate_p};
        *out++ = r;
      } else {
        *out++ = x;
      }
    };
  }

  Statistics& stats;
  Pipeline_options options;
  bool negate_p = false;
  Clock::time_point start;
  Mesh_descriptors<PolygonMeshP> desc_p;
  Mesh_descriptors<PolygonMeshQ> desc_q;
  Mesh_data mp, mq;
};

} // namespace internal
} // namespace Pmsum

/// \ingroup PkgPointMinkowskiSumRef
/// Computes points that cover the boundary of the Minkowski sum `P + Q` (or `-P + Q`).
///
/// Every output point lies exactly on the boundary (decided with exact predicates and a
/// symbolic perturbation, no tolerance), and the output is a `d`-covering of the boundary:
/// every boundary point has an output point closer than `d`. By default it is a
/// (d/2, d)-net: no two lattice points of the output (records without `rational_weights`)
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
/// \tparam OutputIterator receives `Point_3` of the geometric traits, or, if it accepts them,
///         `CGAL::Pmsum::Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, GeomTraits>`
///
/// \param d covering distance, > 0
/// \param np_p named parameters for P and for the algorithm: `vertex_point_map`,
///        `geom_traits`, `use_normal_filter` (true), `use_cd_filter` (true), `use_octree_filter` (true),
///        `use_covering_net` (true), `use_trim_points` (true), `search_islands` (true),
///        `negate_first_mesh` (false), `callback` (a `std::function<bool(double)>` called with
///        the fraction done; returning false throws `CGAL::Pmsum::Operation_cancelled`),
///        `statistics` (a `CGAL::Pmsum::Statistics&` to fill), `maximum_number_of_candidates`,
///        `treat_as_surface` (false: closed components of P are solids), `check_overlaps` (true).
/// \param np_q named parameters for Q: `vertex_point_map`, `treat_as_surface`.
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
  Pmsum::Statistics local_stats;
  const Pmsum::internal::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(
    P, Q, d, np_p, np_q, local_stats);
  Pmsum::internal::run_pipeline<ConcurrencyTag>(sum.mp, sum.mq, d, sum.options, sum.stats, sum.make_emit(out),
                                                sum.start);
  return out;
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_MINKOWSKI_SUM_H
