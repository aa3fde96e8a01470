// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The pipeline after the input stage, on two prepared meshes:
//   stage 1  sampling resolutions (sampling.h) and the CD filter's AABB trees (cd_filter.h)
//   stage 2  the normal filter: kept feature pairs and their directions (normal_filter.h)
//   stage 3a the octree filter: leaf cells of the candidates, certified interior or not
//            (octree_filter.h)
//   stage 3  the candidates p + q of each kept pair outside certified cells, the CD filter,
//            and emit(p, q, direction)
//            for every boundary point, on the calling thread, in canonical order.
// Stage 3 runs in waves of feature pairs, in parallel with CGAL::Parallel_tag.

#ifndef CGAL_PMSUM_INTERNAL_PIPELINE_H
#define CGAL_PMSUM_INTERNAL_PIPELINE_H

#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/cd_filter.h>
#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/octree_filter.h>
#include <CGAL_pmsum/internal/sampling.h>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <atomic>
#include <chrono>
#include <cmath>
#include <string>
#include <functional>
#include <memory>
#include <numeric>
#include <unordered_map>
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
  if (!(d > 0) || !std::isfinite(d))
    throw Invalid_input("d must be positive and finite (got " + std::to_string(d) + ")");
}

struct Pipeline_options
{
  bool use_normal_filter = true;
  bool use_cd_filter = true;
  bool use_octree_filter = true; // only with the CD filter
  std::size_t max_candidates = std::size_t(-1);
  std::function<bool(double)> callback; // progress in [0, 1]; false cancels
};

/// A sample in lowest terms, to recognise the same point in a coarser level's sampling.
inline std::array<std::int32_t, 4> canonical(const Sample& s)
{
  std::int32_t g = s.denominator;
  for (int i = 0; i < 3; ++i) g = std::gcd(g, s.weights[i]);
  return {s.weights[0] / g, s.weights[1] / g, s.weights[2] / g, s.denominator / g};
}

