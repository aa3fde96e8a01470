// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 of the pipeline: the decision of every candidate, in this order:
//   1. reuse      coarse to fine: a candidate the coarser level decided keeps its decision;
//   2. interior   a candidate in an octree cell certified inside the sum is inner;
//   3. net        a candidate closer than d/2 to a chosen output point is covered: dropped
//                 untested (covering_net.h);
//   4. CD         otherwise the exact collision test (cd_filter.h) decides.
// The output is the greedy net of the boundary candidates in canonical order (candidates.h):
// a candidate is output iff it is a boundary point and no earlier output point covers it.
//
// That order is sequential, the tests are not: a wave of pieces of feature pairs (a pair, or
// a run of rows of its lattice: candidates.h) is decided in parallel against the net as it
// stood before the wave (decide_piece), each piece also skipping what its own tentative
// points cover; the wave is then committed in canonical order on one thread (commit_piece),
// which drops what an earlier commit now covers and tests the rare candidate whose covering
// tentative point was dropped. The result is the sequential greedy net, for any number of
// threads. The islands of the pieces' cells are searched last, in waves of their own
// (decide_islands), against the net of all the other points.

#ifndef CGAL_PMSUM_INTERNAL_DECISION_H
#define CGAL_PMSUM_INTERNAL_DECISION_H

#include <CGAL_pmsum/internal/candidates.h>
#include <CGAL_pmsum/internal/cd_filter.h>
#include <CGAL_pmsum/internal/covering_net.h>
#include <CGAL_pmsum/internal/distribution.h>
#include <CGAL_pmsum/internal/octree_filter.h>
#include <CGAL_pmsum/internal/trim_points.h>

#include <array>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// A sample in lowest terms, to recognise the same point in a coarser level's sampling.
inline std::array<std::int32_t, 4> canonical(const Sample& s)
{
  std::int32_t g = s.denominator;
  for (int i = 0; i < 3; ++i) g = std::gcd(g, s.weights[i]);
  return {s.weights[0] / g, s.weights[1] / g, s.weights[2] / g, s.denominator / g};
}

/// Direction index meaning "inner" (decided, not on the boundary), or "not tested yet".
constexpr std::uint32_t inner = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t untested = inner - 1;

/// The CD decisions of coarser levels (coarse to fine): candidate -> direction or inner.
class Decision_cache
{
public:
  struct Key
  {
    std::size_t pair;
    std::array<std::int32_t, 4> p, q;
    static Key of(std::size_t pair, const Sample& p, const Sample& q) { return {pair, canonical(p), canonical(q)}; }
    bool operator==(const Key& o) const { return pair == o.pair && p == o.p && q == o.q; }
  };
  struct Hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::uint64_t h = k.pair * 0x9E3779B97F4A7C15ull;
      for (const auto* a : {&k.p, &k.q})
        for (std::int32_t v : *a) h = (h ^ std::uint64_t(std::uint32_t(v))) * 0x100000001B3ull;
      return std::size_t(h ^ (h >> 29));
    }
  };

  /// The decision (a direction or `inner`), or `untested`.
  std::uint32_t find(const Key& k) const
  {
    const auto it = m_map.find(k);
    return it == m_map.end() ? untested : it->second;
  }
  void add(const Key& k, std::uint32_t decision) { m_map.emplace(k, decision); }
  bool empty() const { return m_map.empty(); }

private:
  std::unordered_map<Key, std::uint32_t, Hash> m_map;
};

/// A candidate that may become an output point: a boundary point with its direction, or one
/// left untested because a tentative point of its own pair covered it.
struct Tentative
{
  Sample p, q;
  Point3 x;
  std::uint32_t direction; // index in Candidate_pairs::directions, or `untested`
  bool kept;               // output whatever covers it (Decision_context::kept())
};

