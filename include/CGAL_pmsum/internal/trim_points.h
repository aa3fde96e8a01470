// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3b of the pipeline, second half: points on the trim curves of the convolution facets.
//
// A 2-dimensional feature pair (a vertex and a triangle, or two edges) spans a convolution
// facet F, a subset of P + Q. Its closed lattice (the sums of the samples of the two
// features, their edges and vertices) cuts F into cells: the lattice's small triangles, or
// the parallelograms of two edge lattices cut along their shorter diagonal. Every point of a
// cell T is closer than f(T) <= d/2 to a corner of T (sampling.h), and diam(T) <= D_F <= d.
//
// Why the lattice alone does not cover: a boundary point y of the sum on F whose nearest
// corner c is inside the sum (a visible strip of F narrower than the spacing, a passage).
// Then the visible piece K of F that contains y, within T, either meets the boundary of T,
// or is an island inside T. If it meets it, the loop around T goes from a free point to
// the inside corner c, so some edge of T holds an end of a free interval (segment_search.h):
// a "trim point", exactly on the boundary of the sum, in T, closer than D_F to y (y is not
// a corner). Every trim point is output unless an output point is closer than d - D_F to
// it, so y has an output point closer than d. Hence: the edges of every cell with a corner
// known to be inside (tested, certified or reused) are searched, but for a cell inside the
// sum whole (no free point there): inside the crossing set of one pair of convex patches of
// the two surfaces, perturbed as the facet's points are (Segment_search::patch_pair_covers(),
// on the facet's plane: a facet on the seam of two boxes that touch along a face lies on the
// border of their crossing sets, inside one once perturbed; the pairs of its corners' witnesses,
// and for a cell with every corner inside, all pairs met, unless such scans keep failing
// there: Facet_trim_search::scan_now()), or shown so by the interior
// certificate. (At coarse d most cells with a corner inside are such: frame + knot at 5%,
// one thread, 5.9 -> 1.8 s, the segments searched 88k -> 1.5k, the same points. Such a skip
// changes no cell's answer, but the island waves are split by the cells left, pipeline.h, so
// the net a later island cell is checked against, and which island points are kept, may
// differ: a covering either way, the same on any number of threads or ranks.) A cell whose corners are
// all free or covered needs nothing: its points are within f(T) <= d/2 of a corner, and
// that corner within d/2 of an output point. Nor does a cell whose three corners are closer
// than d to one output point already chosen (of an earlier wave: decision.h): a ball is
// convex, so that point covers the whole cell, whatever is visible in it; its corners are not
// even tested. Likewise a cell cut into parts (Covering_net::covers_all_parts()), each part's
// corners closer than d to one output point. (Islands, pieces of F strictly inside one cell,
// are bounded by trim curves only; they are not found this way but by the island search,
// island_search.h, in the selected cells whose edges have no trim point: find_island_points(),
// after the level's waves, in the cells that the whole net does not cover then.)
//
// Not needed for the covering, but for a mesh: where a strip of F narrower than d/2 meets
// the border of F (a narrow tunnel's wall meeting the top face), the corner is a trim point
// kept whatever is near (no other point stands for it); see Facet_trim_search::search_border_corners().
// (Found in the searched cells only: where the covering skips a covered cell, a mesh may
// need them, and asks for every cell with a corner inside, Strips::inside_corners or followed.)

#ifndef CGAL_PMSUM_INTERNAL_TRIM_POINTS_H
#define CGAL_PMSUM_INTERNAL_TRIM_POINTS_H

#include <CGAL_pmsum/internal/candidates.h>
#include <CGAL_pmsum/internal/island_search.h>
#include <CGAL_pmsum/internal/segment_search.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <initializer_list>
#include <map>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// The point x0 + lambda (x1 - x0) + mu (x2 - x0) of a lattice cell with corners
/// x0 = p0 + q0, x1 = p + q and x2 = p2 + q2 (same vertex triples on each side): on the
/// lattice segment from x0 to x1 when mu = 0 (a trim point), else inside the cell (an island
/// point). origin_p, origin_q: the features holding its two parts.
struct Trim
{
  Sample p, q;
  CGAL::Exact_rational lambda;
  Sample p2, q2; // with mu = 0: unused
  CGAL::Exact_rational mu;
  Feature origin_p, origin_q;

  /// The samples of corners x1 and x2 on side `side` (0: P, 1: Q).
  const Sample& towards(int side) const { return side == 0 ? p : q; }
  const Sample& towards2(int side) const { return side == 0 ? p2 : q2; }
};

/// Exact barycentric weights over a0's vertices of side `side`'s part of the point of `t`
/// (a0: that side's sample of corner x0).
inline std::array<CGAL::Exact_rational, 3> trim_weights(const Sample& a0, const Trim& t, int side)
{
  using Q = CGAL::Exact_rational;
  auto weight = [](const Sample& s, int i) -> Q { return Q(s.weights[i]) / Q(s.denominator); }; // not an expression template of temporaries
  const bool in_cell = CGAL::sign(t.mu) != CGAL::ZERO;
  std::array<Q, 3> w;
  for (int i = 0; i < 3; ++i) {
    w[i] = (1 - t.lambda - t.mu) * weight(a0, i) + t.lambda * weight(t.towards(side), i);
    if (in_cell) w[i] += t.mu * weight(t.towards2(side), i);
  }
  return w;
}

