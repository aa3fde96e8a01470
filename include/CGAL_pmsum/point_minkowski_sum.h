// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// CGAL::point_minkowski_sum(): points covering the boundary of the Minkowski sum of two
// triangle meshes (J.-M. Lien, "Covering Minkowski sum boundary using points with
// applications", CAGD 2008), every point exactly on the boundary.
//
// Pipeline (one header per stage in internal/):
//   mesh_data.h      input checks, flat exact copy of P (or -P) and Q
//   sampling.h       d-coverings of every vertex, edge and facet, with origins
//   normal_filter.h  feature pairs whose sums can be on the boundary, and their directions
//   cd_filter.h      exact collision test of (-P + x) against Q, symbolically perturbed
//   and this file    enumerates the candidates of the kept pairs and writes the output

#ifndef CGAL_PMSUM_POINT_MINKOWSKI_SUM_H
#define CGAL_PMSUM_POINT_MINKOWSKI_SUM_H

#include <CGAL_pmsum/Minkowski_sum_boundary_point.h>
#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/cd_filter.h>
#include <CGAL_pmsum/internal/mesh_data.h>
#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/sampling.h>
#include <CGAL_pmsum/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
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

/// Fills the public Mesh_feature of a sample.
template <class PolygonMesh>
Mesh_feature<PolygonMesh> to_mesh_feature(const Sample& s, const Mesh_descriptors<PolygonMesh>& desc)
{
  Mesh_feature<PolygonMesh> f;
  f.dimension = s.origin.dimension;
  if (f.dimension == 0) f.vertex = desc.vertices[s.origin.index];
  else if (f.dimension == 1) f.halfedge = desc.edges[s.origin.index];
  else f.face = desc.faces[s.origin.index];
  for (int i = 0; i < 3; ++i) {
    f.vertices[i] = desc.vertices[s.vertices[i]];
    f.weights[i] = s.weights[i];
  }
  f.denominator = s.denominator;
  return f;
}

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t)
{ return std::chrono::duration<double>(Clock::now() - t).count(); }

} // namespace internal
} // namespace Pmsum

/// \ingroup PkgPointMinkowskiSumRef
/// Computes points that cover the boundary of the Minkowski sum `P + Q` (or `-P + Q`).
///
/// Every output point lies exactly on the boundary (decided with exact predicates and a
/// symbolic perturbation, no tolerance), and the output is a `d`-covering of the boundary:
/// every boundary point has an output point closer than `d`. The samples of P and Q are
/// `d/2`-coverings, which leaves room for the boundary's concave creases, where the
/// paper's Theorem 2 alone would not guarantee `d`. Exception: in passages of the sum
/// narrower than the sample spacing, a boundary facet can be a strip without samples
/// (see the user manual, "Known limits"); `pmsum validate` measures coverage.
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
///        `geom_traits`, `use_normal_filter` (true), `use_cd_filter` (true),
///        `negate_first_mesh` (false), `callback` (a `std::function<bool(double)>` called with
///        the fraction done; returning false throws `CGAL::Pmsum::Operation_cancelled`),
///        `statistics` (a `CGAL::Pmsum::Statistics&` to fill), `maximum_number_of_candidates`,
///        `treat_as_surface` (false: closed components of P are solids).
/// \param np_q named parameters for Q: `vertex_point_map`, `treat_as_surface`.
///
/// \pre `d > 0` and finite
/// \pre P and Q are non-empty triangle meshes without degenerate faces, with finite
///      coordinates exactly representable as `double`; closed components are oriented outward
///      and do not overlap each other (touching and nesting are fine).
/// Violations throw `CGAL::Pmsum::Invalid_input`; nothing is written to `out` then.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMeshP, class PolygonMeshQ,
          class OutputIterator, class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersQ = parameters::Default_named_parameters>
