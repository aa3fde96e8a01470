// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A grid of the sphere of directions, used by the normal filter to avoid testing every
// feature pair: each vertex or edge lists the cells in which it may be locally extreme, and
// only pairs sharing a cell get the exact test. The lists are supersets (every cell is
// bounded by a cone with a safety margin, and a cell is dropped only when a constraint is
// violated by every direction of that cone by a clear margin), so the exact tests keep
// exactly the pairs the brute-force loops kept.

#ifndef CGAL_PMSUM_INTERNAL_DIRECTION_GRID_H
#define CGAL_PMSUM_INTERNAL_DIRECTION_GRID_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

class Direction_grid
{
public:
  using V = std::array<double, 3>;

  /// k x k cells on each face of the cube [-1, 1]^3, projected to the sphere.
  explicit Direction_grid(int k = 8) : m_k(k)
  {
    const double pi = std::acos(-1.);
    for (int face = 0; face < 6; ++face)
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          auto dir = [&](double u, double v) { return normalized(on_face(face, u, v)); };
          const double u0 = -1 + 2. * i / k, u1 = -1 + 2. * (i + 1) / k;
          const double v0 = -1 + 2. * j / k, v1 = -1 + 2. * (j + 1) / k;
          const V a = dir((u0 + u1) / 2, (v0 + v1) / 2);
          double theta = 0;
          for (const V& c : {dir(u0, v0), dir(u0, v1), dir(u1, v0), dir(u1, v1)})
            theta = (std::max)(theta, std::acos((std::min)(1., dot3(a, c))));
          theta = (std::min)(pi, theta + 1e-6); // margin for rounding
          m_axis.push_back(a);
          m_cos.push_back(std::cos(theta));
          m_sin.push_back(std::sin(theta));
          m_wide.push_back(theta >= pi / 2);
        }
  }

  int size() const { return int(m_axis.size()); }

  /// The cell whose cone contains the direction n (not necessarily unit, not zero).
  int cell_of(const V& n) const
  {
    int face = 0;
    double m = -1;
    for (int c = 0; c < 3; ++c)
      if (std::abs(n[c]) > m) { m = std::abs(n[c]); face = 2 * c + (n[c] < 0); }
    const int axis = face / 2;
    const double u = n[(axis + 1) % 3] / m, v = n[(axis + 2) % 3] / m;
    auto index = [&](double x) { return (std::min)(m_k - 1, (std::max)(0, int(std::floor((x + 1) / 2 * m_k)))); };
    return (face * m_k + index(u)) * m_k + index(v);
  }

  /// Is u . n > 0 for every direction n of the cell's cone, by a clear margin? That is, is
  /// cos(alpha + theta) > 0, alpha being the angle of u to the cone's axis and theta < pi/2
  /// the cone's half-angle (alpha + theta < 3 pi / 2, where the cosine is negative past pi/2);
  /// by the sum formula, without inverse trigonometric functions.
  bool strictly_positive(int c, const V& u) const
  {
    const double len = std::sqrt(dot3(u, u));
    if (len == 0 || m_wide[c]) return false;
    const double cos_alpha = (std::max)(-1., (std::min)(1., dot3(u, m_axis[c]) / len));
    const double sin_alpha = std::sqrt(1 - cos_alpha * cos_alpha);
    return cos_alpha * m_cos[c] - sin_alpha * m_sin[c] > 1e-9;
  }

  /// Can the cell's cone meet the great circle orthogonal to e?
  bool meets_plane(int c, const V& e) const
  {
    const double len = std::sqrt(dot3(e, e));
    return m_wide[c] || std::abs(dot3(m_axis[c], e)) / len <= m_sin[c] + 1e-9;
  }

private:
  static double dot3(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static V normalized(const V& a)
  {
    const double l = std::sqrt(dot3(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
  }
  static V on_face(int face, double u, double v)
  {
    const int axis = face / 2;
    V p{};
    p[axis] = (face % 2) ? -1 : 1;
    p[(axis + 1) % 3] = u;
    p[(axis + 2) % 3] = v;
    return p;
  }

  int m_k;
  std::vector<V> m_axis;
  std::vector<double> m_cos, m_sin; // of each cone's half-angle theta
  std::vector<std::uint8_t> m_wide;  // theta >= pi/2
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_DIRECTION_GRID_H