/// Converts a rational to FT: exactly if FT is constructible from it, else rounded.
template <class FT>
FT rational_to(const CGAL::Exact_rational& r)
{
  if constexpr (std::is_constructible<FT, CGAL::Exact_rational>::value) return FT(r);
  else return FT(CGAL::to_double(r));
}

/// Coordinate c of an output point p + q, or of the trim point (p, q, trim), in FT (exact
/// with an exact kernel). The one place where output points become coordinates.
template <class FT>
FT sum_coordinate(const Mesh_data& P, const Mesh_data& Q, const Sample& p, const Sample& q, const Trim* trim, int c)
{
  const FT at_lattice = sample_coordinate<FT>(P, p, c) + sample_coordinate<FT>(Q, q, c);
  if (!trim) return at_lattice;
  const FT lambda = rational_to<FT>(trim->lambda);
  FT x = at_lattice + lambda * (sample_coordinate<FT>(P, trim->p, c) + sample_coordinate<FT>(Q, trim->q, c) - at_lattice);
  if (CGAL::sign(trim->mu) == CGAL::ZERO) return x;
  const FT mu = rational_to<FT>(trim->mu);
  return x + mu * (sample_coordinate<FT>(P, trim->p2, c) + sample_coordinate<FT>(Q, trim->q2, c) - at_lattice);
}

/// A box holding the point p + q (intervals: cheaper than the exact point).
inline Vec3<Interval> lattice_point_box(const Mesh_data& P, const Mesh_data& Q, const Sample& p, const Sample& q)
{
  CGAL::Protect_FPU_rounding<true> guard;
  Vec3<Interval> e;
  for (int c = 0; c < 3; ++c) e[c] = sum_coordinate<Interval>(P, Q, p, q, nullptr, c);
  return e;
}

/// A trim point found by a pair's search, with the radius within which an output point
/// covers it (0: only a point within the net's rounding margin, covering_net.h).
struct Trim_point
{
  Sample p, q; // the segment's first end
  Trim trim;
  Point3 x;
  double radius;
  std::uint32_t direction; // index in Candidate_pairs::directions
  Point3 hidden{0, 0, 0};  // unit, along the segment towards its part hidden there (islands: 0)
};

/// The closed lattice of the convolution facet of a 2-dimensional feature pair, or the part
/// of it that a piece of the pair searches (cell rows r of its Pair_rows, candidates.h): the
/// cells of those rows and their corners, lattice rows r.first to r.last.
class Facet_lattice
{
public:
  Facet_lattice(const Mesh_sampling& sp, const Mesh_sampling& sq, const Feature_pair& fp, Row_range rows)
    : m_fp(fp), m_rows(rows)
  {
    const int dp = fp.p.dimension, dq = fp.q.dimension;
    if (dp + dq != 2) return;
    if (dp == 1) edge_lattice(sp, sq);
    else if (dp == 0) triangle_lattice(sq, fp.p.index, false);
    else triangle_lattice(sp, fp.q.index, true);
    m_diameter *= 1 + 1e-9; // rounding of the double lengths
  }

  bool empty() const { return m_cells.empty(); }
  std::size_t size() const { return m_p.size(); }
  const Sample& p(std::size_t i) const { return m_p[i]; }
  const Sample& q(std::size_t i) const { return m_q[i]; }
  /// Is lattice point i one of the piece's own candidates (interior to both features, not a
  /// point of the facet's border, and not in the last row, which the next piece decides)?
  bool is_own_candidate(std::size_t i) const
  { return i < m_last_row_start && interior(m_fp.p, m_p[i]) && interior(m_fp.q, m_q[i]); }
  const std::vector<std::array<std::uint32_t, 3>>& cells() const { return m_cells; }
  /// Do lattice points i and j lie on one side of the facet (one border edge of its
  /// parallelogram or triangle)?
  bool on_border(std::size_t i, std::size_t j) const
  {
    auto shared_zero = [](const Feature& f, const Sample& a, const Sample& b) {
      for (int k = 0; k < f.dimension + 1 && f.dimension > 0; ++k)
        if (a.weights[k] == 0 && b.weights[k] == 0) return true;
      return false;
    };
    return shared_zero(m_fp.p, m_p[i], m_p[j]) || shared_zero(m_fp.q, m_q[i], m_q[j]);
  }
  /// Three corners of the whole facet (of its convex hull), not collinear: (P sample, Q sample).
  std::array<std::pair<Sample, Sample>, 3> facet_corners() const { return m_facet_corners; }
  /// Bound of the diameter of every cell.
  double diameter() const { return m_diameter; }

  /// Lattice point k, rounded to doubles (P and Q: the meshes of the pair's features).
  Point3 position(std::size_t k, const Mesh_data& P, const Mesh_data& Q) const
  {
    Point3 x;
    for (int c = 0; c < 3; ++c) x[c] = sum_coordinate<double>(P, Q, m_p[k], m_q[k], nullptr, c);
    return x;
  }

