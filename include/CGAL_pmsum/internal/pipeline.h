// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline after the input stage, on two prepared meshes; this file only wires the stages:
//   1. sampling.h       sampling resolutions of P and Q (d/2-coverings)
//   2. normal_filter.h  the feature pairs whose sums can be on the boundary (once for all levels);
//      candidates.h     their sample sums, the candidates, in canonical order, and the pairs
//                       cut into pieces (runs of rows of their lattices), the unit of work
//   3. octree_filter.h  octree cells of the candidates certified inside the sum
//      decision.h       each candidate: reused, certified inner, covered by the net, or CD-tested
//                       (cd_filter.h), in waves of pieces of pairs (parallel.h); then the piece's
//                       trim points: trim_points.h (which lattice segments), segment_search.h
//                       (their free parts, exactly); after the waves, the islands of the cells
//                       the net does not cover whole then (island_search.h), in waves too
//      distribution.h   with a communicator: the ranks take each wave's pieces as they come free
//   4. covering_net.h   the output: the greedy (d/2, d)-net of the boundary candidates
//   5. emit(p, q, direction, trim) for each output point (trim: null, or a trim-curve point), on the calling thread, in canonical order.

#ifndef CGAL_PMSUM_INTERNAL_PIPELINE_H
#define CGAL_PMSUM_INTERNAL_PIPELINE_H

#include <CGAL_pmsum/Communicator.h>
#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/candidates.h>
#include <CGAL_pmsum/internal/cd_filter.h>
#include <CGAL_pmsum/internal/covering_net.h>
#include <CGAL_pmsum/internal/decision.h>
#include <CGAL_pmsum/internal/distribution.h>
#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/octree_filter.h>
#include <CGAL_pmsum/internal/parallel.h>
#include <CGAL_pmsum/internal/sampling.h>

#include <CGAL/tags.h>

#include <chrono>
#include <cmath>
#include <string>
#include <functional>
#include <numeric>
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
  bool use_covering_net = true;  // only with the CD filter; false: every boundary candidate
  bool use_trim_points = true;   // only with the CD filter: search the trim curves (trim_points.h)
  bool search_islands = true;    // with trim points: and the islands inside cells (island_search.h)
  bool keep_vertex_sums = false; // with the net: vertex + vertex boundary points too, covered or not
  std::size_t max_candidates = std::size_t(-1);
  std::function<bool(double)> callback; // progress in [0, 1]; false cancels
  Communicator* communicator = nullptr; // the ranks that share the decisions (distribution.h)
};

/// Collective: the totals of every rank's decisions (`mine`: this rank's), and each rank's
/// load into stats.ranks.
inline Decision_totals add_over_ranks(Wave_ranks& ranks, const Decision_totals& mine, Statistics& stats)
{
  Byte_writer w;
  w.pod(mine.counters);
  w.pod(mine.filter);
  w.pod(ranks.load());
  Decision_totals all;
  stats.ranks.clear();
  for (const std::string& bytes : ranks.gather(w.bytes())) {
    Byte_reader r(bytes);
    const auto counters = r.pod<Decision_counters>();
    const auto filter = r.pod<Cd_statistics>();
    const auto load = r.pod<Rank_load>();
    all.counters.add(counters);
    all.filter.add(filter);
    stats.ranks.push_back({load.pieces, load.candidates, load.island_cells, filter.queries - counters.trim_queries,
                           load.seconds_deciding, load.seconds_exchanging});
  }
  return all;
}

/// The work of a wave of decisions, for `total` candidates: about 1/125 of them, small
/// enough that few candidates are tested in vain (covered by an earlier piece of their wave),
/// large enough to hold 16 pieces or more, so that the threads and ranks, which take the
/// pieces as they come free, seldom wait for a costly piece (a long trim search) at the end of
/// a wave. Against 1/500 with 4 pieces (benchmark/mpi, 2 cores): two ranks 1.51-1.74 times
/// faster than one process (were 1.36-1.50), one thread as fast, 0.5% more points on the
/// hooks (7,772 against 7,735) and the same on knot1 and the elephant.
inline std::size_t wave_work(std::size_t total) { return (std::max<std::size_t>)(1, total / 125); }

