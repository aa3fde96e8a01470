// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2 of the pipeline: the candidates. A candidate is a sum p + q of a sample p of P and
// a sample q of Q whose features form a pair kept by the normal filter. Candidates are not
// stored: each feature pair lists its samples, and the candidates are visited in the
// canonical order (pair, then sample of P, then sample of Q), the one order that every later
// stage (octree leaves, decisions, the covering net, the output) follows.

#ifndef CGAL_PMSUM_INTERNAL_CANDIDATES_H
#define CGAL_PMSUM_INTERNAL_CANDIDATES_H

#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/sampling.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

using Point3 = std::array<double, 3>;

/// Rows [first, last) of a pair (Pair_rows).
struct Row_range
{
  std::int32_t first, last;
};

/// The rows of a feature pair's candidates, the unit in which a large pair is cut into pieces
/// (make_pieces). A 2-dimensional pair's rows are those of its facet lattice (trim_points.h):
/// for a triangle and a vertex, the triangle's lattice points with the same first weight i
/// (0 <= i <= n); for two edges, the closed parameters of P's edge in increasing order, each
/// with every parameter of Q's edge. Cell row r holds the lattice cells between rows r and
/// r + 1, and the candidates of lattice row r (those interior to both features). Any other
/// pair is one row.
class Pair_rows
{
public:
  Pair_rows(const Mesh_sampling& sp, const Mesh_sampling& sq, const Feature_pair& fp)
  {
    const int dp = fp.p.dimension, dq = fp.q.dimension;
    if (dp == 1 && dq == 1) {
      m_kind = Kind::edges;
      m_params_p = sp.closed_edge_parameters(fp.p.index);
      m_rows = std::int32_t(m_params_p.size()) - 1;
      m_row_candidates = sq.number_of_samples(fp.q);
    } else if (dp + dq == 2) {
      m_kind = dp == 2 ? Kind::triangle_of_p : Kind::triangle_of_q;
      m_rows = dp == 2 ? sp.triangle_resolution(fp.p.index) : sq.triangle_resolution(fp.q.index);
    } else {
      m_row_candidates = sp.number_of_samples(fp.p) * sq.number_of_samples(fp.q);
    }
  }

  /// The number of cell rows.
  std::int32_t size() const { return m_rows; }

  /// The number of candidates of cell row i.
  std::size_t candidates(std::int32_t i) const
  {
    if (m_kind == Kind::one_row) return m_row_candidates;
    if (i < 1 || i >= m_rows) return 0; // rows 0 and n: on the facet's border
    return m_kind == Kind::edges ? m_row_candidates : std::size_t(m_rows - 1 - i); // n - 1 - i in row i
  }

  /// The samples of side `side` (0: P, 1: Q) of the candidates of cell rows r, in the order
  /// of Mesh_sampling::samples().
  void samples(int side, const Mesh_sampling& s, Feature f, Row_range r, std::vector<Sample>& out) const
  {
    const bool rows_on_this_side = (m_kind == Kind::triangle_of_p || m_kind == Kind::edges) == (side == 0);
    if (m_kind == Kind::one_row || !rows_on_this_side) s.samples(f, out);
    else if (m_kind != Kind::edges) s.triangle_samples(f.index, r.first, r.last, out);
    else {
      // P's edge samples whose parameter k / den lies in [params[first], params[last]).
      const std::size_t before = out.size();
      s.samples(f, out);
      auto less = [](std::int64_t k, std::int64_t den, const std::pair<std::int32_t, std::int32_t>& a) {
        return k * a.second < std::int64_t(a.first) * den;
      };
      const auto& lo = m_params_p[std::size_t(r.first)];
      const auto& hi = m_params_p[std::size_t(r.last)];
      out.erase(std::remove_if(out.begin() + std::ptrdiff_t(before), out.end(),
                               [&](const Sample& x) {
                                 return less(x.weights[1], x.denominator, lo) || !less(x.weights[1], x.denominator, hi);
                               }),
                out.end());
    }
  }

private:
  enum class Kind { one_row, triangle_of_p, triangle_of_q, edges };
  Kind m_kind = Kind::one_row;
  std::int32_t m_rows = 1;
  std::size_t m_row_candidates = 0; // edges: Q's samples; one row: all the candidates
  std::vector<std::pair<std::int32_t, std::int32_t>> m_params_p;
};

/// A piece of a feature pair: the candidates of its cell rows `rows` (Pair_rows), and the
/// trim search of the cells of those rows. The unit of the decisions (decision.h).
struct Pair_piece
{
  std::size_t pair;
  Row_range rows;
};

