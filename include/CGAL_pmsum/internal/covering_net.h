// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 4 of the pipeline: the covering net. The boundary candidates are a d/2-covering of
// the boundary; a subset N in which every boundary candidate has a point closer than d/2 is
// therefore a d-covering, and the greedy choice (take a boundary candidate unless a point of
// N is closer than d/2) keeps the points of N at least d/2 apart: a (d/2, d)-net. A candidate
// already closer than d/2 to N is covered whatever it is, so it needs no collision test.
// (Design note: shared/design/covering-net.md.)
//
// Facing points: a point does not cover one when one of its outward normals makes more than
// 120 degrees with one of the other's (a point on a crease has the normals of its pair's
// cone): the two walls of a passage narrower than d/2, the two sides of a part thinner than
// d/2, the two lips of a passage's mouth (normals {up, +x} and {up, -x}), and two points on
// trim curves whose facets are hidden on opposite sides (the two edges of a face strip
// narrower than d/2, such as a narrow tunnel's wall). Both are kept,
// closer than d/2 to each other: a reconstruction needs points on both sides, and covering
// only needs more points. No normal (unknown) faces none. Two points within the rounding
// margin (next paragraph) of each other are one point: the first covers the other whatever
// they face; a trim point to be kept whatever is near (covers_within() with r = 0) is
// covered by such a point only.
//
// Distances are computed in double on rounded positions, with a margin that makes both
// promises hold for the exact points: a candidate counts as covered only if its exact
// distance is below d/2, and net points are at least d/2 - 2 * margin apart, where the margin
// is a few hundred units in the last place of the largest coordinate.

#ifndef CGAL_PMSUM_INTERNAL_COVERING_NET_H
#define CGAL_PMSUM_INTERNAL_COVERING_NET_H

#include <CGAL_pmsum/internal/candidates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Unit outward normals of a point of the net: `count` from `first` (none: unknown); for a
/// point on a trim curve, also the unit direction in its facet towards the facet's hidden
/// side (zero: none).
struct Net_normals
{
  const Point3* first = nullptr;
  std::uint32_t count = 0;
  Point3 hidden{0, 0, 0};
};

class Covering_net
{
public:
  /// A net for covering distance d of points whose coordinates are at most `scale` in
  /// absolute value. If d is too small next to `scale` for the rounding margin (or for the
  /// cell indices), the net covers nothing: every boundary candidate is kept.
  Covering_net(double d, double scale)
    : m_d(d), m_scale(scale), m_margin(256 * std::numeric_limits<double>::epsilon() * (scale + d)), m_cell(d)
  {
    m_enabled = m_d / 2 - m_margin > 0 && scale / m_cell < double(std::int64_t(1) << 40);
  }

  /// An empty net with the same parameters.
  Covering_net empty_like() const { return Covering_net(m_d, m_scale); }

  bool enabled() const { return m_enabled; }
  std::size_t size() const { return m_points.size(); }
  const Point3& point(std::size_t i) const { return m_points[i]; }
  /// Lower bound of the distance between two points of the net (exact points) that do not
  /// face each other.
  double spacing() const { return m_d / 2 - 2 * m_margin; }

  using Normals = Net_normals;

  /// Do points of normals a and b face each other (two normals, or the hidden sides of two
  /// trim points, more than 120 degrees apart)?
  static bool facing(const Normals& a, const Normals& b)
  {
    if (dot(a.hidden, b.hidden) < -0.5) return true;
    for (std::uint32_t i = 0; i < a.count; ++i)
      for (std::uint32_t j = 0; j < b.count; ++j)
        if (dot(a.first[i], b.first[j]) < -0.5) return true;
    return false;
  }