/// Stages 1 to 3 (see the file comment) on two prepared meshes, for one covering distance or
/// for several, coarse to fine: what does not depend on d (the normal filter, the CD
/// filter's trees, the octree's interior certificate) is computed once, and each level
/// samples with resolutions that are multiples of the coarser level's, so that every
/// coarser candidate is a candidate again and its decision (boundary point with its
/// direction, or inner) is reused instead of tested.
template <class ConcurrencyTag>
class Pipeline
{
public:
  static constexpr bool parallel =
#ifdef CGAL_LINKED_WITH_TBB
    std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
#else
    false;
#endif
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value || parallel,
                "CGAL::Parallel_tag needs TBB (link with CGAL::TBB_support)");

  /// `coarse_to_fine`: keep each level's decisions for the next, finer one.
  Pipeline(const Mesh_data& mp, const Mesh_data& mq, const Pipeline_options& o, bool coarse_to_fine = false)
    : m_p(mp), m_q(mq), m_o(o), m_coarse_to_fine(coarse_to_fine && o.use_cd_filter), m_created(Clock::now())
  {
    auto start = m_created;
    if (o.use_cd_filter) m_geometry.emplace(mp, mq); // AABB trees
    m_seconds_trees = seconds_since(start);
    start = Clock::now();
    m_pairs = candidate_feature_pairs(mp, mq, o.use_normal_filter, parallel, o.max_candidates);
    m_seconds_normal_filter = seconds_since(start);
  }

  /// One level: the points of covering distance d, to emit(p, q, direction). Levels must
  /// come with decreasing d. `start` is when the input stage began (first level).
  template <class Emit>
  void run_level(double d, Statistics& stats, Emit&& emit, Clock::time_point start)
  {
    const Mesh_data &mp = m_p, &mq = m_q;
    const Candidate_pairs& pairs = m_pairs;
    const bool first_level = !m_sp;
    if (m_coarse_to_fine && !first_level && !(d < m_d))
      throw Invalid_input("coarse-to-fine covering distances must decrease");
    // Stage 1: sampling resolutions (samples themselves are generated per pair).
    const auto sampling_start = Clock::now();
    std::optional<Mesh_sampling> coarser_p, coarser_q;
    if (m_coarse_to_fine && m_sp) { coarser_p.swap(m_sp); coarser_q.swap(m_sq); }
    m_sp.emplace(mp, d / 2, "P", coarser_p ? &*coarser_p : nullptr);
    m_sq.emplace(mq, d / 2, "Q", coarser_q ? &*coarser_q : nullptr);
    const Mesh_sampling &sp = *m_sp, &sq = *m_sq;
    m_d = d;
    stats.samples_p = sp.number_of_samples();
    stats.samples_q = sq.number_of_samples();
    stats.seconds_setup = seconds_since(sampling_start); // input and trees: counted in the first level
    if (first_level) stats.seconds_setup += std::chrono::duration<double>(m_created - start).count() + m_seconds_trees;
    stats.feature_pairs = pairs.pairs.size();
    stats.seconds_normal_filter = first_level ? m_seconds_normal_filter : 0;

    std::vector<std::size_t> work(pairs.pairs.size());
    std::size_t total = 0;
    for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
      work[i] = sp.number_of_samples(pairs.pairs[i].p) * sq.number_of_samples(pairs.pairs[i].q);
      total += work[i];
    }
    stats.candidates = total;
    if (total > m_o.max_candidates) throw Too_many_candidates(total, m_o.max_candidates);

    // Candidate positions, rounded to double (for the octree only).
    auto positions = [](const Mesh_data& M, const std::vector<Sample>& samples) {
      std::vector<Point3> out(samples.size());
      for (std::size_t i = 0; i < samples.size(); ++i)
        for (int c = 0; c < 3; ++c) out[i][c] = sample_coordinate<double>(M, samples[i], c);
      return out;
    };

    // Stage 3a: octree filter.
    start = Clock::now();
    std::optional<Octree_filter> octree;
    if (m_geometry && m_o.use_octree_filter && !pairs.pairs.empty()) {
      const auto bp = mesh_box(mp), bq = mesh_box(mq);
      Point3 lo, hi;
      double scale = d;
      for (int c = 0; c < 3; ++c) {
        lo[c] = bp.first[c] + bq.first[c];
        hi[c] = bp.second[c] + bq.second[c];
        scale = (std::max)({scale, std::abs(bp.first[c]), std::abs(bp.second[c]), std::abs(bq.first[c]),
                            std::abs(bq.second[c]), std::abs(lo[c]), std::abs(hi[c])});
      }
      const double tolerance = 1e-9 * scale; // far above the rounding errors of these doubles
      // Grids of about candidates / 8 points each (between 12^3 and 64^3): their set-up
      // costs about as much as testing a tenth of the candidates would. Built once.
      if (!m_certificate) {
        const int resolution = int(std::clamp(std::cbrt(double(total) / 8), 12.0, 64.0));
        m_certificate.emplace(mp, mq, resolution, tolerance, parallel);
      }
      // Leaves of size d, as in the paper, but small enough for the balls to certify them.
      const double leaf = std::clamp(m_certificate->largest_ball() / 4, d / 8, d);
      octree.emplace(*m_certificate, lo, hi, leaf, tolerance);
      if (octree->enabled()) {
        // The leaves holding candidates, by chunks of pairs.
        const std::size_t chunks = (std::min)(pairs.pairs.size(), std::size_t(256));
        std::vector<std::vector<Octree_filter::Key>> leaves(chunks);
        for_each_index(chunks, parallel, [&](std::size_t chunk) {
          std::vector<Sample> samples_p, samples_q;
          auto& out = leaves[chunk];
          for (std::size_t i = chunk * pairs.pairs.size() / chunks; i < (chunk + 1) * pairs.pairs.size() / chunks; ++i) {
            samples_p.clear(); samples_q.clear();
            sp.samples(pairs.pairs[i].p, samples_p);
            sq.samples(pairs.pairs[i].q, samples_q);
            const std::vector<Point3> xp = positions(mp, samples_p), xq = positions(mq, samples_q);
            const std::size_t before = out.size();
            for (const Point3& a : xp)
              for (const Point3& b : xq)
                if (auto k = octree->leaf({a[0] + b[0], a[1] + b[1], a[2] + b[2]})) out.push_back(*k);
            std::sort(out.begin() + before, out.end());
            out.erase(std::unique(out.begin() + before, out.end()), out.end());
          }
        });
        std::vector<Octree_filter::Key> all;
        for (auto& l : leaves) { all.insert(all.end(), l.begin(), l.end()); l = {}; }
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        octree->certify(std::move(all), parallel);
        stats.octree_leaves = octree->number_of_leaves();
        stats.octree_certified_leaves = octree->number_of_certified_leaves();
      } else {
        octree.reset();
      }
    }
    stats.seconds_octree_filter = seconds_since(start);

    // Stage 3: candidates of each kept pair, CD filter, output. Feature pairs are processed
    // in waves; within a wave, in parallel with CGAL::Parallel_tag. Each pair's kept samples
    // are buffered, then emitted on this thread in the pairs' order: the output is the same
    // for any number of threads, and kernel constructions (Epeck's lazy numbers are not
    // thread-safe) and the callback stay on the calling thread.
    start = Clock::now();
    struct Kept { Sample p, q; std::uint32_t direction; }; // absolute index in pairs.directions
    std::atomic<std::size_t> certified_candidates{0}, reused_candidates{0};
    Decisions decisions; // this level's, for the next one
    auto filter_pair = [&](std::size_t i, Cd_filter* filter, std::vector<Kept>& kept) {
      const Feature_pair& fp = pairs.pairs[i];
      std::vector<Sample> samples_p, samples_q;
      sp.samples(fp.p, samples_p);
      sq.samples(fp.q, samples_q);
      std::vector<Point3> xp, xq;
      if (octree) { xp = positions(mp, samples_p); xq = positions(mq, samples_q); }
      // Which samples the coarser level had.
      std::vector<std::uint8_t> old_p(samples_p.size(), 0), old_q(samples_q.size(), 0);
      if (coarser_p) {
        for (std::size_t k = 0; k < samples_p.size(); ++k) old_p[k] = sp.is_sample_of(samples_p[k], *coarser_p);
        for (std::size_t k = 0; k < samples_q.size(); ++k) old_q[k] = sq.is_sample_of(samples_q[k], *coarser_q);
      }
      std::size_t certified = 0, reused = 0;
      const Direction* dirs = pairs.directions.data() + fp.first_direction;
      for (std::size_t ip = 0; ip < samples_p.size(); ++ip)
        for (std::size_t iq = 0; iq < samples_q.size(); ++iq) {
          const Sample &s_p = samples_p[ip], &s_q = samples_q[iq];
          if (!filter) { kept.push_back({s_p, s_q, fp.first_direction}); continue; }
          if (old_p[ip] && old_q[iq]) { // decided by the coarser level
            ++reused;
            const auto it = m_decisions.find(Decision_key::of(i, s_p, s_q));
            if (it != m_decisions.end()) kept.push_back({s_p, s_q, it->second});
            continue;
          }
          if (octree && octree->certified({xp[ip][0] + xq[iq][0], xp[ip][1] + xq[iq][1], xp[ip][2] + xq[iq][2]})) {
            ++certified;
            continue;
          }
          for (std::uint32_t k = 0; k < fp.number_of_directions; ++k) {
            if (filter->is_free(s_p, s_q, dirs, fp.number_of_directions, k)) {
              kept.push_back({s_p, s_q, fp.first_direction + k});
              break;
            }
            if (filter->decided_without_perturbation()) break; // the same for every direction
          }
        }
      certified_candidates += certified;
      reused_candidates += reused;
    };
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
    if (parallel && m_geometry)
      filters = std::make_unique<tbb::enumerable_thread_specific<Cd_filter>>(&*m_geometry);