  /// The lattice point of the candidate (p, q) of this piece (interior samples).
  std::size_t index_of(const Sample& p, const Sample& q) const
  {
    if (m_fp.p.dimension == 1)
      return (edge_index(m_params_p, p) - std::size_t(m_rows.first)) * m_params_q.size() + edge_index(m_params_q, q);
    const Sample& s = m_fp.p.dimension == 0 ? q : p;
    return triangle_index(s.weights[0], s.weights[1]) - triangle_index(m_rows.first, 0);
  }

  /// The feature of side `which` (0: P, 1: Q) holding the point with weights w over that
  /// side's vertex triple.
  Feature origin(int which, const std::array<CGAL::Exact_rational, 3>& w, const Mesh_data& M) const
  {
    const Feature f = which == 0 ? m_fp.p : m_fp.q;
    if (f.dimension == 0) return f;
    std::array<bool, 3> nz;
    for (int i = 0; i < 3; ++i) nz[i] = CGAL::sign(w[i]) != CGAL::ZERO;
    if (f.dimension == 1) {
      if (nz[0] && nz[1]) return f;
      return Feature{0, M.edges[f.index].v[nz[0] ? 0 : 1]};
    }
    const int count = int(nz[0]) + int(nz[1]) + int(nz[2]);
    if (count == 3) return f;
    const auto& t = M.triangles[f.index];
    for (int i = 0; i < 3; ++i) {
      if (count == 1 && nz[i]) return Feature{0, t[i]};
      if (count == 2 && nz[i] && nz[(i + 1) % 3]) return Feature{1, M.triangle_edges[f.index][i]};
    }
    return f;
  }

private:
  /// Index of point (i, j) in the whole triangle lattice, row by row.
  std::size_t triangle_index(std::int32_t i, std::int32_t j) const
  { return std::size_t(i) * (m_n + 1) - std::size_t(i) * (i - 1) / 2 + std::size_t(j); }

  static std::size_t edge_index(const std::vector<std::pair<std::int32_t, std::int32_t>>& params, const Sample& s)
  {
    const std::pair<std::int32_t, std::int32_t> key(s.weights[1], s.denominator);
    return std::size_t(std::lower_bound(params.begin(), params.end(), key, [](const auto& a, const auto& b) {
                         return std::int64_t(a.first) * b.second < std::int64_t(b.first) * a.second;
                       }) - params.begin());
  }

  /// Vertex v of the other side + the lattice of triangle t of `s` (`t_is_p`: t on P's side).
  void triangle_lattice(const Mesh_sampling& s, Index v, bool t_is_p)
  {
    const Index t = t_is_p ? m_fp.p.index : m_fp.q.index;
    const Mesh_data& M = s.mesh();
    const auto& tri = M.triangles[t];
    const std::int32_t n = s.triangle_resolution(t);
    m_n = n;
    const Sample vertex{Feature{0, v}, {v, v, v}, {1, 0, 0}, 1};
    auto point = [&](std::int32_t i, std::int32_t j) {
      const Sample st{Feature{2, t}, tri, {i, j, n - i - j}, n}; // origin: the facet (see origin())
      return t_is_p ? std::make_pair(st, vertex) : std::make_pair(vertex, st);
    };
    const std::int32_t first = m_rows.first, last = (std::min)(m_rows.last, n);
    for (std::int32_t i = first; i <= last; ++i) {
      if (i == last) m_last_row_start = m_p.size();
      for (std::int32_t j = 0; i + j <= n; ++j) {
        const auto [p, q] = point(i, j);
        m_p.push_back(p);
        m_q.push_back(q);
      }
    }
    m_facet_corners = {point(0, 0), point(n, 0), point(0, n)};
    const std::size_t offset = triangle_index(first, 0);
    auto at = [&](std::int32_t i, std::int32_t j) { return std::uint32_t(triangle_index(i, j) - offset); };
    for (std::int32_t i = first; i < last; ++i)
      for (std::int32_t j = 0; i + j < n; ++j) {
        const auto a = at(i, j), b = at(i + 1, j), c = at(i, j + 1);
        m_cells.push_back({a, b, c});
        if (i + j + 1 < n) m_cells.push_back({b, c, at(i + 1, j + 1)});
      }
    double longest = 0;
    for (int k = 0; k < 3; ++k) {
      const auto e = M.points[tri[(k + 1) % 3]] - M.points[tri[k]];
      longest = (std::max)(longest, std::sqrt(dot(e, e)));
    }
    m_diameter = longest / n;
  }