/// Counters of the decision stage (per thread, added up at the end).
struct Decision_counters
{
  std::size_t reused = 0, certified = 0, covered = 0, tested_in_commit = 0;
  std::size_t in_patch_pairs = 0; // lattice points found inner by Facet_patch_test (no CD query)
  std::size_t trim_segments = 0, trim_points = 0, corner_tests = 0, trim_queries = 0, island_cells = 0;
  void add(const Decision_counters& o)
  {
    in_patch_pairs += o.in_patch_pairs;
    reused += o.reused; certified += o.certified; covered += o.covered; tested_in_commit += o.tested_in_commit;
    trim_segments += o.trim_segments; trim_points += o.trim_points; corner_tests += o.corner_tests;
    trim_queries += o.trim_queries; island_cells += o.island_cells;
  }
};

/// The counters of a level's decisions and of their collision filters.
struct Decision_totals
{
  Decision_counters counters;
  Cd_statistics filter;
};

/// Which points on the sum's creases a level outputs: those the covering needs, or also every
/// one on a sharp crease (on_sharp_crease(); a mesh's refinement: its creases and corners).
enum class Creases : std::uint8_t { as_covering_needs, sharp_kept };

/// What the decisions of one level read. Everything but `filter` is shared and read-only
/// while pairs are decided in parallel.
struct Decision_context
{
  const Candidate_pairs* pairs;
  const Mesh_sampling *sp, *sq;
  const Mesh_sampling *coarser_p = nullptr, *coarser_q = nullptr; // coarse to fine
  const Decision_cache* cache = nullptr;                          // coarse to fine
  const Octree_filter* octree = nullptr;
  const Covering_net* net = nullptr;   // nullptr: every boundary candidate is output
  const std::vector<Point3>* normals = nullptr; // unit outward normal of each direction (for the net)
  bool use_cd_filter = true;           // false: every candidate is output
  bool keep_vertex_sums = false;       // vertex + vertex boundary points are output even if covered
  bool keep_sharp_creases = false;     // and those on sharp creases (on_sharp_crease()), for a mesh
  bool record_decisions = false;       // coarse to fine: fill Pair_decision::tested
  bool trim_points = true;             // search the trim curves of 2-dimensional pairs (trim_points.h)
  bool islands = true;                 // and the islands inside lattice cells (island_search.h)
  double d = 0;                        // the covering distance
  Strips strips = Strips::as_covering_needs; // how far the trim search follows narrow strips

  /// Is the boundary point p + q output even if covered (but not twice: a point of the net
  /// at the same place covers it)?
  bool kept(const Sample& p, const Sample& q) const
  {
    return (keep_vertex_sums && p.origin.dimension == 0 && q.origin.dimension == 0) ||
           (keep_sharp_creases && on_sharp_crease(p.origin, q.origin, sp->mesh(), sq->mesh()));
  }
  /// Does `net` cover x, a point that is kept() or not?
  static bool covers(const Covering_net& net, const Point3& x, const Covering_net::Normals& normals, bool kept)
  { return kept ? net.covers_within(x, 0) : net.covers(x, normals); }

  /// The unit outward normals of the directions of pair fp (none if unknown): those of the
  /// pair's points, for the net.
  Covering_net::Normals normals_of(const Feature_pair& fp) const
  { return normals ? Covering_net::Normals{normals->data() + fp.first_direction, fp.number_of_directions}
                   : Covering_net::Normals{}; }
};

/// The outcome of one pair's decisions.
struct Pair_decision
{
  std::vector<Tentative> tentative;     // in canonical order
  std::vector<Trim_point> trims;        // committed after the tentative points, in their order
  std::vector<std::pair<Decision_cache::Key, std::uint32_t>> tested; // if record_decisions
  std::vector<std::uint32_t> island_cells; // of the piece's lattice: searched after the waves (decide_islands)
  void clear() { tentative.clear(); trims.clear(); tested.clear(); island_cells.clear(); }
};

