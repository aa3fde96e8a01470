// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output stage, provenance: where a point of a flat region that the input stage triangulated
// again (planar_patches.h) lies among the region's own triangles (the user's), exactly, so
// that its record names the user's feature (sum_output.h).
//
// The region is flat: a point of it has the same barycentric weights over a triangle of it in
// space as in the coordinate plane the region projects to without degeneracy. A uniform grid
// over the triangles' boxes in that plane lists, for the cell of a point, the few triangles
// that can hold it; those are tested exactly (CGAL::Exact_rational), and every triangle if
// none of them holds it (a point rounded across a cell's side), so the grid only saves time.

#ifndef CGAL_PMSUM_INTERNAL_REGION_LOCATOR_H
#define CGAL_PMSUM_INTERNAL_REGION_LOCATOR_H

#include <CGAL_pmsum/internal/planar_patches.h>

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// The triangles of one flat region, and where a point of the region lies among them.
class Region_locator
{
public:
  using Q = CGAL::Exact_rational;
  using Triangle = std::array<std::uint32_t, 3>;

  /// `triangles`: the region's, over `points`, exactly coplanar and not degenerate (as
  /// merge_planar_patches() takes them). Every call below takes the same `points`.
  Region_locator(const std::vector<std::array<double, 3>>& points, std::vector<Triangle> triangles)
    : m_triangles(std::move(triangles))
  {
    const Triangle& t = m_triangles.front();
    const auto axis = planar_patches::projection_axis(points[t[0]], points[t[1]], points[t[2]]);
    const int k = axis ? axis->first : 2;
    m_u = (k + 1) % 3;
    m_v = (k + 2) % 3;
    build_grid(points);
  }

  const std::vector<Triangle>& triangles() const { return m_triangles; }

  /// The first triangle (its index in triangles()) that holds x, a point of the region's
  /// plane, with x's exact barycentric weights over its corners; nothing if none holds it.
  std::optional<std::pair<std::size_t, std::array<Q, 3>>> locate(const std::vector<std::array<double, 3>>& points,
                                                                  const std::array<Q, 3>& x) const
  {
    const std::pair<int, int> c = cell(CGAL::to_double(x[m_u]), CGAL::to_double(x[m_v]));
    const std::size_t k = std::size_t(c.first) * m_nj + std::size_t(c.second);
    for (std::uint32_t i = m_offsets[k]; i < m_offsets[k + 1]; ++i)
      if (auto w = weights(points, m_listed[i], x)) return std::make_pair(std::size_t(m_listed[i]), *w);
    for (std::size_t t = 0; t < m_triangles.size(); ++t)
      if (auto w = weights(points, t, x)) return std::make_pair(t, *w);
    return std::nullopt;
  }

private:
  /// x's exact weights over the corners of triangle t, if t holds x.
  std::optional<std::array<Q, 3>> weights(const std::vector<std::array<double, 3>>& points, std::size_t t,
                                          const std::array<Q, 3>& x) const
  {
    std::array<std::array<Q, 2>, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = {Q(points[m_triangles[t][i]][m_u]), Q(points[m_triangles[t][i]][m_v])};
    const std::array<Q, 2> p = {x[m_u], x[m_v]};
    auto orient = [](const std::array<Q, 2>& a, const std::array<Q, 2>& b, const std::array<Q, 2>& q) {
      return Q((b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])); // (not an expression template of temporaries)
    };
    const Q area = orient(c[0], c[1], c[2]);
    std::array<Q, 3> w = {orient(c[1], c[2], p), orient(c[2], c[0], p), orient(c[0], c[1], p)};
    for (Q& wi : w) {
      wi /= area;
      if (CGAL::sign(wi) == CGAL::NEGATIVE) return std::nullopt;
    }
    return w;
  }


  /// The grid cell of a projected point (clamped to the grid).
  std::pair<int, int> cell(double a, double b) const
  {
    auto index = [](double x, double lo, double size, int n) {
      const double i = std::floor((x - lo) / size);
      return i < 0 ? 0 : i >= n ? n - 1 : int(i);
    };
    return {index(a, m_lo[0], m_size[0], m_ni), index(b, m_lo[1], m_size[1], m_nj)};
  }

  /// About one cell per triangle over the region's box; each triangle listed in the cells
  /// its box (grown by a relative margin that covers the rounding of a point) meets.
  void build_grid(const std::vector<std::array<double, 3>>& points)
  {
    using Box = std::array<std::array<double, 2>, 2>; // lower and upper corners
    auto box_of = [&](const Triangle& t) {
      Box b;
      for (int c = 0; c < 2; ++c) {
        const int axis = c == 0 ? m_u : m_v;
        b[0][c] = (std::min)({points[t[0]][axis], points[t[1]][axis], points[t[2]][axis]});
        b[1][c] = (std::max)({points[t[0]][axis], points[t[1]][axis], points[t[2]][axis]});
      }
      return b;
    };
    std::vector<Box> boxes;
    boxes.reserve(m_triangles.size());
    for (const Triangle& t : m_triangles) boxes.push_back(box_of(t));
    Box region = boxes.front();
    for (const Box& b : boxes)
      for (int c = 0; c < 2; ++c) {
        region[0][c] = (std::min)(region[0][c], b[0][c]);
        region[1][c] = (std::max)(region[1][c], b[1][c]);
      }
    const auto& [lo, hi] = region;
    const int n = (std::max)(1, (std::min)(1024, int(std::ceil(std::sqrt(double(m_triangles.size()))))));
    m_ni = m_nj = n;
    m_lo = lo;
    for (int c = 0; c < 2; ++c) m_size[c] = hi[c] > lo[c] ? (hi[c] - lo[c]) / n : 1.;
    const double margin = 1e-9 * (std::max)({std::abs(lo[0]), std::abs(lo[1]), std::abs(hi[0]), std::abs(hi[1]), 1e-300});
    std::vector<std::pair<std::uint32_t, std::uint32_t>> entries; // (cell, triangle)
    for (std::uint32_t t = 0; t < m_triangles.size(); ++t) {
      const auto& [a, b] = boxes[t];
      const auto first = cell(a[0] - margin, a[1] - margin), last = cell(b[0] + margin, b[1] + margin);
      for (int i = first.first; i <= last.first; ++i)
        for (int j = first.second; j <= last.second; ++j) entries.push_back({std::uint32_t(i * m_nj + j), t});
    }
    std::sort(entries.begin(), entries.end());
    m_offsets.assign(std::size_t(m_ni) * m_nj + 1, 0);
    m_listed.clear();
    for (const auto& [k, t] : entries) {
      ++m_offsets[k + 1];
      m_listed.push_back(t);
    }
    for (std::size_t k = 0; k + 1 < m_offsets.size(); ++k) m_offsets[k + 1] += m_offsets[k];
  }

  std::vector<Triangle> m_triangles;
  int m_u = 0, m_v = 1;
  std::array<double, 2> m_lo{}, m_size{};
  int m_ni = 1, m_nj = 1;
  std::vector<std::uint32_t> m_offsets, m_listed; // the triangles of cell k: m_listed[m_offsets[k] .. m_offsets[k + 1])
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_REGION_LOCATOR_H