  /// Edge of P + edge of Q: the grid of their closed parameter lists, cells cut along the
  /// shorter diagonal.
  void edge_lattice(const Mesh_sampling& sp, const Mesh_sampling& sq)
  {
    const Mesh_data &P = sp.mesh(), &Q = sq.mesh();
    m_params_p = sp.closed_edge_parameters(m_fp.p.index);
    m_params_q = sq.closed_edge_parameters(m_fp.q.index);
    const auto& ep = P.edges[m_fp.p.index];
    const auto& eq = Q.edges[m_fp.q.index];
    const auto up = P.points[ep.v[1]] - P.points[ep.v[0]];
    const auto uq = Q.points[eq.v[1]] - Q.points[eq.v[0]];
    const auto n = cross(up, uq);
    if (dot(n, n) == 0) return; // parallel edges: no facet
    auto sample = [](const Feature& f, const auto& e, const std::pair<std::int32_t, std::int32_t>& k) {
      return Sample{f, {e.v[0], e.v[1], e.v[1]}, {k.second - k.first, k.first, 0}, k.second};
    };
    const std::size_t np = m_params_p.size(), nq = m_params_q.size();
    const std::size_t first = std::size_t(m_rows.first), last = (std::min)(std::size_t(m_rows.last), np - 1);
    for (std::size_t i = first; i <= last; ++i) {
      if (i == last) m_last_row_start = m_p.size();
      for (const auto& kq : m_params_q) {
        m_p.push_back(sample(m_fp.p, ep, m_params_p[i]));
        m_q.push_back(sample(m_fp.q, eq, kq));
      }
    }
    auto corner = [&](std::size_t i, std::size_t j) {
      return std::make_pair(sample(m_fp.p, ep, m_params_p[i]), sample(m_fp.q, eq, m_params_q[j]));
    };
    m_facet_corners = {corner(0, 0), corner(0, nq - 1), corner(np - 1, 0)};
    const bool anti = dot(up, uq) > 0; // then (i + 1, j) - (i, j + 1) is the shorter diagonal
    const double lp = std::sqrt(dot(up, up)), lq = std::sqrt(dot(uq, uq));
    auto param = [](const std::pair<std::int32_t, std::int32_t>& k) { return double(k.first) / k.second; };
    for (std::size_t i = first; i < last; ++i)
      for (std::size_t j = 0; j + 1 < nq; ++j) {
        const auto a = std::uint32_t((i - first) * nq + j), b = std::uint32_t((i + 1 - first) * nq + j),
                   c = std::uint32_t((i - first) * nq + j + 1), e = std::uint32_t((i + 1 - first) * nq + j + 1);
        if (anti) { m_cells.push_back({a, b, c}); m_cells.push_back({b, c, e}); }
        else { m_cells.push_back({a, b, e}); m_cells.push_back({a, c, e}); }
      }
    // The diameter bound of the whole facet's cells (the same for every piece): their sides
    // and shorter diagonals. The squared diagonal is a convex function of the two sides'
    // lengths, largest at their extremes.
    auto extremes = [&](const std::vector<std::pair<std::int32_t, std::int32_t>>& params, double length) {
      std::pair<double, double> r(length, 0);
      for (std::size_t i = 0; i + 1 < params.size(); ++i) {
        const double l = (param(params[i + 1]) - param(params[i])) * length;
        r = {(std::min)(r.first, l), (std::max)(r.second, l)};
      }
      return r;
    };
    const auto [p_min, p_max] = extremes(m_params_p, lp);
    const auto [q_min, q_max] = extremes(m_params_q, lq);
    m_diameter = (std::max)(p_max, q_max);
    for (double sp_len : {p_min, p_max})
      for (double sq_len : {q_min, q_max}) {
        const std::array<double, 3> diag = {up[0] * (sp_len / lp) + (anti ? -1 : 1) * uq[0] * (sq_len / lq),
                                            up[1] * (sp_len / lp) + (anti ? -1 : 1) * uq[1] * (sq_len / lq),
                                            up[2] * (sp_len / lp) + (anti ? -1 : 1) * uq[2] * (sq_len / lq)};
        m_diameter = (std::max)(m_diameter, std::sqrt(dot(diag, diag)));
      }
  }

  static bool interior(const Feature& f, const Sample& s)
  { return f.dimension == 0 || (s.weights[0] != 0 && s.weights[1] != 0 && (f.dimension == 1 || s.weights[2] != 0)); }

  Feature_pair m_fp;
  Row_range m_rows;
  std::int32_t m_n = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> m_params_p, m_params_q;
  std::vector<Sample> m_p, m_q;
  std::size_t m_last_row_start = 0; // index of the first point of the last row
  std::vector<std::array<std::uint32_t, 3>> m_cells;
  std::array<std::pair<Sample, Sample>, 3> m_facet_corners;
  double m_diameter = 0;
};

/// Starts the plane of the lattice's facet in `search` (Segment_search::start_plane()), points
/// perturbed along `directions` (count of them), unless it is started.
inline void start_facet_plane(Segment_search& search, const Facet_lattice& lattice, const Direction* directions,
                              std::uint32_t count)
{
  if (!search.plane_started()) search.start_plane(lattice.facet_corners(), directions, count);
}

/// Which cells the trim search searches (none inside the sum whole: see select_cells()):
/// where the covering needs it (cells with a corner known inside that no output point covers
/// whole); every cell with a corner known inside (a mesh needs the trim curves around a hole
/// in a face narrower than d, which the points around it cover); or also, following each
/// strip of a facet narrower than d/2, the cells with an untested corner, to the strip's ends
/// (a mesh needs both edges' rows to where the strip meets another face; more points, and
/// more searched segments, on sums with many narrow strips).
enum class Strips : std::uint8_t { as_covering_needs, inside_corners, followed };

