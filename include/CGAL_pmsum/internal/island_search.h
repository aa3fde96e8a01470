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
// points of the sum, inside T. One such point is enough: it is closer than diam(T) to every
// point of every island of T, so the search of a cell stops at the first.
//
// Only cells that need it are searched: one with a corner inside the sum and no end of a
// free interval on its edges (else those ends are in T and closer than diam(T) to its
// islands), that is not certified inside the sum, nor inside one patch pair's crossing set
// (below; the trim search leaves those out: trim_points.h), that the output points do not cover whole
// (searched after the level's other points are chosen: decision.h, decide_islands; on the
// rotated narrow tunnel at d = 4%, 152 cells left of 841), and that no single item pair covers
// with a margin (intervals show T inside the pair's open crossing set, a convex set:
// Cd_filter::crossing_slabs(), the pairs that covered the last cells first). Only skips that
// hold around T too are used: a free end found on a line at T's border may be free just
// outside T (the side of the line is perturbed towards, not into, T), so an exact test that
// a pair crosses on all of T would skip cells whose search finds such a point, and the
// output would depend on which cells had such a test (the octree filter's certified corners
// have none). (One exact test is made, on every cell this search gets alike, so that the
// output does not depend on it: a cell in one patch pair's crossing set once perturbed,
// below; the 88 meshes of the suite at 4 d were all made with it.) Such a point can be found on a line that bounds no island of T at all: a
// pair that never crosses (two triangles in parallel planes, Cd_filter::parallel_triangles())
// still has lines, and they are searched like the others'. Skipping them changes no
// covering (the points they alone find lie just outside their cells, where the neighbouring
// cells answer for the boundary), but the mesh uses those points: on the grates, 27 of
// 419k cells then found none, and the mesh at d failed its checks.
//
// Most such cells are covered by several pairs together and have no island. So T is first
// halved (max_depth times, into 4 triangles each time), and a sub-cell S is dropped when one
// pair certainly crosses on all of S, or when no pair's crossing set has its border in S
// (intervals: the set certainly misses S or certainly holds it). Dropping loses nothing: a
// point y on the edge of an island is a limit of free points and of hidden ones; near y
// some pair's answer must change (if every pair's answer were constant near y, one crossing
// would hide all of it, and without crossings the containment answer would be constant), so
// the border of that pair's crossing set passes through y, and no pair holds y inside. The
// lines searched are then those of the pairs whose borders may cross the sub-cells left (in
// a sub-cell where the pair was kept), each once per cell, over all of T: far fewer than
// T's, and most cells need none. (Bare edges have no slabs: a sub-cell left with only those
// is not halved further.)
//
// The pairs of the halving are pairs of convex planar patches (convex_patches.h: a box's
// square face is one patch, not two triangles). A patch pair's crossing set holds its
// triangle pairs' and the seams between them, where no triangle pair alone covers a
// sub-cell. Every point in it is a collision, so no island's edge lies inside it, and the
// argument above holds for patch pairs as for triangle pairs. The lines searched stay those
// of the triangle pairs whose own crossing sets' borders may cross T, in the leaves where
// their patch pair was kept. (blocks + cube, d = 2%: the halving's cost is gone, the island
// search about 30% cheaper, the same points. The rotated narrow tunnel's cells keep their
// lines: they lie along true borders, where two pairs' sets meet; no change there.)
//
// The cells lie in the plane H of their facet, whose points are all perturbed to the same
// side of H. A pair whose crossing set has H as a supporting plane (coplanar faces) would
// never be decided by intervals: the slab normal to H has H on its border. But on H the
// perturbation decides that slab alike everywhere (Cd_filter::on_plane(), exact, once per
// pair and facet): the pair crosses nowhere on H, or its crossing set on H is bounded by its
// other slabs only. Likewise a predicate zero on all of H has no line to search.
//
// Where two parts of the sum touch face to face, a cell may lie on the border of a patch
// pair's crossing set (undecided by intervals and by what H tells) and be in it at each
// corner once perturbed: then, the set being convex, in it on all of the cell perturbed
// alike (holds_once_perturbed(), exact), with no free point of its own. Its lines could
// still give points just outside it (perturbed away from it), which its neighbours answer
// for: it is not searched. (hooks: the 145 cells searched were all such, and gave 7 of the
// 3,248 points, the same covering without them; blocks + cube: 1,144 of 3,088.)