  /// Is a point of the net that does not face x closer than r <= d/2 to (the exact point
  /// rounded to) x? `normals`: x's. With r = 0: is one within the rounding margin of x?
  bool covers_within(const Point3& x, double r, const Normals& normals = {}) const
  {
    const double rr = r > 0 ? r - m_margin : m_margin; // (r = 0: within the margin only)
    if (!m_enabled || m_points.empty() || !(rr > 0)) return false;
    // Cells have side d: the ball of radius d/2 around x meets the cell of x and, along each
    // axis, the neighbour on the side of x's nearer face: 8 cells.
    std::array<std::int64_t, 3> c, step;
    for (int i = 0; i < 3; ++i) {
      const double t = x[i] / m_cell;
      c[i] = std::int64_t(std::floor(t));
      step[i] = t - double(c[i]) < 0.5 ? -1 : 1;
    }
    for (int o = 0; o < 8; ++o) {
      const std::uint32_t first =
        m_cells.find(key({c[0] + (o & 1 ? step[0] : 0), c[1] + (o & 2 ? step[1] : 0), c[2] + (o & 4 ? step[2] : 0)}));
      for (std::uint32_t n = first; n != none; n = m_next[n]) {
        const Point3& y = m_points[n];
        const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
        const double squared = dx * dx + dy * dy + dz * dz; // (within the margin: one point)
        if (squared < rr * rr && (squared <= m_margin * m_margin || (r > 0 && !facing(m_normals[n], normals)))) return true;
      }
    }
    return false;
  }

  /// Is one point of the net closer than r <= d to each of the points xs (rounded)? Then it
  /// is closer than r to every point of their convex hull (a ball is convex).
  bool covers_all(const std::array<Point3, 3>& xs, double r) const { return reach(xs, r) == Reach::all; }

  /// Is each of the parts of triangle xs (cut into four at its sides' midpoints, again and
  /// again, `depth` times at most) closer than r to one point of the net (covers_all())?
  /// Then so is every point of the triangle.
  bool covers_all_parts(const std::array<Point3, 3>& xs, double r, int depth) const
  {
    const Reach k = reach(xs, r);
    if (k != Reach::first || depth == 0) return k == Reach::all; // (none: xs[0] itself is not covered)
    auto mid = [&](int i, int j) { return scaled(xs[i] + xs[j], 0.5); };
    const Point3 m01 = mid(0, 1), m12 = mid(1, 2), m20 = mid(2, 0);
    return covers_all_parts({xs[0], m01, m20}, r, depth - 1) && covers_all_parts({m01, xs[1], m12}, r, depth - 1) &&
           covers_all_parts({m20, m12, xs[2]}, r, depth - 1) && covers_all_parts({m01, m12, m20}, r, depth - 1);
  }

  /// Is a point of the net that does not face x closer than d/2 to it?
  bool covers(const Point3& x, const Normals& normals = {}) const { return covers_within(x, m_d / 2, normals); }