/// A pair's decisions to bytes (Io = Byte_writer, Decision = const Pair_decision) or back
/// (Byte_reader, Pair_decision), for the other ranks (distribution.h): one list of fields.
template <class Io, class Decision>
void transfer(Io& io, Decision& d)
{
  io.size_of(d.tentative);
  for (auto& t : d.tentative) { io.io(t.p); io.io(t.q); io.io(t.x); io.io(t.direction); io.io(t.kept); }
  io.size_of(d.trims);
  for (auto& t : d.trims) {
    io.io(t.p); io.io(t.q); io.io(t.x); io.io(t.radius); io.io(t.direction);
    io.io(t.trim.p); io.io(t.trim.q); io.io(t.trim.lambda);
    io.io(t.trim.p2); io.io(t.trim.q2); io.io(t.trim.mu);
    io.io(t.trim.origin_p); io.io(t.trim.origin_q);
    io.io(t.hidden);
  }
  io.size_of(d.tested);
  for (auto& [key, decision] : d.tested) { io.io(key); io.io(decision); }
  io.size_of(d.island_cells);
  for (auto& i : d.island_cells) io.io(i);
}
inline void write_bytes(Byte_writer& w, const Pair_decision& d) { transfer(w, d); }
inline void read_bytes(Byte_reader& r, Pair_decision& d) { transfer(r, d); }

/// The CD test of candidate (p, q) of pair fp: its direction, or `inner`.
inline std::uint32_t cd_decision(Cd_filter& filter, const Candidate_pairs& pairs, const Feature_pair& fp,
                                 const Sample& p, const Sample& q)
{
  const Direction* dirs = pairs.directions.data() + fp.first_direction;
  for (std::uint32_t k = 0; k < fp.number_of_directions; ++k) {
    if (filter.is_free(p, q, dirs, fp.number_of_directions, k)) return fp.first_direction + k;
    if (filter.decided_without_perturbation()) break; // the same for every direction
  }
  return inner;
}

/// The CD test's shortcut for the lattice points of a 2-dimensional pair with one direction:
/// a point inside the crossing set of one pair of convex patches, perturbed as the pair's
/// points are (on the facet's plane, Segment_search::patch_pair_covers()), is inner, as the
/// CD query would find. The patch pairs tried: those that held the last points, and that of
/// the last crossing found. Where intervals decide, a few dot products; on a seam where two
/// parts of the sum touch face to face (CAD parts), where every CD query needs the
/// perturbation's exact signs, the facet's plane decides the seam's slab once. (With several
/// directions a point is free if it is free along any of them: no shortcut.)
class Facet_patch_test
{
public:
  Facet_patch_test(Cd_filter& filter, const Facet_lattice& lattice, const Candidate_pairs& pairs, const Feature_pair& fp)
    : m_search(filter), m_filter(filter), m_lattice(lattice), m_directions(pairs.directions.data() + fp.first_direction),
      m_count(fp.number_of_directions)
  {}

  /// Is lattice point p + q (of P and Q) inner by the shortcut?
  bool inner(const Mesh_data& P, const Mesh_data& Q, const Sample& p, const Sample& q)
  {
    if (m_count != 1) return false;
    start_facet_plane(m_search, m_lattice, m_directions, m_count);
    const Vec3<Interval> e = lattice_point_box(P, Q, p, q);
    return m_search.patch_pair_covers({e, e, e}, {m_filter.last_crossing(), std::nullopt, std::nullopt}, false);
  }

  /// The segment search of the facet (its plane started, or not yet), for its trim search.
  Segment_search& search() { return m_search; }

private:
  Segment_search m_search;
  Cd_filter& m_filter;
  const Facet_lattice& m_lattice;
  const Direction* m_directions;
  std::uint32_t m_count;
};

inline void trim_search(const Decision_context& c, const Feature_pair& fp, const Facet_lattice& lattice,
                        std::vector<Corner_info>& corners, Cd_filter& filter, Facet_patch_test& patches,
                        Pair_decision& out, Decision_counters& counters);