#endif
    std::optional<Cd_filter> sequential_filter;
    if (!parallel && m_geometry) sequential_filter.emplace(&*m_geometry);
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
      for (std::size_t b = 0; b < buffers.size(); ++b)
        for (const Kept& k : buffers[b]) {
          ++stats.output_points;
          if (m_coarse_to_fine) decisions.emplace(Decision_key::of(first + b, k.p, k.q), k.direction);
          emit(k.p, k.q, pairs.directions[k.direction]);
        }
      done += wave;
      first = last;
      if (m_o.callback && !m_o.callback(total == 0 ? 1. : double(done) / double(total))) throw Operation_cancelled();
    }
    if (sequential_filter) add_cd_stats(*sequential_filter);
#ifdef CGAL_LINKED_WITH_TBB
    if (filters)
      for (const Cd_filter& f : *filters) add_cd_stats(f);
#endif
    stats.candidates_certified = certified_candidates;
    stats.candidates_reused = reused_candidates;
    stats.cd_queries = cd_stats.cd_queries;
    stats.triangle_pairs = cd_stats.triangle_pairs;
    stats.containment_tests = cd_stats.containment_tests;
    stats.seconds_cd_filter = seconds_since(start);
    m_decisions.swap(decisions);
  }

private:
  /// A candidate by its pair and its samples in lowest terms.
  struct Decision_key
  {
    std::size_t pair;
    std::array<std::int32_t, 4> p, q;
    static Decision_key of(std::size_t pair, const Sample& p, const Sample& q) { return {pair, canonical(p), canonical(q)}; }
    bool operator==(const Decision_key& o) const { return pair == o.pair && p == o.p && q == o.q; }
  };
  struct Decision_hash
  {
    std::size_t operator()(const Decision_key& k) const
    {
      std::uint64_t h = k.pair * 0x9E3779B97F4A7C15ull;
      for (const auto* a : {&k.p, &k.q})
        for (std::int32_t v : *a) h = (h ^ std::uint64_t(std::uint32_t(v))) * 0x100000001B3ull;
      return std::size_t(h ^ (h >> 29));
    }
  };
  /// The boundary points of the last level, with their directions; every other candidate
  /// of that level was inner.
  using Decisions = std::unordered_map<Decision_key, std::uint32_t, Decision_hash>;

  const Mesh_data& m_p;
  const Mesh_data& m_q;
  Pipeline_options m_o;
  bool m_coarse_to_fine;
  Clock::time_point m_created;
  std::optional<Cd_geometry> m_geometry;
  Candidate_pairs m_pairs;
  std::optional<Interior_certificate> m_certificate;
  double m_seconds_trees = 0, m_seconds_normal_filter = 0;
  std::optional<Mesh_sampling> m_sp, m_sq; // the last level's
  double m_d = 0;
  Decisions m_decisions;
};

/// Stages 1 to 3 for one covering distance. `start` is when the input stage began.
template <class ConcurrencyTag, class Emit>
void run_pipeline(const Mesh_data& mp, const Mesh_data& mq, double d, const Pipeline_options& o,
                  Statistics& stats, Emit&& emit, Clock::time_point start)
{
  Pipeline<ConcurrencyTag> pipeline(mp, mq, o);
  pipeline.run_level(d, stats, emit, start);
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PIPELINE_H
