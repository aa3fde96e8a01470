// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A static tree for exact nearest-point queries over a large, fixed set of 3D points lying on a
// surface (the contact space of Penetration_depth.h).
//
// Bounds. For points on a surface queried from a distance r, the axis-aligned box of a tilted
// patch sticks out of the surface by about the patch size s, so every box within about
// sqrt(2 r s) of the foot of the query is opened (measured on 1.45M contact points: 22 leaves of
// 32 points at r = 10 d). So each node also has an oriented box in one of 256 fixed frames (128
// normals spread over a half sphere, each with two tangent pairs 45 degrees apart): the frame
// whose normal is nearest to the smallest principal axis of the node's points, so that a patch's
// box is a thin plate (7 leaves at r = 10 d). The search orders children by the cheap
// axis-aligned bound and computes the oriented one only for a subtree it is about to enter once a
// best point is known.
//
// Layout. The points are copied, reordered so that every leaf is a contiguous run of at most
// `leaf_size` points, into one flat array of doubles. A node is 32 bytes (both boxes quantized to
// 16 bits, rounded outward, a frame number, two indices), children side by side: the nodes of a
// million points take about 1.5 MB. A cache miss costs 100-400 ns on the machine measured, so
// the time of a query is mostly the number of nodes and leaves it reads that are not in cache.
//
// Exactness. nearest() returns a point whose squared distance, as computed by squared_distance(),
// is the minimum over all points of that same computation (the brute-force answer; on ties,
// possibly another point at the same distance). A subtree is skipped only when a lower bound of
// that computed distance for every point inside is >= the best one found:
// - axis-aligned box: its corners are doubles <= (>=) every coordinate inside, and the bound is
//   the same expression as squared_distance() on per-axis gaps never larger than those of a point
//   inside; IEEE rounding is monotone, so it is <= the computed distance of every point inside;
// - oriented box: the rounding of the projections is covered by a margin per axis, the frames'
//   deviation from orthonormality (checked) and the rounding of the distances by a factor.

#ifndef CGAL_PMSUM_INTERNAL_NEAREST_POINT_TREE_H
#define CGAL_PMSUM_INTERNAL_NEAREST_POINT_TREE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Squared distance between two points, computed exactly as Nearest_point_tree::nearest() does.
inline double squared_distance(const double* p, const double* q)
{
  const double a = p[0] - q[0], b = p[1] - q[1], c = p[2] - q[2];
  return a * a + b * b + c * c;
}

/// Eigenvectors of a symmetric 3x3 matrix (cyclic Jacobi; `a` is overwritten), as the rows of
/// `v`, by decreasing eigenvalue.
inline void symmetric_eigenvectors(double a[3][3], double v[3][3])
{
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v[i][j] = i == j;
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (!(off > 1e-30 * diag)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t = (theta >= 0 ? 1 : -1) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 3; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vp = v[p][k], vq = v[q][k];
          v[p][k] = c * vp - s * vq;
          v[q][k] = s * vp + c * vq;
        }
      }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] > a[j][j]; });
  double w[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) w[i][k] = v[order[i]][k];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) v[i][k] = w[i][k];
}

class Nearest_point_tree
{
public:
  static constexpr std::uint32_t leaf_size = 64;

  Nearest_point_tree() = default;

  /// Builds the tree over `n` points given by `coordinate(i, axis)` (finite doubles).
  /// \pre n < 2^32 - 1
  template <class Coordinate>
  Nearest_point_tree(std::size_t n, Coordinate coordinate)
  {
    check_frames();
    if (n == 0) return;
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<double> xyz(3 * n);
    double lo[3], hi[3], radius2 = 0;
    for (int a = 0; a < 3; ++a) { lo[a] = std::numeric_limits<double>::infinity(); hi[a] = -lo[a]; }
    for (std::size_t i = 0; i < n; ++i) {
      for (int a = 0; a < 3; ++a) {
        const double x = coordinate(i, a);
        xyz[3 * i + a] = x;
        lo[a] = (std::min)(lo[a], x);
        hi[a] = (std::max)(hi[a], x);
      }
      const double* p = &xyz[3 * i];
      radius2 = (std::max)(radius2, p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    }
    const double largest = (std::max)({-lo[0], -lo[1], -lo[2], hi[0], hi[1], hi[2]});
    // A projection f.x with |f| <= 1 + 1e-9 and |x|_inf <= largest is computed within
    // 4 * 2^-53 * (|f_0 x_0| + |f_1 x_1| + |f_2 x_2|) < 1e-15 * largest of its exact value.
    m_margin = 1e-15 * largest;
    // Quantization: axis-aligned boxes on a grid over [lo, hi], oriented ones over [-R, R]
    // (R >= every |p|, so >= every projection), 65000 steps each (and a step of slack).
    for (int a = 0; a < 3; ++a) {
      m_origin[a] = lo[a];
      m_step[a] = (std::max)(hi[a] - lo[a], 1e-300) / 65000;
    }
    m_frame_origin = -1.001 * std::sqrt(radius2) - 1e-300;
    m_frame_step = -2 * m_frame_origin / 65000;
    m_nodes.reserve(4 * (n / leaf_size + 1));
    m_nodes.emplace_back();
    build(0, order.data(), 0, std::uint32_t(n), xyz);
    m_index = order;
    m_xyz.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < 3; ++a) m_xyz[3 * i + a] = xyz[3 * order[i] + a];
  }