/// How many times a lattice cell is cut in four, at most, to show that the net covers it
/// (Covering_net::covers_all_parts()). Against one point for the whole cell (0), 2 searches
/// the trim curves of fewer cells (grates: 1.8 times fewer trim queries, the sum 1.6 times
/// faster; joint 13% fewer queries), 3 saves little more (0-2% fewer queries).
constexpr int covered_depth = 2;

/// Is a lattice cell (its corners) covered whole, every point of it closer than d to a point
/// of the net (of the earlier waves: final)? Then its trim curves (where the covering is all
/// their search is for) or its islands (unless a mesh follows narrow strips) need no search.
inline auto covered_whole(const Decision_context& c, bool islands)
{
  const bool skip = islands ? c.strips != Strips::followed : c.strips == Strips::as_covering_needs;
  return [&c, skip](const std::array<Point3, 3>& cell) {
    return skip && c.net && c.net->covers_all_parts(cell, c.d, covered_depth);
  };
}

/// Thread phase: decides the candidates of a piece of a pair (see the file comment) into
/// `out`, then searches the trim points of the piece's cells.
inline void decide_piece(const Decision_context& c, const Pair_piece& piece, Cd_filter* filter,
                         Pair_candidates& candidates, Pair_decision& out, Decision_counters& counters)
{
  const std::size_t i = piece.pair;
  const Feature_pair& fp = c.pairs->pairs[i];
  if (filter) filter->forget_last_crossing(); // the piece's counts: the same on any thread or rank
  const bool positions = c.octree || c.net;
  candidates.load(*c.sp, *c.sq, fp, Pair_rows(*c.sp, *c.sq, fp), piece.rows, positions);
  // Which samples the coarser level had (only their pairs can be in the cache).
  std::vector<std::uint8_t> old_p(candidates.size_p(), 0), old_q(candidates.size_q(), 0);
  if (c.coarser_p && c.cache && !c.cache->empty()) {
    for (std::size_t k = 0; k < old_p.size(); ++k) old_p[k] = c.sp->is_sample_of(candidates.p(k), *c.coarser_p);
    for (std::size_t k = 0; k < old_q.size(); ++k) old_q[k] = c.sq->is_sample_of(candidates.q(k), *c.coarser_q);
  }
  std::optional<Covering_net> own; // this pair's tentative points, on top of c.net
  // The trim search needs what is known of each lattice point of the pair's facet.
  std::optional<Facet_lattice> lattice;
  std::vector<Corner_info> corners;
  if (filter && c.use_cd_filter && c.trim_points && fp.number_of_directions > 0) {
    lattice.emplace(*c.sp, *c.sq, fp, piece.rows);
    if (lattice->empty()) lattice.reset();
    else corners.assign(lattice->size(), Corner_info{});
  }
  std::optional<Facet_patch_test> patches;
  if (lattice) patches.emplace(*filter, *lattice, *c.pairs, fp);
  // What the trim search knows of a candidate: its status, and of an inside one its certified
  // leaf (`certified`: its position) or the item pair whose crossing decided it (`witness`).
  auto known = [&](std::size_t ip, std::size_t iq, Corner k, const Point3* certified = nullptr,
                   const std::optional<std::pair<Index, Index>>& witness = std::nullopt) {
    if (!lattice) return;
    Corner_info& info = corners[lattice->index_of(candidates.p(ip), candidates.q(iq))];
    info.status = k;
    if (certified) info.leaf = c.octree->certified_leaf(*certified);
    info.witness = witness;
  };
  const Covering_net::Normals normals = c.normals_of(fp);
  candidates.for_each([&](std::size_t ip, std::size_t iq) {
    const Sample &p = candidates.p(ip), &q = candidates.q(iq);
    const Point3 x = positions ? candidates.position(ip, iq) : Point3{};
    if (!filter || !c.use_cd_filter) { out.tentative.push_back({p, q, x, fp.first_direction, true}); return; }
    const bool kept = c.kept(p, q);
    std::uint32_t decision = untested;
    if (old_p[ip] && old_q[iq]) {
      decision = c.cache->find(Decision_cache::Key::of(i, p, q));
      if (decision != untested) ++counters.reused;
    }
    if (decision == untested && c.octree && c.octree->certified(x)) {
      ++counters.certified;
      // What the trim search knows must not depend on the octree: as if tested below.
      if (c.net && c.covers(*c.net, x, normals, kept)) known(ip, iq, Corner::covered);
      else if (!own || !c.covers(*own, x, normals, kept)) known(ip, iq, Corner::inside, &x);
      return;
    }
    if (decision == inner) { known(ip, iq, Corner::inside, nullptr, filter->last_crossing()); return; }
    if (c.net && c.covers(*c.net, x, normals, kept)) { ++counters.covered; known(ip, iq, Corner::covered); return; }
    if (own && c.covers(*own, x, normals, kept)) { out.tentative.push_back({p, q, x, untested, kept}); return; }
    if (decision == untested && patches && patches->inner(c.sp->mesh(), c.sq->mesh(), p, q)) {
      ++counters.in_patch_pairs;
      if (c.record_decisions) out.tested.emplace_back(Decision_cache::Key::of(i, p, q), inner);
      known(ip, iq, Corner::inside);
      return;
    }
    if (decision == untested) {
      decision = cd_decision(*filter, *c.pairs, fp, p, q);
      if (c.record_decisions) out.tested.emplace_back(Decision_cache::Key::of(i, p, q), decision);
      if (decision == inner) { known(ip, iq, Corner::inside, nullptr, filter->last_crossing()); return; }
    }
    known(ip, iq, Corner::free);
    out.tentative.push_back({p, q, x, decision, kept});
    if (c.net) {
      if (!own) own.emplace(c.net->empty_like());
      own->insert(x, normals);
    }
  });
  if (lattice) trim_search(c, fp, *lattice, corners, *filter, *patches, out, counters);
}

