// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3b of the pipeline, third part: points of the islands of a lattice cell.
//
// An island is a piece of the visible part of a convolution facet F (its points on the
// boundary of the sum) that lies strictly inside one cell T of F's lattice: no lattice
// segment meets it, so the trim search (trim_points.h) cannot find it (e.g. a piece of the
// boundary of a void of the sum smaller than a cell). Within the plane of F, a point is
// hidden iff some item pair of the CD filter crosses there (or a component is contained,
// which changes only where surfaces cross). A pair's answer is a function of the signs of its
// orientation predicates, each affine in the translation: it changes only on the zero lines
// of those predicates. So the boundary of an island lies on such lines, of pairs near T; the
// island lies on one side of each of its edges. Searching, for every such line that meets T,
// the free parts of its piece in T (segment_search.h) with every point perturbed first
// towards one side, then the other, finds the island's edges: their ends are exact boundary
// points of the sum, inside T (closer than diam(T) to every point of the island).
//
// Only cells that need it are searched: one with a corner inside the sum and no end of a
// free interval on its edges (else those ends are in T and closer than diam(T) to its
// islands), that is not certified inside the sum, and that no single item pair covers (one
// pair crossing at the three corners crosses on all of T: the translations where two
// triangles cross form a convex set; shown by exact tests of the corners' witnesses, or by
// intervals, Cd_filter::crossing_range()).

#ifndef CGAL_PMSUM_INTERNAL_ISLAND_SEARCH_H
#define CGAL_PMSUM_INTERNAL_ISLAND_SEARCH_H

#include <CGAL_pmsum/internal/segment_search.h>

#include <CGAL/Exact_rational.h>

#include <array>
#include <optional>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// A point of a cell by its exact barycentric weights over the cell's corners.
using Cell_weights = std::array<CGAL::Exact_rational, 3>;

/// The islands of lattice cells (see the file comment). One per thread, on that thread's CD
/// filter and segment search.
class Island_search
{
public:
  using Pair = std::pair<Index, Index>;

  Island_search(Cd_filter& filter, Segment_search& search) : m_filter(filter), m_search(search) {}

  /// Number of cells whose lines were searched.
  std::size_t searched_cells() const { return m_cells; }

  /// Appends to `out` the ends of the free parts of the lines in cell T (corners exact, not
  /// collinear) that can bound an island, unless one of the `witnesses` (pairs crossing at
  /// some corner) crosses at all three. Points are perturbed along the directions.
  void island_points(const std::array<Exact_point, 3>& T, const std::array<std::optional<Pair>, 3>& witnesses,
                     const Direction* directions, std::uint32_t count, std::vector<Cell_weights>& out)
  {
    m_directions = directions;
    m_count = count;
    for (const auto& w : witnesses)
      if (w && crosses_at_corners(*w, T)) return;
    std::array<Vec3<Interval>, 3> e;
    for (int k = 0; k < 3; ++k) e[k] = enclosure(T[k]);
    std::vector<Pair>& pairs = m_pairs;
    pairs.clear();
    bool covered = false; // by one pair, shown by intervals: it certainly crosses at the corners
    m_filter.for_each_overlapping_pair(hull(hull(e[0], e[1]), e[2]), [&](Index u, Index v) {
      if (!m_filter.may_cross_in(u, v, e)) return false; // then its lines bound nothing in T
      pairs.emplace_back(u, v);
      return covered = m_filter.crossing_range(u, v, e[0], e[1]).covers_segment() &&
                       m_filter.crossing_range(u, v, e[0], e[2]).covers_segment();
    });
    if (covered) return;
    ++m_cells;
    m_lines.clear();
    const std::size_t first = out.size();
    for (const Pair& pair : pairs) // (a lambda cannot capture structured bindings in C++17)
      m_filter.for_each_predicate(pair.first, pair.second,
                                  [&](const Moving_point& a, const Moving_point& b, const Moving_point& c,
                                      const Moving_point& d) { search_line(T, e, pair, a, b, c, d, out, first); });
  }

private:
  /// A point on the border of T: parameter l of edge k (from corner k to corner k + 1).
  struct Border_point
  {
    int edge;
    Segment_parameter l;
  };

  /// The part [from, to] of the line from a to b.
  struct Line_piece
  {
    Border_point a, b;
    Segment_parameter from, to;
  };

  bool crosses_at_corners(const Pair& pair, const std::array<Exact_point, 3>& T)
  {
    for (const Exact_point& x : T) {
      m_filter.set_point(x, m_directions, m_count);
      if (!m_filter.pair_crosses_here(pair.first, pair.second)) return false;
    }
    return true;
  }