  std::size_t size() const { return m_index.size(); }
  bool empty() const { return m_index.empty(); }
  std::size_t number_of_nodes() const { return m_nodes.size(); }

  /// The index (in the order given to the constructor) of a point nearest to q, and its squared
  /// distance as computed by squared_distance(). \pre !empty() and q finite
  std::pair<std::size_t, double> nearest(const double* q) const
  {
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_i = 0;
    // rounding of the query's projections (see the constructor) on top of the points' margin
    const double margin = m_margin + 1e-15 * (std::max)({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
    // Depth-first, nearer child first; the stack holds the farther children with their bound.
    struct Entry { std::uint32_t node; double d2; };
    Entry stack[64];
    int top = 0;
    std::uint32_t node = 0;
    for (;;) {
      const Node& nd = m_nodes[node];
      if (nd.count != 0) { // leaf
        const double* p = &m_xyz[3 * std::size_t(nd.first)];
        for (std::uint32_t i = 0; i < nd.count; ++i, p += 3) {
          const double d2 = squared_distance(p, q);
          if (d2 < best) { best = d2; best_i = nd.first + i; }
        }
      } else {
        // children ordered by their axis-aligned bound (cheap); the oriented bound is computed
        // only for a subtree about to be entered while a best point is known
        const std::uint32_t l = nd.first, r = nd.first + 1;
        const double dl = box_bound(m_nodes[l], q), dr = box_bound(m_nodes[r], q);
        const bool left_first = dl <= dr;
        const std::uint32_t near = left_first ? l : r, far = left_first ? r : l;
        const double dn = left_first ? dl : dr, df = left_first ? dr : dl;
        if (df < best) stack[top++] = {far, df};
        if (dn < best && (best == std::numeric_limits<double>::infinity() || frame_bound(m_nodes[near], q, margin) < best)) {
          node = near;
          continue;
        }
      }
      // pop the next subtree that can still hold a nearer point
      for (;;) {
        if (top == 0) return {m_index[best_i], best};
        const Entry& e = stack[--top];
        if (e.d2 < best && frame_bound(m_nodes[e.node], q, margin) < best) { node = e.node; break; }
      }
    }
  }

private:
  struct Node
  {
    std::uint16_t lo[3], hi[3];   // axis-aligned box, quantized (see box_coordinate())
    std::uint16_t flo[3], fhi[3]; // extents of frame[k].p, quantized (see frame_coordinate())
    std::uint32_t first = 0;      // inner node: index of the left child (the right one follows); leaf: first point
    std::uint16_t count = 0;      // leaf: number of points (> 0); inner node: 0
    std::uint16_t frame = 0;      // in frames()
  };
  static_assert(sizeof(Node) == 32, "a node is 32 bytes");
  static_assert(leaf_size < 65536, "count is 16 bits");

  using Frame = std::array<std::array<double, 3>, 3>; // rows: normal, two tangents

  /// The fixed frames: for 128 normals n (Fibonacci points on the half sphere z >= 0; a normal
  /// and its opposite give the same box), u = n x e_k (k the smallest coordinate of n)
  /// normalized, v = n x u, and the same turned by 45 degrees.
  static const std::vector<Frame>& frames()
  {
    static const std::vector<Frame> table = [] {
      std::vector<Frame> t;
      const int normals = 128;
      const double pi = 3.14159265358979323846, golden = pi * (3 - std::sqrt(5.));
      for (int i = 0; i < normals; ++i) {
        const double z = 1 - (i + 0.5) / normals, r = std::sqrt(1 - z * z), a = golden * i;
        const double n[3] = {r * std::cos(a), r * std::sin(a), z};
        double u[3];
        const double ax = std::abs(n[0]), ay = std::abs(n[1]), az = std::abs(n[2]);
        if (ax <= ay && ax <= az) { u[0] = 0; u[1] = n[2]; u[2] = -n[1]; }
        else if (ay <= az) { u[0] = -n[2]; u[1] = 0; u[2] = n[0]; }
        else { u[0] = n[1]; u[1] = -n[0]; u[2] = 0; }
        const double l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (double& c : u) c /= l;
        const double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
        const double h = std::sqrt(0.5);
        Frame f0, f1;
        for (int k = 0; k < 3; ++k) {
          f0[0][k] = f1[0][k] = n[k];
          f0[1][k] = u[k];
          f0[2][k] = v[k];
          f1[1][k] = h * (u[k] + v[k]);
          f1[2][k] = h * (v[k] - u[k]);
        }
        t.push_back(f0);
        t.push_back(f1);
      }
      return t;
    }();
    return table;
  }

  // |F F^T - I| (Frobenius) <= 1e-10 for every frame: their largest singular values are <= 1 + 1e-10.
  static void check_frames()
  {
    for (const Frame& f : frames()) {
      double err = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double dot = f[i][0] * f[j][0] + f[i][1] * f[j][1] + f[i][2] * f[j][2] - (i == j);
          err += dot * dot;
        }
      if (!(err <= 1e-20)) throw std::logic_error("Nearest_point_tree: a frame is not orthonormal");
    }
  }

  // |t - p|^2 >= sum_k (frame_k.(t - p))^2 / (1 + 1e-9) for the frames checked above; 1 - 1e-12
  // covers the rounding of the computed squared distances and of the bound.
  static constexpr double safety = (1 - 1e-12) / (1 + 1e-9);

  double box_coordinate(int a, std::uint16_t i) const { return m_origin[a] + double(i) * m_step[a]; }
  double frame_coordinate(std::uint16_t i) const { return m_frame_origin + double(i) * m_frame_step; }

  // Lower bounds of squared_distance(p, q) for every point p of the node: from its axis-aligned
  // box, and from its oriented box.
  double box_bound(const Node& b, const double* q) const
  {
    double t = 0;
    for (int a = 0; a < 3; ++a) {
      const double lo = box_coordinate(a, b.lo[a]), hi = box_coordinate(a, b.hi[a]);
      const double g = q[a] < lo ? lo - q[a] : (q[a] > hi ? q[a] - hi : 0.);
      t += g * g;
    }
    return t;
  }
  double frame_bound(const Node& b, const double* q, double margin) const
  {
    const Frame& f = (*m_frames)[b.frame];
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const double x = f[k][0] * q[0] + f[k][1] * q[1] + f[k][2] * q[2];
      const double g = (std::max)({frame_coordinate(b.flo[k]) - x, x - frame_coordinate(b.fhi[k]), 0.}) - 2 * margin;
      if (g > 0) s += g * g;
    }
    return s * safety;
  }