/// The trim points of a piece of pair fp's facet (trim_points.h). Lattice points that are not
/// the piece's candidates (on the facet's edges, or the next piece's) are covered if the net
/// covers them, else tested with the pair's directions.
inline void trim_search(const Decision_context& c, const Feature_pair& fp, const Facet_lattice& lattice,
                        std::vector<Corner_info>& corners, Cd_filter& filter, Facet_patch_test& patches,
                        Pair_decision& out, Decision_counters& counters)
{
  const Mesh_data &P = c.sp->mesh(), &Q = c.sq->mesh();
  auto corner = [&](std::uint32_t k) -> const Corner_info& {
    Corner_info& info = corners[k];
    if (lattice.is_own_candidate(k) || info.status != Corner::unknown) return info;
    const Point3 x = lattice.position(k, P, Q);
    if (c.net && c.net->covers(x, c.normals_of(fp))) { info.status = Corner::covered; return info; }
    if (c.octree && (info.leaf = c.octree->certified_leaf(x))) { info.status = Corner::inside; return info; }
    if (patches.inner(P, Q, lattice.p(k), lattice.q(k))) {
      ++counters.in_patch_pairs;
      info.status = Corner::inside;
      return info;
    }
    ++counters.corner_tests;
    const bool inside = cd_decision(filter, *c.pairs, fp, lattice.p(k), lattice.q(k)) == inner;
    info.status = inside ? Corner::inside : Corner::free;
    if (inside) info.witness = filter.last_crossing();
    return info;
  };
  Segment_search& search = patches.search();
  const std::size_t before = out.trims.size(), queries_before = filter.statistics().queries;
  // Certified inside the sum: a box, by the octree's leaves; else a ball, by the certificate.
  Interior_certificate::Hint hint;
  auto certified = [&](const Point3& lo, const Point3& hi, bool ball) {
    if (!c.octree) return false;
    if (c.octree->certifies_box(lo, hi)) return true;
    if (!ball) return false;
    Point3 centre;
    for (int i = 0; i < 3; ++i) centre[i] = 0.5 * (lo[i] + hi[i]);
    return c.octree->certifies_ball(centre, 0.5 * std::sqrt(dot(hi - lo, hi - lo)), &hint);
  };
  find_trim_points(lattice, P, Q, *c.pairs, fp, c.d, c.strips, corner, certified, covered_whole(c, false), search,
                   c.islands ? &out.island_cells : nullptr, out.trims);
  counters.trim_segments += search.searched_segments();
  counters.trim_points += out.trims.size() - before;
  counters.trim_queries += filter.statistics().queries - queries_before;
}