/// The pieces of every pair, in canonical order, and each piece's number of candidates
/// (`work`): a pair with more than `piece_work` candidates is cut into runs of at least
/// `min_rows` cell rows holding about `piece_work` candidates each (at least one each), so
/// that the waves of decisions (parallel.h) are shared out evenly; other pairs are one
/// piece. Depends on nothing but the pairs, the samplings and the two numbers.
inline std::vector<Pair_piece> make_pieces(const Candidate_pairs& pairs, const Mesh_sampling& sp,
                                           const Mesh_sampling& sq, std::size_t piece_work, std::int32_t min_rows,
                                           std::vector<std::size_t>& work)
{
  std::vector<Pair_piece> pieces;
  work.clear();
  for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
    const Pair_rows rows(sp, sq, pairs.pairs[i]);
    std::int32_t first = 0;
    std::size_t left = sp.number_of_samples(pairs.pairs[i].p) * sq.number_of_samples(pairs.pairs[i].q);
    while (first < rows.size()) {
      std::int32_t last = first;
      std::size_t piece = 0;
      if (left <= piece_work) last = rows.size(); // the rest in one piece
      while (last < rows.size() && (piece < piece_work || last - first < min_rows)) piece += rows.candidates(last++);
      if (rows.size() - last < min_rows) // no short piece at the end
        while (last < rows.size()) piece += rows.candidates(last++);
      if (last == rows.size()) piece = left;
      pieces.push_back({i, {first, last}});
      work.push_back(piece);
      left -= piece;
      first = last;
    }
  }
  return pieces;
}

/// The candidates of one feature pair, or of a piece of it: the samples of its two features
/// and, if asked, their positions rounded to double (for the octree and the covering net;
/// decisions are exact).
class Pair_candidates
{
public:
  /// Every candidate of pair fp.
  void load(const Mesh_sampling& sp, const Mesh_sampling& sq, const Feature_pair& fp, bool with_positions)
  {
    m_p.clear();
    m_q.clear();
    sp.samples(fp.p, m_p);
    sq.samples(fp.q, m_q);
    load_positions(sp, sq, with_positions);
  }

  /// The candidates of cell rows r of pair fp (rows: its Pair_rows).
  void load(const Mesh_sampling& sp, const Mesh_sampling& sq, const Feature_pair& fp, const Pair_rows& rows,
            Row_range r, bool with_positions)
  {
    m_p.clear();
    m_q.clear();
    rows.samples(0, sp, fp.p, r, m_p);
    rows.samples(1, sq, fp.q, r, m_q);
    load_positions(sp, sq, with_positions);
  }

  std::size_t size_p() const { return m_p.size(); }
  std::size_t size_q() const { return m_q.size(); }
  const Sample& p(std::size_t i) const { return m_p[i]; }
  const Sample& q(std::size_t j) const { return m_q[j]; }
  /// Rounded position of candidate (i, j); needs `with_positions`.
  Point3 position(std::size_t i, std::size_t j) const
  { return {m_xp[i][0] + m_xq[j][0], m_xp[i][1] + m_xq[j][1], m_xp[i][2] + m_xq[j][2]}; }

  /// Calls f(i, j) for every candidate, in canonical order.
  template <class F>
  void for_each(const F& f) const
  {
    for (std::size_t i = 0; i < m_p.size(); ++i)
      for (std::size_t j = 0; j < m_q.size(); ++j) f(i, j);
  }

private:
  void load_positions(const Mesh_sampling& sp, const Mesh_sampling& sq, bool with_positions)
  {
    m_xp.clear();
    m_xq.clear();
    if (with_positions) {
      positions(sp.mesh(), m_p, m_xp);
      positions(sq.mesh(), m_q, m_xq);
    }
  }

  static void positions(const Mesh_data& M, const std::vector<Sample>& samples, std::vector<Point3>& out)
  {
    out.resize(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i)
      for (int c = 0; c < 3; ++c) out[i][c] = sample_coordinate<double>(M, samples[i], c);
  }

  std::vector<Sample> m_p, m_q;
  std::vector<Point3> m_xp, m_xq;
};

/// Largest absolute value of a coordinate of M.
inline double largest_coordinate(const Mesh_data& M)
{
  double s = 0;
  for (const auto& x : M.points)
    for (double c : x) s = (std::max)(s, std::abs(c));
  return s;
}

/// The number of candidates of all the pairs.
inline std::size_t number_of_candidates(const Candidate_pairs& pairs, const Mesh_sampling& sp, const Mesh_sampling& sq)
{
  std::size_t total = 0;
  for (const Feature_pair& fp : pairs.pairs) total += sp.number_of_samples(fp.p) * sq.number_of_samples(fp.q);
  return total;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_CANDIDATES_H