  /// The zero line of the predicate (a, b, c, d) of `pair` in the plane of T, if it crosses T:
  /// the part of its piece in T where the pair may cross (or bound a crossing) is searched
  /// from both sides (only from a side holding a corner of T).
  void search_line(const std::array<Exact_point, 3>& T, const std::array<Vec3<Interval>, 3>& e, const Pair& pair,
                   const Moving_point& a,
                   const Moving_point& b, const Moving_point& c, const Moving_point& d, std::vector<Cell_weights>& out,
                   std::size_t first)
  {
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval d0 = value_at_origin<Interval>(a, b, c, d);
      const Vec3<Interval> g = gradient<Interval>(a, b, c, d);
      bool positive = true, negative = true;
      for (int k = 0; k < 3; ++k) {
        const Interval v = d0 + dot(g, e[k]);
        positive = positive && v.inf() > 0;
        negative = negative && v.sup() < 0;
      }
      if (positive || negative) return; // the line misses T
    }
    const Exact_nt d0 = value_at_origin<Exact_nt>(a, b, c, d);
    const Vec3<Exact_nt> g = gradient<Exact_nt>(a, b, c, d);
    std::array<Exact_nt, 3> D; // W_k times the predicate at corner k
    std::array<CGAL::Sign, 3> s;
    for (int k = 0; k < 3; ++k) {
      D[k] = T[k].W * d0 + dot(g, T[k].X);
      s[k] = CGAL::sign(D[k]);
    }
    if (s[0] == CGAL::ZERO && s[1] == CGAL::ZERO && s[2] == CGAL::ZERO) return; // constant on the plane
    std::vector<Border_point> ends;
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      if (s[k] == CGAL::ZERO) ends.push_back({k, Segment_parameter::zero()});
      else if (s[j] != CGAL::ZERO && s[j] != s[k]) {
        // D / W is affine along the edge: l = (D_k / W_k) / (D_k / W_k - D_j / W_j).
        Segment_parameter l{D[k] * T[j].W, D[k] * T[j].W - D[j] * T[k].W};
        if (CGAL::sign(l.den) == CGAL::NEGATIVE) { l.num = -l.num; l.den = -l.den; }
        ends.push_back({k, l});
      }
    }
    if (ends.size() != 2) return;
    // Only where the pair's crossing set, or its closure, can be: [low, high] (intervals).
    // Other pairs can share the line with other ranges: each clipped piece is searched once.
    const Exact_point p0 = point(T, ends[0]), p1 = point(T, ends[1]);
    const Crossing_range range = m_filter.crossing_range(pair.first, pair.second, enclosure(p0), enclosure(p1));
    if (range.misses_segment()) return;
    const Segment_parameter from = range.low > 0 ? Segment_parameter{Exact_nt(range.low), Exact_nt(1)} : Segment_parameter::zero();
    const Segment_parameter to = range.high < 1 ? Segment_parameter{Exact_nt(range.high), Exact_nt(1)} : Segment_parameter::one();
    if (is_searched({ends[0], ends[1], from, to})) return;
    m_lines.push_back({ends[0], ends[1], from, to});
    const Translation_segment line(Translation_segment(p0, p1).at(from), Translation_segment(p0, p1).at(to));
    if (hidden(line)) return;
    const Cell_weights w0 = along(weights(ends[0]), weights(ends[1]), from), w1 = along(weights(ends[0]), weights(ends[1]), to);
    for (CGAL::Sign side : {CGAL::POSITIVE, CGAL::NEGATIVE}) {
      int k = 0;
      while (k < 3 && s[k] != side) ++k;
      if (k == 3) continue; // no corner on that side: the side is another cell's
      // Towards corner k from p0, in homogeneous coordinates (a positive multiple).
      Vec3<Exact_nt> towards;
      for (int c = 0; c < 3; ++c) towards[c] = T[k].X[c] * line.a.W - line.a.X[c] * T[k].W;
      m_ends.clear();
      m_search.free_ends(line, m_directions, m_count, m_ends, {}, &towards);
      for (std::size_t i = 0; i < m_ends.size(); ++i) {
        if (i > 0 && compare(m_ends[i], m_ends[i - 1]) == CGAL::ZERO) continue;
        const Cell_weights w = along(w0, w1, m_ends[i]);
        bool known = false;
        for (std::size_t j = first; j < out.size() && !known; ++j) known = out[j] == w;
        if (!known) out.push_back(w);
      }
    }
  }

  /// Do intervals show that one of the cell's pairs crosses on all of s (any perturbation)?
  /// The last pair that did is tried first.
  bool hidden(const Translation_segment& s)
  {
    const Vec3<Interval> a = enclosure(s.a), b = enclosure(s.b);
    if (m_last_cover < m_pairs.size() &&
        m_filter.crossing_range(m_pairs[m_last_cover].first, m_pairs[m_last_cover].second, a, b).covers_segment())
      return true;
    for (std::size_t k = 0; k < m_pairs.size(); ++k)
      if (m_filter.crossing_range(m_pairs[k].first, m_pairs[k].second, a, b).covers_segment()) {
        m_last_cover = k;
        return true;
      }
    return false;
  }

  /// Was this piece (the same line, clipped to the same parameters) searched in this cell?
  bool is_searched(const Line_piece& piece) const
  {
    auto same = [](const Border_point& x, const Border_point& y) { return x.edge == y.edge && compare(x.l, y.l) == CGAL::ZERO; };
    for (const Line_piece& p : m_lines)
      if (same(p.a, piece.a) && same(p.b, piece.b) && compare(p.from, piece.from) == CGAL::ZERO &&
          compare(p.to, piece.to) == CGAL::ZERO)
        return true;
    return false;
  }

  static Exact_point point(const std::array<Exact_point, 3>& T, const Border_point& p)
  { return Translation_segment(T[p.edge], T[(p.edge + 1) % 3]).at(p.l); }

  static Cell_weights weights(const Border_point& p)
  {
    const CGAL::Exact_rational l = p.l.value();
    Cell_weights w = {0, 0, 0};
    w[p.edge] = 1 - l;
    w[(p.edge + 1) % 3] = l;
    return w;
  }

  static Cell_weights along(const Cell_weights& a, const Cell_weights& b, const Segment_parameter& l)
  {
    const CGAL::Exact_rational t = l.value();
    Cell_weights w;
    for (int k = 0; k < 3; ++k) w[k] = (1 - t) * a[k] + t * b[k];
    return w;
  }

  Cd_filter& m_filter;
  Segment_search& m_search;
  const Direction* m_directions = nullptr;
  std::uint32_t m_count = 0;
  std::size_t m_cells = 0;
  std::vector<Pair> m_pairs; // of the current cell, that may cross in it
  std::size_t m_last_cover = 0;
  std::vector<Line_piece> m_lines; // searched in the current cell
  std::vector<Segment_parameter> m_ends;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_ISLAND_SEARCH_H
