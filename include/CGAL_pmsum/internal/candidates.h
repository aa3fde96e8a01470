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

/// The candidates of one feature pair: the samples of its two features and, if asked, their
/// positions rounded to double (for the octree and the covering net; decisions are exact).
class Pair_candidates
{
public:
  void load(const Mesh_sampling& sp, const Mesh_sampling& sq, const Feature_pair& fp, bool with_positions)
  {
    m_p.clear();
    m_q.clear();
    sp.samples(fp.p, m_p);
    sq.samples(fp.q, m_q);
    m_xp.clear();
    m_xq.clear();
    if (with_positions) {
      positions(sp.mesh(), m_p, m_xp);
      positions(sq.mesh(), m_q, m_xq);
    }
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

/// Number of candidates of each pair, and their total.
inline std::vector<std::size_t> candidates_per_pair(const Candidate_pairs& pairs, const Mesh_sampling& sp,
                                                    const Mesh_sampling& sq, std::size_t& total)
{
  std::vector<std::size_t> work(pairs.pairs.size());
  total = 0;
  for (std::size_t i = 0; i < pairs.pairs.size(); ++i) {
    work[i] = sp.number_of_samples(pairs.pairs[i].p) * sq.number_of_samples(pairs.pairs[i].q);
    total += work[i];
  }
  return work;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_CANDIDATES_H