/// The islands of a piece's cells whose edges have no trim point (`cells`, recorded in its
/// Pair_decision by its trim search), searched after the level's waves (pipeline.h): a cell
/// that the net then covers whole needs none, and most do. Island points go to out.trims.
inline void decide_islands(const Decision_context& c, const Pair_piece& piece, const std::vector<std::uint32_t>& cells,
                           Cd_filter& filter, Pair_decision& out, Decision_counters& counters)
{
  const Feature_pair& fp = c.pairs->pairs[piece.pair];
  filter.forget_last_crossing(); // (as in decide_piece)
  const Facet_lattice lattice(*c.sp, *c.sq, fp, piece.rows);
  Segment_search search(filter);
  Island_search islands(filter, search);
  const std::size_t queries_before = filter.statistics().queries;
  find_island_points(lattice, c.sp->mesh(), c.sq->mesh(), *c.pairs, fp, c.d, cells, covered_whole(c, true), search, islands,
                     out.trims);
  counters.island_cells += islands.searched_cells();
  counters.trim_points += out.trims.size();
  counters.trim_queries += filter.statistics().queries - queries_before;
}

/// Commit phase of a piece of pair i's trim points (after its tentative points): each is
/// output, and inserted in `net`, unless a point of the net covers it within its radius.
template <class Emit>
void commit_trims(const Decision_context& c, std::size_t i, const Pair_decision& decided, Covering_net* net,
                  const Emit& emit)
{
  const Covering_net::Normals normals = c.normals_of(c.pairs->pairs[i]);
  for (const Trim_point& t : decided.trims) {
    Covering_net::Normals trim_normals = normals;
    trim_normals.hidden = t.hidden;
    if (net && net->covers_within(t.x, t.radius, trim_normals)) continue;
    if (net) net->insert(t.x, trim_normals);
    emit(t);
  }
}

/// Commit phase, on one thread, pieces in canonical order: the sequential greedy choice over
/// the tentative points of a piece of pair i. Calls emit(tentative with its direction) for
/// each output point and inserts it in `net`; `filter` tests what decide_piece left
/// untested. With `cache` (coarse to fine), every decision of the piece is added to it.
template <class Emit>
void commit_piece(const Decision_context& c, std::size_t i, Pair_decision& decided, Covering_net* net,
                 Cd_filter* filter, Decision_counters& counters, Decision_cache* cache, const Emit& emit)
{
  const Feature_pair& fp = c.pairs->pairs[i];
  if (cache)
    for (const auto& [key, decision] : decided.tested) cache->add(key, decision);
  const Covering_net::Normals normals = c.normals_of(fp);
  for (Tentative& t : decided.tentative) {
    if (net && c.covers(*net, t.x, normals, t.kept)) {
      counters.covered += (t.direction == untested);
      continue;
    }
    if (t.direction == untested) {
      ++counters.tested_in_commit;
      t.direction = cd_decision(*filter, *c.pairs, fp, t.p, t.q);
      if (cache) cache->add(Decision_cache::Key::of(i, t.p, t.q), t.direction);
      if (t.direction == inner) continue;
    }
    if (net) net->insert(t.x, normals);
    emit(t);
  }
  commit_trims(c, i, decided, net, emit);
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_DECISION_H