  // An i with decode(i) <= x, and one with decode(i) >= x, one step beyond the nearest (decode()
  // is the function the queries use; decode(0) is exact: the smallest coordinate, or -1.001 R;
  // decode(65535) is above the largest). The step of slack covers a compiler that would evaluate
  // decode() differently here and in a query (e.g. contracting it to a fused multiply-add).
  template <class Decode>
  static std::uint16_t quantize_below(double x, double origin, double step, Decode decode)
  {
    double k = std::floor((x - origin) / step) - 1;
    std::uint16_t i = std::uint16_t((std::max)(0., (std::min)(65535., k)));
    while (i > 0 && decode(i) > x) --i;
    if (decode(i) > x) throw std::logic_error("Nearest_point_tree: quantization");
    return i > 0 ? i - 1 : i; // a step of slack: no reliance on decode() rounding the same way twice
  }
  template <class Decode>
  static std::uint16_t quantize_above(double x, double origin, double step, Decode decode)
  {
    double k = std::ceil((x - origin) / step) + 1;
    std::uint16_t i = std::uint16_t((std::max)(0., (std::min)(65535., k)));
    while (i < 65535 && decode(i) < x) ++i;
    if (decode(i) < x) throw std::logic_error("Nearest_point_tree: quantization");
    return i < 65535 ? i + 1 : i;
  }