  /// Adds x, of outward `normals`, to the net (the caller has checked that it is not
  /// covered); the normals must outlive the net.
  void insert(const Point3& x, const Normals& normals = {})
  {
    if (!m_enabled) return;
    std::uint32_t& last = m_cells.at(key(cell_of(x)));
    m_points.push_back(x);
    m_normals.push_back(normals);
    m_next.push_back(last);
    last = std::uint32_t(m_points.size() - 1);
  }

private:
  /// Is one point of the net closer than r <= d to each of the points xs (all), else one
  /// closer than r to xs[0] (first), or none?
  enum class Reach { all, first, none };
  Reach reach(const std::array<Point3, 3>& xs, double r) const
  {
    const double rr = r - m_margin;
    if (!m_enabled || m_points.empty() || !(rr > 0)) return Reach::none;
    // Cells have side d: the ball of radius r around xs[0] meets the 27 cells around its own.
    const std::array<std::int64_t, 3> c = cell_of(xs[0]);
    Reach found = Reach::none;
    for (int o = 0; o < 27; ++o) {
      const std::uint32_t first = m_cells.find(key({c[0] + o % 3 - 1, c[1] + o / 3 % 3 - 1, c[2] + o / 9 - 1}));
      for (std::uint32_t n = first; n != none; n = m_next[n]) {
        auto within = [&](const Point3& x) { return dot(x - m_points[n], x - m_points[n]) < rr * rr; };
        if (!within(xs[0])) continue;
        if (within(xs[1]) && within(xs[2])) return Reach::all;
        found = Reach::first;
      }
    }
    return found;
  }

  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  /// Cell -> last point inserted there: open addressing with linear probing (the net is
  /// queried for every candidate).
  class Cell_table
  {
  public:
    /// The value of `key`, or `none`.
    std::uint32_t find(std::uint64_t key) const
    {
      if (m_keys.empty()) return none;
      for (std::size_t i = slot(key);; i = (i + 1) & (m_keys.size() - 1)) {
        if (m_keys[i] == key) return m_values[i];
        if (m_keys[i] == empty) return none;
      }
    }
    /// The value of `key`, inserted as `none` if absent.
    std::uint32_t& at(std::uint64_t key)
    {
      if (2 * (m_size + 1) > m_keys.size()) grow();
      std::size_t i = slot(key);
      for (; m_keys[i] != key; i = (i + 1) & (m_keys.size() - 1))
        if (m_keys[i] == empty) {
          m_keys[i] = key;
          m_values[i] = none;
          ++m_size;
          break;
        }
      return m_values[i];
    }

  private:
    static constexpr std::uint64_t empty = std::numeric_limits<std::uint64_t>::max(); // keys have 63 bits
    std::size_t slot(std::uint64_t key) const
    { return std::size_t((key * 0x9E3779B97F4A7C15ull) >> 32) & (m_keys.size() - 1); }
    void grow()
    {
      std::vector<std::uint64_t> keys(m_keys.empty() ? 16 : 2 * m_keys.size(), empty);
      std::vector<std::uint32_t> values(keys.size(), none);
      keys.swap(m_keys);
      values.swap(m_values);
      for (std::size_t j = 0; j < keys.size(); ++j)
        if (keys[j] != empty) {
          std::size_t i = slot(keys[j]);
          while (m_keys[i] != empty) i = (i + 1) & (m_keys.size() - 1);
          m_keys[i] = keys[j];
          m_values[i] = values[j];
        }
    }
    std::vector<std::uint64_t> m_keys;
    std::vector<std::uint32_t> m_values;
    std::size_t m_size = 0;
  };

  std::array<std::int64_t, 3> cell_of(const Point3& x) const
  {
    return {std::int64_t(std::floor(x[0] / m_cell)), std::int64_t(std::floor(x[1] / m_cell)),
            std::int64_t(std::floor(x[2] / m_cell))};
  }
  static std::uint64_t key(const std::array<std::int64_t, 3>& c)
  {
    // 21 bits per axis after an offset: cells are unique within 2^20 cells of the origin in
    // each direction, and farther cells only share buckets (the distance test decides).
    const auto part = [](std::int64_t v) { return std::uint64_t(v + (std::int64_t(1) << 20)) & 0x1FFFFF; };
    return part(c[0]) | (part(c[1]) << 21) | (part(c[2]) << 42);
  }

  double m_d, m_scale, m_margin, m_cell;
  bool m_enabled;
  Cell_table m_cells;
  std::vector<Point3> m_points;
  std::vector<Normals> m_normals;
  std::vector<std::uint32_t> m_next; // previous point of the same cell
};

/// The greedy (d/2, d)-net of `points` in their order: the indices of the points kept.
/// For a d/2-covering of a surface by points on it, the kept points cover it within d.
inline std::vector<std::size_t> greedy_net(const std::vector<Point3>& points, double d)
{
  double scale = 0;
  for (const Point3& x : points)
    for (double c : x) scale = (std::max)(scale, std::abs(c));
  Covering_net net(d, scale);
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!net.covers(points[i])) {
      net.insert(points[i]);
      kept.push_back(i);
    }
  return kept;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_COVERING_NET_H