OutputIterator point_minkowski_sum(const PolygonMeshP& P, const PolygonMeshQ& Q, double d, OutputIterator out,
                                   const NamedParametersP& np_p = parameters::default_values(),
                                   const NamedParametersQ& np_q = parameters::default_values())
{
  namespace in = Pmsum::internal;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using GT = typename GetGeomTraits<PolygonMeshP, NamedParametersP>::type;
  using Record = Pmsum::Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, GT>;
  using FT = typename GT::FT;

  const auto vpm_p = choose_parameter(get_parameter(np_p, internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, P));
  const auto vpm_q = choose_parameter(get_parameter(np_q, internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, Q));
  const bool use_normal_filter = choose_parameter(get_parameter(np_p, Pmsum::internal_np::use_normal_filter), true);
  const bool use_cd_filter = choose_parameter(get_parameter(np_p, Pmsum::internal_np::use_cd_filter), true);
  const bool negate_p = choose_parameter(get_parameter(np_p, Pmsum::internal_np::negate_first_mesh), false);
  const std::size_t max_candidates = choose_parameter(
    get_parameter(np_p, Pmsum::internal_np::maximum_number_of_candidates), std::size_t(-1));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np_p, internal_np::callback), std::function<bool(double)>());
  Pmsum::Statistics local_stats;
  Pmsum::Statistics& stats = *choose_parameter(get_parameter(np_p, Pmsum::internal_np::statistics), &local_stats);
  stats = Pmsum::Statistics();

  CGAL_precondition_msg(d > 0 && std::isfinite(d), "d must be positive and finite");
  if (!(d > 0) || !std::isfinite(d))
    throw Pmsum::Invalid_input("d must be positive and finite (got " + std::to_string(d) + ")");

  // Stage 0: input.
  auto start = in::Clock::now();
  in::Mesh_descriptors<PolygonMeshP> desc_p;
  in::Mesh_descriptors<PolygonMeshQ> desc_q;
  const in::Mesh_data mp = in::make_mesh_data(
    P, vpm_p, negate_p, choose_parameter(get_parameter(np_p, Pmsum::internal_np::treat_as_surface), false), "P", desc_p);
  const in::Mesh_data mq = in::make_mesh_data(
    Q, vpm_q, false, choose_parameter(get_parameter(np_q, Pmsum::internal_np::treat_as_surface), false), "Q", desc_q);

  // Stage 1: sampling resolutions (samples themselves are generated per pair).
  const double radius = d / 2;
  const in::Mesh_sampling sp(mp, radius, "P"), sq(mq, radius, "Q");
  stats.samples_p = sp.number_of_samples();
  stats.samples_q = sq.number_of_samples();
  std::optional<in::Cd_geometry> geometry; // AABB trees
  if (use_cd_filter) geometry.emplace(mp, mq);
  stats.seconds_setup = in::seconds_since(start);

  // Stage 2: normal filter.
  start = in::Clock::now();
  const in::Candidate_pairs pairs = in::candidate_feature_pairs(mp, mq, use_normal_filter);
  std::vector<std::size_t> work(pairs.pairs.size());
  std::size_t total = 0;
  for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
    work[i] = sp.number_of_samples(pairs.pairs[i].p) * sq.number_of_samples(pairs.pairs[i].q);
    total += work[i];
  }
  stats.feature_pairs = pairs.pairs.size();
  stats.candidates = total;
  stats.seconds_normal_filter = in::seconds_since(start);
  if (total > max_candidates) throw Pmsum::Too_many_candidates(total, max_candidates);

  // Stage 3: candidates of each kept pair, CD filter, output. Feature pairs are processed
  // in waves; within a wave, in parallel with CGAL::Parallel_tag. Each pair's kept samples
  // are buffered, then emitted on this thread in the pairs' order: the output is the same
  // for any number of threads, and kernel constructions (Epeck's lazy numbers are not
  // thread-safe) and the callback stay on the calling thread.
  start = in::Clock::now();
  struct Kept { in::Sample p, q; std::uint32_t direction; }; // absolute index in pairs.directions
  auto filter_pair = [&](std::size_t i, in::Cd_filter* filter, std::vector<Kept>& kept) {
    const in::Feature_pair& fp = pairs.pairs[i];
    std::vector<in::Sample> samples_p, samples_q;
    sp.samples(fp.p, samples_p);
    sq.samples(fp.q, samples_q);
    const in::Direction* dirs = pairs.directions.data() + fp.first_direction;
    for (const in::Sample& s_p : samples_p)
      for (const in::Sample& s_q : samples_q) {
        if (!filter) { kept.push_back({s_p, s_q, fp.first_direction}); continue; }
        for (std::uint32_t k = 0; k < fp.number_of_directions; ++k)
          if (filter->is_free(s_p, s_q, dirs, fp.number_of_directions, k)) {
            kept.push_back({s_p, s_q, fp.first_direction + k});
            break;
          }
      }
  };
  auto coordinate = [&](const in::Mesh_data& M, const in::Sample& s, int c) {
    // FT arithmetic: exact with an exact kernel, rounded otherwise.
    FT v(0);
    for (int i = 0; i < 3; ++i)
      if (s.weights[i] != 0) v += FT(s.weights[i]) * FT(M.points[s.vertices[i]][c]);
    return v / FT(s.denominator);
  };
  auto emit = [&](const Kept& k) {
    ++stats.output_points;
    const typename GT::Point_3 x(coordinate(mp, k.p, 0) + coordinate(mq, k.q, 0),
                                 coordinate(mp, k.p, 1) + coordinate(mq, k.q, 1),
                                 coordinate(mp, k.p, 2) + coordinate(mq, k.q, 2));
    if constexpr (Pmsum::internal::Accepts_record<OutputIterator, Record>::value) {
      const auto n = pairs.directions[k.direction].template vector<double>(mp, mq);
      const double len = std::sqrt(in::dot(n, n));
      Record r{x, typename GT::Vector_3(n[0] / len, n[1] / len, n[2] / len), in::to_mesh_feature(k.p, desc_p),
               in::to_mesh_feature(k.q, desc_q), negate_p};
      *out++ = r;
    } else {
      *out++ = x;
    }
  };

  constexpr bool parallel =