/// The point of lattice point a plus trim (exact weights) of pair fp, with its origins and
/// position.
inline Trim_point lattice_trim_point(const Facet_lattice& lattice, const Mesh_data& P, const Mesh_data& Q,
                                     const Feature_pair& fp, std::uint32_t a, Trim trim, const Point3& hidden,
                                     double covered_within)
{
  Trim_point t{lattice.p(a), lattice.q(a), std::move(trim), {}, covered_within, fp.first_direction, hidden};
  t.trim.origin_p = lattice.origin(0, trim_weights(t.p, t.trim, 0), P);
  t.trim.origin_q = lattice.origin(1, trim_weights(t.q, t.trim, 1), Q);
  for (int c = 0; c < 3; ++c) t.x[c] = sum_coordinate<double>(P, Q, t.p, t.q, &t.trim, c);
  return t;
}

/// The radius within which an output point covers a trim point of a lattice's cell (d minus
/// the cells' diameter: see the file comment).
inline double trim_covering_radius(const Facet_lattice& lattice, double d)
{ return (std::max)(0., d - lattice.diameter()); }

/// What is known of a lattice point when the trim search starts: its status, and for an
/// inside one, the item pair whose crossing decided it, or its certified octree leaf.
enum class Corner : std::uint8_t { unknown, inside, free, covered };
struct Corner_info
{
  Corner status = Corner::unknown;
  std::optional<std::pair<Index, Index>> witness;
  std::optional<std::uint64_t> leaf;
};

/// The trim search of one facet lattice, stage by stage (find_trim_points() runs them): the
/// cells with a corner `inside` and their segments; the segments' free parts (following
/// narrow strips, with Strips::followed); the corners where narrow strips meet the facet's
/// border; the islands. Trim points are appended to `out` in a canonical order.
template <class CornerInfo, class Certified, class Covered>
class Facet_trim_search
{
public:
  Facet_trim_search(const Facet_lattice& lattice, const Mesh_data& P, const Mesh_data& Q, const Candidate_pairs& pairs,
                    const Feature_pair& fp, double d, Strips strips, const CornerInfo& corner,
                    const Certified& certified_box, const Covered& covered, Segment_search& search,
                    std::vector<Trim_point>& out)
    : m_lattice(lattice), m_p(P), m_q(Q), m_fp(fp), m_d(d), m_strips(strips), m_corner(corner),
      m_certified_box(certified_box), m_covered(covered), m_search(search), m_out(out),
      m_directions(pairs.directions.data() + fp.first_direction),
      m_radius(trim_covering_radius(lattice, d)), m_searched_cell(lattice.cells().size(), false),
      m_uncertified_cell(lattice.cells().size(), false), m_exact(lattice.size()), m_rounded(lattice.size())
  {}

  /// Selects the cells with a corner inside, and their segments, in a canonical order; not
  /// those that `covered` tells are covered whole, nor those inside one patch pair's
  /// crossing set, nor those with every corner inside that are certified inside the sum
  /// (their segments have no free part, nor they an island: one test for the cell rather
  /// than one for each of its segments, which were tested alone, and one for the cell
  /// before its island search). Returns: is there any?
  bool select_cells()
  {
    for (std::size_t i = 0; i < m_lattice.cells().size(); ++i) {
      const auto& cell = m_lattice.cells()[i];
      if (m_covered({position(cell[0]), position(cell[1]), position(cell[2])})) continue; // (its corners untested)
      int inside = 0;
      for (std::uint32_t c : cell) inside += m_corner(c).status == Corner::inside;
      if (inside > 0 && covered_by_one_patch_pair(cell, false)) continue;
      if (inside == 3) {
        // (a scan put off: the test above has failed on this cell already)
        if (certified({cell[0], cell[1], cell[2]}, true) || (scan_now() && covered_by_one_patch_pair(cell, true)))
          continue;
        m_uncertified_cell[i] = true;
      }
      if (inside > 0) search_cell(i);
    }
    std::sort(m_to_search.begin(), m_to_search.end());
    return !m_cells.empty();
  }

  /// The free parts of the selected segments (and of those of the cells added by following
  /// narrow strips, Strips::followed), each searched once.
  void search_segments()
  {
    start_plane();
    std::vector<Segment_parameter> ends;
    for (std::size_t n = 0; n < m_to_search.size(); ++n) {
      const Segment ab = m_to_search[n];
      Segment_info& info = m_segments[ab];
      const auto [a, b] = ab;
      const Corner_info &ca = m_corner(a), &cb = m_corner(b);
      // Both ends inside: skipped if certified, also by the certificate's balls where both
      // ends are in certified leaves (else the balls mostly fail, at up to 512 lookups).
      const bool in_leaves = ca.leaf && cb.leaf;
      if (in_leaves && *ca.leaf == *cb.leaf) continue;
      if (ca.status == Corner::inside && cb.status == Corner::inside && certified({a, b}, in_leaves)) continue;
      ends.clear();
      m_search.free_ends(lattice_segment(a, b), m_directions, m_fp.number_of_directions, ends,
                         {{ca.witness, cb.witness}, ca.status == Corner::free || cb.status == Corner::free});
      info.has_ends = !ends.empty();
      info.narrow = add_ends(a, b, ends, {}, false);
      if (info.has_ends && m_lattice.on_border(a, b)) m_border.emplace_back(ab, ends);
      // Followed (Strips): a strip narrower than d/2 into the cells on both sides of the
      // segment with an untested corner, which the covering does not need.
      if (info.narrow && m_strips == Strips::followed) follow(ab);
    }
  }

