// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3b of the pipeline, first half: the free parts of a segment of translations, exactly.
//
// Along a segment x(l) = a + l (b - a), l in [0, 1], every predicate of the CD filter
// (cd_filter.h) is an orientation determinant affine in the translation, hence affine in l:
// its sign changes at most once, at a rational root l = D(a) / (D(a) - D(b)). Between two
// consecutive roots of the predicates of an item pair the pair's answer is constant, so the
// set of l where the pair crosses is a union of "elements": roots (points) and the open
// intervals between them. The answer on an open interval is the answer at its left root
// perturbed first along +(b - a) (Cd_filter::set_point's prefix), which is exact; the
// answer at a root is the CD filter's own (perturbed along the candidate's directions).
// The segment's elements are the roots of all pairs whose boxes can overlap on the segment;
// an element is colliding if some pair crosses there. A run of consecutive non-colliding
// elements has the same containment answer everywhere (it changes only where surfaces
// cross), so one full CD query per run decides it. The closure of a free run is free of
// int(P + Q); its two ends are exact boundary points of the sum when the segment lies on a
// convolution facet (they are points of the facet, hence of P + Q, and limits of free points).
//
// The translations t at which two triangles cross form an open convex polytope U (their
// Minkowski difference), so a pair crosses on one interval of the segment. Intervals alone
// often know most of it (Cd_filter::crossing_range(): parameters where the pair certainly
// crosses, and where it certainly does not); the exact tests are left for the elements near
// the ends of that interval. Quick exits, cheapest first (none where an end is known free:
// then something is free, Known_ends):
//  - the witnesses of the ends certainly cross on all of the segment (intervals only);
//  - one pair crosses at a + delta and at b + delta (the same infinitesimal perturbation
//    delta): then x(l) + delta is in U for every l (convexity), and nothing is free; first
//    tried with the few pairs known to cross near the segment (its ends' witnesses, the pair
//    of the last quick exit, the filter's last crossing), a few exact tests;
//  - hops: a chain of pairs' runs, each found by a CD query where the previous one ends;
//  - the convexity exit again, with every pair whose box overlaps the segment's; not tried
//    when the hops' first query found no pair crossing at the point 0 (free, or inside by
//    containment): then no pair covers s. That query also answers, in the search below, for
//    every pair at the point 0, and for the run of elements without crossings holding it
//    (the rotated narrow tunnel's island lines: 2,529 of its 2,728 full searches).
// Otherwise only the pairs that can change the union of the runs are searched: a pair that
// can only cross where others certainly cross is dropped (keep_pairs_that_matter()).
// Segments on a plane of translations (a convolution facet's: start_plane()) ignore the pairs
// that cross nowhere on it, whatever intervals say (coplanar faces touching all along).

#ifndef CGAL_PMSUM_INTERNAL_SEGMENT_SEARCH_H
#define CGAL_PMSUM_INTERNAL_SEGMENT_SEARCH_H

#include <CGAL_pmsum/internal/cd_filter.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Converts an Mpzf exactly to CGAL::Exact_rational (GMP's mpq_class, or CGAL::Gmpq).
template <class Q = CGAL::Exact_rational>
Q to_rational(const Exact_nt& x)
{
  if constexpr (std::is_constructible<Q, CGAL::Gmpq>::value) {
    return Q(CGAL::Gmpq(x));
  } else {
    Q r;
    x.export_to_mpq_t(r.get_mpq_t());
    return r;
  }
}

/// A parameter num / den of a segment, exactly (den > 0).
struct Segment_parameter
{
  Exact_nt num, den;
  /// The points of an orientation predicate zero at this parameter, if known (a root's).
  std::optional<Predicate_points> zero_of;
  static Segment_parameter zero() { return {Exact_nt(0), Exact_nt(1)}; }
  static Segment_parameter one() { return {Exact_nt(1), Exact_nt(1)}; }
  CGAL::Exact_rational value() const { return to_rational(num) / to_rational(den); }
};

inline CGAL::Sign compare(const Segment_parameter& a, const Segment_parameter& b)
{ return CGAL::sign(a.num * b.den - b.num * a.den); }
inline bool operator<(const Segment_parameter& a, const Segment_parameter& b) { return compare(a, b) == CGAL::NEGATIVE; }