#ifdef CGAL_LINKED_WITH_TBB
    std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#else
    false;
#endif
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value || parallel,
                "CGAL::Parallel_tag needs TBB (link with CGAL::TBB_support)");
  Pmsum::Statistics cd_stats;
  auto add_cd_stats = [&](const in::Cd_filter& f) {
    cd_stats.cd_queries += f.statistics().queries;
    cd_stats.triangle_pairs += f.statistics().triangle_pairs;
    cd_stats.containment_tests += f.statistics().containment_tests;
  };
  // Waves of about 1/200 of the work (progress granularity), at least one pair each.
  const std::size_t wave_work = (std::max<std::size_t>)(1, total / 200);
  std::size_t done = 0;
  std::vector<std::vector<Kept>> buffers;
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::enumerable_thread_specific<in::Cd_filter>> filters;
  if (parallel && geometry)
    filters = std::make_unique<tbb::enumerable_thread_specific<in::Cd_filter>>(&*geometry);
#endif
  std::optional<in::Cd_filter> sequential_filter;
  if (!parallel && geometry) sequential_filter.emplace(&*geometry);
  for (std::size_t first = 0; first < pairs.pairs.size();) {
    std::size_t last = first, wave = 0;
    while (last < pairs.pairs.size() && (wave < wave_work || last == first)) wave += work[last++];
    buffers.assign(last - first, {});
    if constexpr (parallel) {
#ifdef CGAL_LINKED_WITH_TBB
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last), [&](const tbb::blocked_range<std::size_t>& r) {
        in::Cd_filter* f = filters ? &filters->local() : nullptr;
        for (std::size_t i = r.begin(); i != r.end(); ++i) filter_pair(i, f, buffers[i - first]);
      });
#endif
    } else {
      for (std::size_t i = first; i < last; ++i)
        filter_pair(i, sequential_filter ? &*sequential_filter : nullptr, buffers[i - first]);
    }
    for (const auto& b : buffers)
      for (const Kept& k : b) emit(k);
    done += wave;
    first = last;
    if (callback && !callback(total == 0 ? 1. : double(done) / double(total))) throw Pmsum::Operation_cancelled();
  }
  if (sequential_filter) add_cd_stats(*sequential_filter);
#ifdef CGAL_LINKED_WITH_TBB
  if (filters)
    for (const in::Cd_filter& f : *filters) add_cd_stats(f);
#endif
  stats.cd_queries = cd_stats.cd_queries;
  stats.triangle_pairs = cd_stats.triangle_pairs;
  stats.containment_tests = cd_stats.containment_tests;
  stats.seconds_cd_filter = in::seconds_since(start);
  return out;
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_MINKOWSKI_SUM_H