  /// On the facet's border, a segment may be free where the facet next to it is hidden (the
  /// border lies on another face of the boundary): seen from inside the facet, its free parts
  /// end where a trim curve meets the border. Where a strip narrower than d/2 enters the
  /// segment's cell through one other edge (and leaves through the border, not through the
  /// third edge), the strip's ends on the border are corners of the boundary that no other
  /// point stands for (a narrow tunnel's mouth): searched again from the facet's side (only
  /// where a free part is longer than a point: the side's free parts are within them), kept.
  void search_border_corners()
  {
    std::vector<Segment_parameter> ends;
    for (const auto& [ab, known] : m_border) {
      const auto [a, b] = ab;
      const std::uint32_t o = m_segments[ab].opposite;
      if (m_segments[segment({a, b, o}, 1)].narrow == m_segments[segment({a, b, o}, 2)].narrow) continue;
      bool longer = false;
      for (std::size_t k = 0; k + 1 < known.size(); k += 2) longer = longer || compare(known[k], known[k + 1]) != CGAL::ZERO;
      if (!longer) continue;
      const Translation_segment s = lattice_segment(a, b);
      Vec3<Exact_nt> inward;
      for (int c = 0; c < 3; ++c) inward[c] = point(o).X[c] * s.a.W - s.a.X[c] * point(o).W;
      ends.clear();
      m_search.free_ends(s, m_directions, m_fp.number_of_directions, ends, {{m_corner(a).witness, m_corner(b).witness}},
                         &inward); // (an end free along the directions may be hidden on the inward side)
      add_ends(a, b, ends, known, true);
    }
  }

  /// The selected cells whose edges have no free part and that are not certified inside the
  /// sum (indices in the lattice's cells(), in order): those whose islands are searched
  /// (find_island_points()).
  void island_cells(std::vector<std::uint32_t>& out)
  {
    for (std::size_t i : m_cells) {
      const auto& cell = m_lattice.cells()[i];
      bool has_ends = false;
      for (int k = 0; k < 3; ++k) has_ends = has_ends || m_segments[segment(cell, k)].has_ends;
      // (a cell that failed the test in select_cells() is not tested again: same answer)
      if (!has_ends && (m_uncertified_cell[i] || !certified({cell[0], cell[1], cell[2]}, true)))
        out.push_back(std::uint32_t(i));
    }
  }

private:
  using Segment = std::pair<std::uint32_t, std::uint32_t>;
  struct Segment_info
  {
    bool has_ends = false;      // has it free parts?
    bool narrow = false;        // one shorter than d/2?
    std::uint32_t opposite = 0; // the third corner of a cell of the segment
  };

  static Segment segment(const std::array<std::uint32_t, 3>& cell, int k)
  { return Segment((std::min)(cell[k], cell[(k + 1) % 3]), (std::max)(cell[k], cell[(k + 1) % 3])); }

  /// Selects cell i: its new segments are searched after those already selected.
  void search_cell(std::size_t i)
  {
    const auto& cell = m_lattice.cells()[i];
    m_searched_cell[i] = true;
    m_cells.push_back(i);
    for (int k = 0; k < 3; ++k)
      if (m_segments.emplace(segment(cell, k), Segment_info{false, false, cell[(k + 2) % 3]}).second)
        m_to_search.push_back(segment(cell, k));
  }

  /// Selects the cells of segment ab with an untested (maybe inside) corner. The cells of
  /// each segment (two at most) are listed when a strip is first followed.
  void follow(const Segment& ab)
  {
    if (m_cells_of.empty())
      for (std::size_t i = 0; i < m_lattice.cells().size(); ++i)
        for (int k = 0; k < 3; ++k) {
          auto [it, added] = m_cells_of.emplace(segment(m_lattice.cells()[i], k),
                                                std::array<std::uint32_t, 2>{std::uint32_t(i), std::uint32_t(i)});
          if (!added) it->second[1] = std::uint32_t(i);
        }
    for (std::uint32_t i : m_cells_of[ab]) {
      bool covered = false;
      for (std::uint32_t c : m_lattice.cells()[i]) covered = covered || m_corner(c).status == Corner::covered;
      if (!m_searched_cell[i] && covered) search_cell(i);
    }
  }

  /// The segment between lattice points a and b.
  Translation_segment lattice_segment(std::uint32_t a, std::uint32_t b)
  {
    return Translation_segment(point(a), point(b),
                               std::array<std::pair<Sample, Sample>, 2>{{{m_lattice.p(a), m_lattice.q(a)},
                                                                          {m_lattice.p(b), m_lattice.q(b)}}});
  }

  /// Lattice point k, exactly and rounded (each computed once).
  const Exact_point& point(std::uint32_t k)
  {
    if (!m_exact[k]) m_exact[k] = exact_sum(m_p, m_lattice.p(k), m_q, m_lattice.q(k));
    return *m_exact[k];
  }
  const Point3& position(std::uint32_t k)
  {
    if (!m_rounded[k]) m_rounded[k] = m_lattice.position(k, m_p, m_q);
    return *m_rounded[k];
  }