/// A segment of translations [a, b], with a common denominator W.
struct Translation_segment
{
  Exact_point a, b;
  /// The samples whose sums are a and b, if they are known (lattice points).
  std::optional<std::array<std::pair<Sample, Sample>, 2>> sums;

  Translation_segment(const Exact_point& pa, const Exact_point& pb,
                      std::optional<std::array<std::pair<Sample, Sample>, 2>> ends = std::nullopt)
    : a(pa), b(pb), sums(std::move(ends))
  {
    if (pa.W == pb.W) return;
    a = {{pa.X[0] * pb.W, pa.X[1] * pb.W, pa.X[2] * pb.W}, pa.W * pb.W};
    b = {{pb.X[0] * pa.W, pb.X[1] * pa.W, pb.X[2] * pa.W}, pa.W * pb.W};
  }

  /// The samples whose affine hulls' sum holds the point of parameter l, if known: those of
  /// the ends (of one end at l = 0 or 1).
  Spans spans(const Segment_parameter& l) const
  {
    if (!sums) return {};
    if (CGAL::is_zero(l.num)) return end_spans(0);
    if (l.num == l.den) return end_spans(1);
    return {&(*sums)[0], &(*sums)[1]};
  }
  /// Those of end k (a: 0, b: 1).
  Spans end_spans(int k) const { return sums ? Spans{&(*sums)[k]} : Spans{}; }

  /// The point of parameter l, exactly: (den Xa + num (Xb - Xa)) / (den W).
  Exact_point at(const Segment_parameter& l) const
  {
    Exact_point r;
    for (int c = 0; c < 3; ++c) r.X[c] = l.den * a.X[c] + l.num * (b.X[c] - a.X[c]);
    r.W = l.den * a.W;
    return r;
  }
};

/// What is known of the ends of a segment of translations before its search.
struct Known_ends
{
  /// Item pairs known to cross at a and at b (the end is inside the sum), tried first.
  std::array<std::optional<std::pair<Index, Index>>, 2> witnesses;
  /// Is an end known free (a lattice point the CD filter found on the boundary)? Then the
  /// segment is not covered, and no quick exit is tried (each is an exact proof that it is:
  /// skipping them changes no answer).
  bool an_end_free = false;
};

/// The free parts of segments of translations (see the file comment). One per thread, on
/// that thread's CD filter.
class Segment_search
{
public:
  explicit Segment_search(Cd_filter& filter) : m_filter(filter) {}

  /// Starts the segments of the plane H of the triangle F with corners p_k + q_k (`corners`:
  /// the samples (p_k, q_k); not collinear):
  /// until the next call, every segment searched lies in H, its side (if any) is parallel to
  /// H, and its points are perturbed along `directions` (count of them). The item pairs that
  /// cross nowhere on H (Cd_filter::on_plane(), exact) are then neither searched nor tested
  /// by the queries (Cd_filter::set_point_on_plane()): most of those that touch along the
  /// segment (coplanar faces), which only exact tests could decide.
  /// Sets the CD filter's plane (Cd_filter::set_plane()).
  void start_plane(const std::array<std::pair<Sample, Sample>, 3>& corners, const Direction* directions,
                   std::uint32_t count)
  {
    m_filter.set_plane(corners, directions, count);
    m_in_plane = true;
  }

  /// Was start_plane() called?
  bool plane_started() const { return m_in_plane; }

  /// Number of segments searched.
  std::size_t searched_segments() const { return m_segments; }

