// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The pipeline after the input stage, on two prepared meshes:
//   stage 1  sampling resolutions (sampling.h) and the CD filter's AABB trees (cd_filter.h)
//   stage 2  the normal filter: kept feature pairs and their directions (normal_filter.h)
//   stage 3  the candidates p + q of each kept pair, the CD filter, and emit(p, q, direction)
//            for every boundary point, on the calling thread, in canonical order.
// Stage 3 runs in waves of feature pairs, in parallel with CGAL::Parallel_tag.

#ifndef CGAL_PMSUM_INTERNAL_PIPELINE_H
#define CGAL_PMSUM_INTERNAL_PIPELINE_H

#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/cd_filter.h>
#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/sampling.h>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <chrono>
#include <cmath>
#include <string>
#include <functional>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t)
{ return std::chrono::duration<double>(Clock::now() - t).count(); }

/// The covering distance precondition of every entry point: d > 0 and finite.
inline void check_covering_distance(double d)
{
  CGAL_precondition_msg(d > 0 && std::isfinite(d), "d must be positive and finite");
  if (!(d > 0) || !std::isfinite(d))
    throw Invalid_input("d must be positive and finite (got " + std::to_string(d) + ")");
}

struct Pipeline_options
{
  bool use_normal_filter = true;
  bool use_cd_filter = true;
  std::size_t max_candidates = std::size_t(-1);
  std::function<bool(double)> callback; // progress in [0, 1]; false cancels
};

/// Stages 1 to 3 (see the file comment). `start` is when the input stage began.
template <class ConcurrencyTag, class Emit>
void run_pipeline(const Mesh_data& mp, const Mesh_data& mq, double d, const Pipeline_options& o,
                  Statistics& stats, Emit&& emit, Clock::time_point start)
{
  // Stage 1: sampling resolutions (samples themselves are generated per pair).
  const double radius = d / 2;
  const Mesh_sampling sp(mp, radius, "P"), sq(mq, radius, "Q");
  stats.samples_p = sp.number_of_samples();
  stats.samples_q = sq.number_of_samples();
  std::optional<Cd_geometry> geometry; // AABB trees
  if (o.use_cd_filter) geometry.emplace(mp, mq);
  stats.seconds_setup = seconds_since(start);

  // Stage 2: normal filter.
  start = Clock::now();
  const Candidate_pairs pairs = candidate_feature_pairs(mp, mq, o.use_normal_filter);
  std::vector<std::size_t> work(pairs.pairs.size());
  std::size_t total = 0;
  for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
    work[i] = sp.number_of_samples(pairs.pairs[i].p) * sq.number_of_samples(pairs.pairs[i].q);
    total += work[i];
  }
  stats.feature_pairs = pairs.pairs.size();
  stats.candidates = total;
  stats.seconds_normal_filter = seconds_since(start);
  if (total > o.max_candidates) throw Too_many_candidates(total, o.max_candidates);

  // Stage 3: candidates of each kept pair, CD filter, output. Feature pairs are processed
  // in waves; within a wave, in parallel with CGAL::Parallel_tag. Each pair's kept samples
  // are buffered, then emitted on this thread in the pairs' order: the output is the same
  // for any number of threads, and kernel constructions (Epeck's lazy numbers are not
  // thread-safe) and the callback stay on the calling thread.
  start = Clock::now();
  struct Kept { Sample p, q; std::uint32_t direction; }; // absolute index in pairs.directions
  auto filter_pair = [&](std::size_t i, Cd_filter* filter, std::vector<Kept>& kept) {
    const Feature_pair& fp = pairs.pairs[i];
    std::vector<Sample> samples_p, samples_q;
    sp.samples(fp.p, samples_p);
    sq.samples(fp.q, samples_q);
    const Direction* dirs = pairs.directions.data() + fp.first_direction;
    for (const Sample& s_p : samples_p)
      for (const Sample& s_q : samples_q) {
        if (!filter) { kept.push_back({s_p, s_q, fp.first_direction}); continue; }
        for (std::uint32_t k = 0; k < fp.number_of_directions; ++k) {
          if (filter->is_free(s_p, s_q, dirs, fp.number_of_directions, k)) {
            kept.push_back({s_p, s_q, fp.first_direction + k});
            break;
          }
          if (filter->decided_without_perturbation()) break; // the same for every direction
        }
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
  Statistics cd_stats;
  auto add_cd_stats = [&](const Cd_filter& f) {
    cd_stats.cd_queries += f.statistics().queries;
    cd_stats.triangle_pairs += f.statistics().triangle_pairs;
    cd_stats.containment_tests += f.statistics().containment_tests;
  };
  // Waves of about 1/200 of the work (progress granularity), at least one pair each.
  const std::size_t wave_work = (std::max<std::size_t>)(1, total / 200);
  std::size_t done = 0;
  std::vector<std::vector<Kept>> buffers;
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::enumerable_thread_specific<Cd_filter>> filters;
  if (parallel && geometry)
    filters = std::make_unique<tbb::enumerable_thread_specific<Cd_filter>>(&*geometry);
#endif
  std::optional<Cd_filter> sequential_filter;
  if (!parallel && geometry) sequential_filter.emplace(&*geometry);
  for (std::size_t first = 0; first < pairs.pairs.size();) {
    std::size_t last = first, wave = 0;
    while (last < pairs.pairs.size() && (wave < wave_work || last == first)) wave += work[last++];
    buffers.assign(last - first, {});
    if constexpr (parallel) {
#ifdef CGAL_LINKED_WITH_TBB
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last), [&](const tbb::blocked_range<std::size_t>& r) {
        Cd_filter* f = filters ? &filters->local() : nullptr;
        for (std::size_t i = r.begin(); i != r.end(); ++i) filter_pair(i, f, buffers[i - first]);
      });
#endif
    } else {
      for (std::size_t i = first; i < last; ++i)
        filter_pair(i, sequential_filter ? &*sequential_filter : nullptr, buffers[i - first]);
    }
    for (const auto& b : buffers)
      for (const Kept& k : b) {
        ++stats.output_points;
        emit(k.p, k.q, pairs.directions[k.direction]);
      }
    done += wave;
    first = last;
    if (o.callback && !o.callback(total == 0 ? 1. : double(done) / double(total))) throw Operation_cancelled();
  }
  if (sequential_filter) add_cd_stats(*sequential_filter);
#ifdef CGAL_LINKED_WITH_TBB
  if (filters)
    for (const Cd_filter& f : *filters) add_cd_stats(f);
#endif
  stats.cd_queries = cd_stats.cd_queries;
  stats.triangle_pairs = cd_stats.triangle_pairs;
  stats.containment_tests = cd_stats.containment_tests;
  stats.seconds_cd_filter = seconds_since(start);
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PIPELINE_H