/// The work of a piece of a pair (candidates.h, make_pieces), for `total` candidates: a
/// sixteenth of a wave's, so that a wave holds several pieces to share among the threads and
/// the ranks, even where single pairs are larger than a wave.
inline std::size_t piece_work(std::size_t total) { return (std::max<std::size_t>)(1, wave_work(total) / 16); }

/// The fewest cell rows in a piece: a piece tests the corners of its last lattice row again
/// (the next piece's candidates) when its trim search needs them.
constexpr std::int32_t piece_rows = 2;

/// Stages 1 to 5 (see the file comment) on two prepared meshes, for one covering distance or
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

  /// The meshes and trees of the CD filter; null if the pipeline has none (use_cd_filter false).
  const Cd_geometry* geometry() const { return m_geometry ? &*m_geometry : nullptr; }
  /// The feature pairs the normal filter kept (once for all levels).
  const Candidate_pairs& pairs() const { return m_pairs; }

  /// `coarse_to_fine`: keep each level's decisions for the next, finer one.
  Pipeline(const Mesh_data& mp, const Mesh_data& mq, const Pipeline_options& o, bool coarse_to_fine = false)
    : m_p(mp), m_q(mq), m_o(o), m_coarse_to_fine(coarse_to_fine && o.use_cd_filter), m_created(Clock::now())
  {
    auto start = m_created;
    if (o.use_cd_filter) m_geometry.emplace(mp, mq); // AABB trees
    m_scale = largest_coordinate(mp) + largest_coordinate(mq);
    m_seconds_trees = seconds_since(start);
    start = Clock::now();
    // The ranks share the normal filter's tests: they must have the same meshes first.
    if (o.communicator) check_same_work(*o.communicator, mesh_fingerprint(mp, mq));
    m_pairs = candidate_feature_pairs(mp, mq, o.use_normal_filter, parallel, o.max_candidates, o.communicator);
    // Unit outward normals of the directions, for the net (facing points do not cover each other).
    m_normals.reserve(m_pairs.directions.size());
    for (const Direction& direction : m_pairs.directions) {
      const auto n = direction.vector<double>(mp, mq);
      const double length = std::sqrt(dot(n, n));
      m_normals.push_back(length > 0 ? Point3{n[0] / length, n[1] / length, n[2] / length} : Point3{0, 0, 0});
    }
    m_seconds_normal_filter = seconds_since(start);
  }

  /// One level: the points of covering distance d, to emit(p, q, direction). Levels must
  /// come with decreasing d. `start` is when the input stage began (first level); `strips`:
  /// how far the trim search follows narrow strips (trim_points.h); `creases`: which points
  /// on the sum's creases are output beyond the covering's (decision.h).
  template <class Emit>
  void run_level(double d, Statistics& stats, Emit&& emit, Clock::time_point start,
                 Strips strips = Strips::as_covering_needs, Creases creases = Creases::as_covering_needs)
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

    // Stage 2: the candidates, counted, and the pairs cut into pieces.
    const std::size_t total = number_of_candidates(pairs, sp, sq);
    stats.candidates = total;
    if (total > m_o.max_candidates) throw Too_many_candidates(total, m_o.max_candidates); // (before the pieces: prompt)
    std::vector<std::size_t> work;
    const std::vector<Pair_piece> pieces = make_pieces(pairs, sp, sq, piece_work(total), piece_rows, work);
    if (m_o.communicator) check_same_work(*m_o.communicator, fingerprint(d, work));

    // Stage 3a: the octree filter.
    start = Clock::now();
    std::optional<Octree_filter> octree;
    if (m_geometry && m_o.use_octree_filter && !pairs.pairs.empty()) {
      const Octree_settings settings(mp, mq, d);
      if (!m_certificate)
        m_certificate.emplace(mp, mq, Octree_settings::certificate_resolution(total), settings.tolerance, parallel,
                              m_o.communicator);
      octree = make_level_octree(*m_certificate, settings, pairs, sp, sq, d, parallel, m_o.communicator);
      if (octree) {
        stats.octree_leaves = octree->number_of_leaves();
        stats.octree_certified_leaves = octree->number_of_certified_leaves();
      }
    }
    stats.seconds_octree_filter = seconds_since(start);

    // Stages 3 to 5: decisions in waves of pieces of pairs (parallel), committed in canonical
    // order to the net and the output on this thread, so that the output is the same for any
    // number of threads, and kernel constructions (Epeck's lazy numbers are not thread-safe)
    // and the callback stay on the calling thread.
    start = Clock::now();
    std::optional<Covering_net> net;
    if (m_geometry && m_o.use_covering_net) net.emplace(d, m_scale);
    std::vector<Tentative> output; // this level's, for the next one
    auto output_point = [&](const auto& t) {
      ++stats.output_points;
      if constexpr (std::is_same<std::decay_t<decltype(t)>, Tentative>::value) {
        if (m_coarse_to_fine && net) output.push_back(t);
        emit(t.p, t.q, pairs.directions[t.direction], nullptr);
      } else {
        ++stats.trim_points;
        emit(t.p, t.q, pairs.directions[t.direction], &t.trim);
      }
    };
    // Coarse to fine: the coarser level's points (at least d/2 apart) come first.
    for (const Tentative& t : m_output) {
      // (the normals of its pair: the one whose directions hold t's)
      const auto fp = std::upper_bound(pairs.pairs.begin(), pairs.pairs.end(), t.direction,
                                       [](std::uint32_t k, const Feature_pair& f) { return k < f.first_direction; }) - 1;
      net->insert(t.x, Covering_net::Normals{m_normals.data() + fp->first_direction, fp->number_of_directions});
      output_point(t);
    }
    Decision_context context{&pairs, &sp, &sq};
    if (coarser_p) {
      context.coarser_p = &*coarser_p;
      context.coarser_q = &*coarser_q;
      context.cache = &m_cache;
    }
    context.octree = octree ? &*octree : nullptr;
    context.net = net ? &*net : nullptr;
    context.normals = &m_normals;
    context.use_cd_filter = bool(m_geometry);
    context.record_decisions = m_coarse_to_fine;
    context.keep_vertex_sums = m_o.keep_vertex_sums;
    context.keep_sharp_creases = creases == Creases::sharp_kept;
    context.d = d;
    context.strips = strips;
    context.trim_points = m_o.use_trim_points;
    context.islands = m_o.search_islands;
    // The filters of the decisions, and the commits' own: the counters of the decisions are
    // added up over the ranks, those of the commits (the same on every rank) counted once.
    std::optional<Per_thread<Cd_filter>> filters;
    std::optional<Cd_filter> commit_filter;
    if (m_geometry) {
      filters.emplace(parallel, &*m_geometry);
      commit_filter.emplace(&*m_geometry);
    }
    Per_thread<Pair_candidates> candidates(parallel);
    Per_thread<Decision_counters> counters(parallel);
    Decision_counters commit_counters;
    std::optional<Wave_ranks> ranks;
    if (m_o.communicator) ranks.emplace(*m_o.communicator);
    // Progress: the islands' search (below) is reported as the last part of the level.
    constexpr double islands_share = 0.1;
    auto progress = [&](double from, double share) -> std::function<bool(double)> {
      if (!m_o.callback) return {};
      return [&, from, share](double f) { return m_o.callback(from + share * f); };
    };
    std::vector<std::vector<std::uint32_t>> island_cells(pieces.size()); // of each piece, from its trim search
    run_in_waves<Pair_decision>(
      work, wave_work(total), parallel,
      [&](std::size_t k, Pair_decision& decided) {
        decide_piece(context, pieces[k], filters ? &filters->local() : nullptr, candidates.local(), decided,
                     counters.local());
      },
      [&](std::size_t k, Pair_decision& decided) {
        commit_piece(context, pieces[k].pair, decided, net ? &*net : nullptr, commit_filter ? &*commit_filter : nullptr,
                    commit_counters, m_coarse_to_fine ? &m_cache : nullptr, output_point);
        island_cells[k].swap(decided.island_cells);
      },
      progress(0, 1 - islands_share), ranks ? &*ranks : nullptr);
    // Stage 3c: the islands, after the waves, so that a cell the whole net covers needs no
    // search (decide_islands); in waves too, each against the net as it stands.
    std::vector<std::size_t> with_islands, island_work; // the pieces with such cells, and how many
    for (std::size_t k = 0; k < pieces.size(); ++k)
      if (!island_cells[k].empty()) {
        with_islands.push_back(k);
        island_work.push_back(island_cells[k].size());
      }
    if (!with_islands.empty()) { // (the same on every rank: the commits are)
      if (ranks) ranks->start_islands();
      const std::size_t cells = std::accumulate(island_work.begin(), island_work.end(), std::size_t(0));
      run_in_waves<Pair_decision>(
        island_work, wave_work(cells), parallel,
        [&](std::size_t n, Pair_decision& decided) {
          const std::size_t k = with_islands[n];
          decide_islands(context, pieces[k], island_cells[k], filters->local(), decided, counters.local());
        },
        [&](std::size_t n, Pair_decision& decided) {
          commit_trims(context, pieces[with_islands[n]].pair, decided, net ? &*net : nullptr, output_point);
        },
        progress(1 - islands_share, islands_share), ranks ? &*ranks : nullptr);
    } else if (m_o.callback) {
      m_o.callback(1); // (the level is done: nothing left to cancel)
    }
    Decision_totals decided;
    counters.for_each([&](const Decision_counters& c) { decided.counters.add(c); });
    if (filters) filters->for_each([&](const Cd_filter& f) { decided.filter.add(f.statistics()); });
    if (ranks) decided = add_over_ranks(*ranks, decided, stats);
    decided.counters.add(commit_counters);
    if (commit_filter) decided.filter.add(commit_filter->statistics());
    stats.candidates_reused = decided.counters.reused;
    stats.candidates_certified = decided.counters.certified;
    stats.candidates_covered = decided.counters.covered;
    stats.candidates_in_patch_pairs = decided.counters.in_patch_pairs;
    stats.trim_segments = decided.counters.trim_segments;
    stats.island_cells = decided.counters.island_cells;
    stats.corner_tests = decided.counters.corner_tests;
    stats.trim_queries = decided.counters.trim_queries;
    stats.cd_queries = decided.filter.queries - stats.trim_queries;
    stats.triangle_pairs = decided.filter.triangle_pairs;
    stats.containment_tests = decided.filter.containment_tests;
    stats.seconds_cd_filter = seconds_since(start);
    // (a level with the crease points kept is a variant of the last one: the next level starts
    // from the last one's points, as if it had not run)
    if (creases == Creases::as_covering_needs) m_output.swap(output);
  }