  /// Does one patch pair's crossing set (Cd_filter::patch_crossing_slabs()) hold all of the
  /// triangle of translations e (boxes holding its corners), with a margin (intervals)? Then
  /// every point of it, perturbed, is a collision: a segment there has no free part, a
  /// lattice cell no island. The patch pairs tried: the last ones that held a triangle
  /// (neighbours are often held by the same), those of the item pairs `witnesses` (known to
  /// cross at its corners), and with `scan`, every patch pair whose items' boxes overlap on e
  /// (a traversal, as a CD query's). After start_plane(), e lies on the plane and its points
  /// are perturbed as the plane's: what the plane tells of a pair is used too
  /// (Cd_filter::patch_crossing_slabs_on_plane(): coplanar faces, whose crossing set has the
  /// plane as a bounding plane, as on the seams of boxes that touch along faces). With the
  /// scan, the answer does not depend on the pairs tried before; without it, a pair missed
  /// only costs work.
  bool patch_pair_covers(const std::array<Vec3<Interval>, 3>& e,
                         const std::array<std::optional<std::pair<Index, Index>>, 3>& witnesses, bool scan)
  {
    auto where = [&](const std::pair<Index, Index>& patches) {
      if (m_in_plane) return m_filter.patch_crossing_slabs_on_plane(patches.first, patches.second, e).second;
      CGAL::Protect_FPU_rounding<true> guard;
      return m_filter.patch_crossing_slabs(patches.first, patches.second, e).second;
    };
    auto holds = [&](const std::pair<Index, Index>& patches) {
      if (where(patches) != Crossing_slabs::Where::inside) return false;
      if (std::find(m_recent_covers.begin(), m_recent_covers.end(), patches) == m_recent_covers.end())
        m_recent_covers[m_next_recent++ % m_recent_covers.size()] = patches;
      return true;
    };
    for (const auto& patches : m_recent_covers)
      if (patches && holds(*patches)) return true;
    for (const auto& w : witnesses)
      if (w && holds({m_filter.moving_patch(w->first), m_filter.static_patch(w->second)})) return true;
    if (!scan) return false;
    m_patches_met.clear();
    bool covered = false;
    m_filter.for_each_overlapping_pair(hull(hull(e[0], e[1]), e[2]), [&](Index u, Index v) {
      const std::pair<Index, Index> patches(m_filter.moving_patch(u), m_filter.static_patch(v));
      return m_patches_met.insert(pair_key(patches.first, patches.second)).second && (covered = holds(patches));
    });
    return covered;
  }

  /// Appends to `ends` the parameters of the ends of the free parts of s (sorted, each free
  /// part giving its first and last parameter, equal for an isolated free point). Points are
  /// perturbed along directions[0], ..., directions[count - 1], then the axes.
  /// `known`: what is known of s's ends. `side`: if given, every
  /// point is perturbed first along it (after the segment's own direction on open
  /// intervals): the free parts are then those of the side of s that it points to.
  void free_ends(const Translation_segment& s, const Direction* directions, std::uint32_t count,
                 std::vector<Segment_parameter>& ends, const Known_ends& known = {},
                 const Vec3<Exact_nt>* side = nullptr)
  {
    ++m_segments;
    if (!m_roots_of || !same_point(m_roots_of->first, s.a) || !same_point(m_roots_of->second, s.b)) {
      m_roots.clear();
      m_roots_of = std::make_pair(s.a, s.b);
    }
    m_directions = directions;
    m_count = count;
    m_side = side;
    for (int c = 0; c < 3; ++c) m_forward[c] = s.b.X[c] - s.a.X[c];
    m_a = enclosure(s.a);
    m_b = enclosure(s.b);
    // Quick exits; else m_pairs holds the item pairs whose boxes overlap on the segment.
    m_start = Start::unknown;
    if (known.an_end_free) {
      collect_pairs(s, Pairs::all);
    } else {
      const auto& witnesses = known.witnesses;
      std::array<Crossing_range, 2> ranges; // the witnesses' (nothing known without one)
      for (int k = 0; k < 2; ++k)
        if (witnesses[k]) ranges[k] = m_filter.crossing_range(witnesses[k]->first, witnesses[k]->second, m_a, m_b);
      if (certainly_covered(ranges) || known_pair_covers(s, witnesses, ranges) || covered_by_hops(s, witnesses[0], ranges[0]))
        return;
      // (no pair covers s if the hops found no pair crossing at its point 0)
      if (collect_pairs(s, m_start == Start::unknown ? Pairs::until_one_covers : Pairs::all)) return;
    }

    // Each pair's crossing set: runs of its own elements (between the roots of its own
    // predicates). The elements of the segment: R_0 = 0 < R_1 < ... < R_k = 1, the ends of
    // those runs; element 2i is the point R_i and element 2i + 1 the open interval
    // (R_i, R_i+1). Every pair's answer is constant on every element.
    std::vector<std::pair<Segment_parameter, Segment_parameter>> runs; // closed or open ends: see below
    std::vector<std::array<bool, 2>> open_ends;                       // is the run's first / last end excluded?
    std::vector<Segment_parameter> roots = {Segment_parameter::zero(), Segment_parameter::one()};
    keep_pairs_that_matter();
    for (std::size_t k = 0; k < m_pairs.size(); ++k) {
      const auto& pair = m_pairs[k];
      const std::vector<Segment_parameter>& local = cached_roots(s, pair.first, pair.second);
      const std::size_t n = 2 * local.size() - 1;
      std::size_t e = 0;
      while (e < n) {
        if ((e == 0 && m_start != Start::unknown) || !crosses_on(s, local, e, pair, m_ranges[k])) { ++e; continue; }
        std::size_t end = e;
        while (end + 1 < n && crosses_on(s, local, end + 1, pair, m_ranges[k])) ++end;
        runs.emplace_back(local[e / 2], local[(end + 1) / 2]);
        open_ends.push_back({e % 2 == 1, end % 2 == 1});
        roots.push_back(local[e / 2]);
        roots.push_back(local[(end + 1) / 2]);
        e = end + 1;
      }
    }
    sort_unique(roots);
    const std::size_t elements = 2 * roots.size() - 1;
    std::vector<int> delta(elements + 1, 0); // covering counts, as differences
    auto index = [&](const Segment_parameter& l) { return std::size_t(std::lower_bound(roots.begin(), roots.end(), l) - roots.begin()); };
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const std::size_t first = 2 * index(runs[r].first) + (open_ends[r][0] ? 1 : 0);
      const std::size_t last = 2 * index(runs[r].second) - (open_ends[r][1] ? 1 : 0);
      if (first > last) continue;
      ++delta[first];
      --delta[last + 1];
    }
    std::vector<std::uint8_t> colliding(elements, 0);
    for (std::size_t e = 0, count = 0; e < elements; ++e) colliding[e] = (count += delta[e]) > 0;