  /// Is a scan of every patch pair met (covered_by_one_patch_pair()) worth its cost for the
  /// next cell with every corner inside? Where the scans keep failing (coplanar faces: the
  /// crossing sets of single patch pairs leave their common plane undecided, the islands'
  /// search settles it), they are put off: after 4 failures in a row, the next n - 3 cells
  /// are not scanned (n failures in a row, at most 32 cells); a scan that succeeds resets
  /// the count. A cell not scanned only costs work (its island search), and what is put off
  /// depends on the cells' order alone: the same on any thread or rank.
  bool scan_now()
  {
    if (m_scans_put_off > 0) {
      --m_scans_put_off;
      return false;
    }
    return true;
  }

  /// Records whether a scan (scan_now()) found a covering patch pair.
  void scanned(bool covered)
  {
    m_scan_failures = covered ? 0 : m_scan_failures + 1;
    if (m_scan_failures >= 4) m_scans_put_off = (std::min)(m_scan_failures - 3, 32u);
  }

  /// Is the cell (no corner free) inside the crossing set of one patch pair
  /// (Segment_search::patch_pair_covers(): with its corners' witnesses, and with `scan` every
  /// pair met)? Then it is inside the sum whole: neither its segments nor its islands have a
  /// free point.
  bool covered_by_one_patch_pair(const std::array<std::uint32_t, 3>& cell, bool scan)
  {
    std::array<std::optional<std::pair<Index, Index>>, 3> witnesses;
    for (int k = 0; k < 3; ++k) {
      const Corner_info& c = m_corner(cell[k]);
      if (c.status == Corner::free) return false;
      if (c.status == Corner::inside) witnesses[k] = c.witness;
    }
    start_plane(); // (the facet's plane decides the seams between coplanar faces)
    const bool covered = m_search.patch_pair_covers({box_of(cell[0]), box_of(cell[1]), box_of(cell[2])}, witnesses, scan);
    if (scan) scanned(covered);
    return covered;
  }

  /// Starts the facet's plane in the segment search, once (Segment_search::start_plane()).
  void start_plane()
  {
    start_facet_plane(m_search, m_lattice, m_directions, m_fp.number_of_directions);
  }

  /// A box holding lattice point k.
  Vec3<Interval> box_of(std::uint32_t k) const { return lattice_point_box(m_p, m_q, m_lattice.p(k), m_lattice.q(k)); }

  /// Is the bounding box of these lattice points certified inside the sum?
  bool certified(std::initializer_list<std::uint32_t> corners, bool ball)
  {
    Point3 lo = position(*corners.begin()), hi = lo;
    for (std::uint32_t k : corners)
      for (int c = 0; c < 3; ++c) {
        lo[c] = (std::min)(lo[c], position(k)[c]);
        hi[c] = (std::max)(hi[c], position(k)[c]);
      }
    return m_certified_box(lo, hi, ball);
  }

  /// Outputs the point of corner a plus trim (lattice_trim_point()).
  void add(std::uint32_t a, Trim trim, const Point3& hidden, double covered_within)
  { m_out.push_back(lattice_trim_point(m_lattice, m_p, m_q, m_fp, a, std::move(trim), hidden, covered_within)); }

  /// Outputs the ends of the free parts of segment ab (`ends`: first and last of each; the
  /// segment is hidden before a first end, after a last one), but those in `known`. A free
  /// part shorter than d/2 crosses a strip of the facet narrower than that: its ends get
  /// their hidden sides, so that the net keeps both edges' points; `pin`: and no other point
  /// covers them. Returns: was there such a free part?
  bool add_ends(std::uint32_t a, std::uint32_t b, const std::vector<Segment_parameter>& ends,
                const std::vector<Segment_parameter>& known, bool pin)
  {
    if (ends.empty()) return false;
    auto is_known = [&](const Segment_parameter& t) {
      return std::any_of(known.begin(), known.end(), [&](const Segment_parameter& e) { return compare(e, t) == CGAL::ZERO; });
    };
    Point3 forward = position(b) - position(a);
    const double length = std::sqrt(dot(forward, forward));
    forward = length > 0 ? scaled(forward, 1 / length) : Point3{0, 0, 0};
    bool narrow = false;
    for (std::size_t k = 0; k < ends.size(); ++k) {
      if (k > 0 && compare(ends[k], ends[k - 1]) == CGAL::ZERO) continue; // an isolated free point
      const std::size_t other = k % 2 == 0 ? k + 1 : k - 1; // the other end of its free part
      const double width =
        other < ends.size() ? std::abs(CGAL::to_double(ends[k].value()) - CGAL::to_double(ends[other].value())) * length
                            : m_d;
      const bool strip = width > 0 && width < m_d / 2;
      narrow = narrow || strip;
      // (a free part found again: nothing new; a known end: kept only as a narrow strip's corner)
      const bool known_end = is_known(ends[k]);
      if (known_end && (other >= ends.size() || is_known(ends[other]) || !(strip && pin))) continue;
      add(a, Trim{m_lattice.p(b), m_lattice.q(b), ends[k].value(), {}, {}, {}, {}, {}},
          !strip ? Point3{0, 0, 0} : k % 2 == 0 ? scaled(forward, -1.) : forward, strip && pin ? 0. : m_radius);
    }
    return narrow;
  }