  // Fills node `id` for the points order[b, e) and builds its subtree.
  void build(std::uint32_t id, std::uint32_t* order, std::uint32_t b, std::uint32_t e, const std::vector<double>& xyz)
  {
    auto point = [&](std::uint32_t i) { return &xyz[3 * std::size_t(order[i])]; };
    Node nd;
    // axis-aligned box
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) { lo[a] = std::numeric_limits<double>::infinity(); hi[a] = -lo[a]; }
    double c[3] = {0, 0, 0};
    for (std::uint32_t i = b; i < e; ++i)
      for (int a = 0; a < 3; ++a) {
        const double x = point(i)[a];
        lo[a] = (std::min)(lo[a], x);
        hi[a] = (std::max)(hi[a], x);
        c[a] += x;
      }
    for (int a = 0; a < 3; ++a) {
      auto decode = [&](std::uint16_t i) { return box_coordinate(a, i); };
      nd.lo[a] = quantize_below(lo[a], m_origin[a], m_step[a], decode);
      nd.hi[a] = quantize_above(hi[a], m_origin[a], m_step[a], decode);
      c[a] /= double(e - b);
    }
    // oriented box: the frame nearest to the principal axes (normal first)
    double cov[3][3] = {};
    for (std::uint32_t i = b; i < e; ++i) {
      const double* p = point(i);
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) cov[a][k] += (p[a] - c[a]) * (p[k] - c[k]);
    }
    double v[3][3];
    symmetric_eigenvectors(cov, v);
    auto dot = [](const std::array<double, 3>& f, const double* w) { return f[0] * w[0] + f[1] * w[1] + f[2] * w[2]; };
    double best_fit = -1;
    for (std::size_t i = 0; i < m_frames->size(); ++i) {
      const Frame& g = (*m_frames)[i];
      const double nn = dot(g[0], v[2]), t1 = dot(g[1], v[0]), t2 = dot(g[2], v[0]);
      const double fit = 4 * nn * nn + (std::max)(t1 * t1, t2 * t2);
      if (fit > best_fit) { best_fit = fit; nd.frame = std::uint16_t(i); }
    }
    const Frame& f = (*m_frames)[nd.frame];
    double flo[3], fhi[3];
    for (int k = 0; k < 3; ++k) { flo[k] = std::numeric_limits<double>::infinity(); fhi[k] = -flo[k]; }
    for (std::uint32_t i = b; i < e; ++i) {
      const double* p = point(i);
      for (int k = 0; k < 3; ++k) {
        const double x = f[k][0] * p[0] + f[k][1] * p[1] + f[k][2] * p[2];
        flo[k] = (std::min)(flo[k], x);
        fhi[k] = (std::max)(fhi[k], x);
      }
    }
    auto decode = [&](std::uint16_t i) { return frame_coordinate(i); };
    for (int k = 0; k < 3; ++k) {
      nd.flo[k] = quantize_below(flo[k], m_frame_origin, m_frame_step, decode);
      nd.fhi[k] = quantize_above(fhi[k], m_frame_origin, m_frame_step, decode);
    }
    if (e - b <= leaf_size) {
      nd.first = b;
      nd.count = std::uint16_t(e - b);
      m_nodes[id] = nd;
      return;
    }
    // split at the median of the widest axis
    int axis = 0;
    for (int a = 1; a < 3; ++a)
      if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    const std::uint32_t m = b + (e - b) / 2;
    std::nth_element(order + b, order + m, order + e, [&](std::uint32_t i, std::uint32_t j) {
      return xyz[3 * std::size_t(i) + axis] < xyz[3 * std::size_t(j) + axis];
    });
    nd.first = std::uint32_t(m_nodes.size());
    nd.count = 0;
    m_nodes[id] = nd;
    m_nodes.emplace_back();
    m_nodes.emplace_back();
    build(nd.first, order, b, m, xyz);
    build(nd.first + 1, order, m, e, xyz);
  }

  const std::vector<Frame>* m_frames = &frames();
  std::vector<Node> m_nodes;
  std::vector<double> m_xyz;          // the points, leaf by leaf
  std::vector<std::uint32_t> m_index; // their indices in the input order
  double m_margin = 0;                // rounding of the points' projections
  double m_origin[3] = {0, 0, 0}, m_step[3] = {1, 1, 1}; // quantization of the axis-aligned boxes
  double m_frame_origin = -1, m_frame_step = 1;          // and of the oriented ones
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_NEAREST_POINT_TREE_H