    // One query per run of non-colliding elements.
    for (std::size_t e = 0; e < elements;) {
      if (colliding[e]) { ++e; continue; }
      std::size_t end = e;
      while (end + 1 < elements && !colliding[end + 1]) ++end;
      std::size_t rep = e;
      while (rep <= end && rep % 2 == 0) ++rep;
      if (rep > end) rep = e;
      // The run holding the point 0 is as covered_by_hops() found that point, if it did.
      if (e == 0 && m_start != Start::unknown ? m_start == Start::free : free_at(s, roots, rep)) {
        ends.push_back(roots[e / 2]);             // a point, or an interval's left root
        ends.push_back(roots[(end + 1) / 2]);     // a point, or an interval's right root
      }
      e = end + 1;
    }
  }

private:
  /// Does the item pair cross on all of s? Yes if intervals (`range`, crossing_range())
  /// show it, or if it crosses at both ends of s (perturbed along the directions, then the
  /// axes; see the file comment), tested exactly where intervals do not show it missing one.
  bool pair_covers(const Translation_segment& s, const std::pair<Index, Index>& pair, const Crossing_range& range)
  {
    if (range.covers_segment()) return true;
    if (range.low > 0 || range.high < 1) return false;
    return m_filter.pair_crosses_at(pair.first, pair.second, {{&s.a, {s.end_spans(0)}}, {&s.b, {s.end_spans(1)}}},
                                    m_directions, m_count, {m_side, nullptr});
  }

  /// Does a pair known to cross near s (the ends' witnesses, whose crossing ranges are
  /// `ranges`, the last pair that covered a segment, the filter's last crossing) cover s? A
  /// few pairs, each tried once: cheaper than a CD query.
  bool known_pair_covers(const Translation_segment& s, const std::array<std::optional<std::pair<Index, Index>>, 2>& witnesses,
                         const std::array<Crossing_range, 2>& ranges)
  {
    const std::array<std::optional<std::pair<Index, Index>>, 4> pairs = {witnesses[0], witnesses[1], m_last_quick,
                                                                         m_filter.last_crossing()};
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto& pair = pairs[k];
      if (!pair || std::find(pairs.begin(), pairs.begin() + k, pair) != pairs.begin() + k) continue;
      if (pair_covers(s, *pair, k < 2 ? ranges[k] : m_filter.crossing_range(pair->first, pair->second, m_a, m_b))) {
        m_last_quick = pair;
        return true;
      }
    }
    return false;
  }

  /// How far collect_pairs() goes.
  enum class Pairs : std::uint8_t { until_one_covers, all };

  /// Fills m_pairs with the item pairs whose boxes overlap on s and that may cross on it, and
  /// m_ranges with what is known of where (Cd_filter::crossing_range()). With
  /// Pairs::until_one_covers, stops at the first that covers s (pair_covers()) and returns true.
  bool collect_pairs(const Translation_segment& s, Pairs how)
  {
    m_pairs.clear();
    m_ranges.clear();
    bool found = false;
    m_filter.for_each_overlapping_pair(hull(m_a, m_b), [&](Index u, Index v) {
      const Crossing_range range = m_filter.crossing_range(u, v, m_a, m_b);
      if (range.misses_segment() || m_filter.parallel_triangles(u, v) || (m_in_plane && m_filter.on_plane(u, v).never))
        return false;
      m_pairs.emplace_back(u, v);
      m_ranges.push_back(range);
      if (how == Pairs::all || !pair_covers(s, m_pairs.back(), range)) return false;
      m_last_quick = m_pairs.back();
      return found = true;
    });
    return found;
  }

  /// Drops from m_pairs the pairs whose crossings cannot change the union of all crossings:
  /// C, the union of the intervals where some pair certainly crosses, is covered by a few of
  /// those pairs (greedily), which are kept; a pair that can only cross inside one component
  /// of C is dropped (its run lies in the union of the kept ones'). The union of the kept
  /// pairs' runs is the union of all runs.
  void keep_pairs_that_matter()
  {
    std::vector<std::size_t> order;
    for (std::size_t k = 0; k < m_pairs.size(); ++k)
      if (m_ranges[k].in_from < m_ranges[k].in_to) order.push_back(k);
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return m_ranges[i].in_from < m_ranges[j].in_from; });
    std::vector<std::uint8_t> keep(m_pairs.size(), 0);
    std::vector<std::pair<double, double>> components; // of C, open
    for (std::size_t i = 0; i < order.size();) {
      // A component starts at the first interval left; the interval reaching farthest among
      // those that overlap it so far extends it, while one does.
      const double from = m_ranges[order[i]].in_from;
      double reach = from;
      for (;;) {
        std::optional<std::size_t> best;
        for (; i < order.size() && (m_ranges[order[i]].in_from < reach || m_ranges[order[i]].in_from == from); ++i)
          if (!best || m_ranges[order[i]].in_to > m_ranges[*best].in_to) best = order[i];
        if (!best || !(m_ranges[*best].in_to > reach)) break;
        keep[*best] = 1;
        reach = m_ranges[*best].in_to;
      }
      components.emplace_back(from, reach);
    }
    std::size_t kept = 0;
    for (std::size_t k = 0; k < m_pairs.size(); ++k) {
      bool hidden = false;
      if (!keep[k]) {
        const auto c = std::upper_bound(components.begin(), components.end(), m_ranges[k].low,
                                        [](double l, const std::pair<double, double>& x) { return l < x.first; });
        hidden = c != components.begin() && std::prev(c)->first < m_ranges[k].low && m_ranges[k].high < std::prev(c)->second;
      }
      if (hidden) continue;
      m_pairs[kept] = m_pairs[k];
      m_ranges[kept++] = m_ranges[k];
    }
    m_pairs.resize(kept);
    m_ranges.resize(kept);
  }

  /// Do intervals alone show that the witnesses' crossings (their crossing ranges `r`,
  /// Cd_filter::crossing_range()) cover s: the first from 0, the second up to 1, meeting?
  static bool certainly_covered(const std::array<Crossing_range, 2>& r)
  {
    return r[0].covers_segment() || r[1].covers_segment() ||
           (r[0].in_from < 0 && r[1].in_to > 1 && r[0].in_to > r[1].in_from);
  }

  /// Is the segment covered by the crossing runs of a chain of item pairs, each found by a
  /// CD query on the element where the previous run ends (at most 16)? Cheap when many
  /// small items hide the segment one after the other (fine meshes), where no single pair
  /// crosses at both ends. The first run is `start`'s if intervals (`start_range`, its
  /// crossing range) show it crosses at 0. Sets m_start if its first query found that no
  /// pair crosses at the point 0.
  bool covered_by_hops(const Translation_segment& s, const std::optional<std::pair<Index, Index>>& start,
                       const Crossing_range& start_range)
  {
    m_start = Start::unknown;
    Segment_parameter at = Segment_parameter::zero();
    bool on_gap = false; // the element: the point `at`, or the open interval just after it
    for (int hop = 0; hop < 16; ++hop) {
      std::optional<std::pair<Index, Index>> hit;
      Crossing_range range;
      if (hop == 0 && start && start_range.in_from < 0 && start_range.in_to > 0) {
        range = start_range;
        hit = start;
      }
      if (!hit) {
        set_query(s.at(at), on_gap, s, at);
        if (m_filter.is_free_here()) {
          if (hop == 0) m_start = Start::free;
          return false;
        }
        hit = m_filter.last_crossing(); // this query's, if it found a crossing
        if (!hit || !m_filter.pair_crosses_here(hit->first, hit->second)) { // containment
          if (hop == 0) m_start = Start::contained;
          return false;
        }
        range = m_filter.crossing_range(hit->first, hit->second, m_a, m_b);
      }
      if (range.in_to > 1) return true; // crosses from here (convex) up to the point 1
      const std::vector<Segment_parameter>& local = cached_roots(s, hit->first, hit->second);
      const std::size_t k = std::size_t(std::upper_bound(local.begin(), local.end(), at) - local.begin()) - 1;
      const bool root = compare(local[k], at) == CGAL::ZERO;
      std::size_t end = (root && !on_gap) ? 2 * k : 2 * k + 1; // the pair's element holding ours
      const std::size_t n = 2 * local.size() - 1;
      while (end + 1 < n && crosses_on(s, local, end + 1, *hit, range)) ++end;
      if (end + 1 == n) return true; // up to the point 1
      at = local[(end + 1) / 2];
      on_gap = (end + 1) % 2 == 1;
    }
    return false;
  }

  static void sort_unique(std::vector<Segment_parameter>& v)
  {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end(),
                        [](const Segment_parameter& a, const Segment_parameter& b) { return compare(a, b) == CGAL::ZERO; }),
            v.end());
  }

  /// pair_roots(s, u, v), computed once per segment: kept while the same segment is searched
  /// again (the island search searches each line twice, to either side; covered_by_hops()
  /// and the pairs' runs ask for the same pairs). They do not depend on the perturbation.
  const std::vector<Segment_parameter>& cached_roots(const Translation_segment& s, Index u, Index v)
  {
    auto [it, added] = m_roots.try_emplace({u, v});
    if (added) it->second = pair_roots(s, u, v);
    return it->second;
  }

  static bool same_point(const Exact_point& a, const Exact_point& b)
  { return a.W == b.W && a.X[0] == b.X[0] && a.X[1] == b.X[1] && a.X[2] == b.X[2]; }

  /// 0, the roots in (0, 1) of the predicates of pair (u, v) along s, and 1, sorted, unique.
  std::vector<Segment_parameter> pair_roots(const Translation_segment& s, Index u, Index v) const
  {
    std::vector<Segment_parameter> r = {Segment_parameter::zero()};
    m_filter.for_each_predicate(u, v, [&](const Moving_point& a, const Moving_point& b, const Moving_point& c,
                                          const Moving_point& d) {
      // D(x) = D(0) + g.x at the ends: no root inside if both certainly have the same sign.
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const auto [d0, g] = m_filter.affine_enclosure(a, b, c, d);
        const Interval da = d0 + dot(g, m_a), db = d0 + dot(g, m_b);
        if ((da.inf() > 0 && db.inf() > 0) || (da.sup() < 0 && db.sup() < 0)) return;
        if ((da.inf() == 0 && da.sup() == 0) || (db.inf() == 0 && db.sup() == 0)) return; // zero at an end
      }
      // W D(a) and W D(b), exactly; the root is l = D(a) / (D(a) - D(b)).
      const Affine_predicate& f = m_filter.exact_affine_form(a, b, c, d);
      const Exact_nt da = s.a.W * f.d0 + dot(f.g, s.a.X), db = s.b.W * f.d0 + dot(f.g, s.b.X);
      const CGAL::Sign sa = CGAL::sign(da), sb = CGAL::sign(db);
      if (sa == sb || sa == CGAL::ZERO || sb == CGAL::ZERO) return; // no root strictly inside
      Segment_parameter l{da, da - db, Predicate_points{a, b, c, d}};
      if (CGAL::sign(l.den) == CGAL::NEGATIVE) { l.num = -l.num; l.den = -l.den; }
      r.push_back(l);
    });
    r.push_back(Segment_parameter::one());
    sort_unique(r);
    return r;
  }

  /// Sets the query to element e of `roots`: the point, or the interval just after its
  /// left root.
  void set_element(const Translation_segment& s, const std::vector<Segment_parameter>& roots, std::size_t e)
  {
    set_query(s.at(roots[e / 2]), e % 2 == 1, s, roots[e / 2]);
  }

  /// Sets the query to the point x of parameter l of s, perturbed first along the segment if
  /// `forward`, then to the side (if any), then along the directions.
  void set_query(const Exact_point& x, bool forward, const Translation_segment& s, const Segment_parameter& l)
  {
    const Cd_filter::Prefix prefix = {forward ? &m_forward : m_side, forward ? m_side : nullptr};
    const Known_zeros zeros{s.spans(l), l.zero_of ? &*l.zero_of : nullptr};
    if (m_in_plane) m_filter.set_point_on_plane(x, prefix, zeros);
    else m_filter.set_point(x, m_directions, m_count, prefix, zeros);
  }

  bool free_at(const Translation_segment& s, const std::vector<Segment_parameter>& roots, std::size_t e)
  {
    set_element(s, roots, e);
    return m_filter.is_free_here();
  }

  /// Does the pair cross on element e of its own roots `local`? Known from `range` when
  /// the element's parameters are certainly in or out of it, else tested.
  bool crosses_on(const Translation_segment& s, const std::vector<Segment_parameter>& local, std::size_t e,
                  const std::pair<Index, Index>& pair, const Crossing_range& range)
  {
    CGAL::Protect_FPU_rounding<true> guard;
    auto parameter = [&](const Segment_parameter& l) { return Interval(CGAL::to_interval(l.num)) / CGAL::to_interval(l.den); };
    const Interval first = parameter(local[e / 2]);
    const Interval last = e % 2 ? parameter(local[e / 2 + 1]) : first;
    if (last.sup() < range.low || first.inf() > range.high) return false;
    if (first.inf() > range.in_from && last.sup() < range.in_to) return true;
    return crosses_on(s, local, e, pair);
  }

  /// Does the pair cross on element e of its own roots `local`? (Tested.)
  bool crosses_on(const Translation_segment& s, const std::vector<Segment_parameter>& local, std::size_t e,
                  const std::pair<Index, Index>& pair)
  {
    set_element(s, local, e);
    return m_filter.pair_crosses_here(pair.first, pair.second);
  }

  Cd_filter& m_filter;
  std::size_t m_segments = 0;
  const Direction* m_directions = nullptr;
  std::uint32_t m_count = 0;
  Vec3<Exact_nt> m_forward;
  const Vec3<Exact_nt>* m_side = nullptr;
  bool m_in_plane = false; // start_plane() was called
  /// What covered_by_hops()'s first query found at the point 0 of the segment: no pair
  /// crosses there, and the point is free, or inside by containment (then so is the run of
  /// elements without crossings that starts there: containment changes only where surfaces
  /// cross).
  enum class Start : std::uint8_t { unknown, free, contained };
  Start m_start = Start::unknown;
  Vec3<Interval> m_a, m_b; // enclosures of the segment's ends
  std::vector<std::pair<Index, Index>> m_pairs;
  std::vector<Crossing_range> m_ranges;
  std::optional<std::pair<Index, Index>> m_last_quick; // the pair of the last quick exit
  std::array<std::optional<std::pair<Index, Index>>, 2> m_recent_covers; // the last patch pairs that held a triangle (patch_pair_covers())
  std::size_t m_next_recent = 0;
  std::unordered_set<std::uint64_t> m_patches_met; // (patch_pair_covers())
  std::optional<std::pair<Exact_point, Exact_point>> m_roots_of;                 // the segment of m_roots
  std::map<std::pair<Index, Index>, std::vector<Segment_parameter>> m_roots; // cached_roots()
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_SEGMENT_SEARCH_H