#ifndef CGAL_PMSUM_INTERNAL_ISLAND_SEARCH_H
#define CGAL_PMSUM_INTERNAL_ISLAND_SEARCH_H

#include <CGAL_pmsum/internal/segment_search.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <optional>
#include <unordered_map>
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

  /// Number of halvings of a cell before the lines that may cross its remaining sub-cells
  /// are searched.
  static constexpr int max_depth = 4;

  Island_search(Cd_filter& filter, Segment_search& search) : m_filter(filter), m_search(search) {}

  /// Number of cells whose lines were searched.
  std::size_t searched_cells() const { return m_cells; }

  /// Starts the cells of a facet of translations, whose points are perturbed along the
  /// directions. @pre The segment search's plane is the facet's, with the same directions
  /// (Segment_search::start_plane()).
  void start_facet(const Direction* directions, std::uint32_t count)
  {
    m_directions = directions;
    m_count = count;
    m_on_plane.clear();
  }

  /// A point (weights over T's corners) of an island of cell T (corners exact, not
  /// collinear), exactly on the boundary of the sum, if T has islands: the first end of a
  /// free part found on the lines that can bound one. It is closer than diam(T) to every
  /// point of every island of T, which is all that coverage needs. T lies in the facet of
  /// start_facet(). `spans`: what is known of T's corners (Known_zeros).
  /// None if T lies in one patch pair's crossing set once perturbed, on its border (where
  /// two parts of the sum touch face to face: holds_once_perturbed()).
  std::optional<Cell_weights> island_point(const std::array<Exact_point, 3>& T, const std::array<Spans, 3>& spans)
  {
    Sub_cell whole{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, 0, {}};
    for (int k = 0; k < 3; ++k) whole.e[k] = m_e[k] = enclosure(T[k]);
    m_pairs.clear();
    m_cell_patches.clear();
    m_met.clear();
    m_touching.clear();
    // Neighbouring cells are often covered by the same patch pair: the last ones that did first.
    for (const auto& pair : m_recent_covers)
      if (pair && crossing_slabs(*pair, whole.e).second == Where::inside) return {};
    bool covered = false;
    m_filter.for_each_overlapping_pair(hull(hull(whole.e[0], whole.e[1]), whole.e[2]), [&](Index u, Index v) {
      {
        CGAL::Protect_FPU_rounding<true> guard;
        if (!m_filter.may_meet_plane(u, v)) return false;
      }
      const Pair patches(m_filter.moving_patch(u), m_filter.static_patch(v));
      auto [it, first] = m_cell_patches.emplace(pair_key(patches.first, patches.second), no_index);
      if (first) {
        auto [slabs, w] = crossing_slabs(patches, whole.e);
        if (w == Where::inside) {
          m_recent_covers[m_next_recent++ % m_recent_covers.size()] = patches;
          return covered = true;
        }
        if (w == Where::border) {
          {
            CGAL::Protect_FPU_rounding<true> guard;
            if (slabs.known && !slabs.leaves(whole.e)) m_touching.push_back(patches); // T may be in its closure
          }
          it->second = Index(m_pairs.size());
          m_pairs.push_back({std::move(slabs), {}});
        }
      }
      if (it->second != no_index) m_met.push_back({{u, v}, it->second});
      return false;
    });
    if (covered || m_pairs.empty()) return {};
    if (std::any_of(m_touching.begin(), m_touching.end(),
                    [&](const Pair& patches) { return holds_once_perturbed(patches, T, spans); }))
      return {};
    // The item pairs' lines are searched only where their own crossing sets' borders may
    // cross T (asked only now: most cells are covered, and the plane's answer costs).
    for (const auto& [pair, k] : m_met) {
      Plane_pair& plane = on_plane(pair);
      if (!m_pairs[k].slabs.known || pair_where(pair, plane, whole.e) == Where::border)
        m_pairs[k].members.push_back({pair, &plane});
    }
    std::vector<std::uint32_t> border(m_pairs.size()); // of m_pairs: those whose crossing sets' borders may cross T
    std::iota(border.begin(), border.end(), 0);
    m_T = T; // over a common denominator: the sub-cells' corners are integer combinations
    if (!(T[0].W == T[1].W && T[1].W == T[2].W))
      for (int k = 0; k < 3; ++k) {
        for (int j = 0; j < 3; ++j)
          if (j != k)
            for (int c = 0; c < 3; ++c) m_T[k].X[c] *= T[j].W;
        m_T[k].W = T[0].W * T[1].W * T[2].W;
      }
    m_found.reset();
    m_leaves.clear();
    search(whole, border, corner_values(border));
    if (m_leaves.empty()) return {};
    ++m_cells;
    search_lines(whole);
    return m_found;
  }