  const Facet_lattice& m_lattice;
  const Mesh_data& m_p;
  const Mesh_data& m_q;
  const Feature_pair& m_fp;
  double m_d;
  Strips m_strips;
  const CornerInfo& m_corner;
  const Certified& m_certified_box;
  const Covered& m_covered;
  Segment_search& m_search;
  std::vector<Trim_point>& m_out;
  const Direction* m_directions;
  double m_radius; // within which an output point covers a trim point
  std::vector<std::size_t> m_cells;                    // selected, in order
  std::vector<bool> m_searched_cell;                   // selected?
  std::vector<bool> m_uncertified_cell;                // its whole-cell test failed (select_cells())?
  std::uint32_t m_scan_failures = 0;                   // scans that failed in a row (scan_now())
  std::uint32_t m_scans_put_off = 0;                   // cells left to skip the scan on
  std::map<Segment, Segment_info> m_segments;          // of the selected cells, each once
  std::vector<Segment> m_to_search;                    // in the order searched
  std::map<Segment, std::array<std::uint32_t, 2>> m_cells_of; // (follow())
  std::vector<std::pair<Segment, std::vector<Segment_parameter>>> m_border; // border segments with free parts
  std::vector<std::optional<Exact_point>> m_exact;     // lattice points
  std::vector<std::optional<Point3>> m_rounded;
};

/// The trim points of a facet lattice (see the file comment): the free-part ends of the
/// edges of every cell with a corner `inside` (corner(i) gives what is known of lattice
/// point i, computing it if needed), appended to `out` in a canonical order (`strips`: see
/// Strips); with `island_cells`, those of the cells whose edges had none, whose islands are
/// then searched (find_island_points()). A cell is skipped without a search when
/// `covered(corners)` tells that every point of it is closer than d to an output point (the
/// caller's choice: with Strips::as_covering_needs only); a segment or a cell when
/// `certified(lo, hi, ball)` tells that its bounding box is inside the sum (by octree leaves;
/// `ball`: also by the certificate's balls, costlier, for cells and for segments between two
/// certified leaves), or a segment's ends lie in one certified octree leaf; a cell when one
/// patch pair certainly crosses on all of it (`search`'s Segment_search::patch_pair_covers()).
/// `search`: its plane not started yet, or started on the lattice's facet.
template <class CornerInfo, class Certified, class Covered>
void find_trim_points(const Facet_lattice& lattice, const Mesh_data& P, const Mesh_data& Q,
                      const Candidate_pairs& pairs, const Feature_pair& fp, double d, Strips strips, const CornerInfo& corner,
                      const Certified& certified_box, const Covered& covered, Segment_search& search,
                      std::vector<std::uint32_t>* island_cells, std::vector<Trim_point>& out)
{
  Facet_trim_search<CornerInfo, Certified, Covered> trim(lattice, P, Q, pairs, fp, d, strips, corner, certified_box,
                                                         covered, search, out);
  if (!trim.select_cells()) return;
  trim.search_segments();
  trim.search_border_corners();
  if (island_cells) trim.island_cells(*island_cells);
}

/// An island point (island_search.h) of each of the lattice's `cells` (indices in cells(),
/// from find_trim_points()) that has islands, appended to `out` in the cells' order; a cell
/// is skipped without a search when `covered(corners)` tells that one output point is closer
/// than d to all of it.
template <class Covered>
void find_island_points(const Facet_lattice& lattice, const Mesh_data& P, const Mesh_data& Q,
                        const Candidate_pairs& pairs, const Feature_pair& fp, double d,
                        const std::vector<std::uint32_t>& cells, const Covered& covered, Segment_search& search,
                        Island_search& islands, std::vector<Trim_point>& out)
{
  const Direction* directions = pairs.directions.data() + fp.first_direction;
  bool started = false;
  for (std::uint32_t i : cells) {
    const auto& cell = lattice.cells()[i];
    if (covered({lattice.position(cell[0], P, Q), lattice.position(cell[1], P, Q), lattice.position(cell[2], P, Q)}))
      continue;
    if (!started) { // the facet's plane, as in the trim search
      start_facet_plane(search, lattice, directions, fp.number_of_directions);
      islands.start_facet(directions, fp.number_of_directions);
      started = true;
    }
    std::array<Exact_point, 3> T;
    std::array<std::pair<Sample, Sample>, 3> sums;
    std::array<Spans, 3> spans;
    for (int k = 0; k < 3; ++k) {
      T[k] = exact_sum(P, lattice.p(cell[k]), Q, lattice.q(cell[k]));
      sums[k] = {lattice.p(cell[k]), lattice.q(cell[k])};
      spans[k] = Spans{&sums[k]};
    }
    if (const std::optional<Cell_weights> w = islands.island_point(T, spans))
      out.push_back(lattice_trim_point(
        lattice, P, Q, fp, cell[0],
        Trim{lattice.p(cell[1]), lattice.q(cell[1]), (*w)[1], lattice.p(cell[2]), lattice.q(cell[2]), (*w)[2], {}, {}},
        Point3{0, 0, 0}, trim_covering_radius(lattice, d)));
  }
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_TRIM_POINTS_H