private:
  /// What the ranks must agree on before they share the filters' tests: the meshes.
  static std::string mesh_fingerprint(const Mesh_data& mp, const Mesh_data& mq)
  {
    Byte_writer w;
    for (const Mesh_data* m : {&mp, &mq}) {
      Fnv1a h; // of the points, the triangles and the bare edges
      h.add(m->points);
      h.add(m->triangles);
      for (Index e : m->bare_edges) h.add(m->edges[e].v);
      w.pod(std::uint64_t(m->points.size()));
      w.pod(std::uint64_t(m->triangles.size()));
      w.pod(h.value());
    }
    return w.bytes();
  }

  /// What the ranks must agree on before they share the decisions (distribution.h).
  std::string fingerprint(double d, const std::vector<std::size_t>& work) const
  {
    Byte_writer w;
    w.pod(d);
    w.pod(m_o.max_candidates);
    for (bool b : {m_o.use_normal_filter, m_o.use_cd_filter, m_o.use_octree_filter, m_o.use_covering_net,
                   m_o.use_trim_points, m_o.search_islands, m_o.keep_vertex_sums, m_coarse_to_fine})
      w.pod(std::uint8_t(b));
    Fnv1a h; // of the work of every piece
    h.add(work);
    w.pod(std::uint64_t(work.size()));
    w.pod(h.value());
    return w.bytes();
  }

  const Mesh_data& m_p;
  const Mesh_data& m_q;
  Pipeline_options m_o;
  bool m_coarse_to_fine;
  Clock::time_point m_created;
  double m_scale = 0; // bound of the candidates' coordinates
  std::optional<Cd_geometry> m_geometry;
  Candidate_pairs m_pairs;
  std::vector<Point3> m_normals; // of m_pairs.directions
  std::optional<Interior_certificate> m_certificate;
  double m_seconds_trees = 0, m_seconds_normal_filter = 0;
  std::optional<Mesh_sampling> m_sp, m_sq; // the last level's
  double m_d = 0;
  Decision_cache m_cache;        // coarse to fine: every CD decision so far
  std::vector<Tentative> m_output; // coarse to fine, with the net: the last level's points
};

/// Stages 1 to 5 for one covering distance. `start` is when the input stage began.
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