private:
  /// A triangle inside T: its corners' integer weights over T's corners, divided by 2^depth,
  /// and their enclosures.
  struct Sub_cell
  {
    std::array<std::array<std::int64_t, 3>, 3> corner;
    int depth;
    std::array<Vec3<Interval>, 3> e;
  };

  using Where = Crossing_slabs::Where;

  /// Does the patch pair cross at each corner of T, perturbed along the facet's directions
  /// (Cd_filter::patch_pair_crosses_at(), exact)? Where two convex patches cross is convex:
  /// then they cross on all of T, perturbed alike, and T has no island. Not around T: on the
  /// border of the pair's crossing set, points just outside T may be free.
  bool holds_once_perturbed(const Pair& patches, const std::array<Exact_point, 3>& T, const std::array<Spans, 3>& spans)
  {
    return m_filter.patch_pair_crosses_at(patches.first, patches.second,
                                          {{&T[0], {spans[0]}}, {&T[1], {spans[1]}}, {&T[2], {spans[2]}}}, m_directions,
                                          m_count);
  }

  /// What is known of a pair on the current facet's plane: where it may cross
  /// (Cd_filter::on_plane()), and which of its predicates (bit i: the i-th of
  /// Cd_filter::for_each_predicate()) are known to be zero on all of the plane (`flat`): a
  /// flat one has the same perturbed sign everywhere there, no line to search.
  struct Plane_pair
  {
    Cd_filter::Plane_crossing crossing;
    std::uint32_t flat = 0;
  };

  /// The pair's Plane_pair, computed on first use in the facet.
  Plane_pair& on_plane(const Pair& pair)
  {
    const std::uint64_t key = pair_key(pair.first, pair.second);
    auto it = m_on_plane.find(key);
    if (it == m_on_plane.end()) it = m_on_plane.emplace(key, Plane_pair{m_filter.on_plane(pair.first, pair.second)}).first;
    return it->second;
  }

  /// The slabs of the crossing set of a pair of patches (Cd_filter::moving_patch(),
  /// static_patch()) on the facet's plane, and where the triangle e of translations (boxes)
  /// lies (Cd_filter::patch_crossing_slabs_on_plane()).
  std::pair<Crossing_slabs, Where> crossing_slabs(const Pair& patches, const std::array<Vec3<Interval>, 3>& e)
  { return m_filter.patch_crossing_slabs_on_plane(patches.first, patches.second, e); }

  /// Where the triangle e lies with respect to the crossing set of the item pair (two
  /// triangles), with what `plane` knows of it.
  Where pair_where(const Pair& pair, const Plane_pair& plane, const std::array<Vec3<Interval>, 3>& e)
  {
    Crossing_slabs slabs;
    slabs.known = true;
    Where w;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      for (const Crossing_slabs::Slab& s : m_filter.slabs(pair.first, pair.second)) slabs.slabs.push_back(s);
      w = slabs.where(e);
    }
    return w == Where::border ? Cd_filter::with_plane(std::move(slabs), plane.crossing, e).second : w;
  }

  /// An item pair met in the current cell, with what is known of it on the facet's plane.
  struct Member
  {
    Pair pair;
    Plane_pair* plane;
  };
  /// A pair of patches that may cross in the current cell: its crossing set's slabs and its
  /// item pairs met there.
  struct Cell_pair
  {
    Crossing_slabs slabs;
    std::vector<Member> members;
  };

  /// w.x at the corners x of a sub-cell (enclosures), for one slab w of a pair.
  using Corner_values = std::array<Interval, 3>;

  /// The values at the current cell's corners of the slabs of `pairs`, pair after pair.
  std::vector<Corner_values> corner_values(const std::vector<std::uint32_t>& pairs) const
  {
    std::vector<Corner_values> r;
    CGAL::Protect_FPU_rounding<true> guard;
    for (std::uint32_t i : pairs)
      for (const Crossing_slabs::Slab& slab : m_pairs[i].slabs.slabs)
        r.push_back({dot(slab.w, m_e[0]), dot(slab.w, m_e[1]), dot(slab.w, m_e[2])});
    return r;
  }

  /// S with the enclosures of its corners.
  Sub_cell with_enclosures(Sub_cell S) const
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const Interval scale = Interval(1) / Interval(double(std::int64_t(1) << S.depth));
    for (int k = 0; k < 3; ++k)
      for (int x = 0; x < 3; ++x) {
        Interval v(0);
        for (int j = 0; j < 3; ++j) v += Interval(double(S.corner[k][j])) * m_e[j][x];
        S.e[k][x] = v * scale;
      }
    return S;
  }

  /// Puts into m_leaves the sub-cells of S (whose `pairs` may have their crossing sets'
  /// borders in S) where an island's edge can be: S is halved while shallower than
  /// max_depth, dropping the sub-cells that one pair covers or that no border meets (no
  /// island's edge lies there: see the file comment). `values`: the pairs' slabs at S's
  /// corners (corner_values()); w.x is affine in x, so at the middle of a side it is the
  /// mean of its ends' (intervals: additions, no product).
  void search(const Sub_cell& S, const std::vector<std::uint32_t>& pairs, const std::vector<Corner_values>& values)
  {
    // Halving helps only the pairs whose crossing sets' slabs are known (not bare edges).
    const bool known = std::any_of(pairs.begin(), pairs.end(), [&](std::uint32_t i) { return m_pairs[i].slabs.known; });
    if (S.depth == max_depth || !known) { m_leaves.push_back({with_enclosures(S), pairs}); return; }
    const auto& c = S.corner;
    auto mid = [&](int i, int j) {
      return std::array<std::int64_t, 3>{c[i][0] + c[j][0], c[i][1] + c[j][1], c[i][2] + c[j][2]};
    };
    auto twice = [&](int i) { return std::array<std::int64_t, 3>{2 * c[i][0], 2 * c[i][1], 2 * c[i][2]}; };
    const auto m01 = mid(0, 1), m12 = mid(1, 2), m20 = mid(2, 0);
    const std::array<std::array<std::array<std::int64_t, 3>, 3>, 4> children = {
      {{twice(0), m01, m20}, {m01, twice(1), m12}, {m20, m12, twice(2)}, {m01, m12, m20}}};
    // The children's corners among S's corners (0, 1, 2) and the middles of its sides 01, 12, 20 (3, 4, 5).
    static constexpr std::array<std::array<int, 3>, 4> picks = {{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}};
    std::vector<std::array<Interval, 6>> at; // the slabs' values at those six points
    at.reserve(values.size());
    {
      CGAL::Protect_FPU_rounding<true> guard;
      for (const Corner_values& v : values)
        at.push_back({v[0], v[1], v[2], (v[0] + v[1]) * 0.5, (v[1] + v[2]) * 0.5, (v[2] + v[0]) * 0.5});
    }
    std::vector<std::uint32_t> kept;
    std::vector<Corner_values> kept_values;
    for (int n = 0; n < 4; ++n) {
      kept.clear();
      kept_values.clear();
      bool covered = false;
      std::size_t first = 0; // the pair's first slab in `at`
      for (std::uint32_t i : pairs) {
        const Crossing_slabs& slabs = m_pairs[i].slabs;
        const Where w = where(slabs, at.data() + first, picks[n]);
        if (w == Where::inside) { covered = true; break; }
        if (w == Where::border) {
          kept.push_back(i);
          for (std::size_t s = first; s < first + slabs.slabs.size(); ++s)
            kept_values.push_back({at[s][picks[n][0]], at[s][picks[n][1]], at[s][picks[n][2]]});
        }
        first += slabs.slabs.size();
      }
      if (!covered && !kept.empty()) search(Sub_cell{children[n], S.depth + 1, {}}, kept, kept_values);
    }
  }

  /// Crossing_slabs::where() on the triangle whose corners are the points `corners` of
  /// `at` (the slabs' values there, slab after slab).
  static Where where(const Crossing_slabs& slabs, const std::array<Interval, 6>* at, const std::array<int, 3>& corners)
  {
    return slabs.where_by([&](std::size_t s) {
      double tl = HUGE_VAL, th = -HUGE_VAL;
      for (int k : corners) {
        tl = (std::min)(tl, at[s][k].inf());
        th = (std::max)(th, at[s][k].sup());
      }
      return std::make_pair(tl, th);
    });
  }

  /// A point on the border of the cell: parameter l of edge k (from corner k to k + 1).
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

  /// Searches, in the cell T, the lines of the predicates of each pair that may cross a
  /// leaf (m_leaves) where that pair was kept (search_line()): each line once per cell.
  void search_lines(const Sub_cell& T)
  {
    std::vector<std::vector<std::uint32_t>> leaves(m_pairs.size()); // where each pair was kept
    std::vector<std::uint32_t> pairs;                                // kept in some leaf
    for (std::uint32_t k = 0; k < m_leaves.size(); ++k)
      for (std::uint32_t i : m_leaves[k].pairs) {
        if (leaves[i].empty()) pairs.push_back(i);
        leaves[i].push_back(k);
      }
    std::array<Exact_point, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = exact_point(T.corner[k], T.depth);
    m_lines.clear();
    for (std::uint32_t i : pairs)
      for (const Member& member : m_pairs[i].members) {
        const Pair& pair = member.pair;
        Plane_pair& plane = *member.plane;
        m_pair_lines.clear();
        std::uint32_t bit = 1;
        m_filter.for_each_predicate(pair.first, pair.second,
                                    [&](const Moving_point& a, const Moving_point& b, const Moving_point& c, const Moving_point& d) {
                                      if (!m_found && !(plane.flat & bit) && meets_leaf(leaves[i], a, b, c, d) &&
                                          !search_line(corners, pair, pairs, a, b, c, d))
                                        plane.flat |= bit;
                                      bit <<= 1;
                                    });
        if (m_found) return;
      }
  }

  /// May the zero line of the predicate (a, b, c, d) cross one of the `leaves` (intervals)?
  bool meets_leaf(const std::vector<std::uint32_t>& leaves, const Moving_point& a, const Moving_point& b,
                  const Moving_point& c, const Moving_point& d) const
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const auto [d0, g] = m_filter.affine_enclosure(a, b, c, d);
    for (std::uint32_t k : leaves) {
      bool positive = true, negative = true;
      for (const Vec3<Interval>& x : m_leaves[k].cell.e) {
        const Interval v = d0 + dot(g, x);
        positive = positive && v.inf() > 0;
        negative = negative && v.sup() < 0;
      }
      if (!positive && !negative) return true;
    }
    return false;
  }

  /// The zero line of the predicate (a, b, c, d) of `pair` in the plane of the cell
  /// (corners: its corners, exact), if it crosses the cell: the part of its piece there
  /// where the pair may cross (or bound a crossing) is searched from both sides (only from
  /// a side holding a corner of the cell), unless one of `pairs` certainly crosses on all
  /// of it. Sets m_found to the first end of a free part. False iff the predicate is zero
  /// on all of the plane.
  bool search_line(const std::array<Exact_point, 3>& corners, const Pair& pair, const std::vector<std::uint32_t>& pairs,
                   const Moving_point& a, const Moving_point& b, const Moving_point& c, const Moving_point& d)
  {
    const Affine_predicate f = m_filter.affine_form(a, b, c, d);
    std::array<Exact_nt, 3> D; // W times the predicate at corner k (a common W)
    std::array<CGAL::Sign, 3> s;
    for (int k = 0; k < 3; ++k) {
      D[k] = corners[k].W * f.d0 + dot(f.g, corners[k].X);
      s[k] = CGAL::sign(D[k]);
    }
    if (s[0] == CGAL::ZERO && s[1] == CGAL::ZERO && s[2] == CGAL::ZERO) return false; // constant on the plane
    std::vector<Border_point> ends;
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      if (s[k] == CGAL::ZERO) ends.push_back({k, Segment_parameter::zero()});
      else if (s[j] != CGAL::ZERO && s[j] != s[k]) {
        Segment_parameter l{D[k], D[k] - D[j]}; // D is affine along the edge
        if (CGAL::sign(l.den) == CGAL::NEGATIVE) { l.num = -l.num; l.den = -l.den; }
        ends.push_back({k, l});
      }
    }
    if (ends.size() != 2) return true;
    // Several predicates of a pair often share a line (so do other pairs': m_lines): its
    // piece is the same, searched already.
    for (const auto& line : m_pair_lines)
      if (same(line[0], ends[0]) && same(line[1], ends[1])) return true;
    m_pair_lines.push_back({ends[0], ends[1]});
    // Only where the pair's crossing set, or its closure, can be: [low, high] (intervals).
    // Other pairs can share the line with other ranges: each clipped piece is searched once.
    const Exact_point p0 = point(corners, ends[0]), p1 = point(corners, ends[1]);
    const Crossing_range range = m_filter.crossing_range(pair.first, pair.second, enclosure(p0), enclosure(p1));
    if (range.misses_segment()) return true;
    const Segment_parameter from = range.low > 0 ? Segment_parameter{Exact_nt(range.low), Exact_nt(1)} : Segment_parameter::zero();
    const Segment_parameter to = range.high < 1 ? Segment_parameter{Exact_nt(range.high), Exact_nt(1)} : Segment_parameter::one();
    if (is_searched({ends[0], ends[1], from, to})) return true;
    m_lines.push_back({ends[0], ends[1], from, to});
    const Translation_segment line(Translation_segment(p0, p1).at(from), Translation_segment(p0, p1).at(to));
    if (hidden(line, pairs)) return true;
    const Cell_weights w0 = along(weights(ends[0]), weights(ends[1]), from), w1 = along(weights(ends[0]), weights(ends[1]), to);
    for (CGAL::Sign side : {CGAL::POSITIVE, CGAL::NEGATIVE}) {
      int k = 0;
      while (k < 3 && s[k] != side) ++k;
      if (k == 3) continue; // no corner on that side: the side is another cell's
      // Towards corner k from the line's first end, in homogeneous coordinates (a positive multiple).
      Vec3<Exact_nt> towards;
      for (int x = 0; x < 3; ++x) towards[x] = corners[k].X[x] * line.a.W - line.a.X[x] * corners[k].W;
      m_ends.clear();
      m_search.free_ends(line, m_directions, m_count, m_ends, {}, &towards);
      if (!m_ends.empty()) {
        m_found = along(w0, w1, m_ends.front());
        return true;
      }
    }
    return true;
  }

  /// Do intervals show that one of `pairs` crosses on all of s (any perturbation)? The last
  /// pair that did is tried first.
  bool hidden(const Translation_segment& s, const std::vector<std::uint32_t>& pairs)
  {
    const Vec3<Interval> a = enclosure(s.a), b = enclosure(s.b);
    auto covers = [&](const Pair& pair) { return m_filter.crossing_range(pair.first, pair.second, a, b).covers_segment(); };
    if (m_last_cover && covers(*m_last_cover)) return true;
    for (std::uint32_t i : pairs)
      for (const Member& member : m_pairs[i].members)
        if (member.pair != m_last_cover && covers(member.pair)) {
          m_last_cover = member.pair;
          return true;
        }
    return false;
  }

  static bool same(const Border_point& x, const Border_point& y)
  { return x.edge == y.edge && compare(x.l, y.l) == CGAL::ZERO; }

  /// Was this piece (the same line, clipped to the same parameters) searched in this cell?
  bool is_searched(const Line_piece& piece) const
  {
    for (const Line_piece& p : m_lines)
      if (same(p.a, piece.a) && same(p.b, piece.b) && compare(p.from, piece.from) == CGAL::ZERO &&
          compare(p.to, piece.to) == CGAL::ZERO)
        return true;
    return false;
  }

  /// The point of T with weights w / 2^depth over T's corners, exactly.
  Exact_point exact_point(const std::array<std::int64_t, 3>& w, int depth) const
  {
    Exact_point x{{Exact_nt(0), Exact_nt(0), Exact_nt(0)}, m_T[0].W * Exact_nt(double(std::int64_t(1) << depth))};
    for (int j = 0; j < 3; ++j)
      if (w[j] != 0)
        for (int c = 0; c < 3; ++c) x.X[c] += Exact_nt(double(w[j])) * m_T[j].X[c];
    return x;
  }

  static Exact_point point(const std::array<Exact_point, 3>& corners, const Border_point& p)
  { return Translation_segment(corners[p.edge], corners[(p.edge + 1) % 3]).at(p.l); }

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
  std::optional<Cell_weights> m_found;     // its island point
  std::array<Exact_point, 3> m_T;          // the current cell's corners, over a common denominator
  std::array<Vec3<Interval>, 3> m_e;       // and their enclosures
  std::vector<Cell_pair> m_pairs;          // whose crossing sets' borders may cross the current cell
  std::unordered_map<std::uint64_t, Plane_pair> m_on_plane; // of the pairs met in the current facet
  std::vector<std::pair<Pair, Index>> m_met; // the item pairs met in the current cell, with their patch pair's index in m_pairs
  std::unordered_map<std::uint64_t, Index> m_cell_patches; // patch pairs met in the current cell: their index in m_pairs, or no_index
  std::vector<Pair> m_touching;            // those on whose border the current cell may lie (holds_once_perturbed())
  std::array<std::optional<Pair>, 4> m_recent_covers; // the last patch pairs that covered a cell
  std::size_t m_next_recent = 0;
  std::optional<Pair> m_last_cover;        // the last pair that hid a line
  struct Leaf
  {
    Sub_cell cell;
    std::vector<std::uint32_t> pairs; // of m_pairs: whose crossing sets' borders may cross it
  };
  std::vector<Leaf> m_leaves;              // of the current cell, where an island's edge can be
  std::vector<Line_piece> m_lines;         // searched in the current cell
  std::vector<std::array<Border_point, 2>> m_pair_lines; // the current pair's lines met in the cell
  std::vector<Segment_parameter> m_ends;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_ISLAND_SEARCH_H
