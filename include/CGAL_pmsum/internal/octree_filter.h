// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A filter of the decision stage: the octree filter (paper section 6), complete.
//
// The paper floods an octree of cells of size d from seed points, so that interior regions
// are never CD-tested; seeds for "difficult" holes (voids with no vertex + vertex point)
// can be missing, and then a whole void shell is lost. We classify cells instead of
// exploring from seeds: a cell is skipped only if it is CERTIFIED to lie in the interior
// of P + Q, and every candidate of every other cell goes to the CD filter. The output is
// the same with and without this filter, for every shell, whatever its seeds.
//
// Certificate. Let B(a, r) be an open ball inside P and y a point of Q. Then the open ball
// B(a + y, r) lies in int(P) + Q, inside int(P + Q). So an axis-aligned cell with centre c
// and half-diagonal rho is interior as soon as
//     dist(c - a, Q) < r - rho     for some ball B(a, r) inside P,
// or the same with P and Q exchanged. Balls inside P: points of a grid inside P with their
// distance to the surface, thinned greedily (a discrete medial axis). Distances to Q: from
// the corners g of z's cell in a grid around Q, dist(z, Q) <= |z - s(g)| with s(g) the
// surface point nearest to g, and <= max(0, |z - g| - r(g)) when g is inside Q at distance
// r(g) from its surface. Inside/outside of grid
// points comes from exact parity along grid rows (CGAL's exact 2D orientation decides which
// triangles a row crosses, interval arithmetic bounds where); a point within such an interval
// is "unknown" and certifies nothing. Every double quantity is turned into a bound
// with a relative margin far above its rounding error, so the certificate is sound; the
// margins only make it certify a little less (never a wrong candidate skipped).
//
// What it cannot certify, at any radius: the points of int(P + Q) that lie in neither
// int(P) + Q nor P + int(Q). Where parts of a solid touch along a face or an edge, their sums
// with Q meet along planes (blocks.off, boxes touching at edges, plus a cube: the sums of two
// boxes are [0,2]x[0,2]x[0,1.5] and [2,4]x[0,2]x[0,1.5], and (2, 0.5, z) is inside the sum but
// c - q misses every open box of blocks for every q in the cube). Such a seam's points,
// and the lattice cells of the convolution facets that lie on it, are always searched.
//
// Cells form an octree over the candidates' leaf cells of size h: a node is certified as a
// whole when it can be, else its children are tried, down to the leaves.

#ifndef CGAL_PMSUM_INTERNAL_OCTREE_FILTER_H
#define CGAL_PMSUM_INTERNAL_OCTREE_FILTER_H

#include <CGAL_pmsum/internal/candidates.h>
#include <CGAL_pmsum/internal/cd_filter.h>
#include <CGAL_pmsum/internal/parallel.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

inline double distance3(const Point3& a, const Point3& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// Bounding box of the non-isolated vertices of a mesh.
inline std::pair<Point3, Point3> mesh_box(const Mesh_data& M)
{
  const double inf = std::numeric_limits<double>::infinity();
  Point3 lo = {inf, inf, inf}, hi = {-inf, -inf, -inf};
  for (Index v = 0; v < M.number_of_vertices(); ++v) {
    if (M.vertex_is_isolated(v)) continue;
    for (int c = 0; c < 3; ++c) {
      lo[c] = (std::min)(lo[c], M.points[v][c]);
      hi[c] = (std::max)(hi[c], M.points[v][c]);
    }
  }
  return {lo, hi};
}

/// A ball inside a solid: every point at distance < r from c is in its interior.
struct Inner_ball
{
  Point3 c;
  double r;
};

/// Upper bounds of the distance to one mesh (to its solid where components are closed) from
/// any point near a grid, and balls inside its closed components. See the file comment.
class Distance_grid
{
public:
  /// Grid over [lo, hi] with `resolution` points along the longest side. `tolerance` is an
  /// absolute bound far above the rounding errors of the coordinates involved.
  /// The closest points are searched in parallel if asked, and shared among the ranks of
  /// `comm` (collective) if not null.
  Distance_grid(const Mesh_data& M, const Point3& lo, const Point3& hi, int resolution, double tolerance,
                std::size_t max_balls, bool parallel, Communicator* comm)
    : m_lo(lo), m_tol(tolerance), m_box(mesh_box(M))
  {
    const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    m_s = extent / resolution;
    if (!(m_s > 0) || (M.number_of_triangles() == 0 && M.bare_edges.empty())) return;
    for (int c = 0; c < 3; ++c) m_n[c] = int(std::ceil((hi[c] - lo[c]) / m_s)) + 1;
    const std::size_t N = std::size_t(m_n[0]) * m_n[1] * m_n[2];
    m_inside.assign(N, 0);
    m_radius.assign(N, 0);

    const std::vector<std::uint8_t> state = classify(M); // 0 outside, 1 inside, 2 unknown
    // An AABB tree of the triangles, for closest points (built, with its distance search
    // tree, before going parallel).
    std::vector<std::pair<Index, Epick::Triangle_3>> triangles;
    auto vertex = [&](Index v) { return Epick::Point_3(M.points[v][0], M.points[v][1], M.points[v][2]); };
    for (Index t = 0; t < M.number_of_triangles(); ++t) {
      const auto& tri = M.triangles[t];
      triangles.emplace_back(t, Epick::Triangle_3(vertex(tri[0]), vertex(tri[1]), vertex(tri[2])));
    }
    Triangle_tree surface(triangles.cbegin(), triangles.cend());
    if (!triangles.empty()) {
      surface.accelerate_distance_queries();
      surface.closest_point(Epick::Point_3(lo[0], lo[1], lo[2]));
    }
    // More bare edges than that are ignored: distances to a subset of the mesh are upper bounds too.
    const bool few_edges = M.bare_edges.size() <= 1024;
    m_closest = map_ranges<Point3>(N, parallel, comm,
      [&](std::size_t first, std::size_t last, std::vector<Point3>& out) {
        for (std::size_t i = first; i < last; ++i) {
          const Point3 g = point(i);
          double best = std::numeric_limits<double>::infinity();
          Point3 c = g;
          if (M.number_of_triangles() > 0) {
            const Epick::Point_3 x = surface.closest_point(Epick::Point_3(g[0], g[1], g[2]));
            c = {x.x(), x.y(), x.z()};
            best = distance3(g, c);
          }
          if (few_edges)
            for (Index e : M.bare_edges) {
              const Point3 x = closest_on_segment(g, M.points[M.edges[e].v[0]], M.points[M.edges[e].v[1]]);
              if (distance3(g, x) < best) { best = distance3(g, x); c = x; }
            }
          out.push_back(c);
        }
      });
    for (std::size_t i = 0; i < N; ++i) {
      if (state[i] == 1) {
        m_inside[i] = 1;
        m_radius[i] = distance3(point(i), m_closest[i]) * (1 - 1e-9) - m_tol;
      }
    }

    // Balls: inside points by decreasing radius, skipping one almost inside a kept ball.
    std::vector<std::size_t> inside;
    for (std::size_t i = 0; i < N; ++i)
      if (m_inside[i] && m_radius[i] > 0) inside.push_back(i);
    std::sort(inside.begin(), inside.end(), [&](std::size_t a, std::size_t b) {
      return m_radius[a] != m_radius[b] ? m_radius[a] > m_radius[b] : a < b;
    });
    for (std::size_t i : inside) {
      if (m_balls.size() >= max_balls) break;
      const Point3 g = point(i);
      bool covered = false;
      for (const Inner_ball& b : m_balls)
        if (distance3(g, b.c) + m_radius[i] <= b.r + m_s) { covered = true; break; }
      if (!covered) m_balls.push_back({g, m_radius[i]});
    }
  }

  /// Is the distance from z to the mesh smaller than `bound` (surely)? Infinite outside
  /// the grid. From a grid point g near z: the ball B(g, r) inside the mesh, or the surface
  /// point closest to g, gives an upper bound.
  bool closer_than(const Point3& z, double bound) const
  {
    if (m_closest.empty() || !(bound > 0)) return false;
    // The solid lies in the mesh's box, so z is no closer than that box: this drops most of
    // the interior certificate's tries (a ball far from the other mesh) without a lookup.
    double outside = 0;
    for (int c = 0; c < 3; ++c) {
      const double e = (std::max)({m_box.first[c] - z[c], z[c] - m_box.second[c], 0.0});
      outside += e * e;
    }
    if (outside > bound * bound * (1 + 1e-9)) return false;
    std::array<int, 3> k;
    for (int c = 0; c < 3; ++c) {
      const double f = std::floor((z[c] - m_lo[c]) / m_s);
      if (!(f >= 0 && f < m_n[c] - 1)) return false;
      k[c] = int(f);
    }
    // The nearest corner of z's grid cell first, then (if it may still succeed) the others.
    int nearest = 0;
    for (int c = 0; c < 3; ++c)
      if (z[c] - (m_lo[c] + m_s * k[c]) > 0.5 * m_s) nearest |= 1 << c;
    const double diagonal = std::sqrt(3.0) * m_s;
    for (int corner = 0; corner < 8; ++corner) {
      const int bits = corner ^ nearest;
      const std::size_t i = index(k[0] + (bits & 1), k[1] + ((bits >> 1) & 1), k[2] + ((bits >> 2) & 1));
      const double u = upper_distance(z, i);
      if (u < bound) return true;
      if (corner == 0 && u - diagonal >= bound) return false;
    }
    return false;
  }

  const std::vector<Inner_ball>& balls() const { return m_balls; }

private:
  std::size_t index(int i, int j, int k) const { return (std::size_t(k) * m_n[1] + j) * m_n[0] + i; }
  Point3 point(std::size_t i) const
  {
    const std::size_t x = i % m_n[0], y = (i / m_n[0]) % m_n[1], z = i / (std::size_t(m_n[0]) * m_n[1]);
    return {m_lo[0] + m_s * double(x), m_lo[1] + m_s * double(y), m_lo[2] + m_s * double(z)};
  }

  double upper_distance(const Point3& z, std::size_t i) const
  {
    const double to_closest = distance3(z, m_closest[i]) * (1 + 1e-9) + m_tol;
    if (!m_inside[i]) return to_closest;
    const double outside_ball = distance3(z, point(i)) * (1 + 1e-9) + m_tol - m_radius[i];
    return (std::min)(to_closest, (std::max)(0.0, outside_ball));
  }

  static Point3 closest_on_segment(const Point3& p, const Point3& a, const Point3& b)
  {
    const Point3 u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double uu = dot(u, u);
    const double s = uu > 0 ? (std::min)(1.0, (std::max)(0.0, dot(w, u) / uu)) : 0.0;
    return {a[0] + s * u[0], a[1] + s * u[1], a[2] + s * u[2]};
  }

  /// Inside (1), outside (0) or unknown (2) for every grid point: parity of the crossings of
  /// closed triangles along each grid row parallel to the x axis.
  std::vector<std::uint8_t> classify(const Mesh_data& M) const
  {
    const std::size_t N = m_inside.size();
    std::vector<std::uint8_t> state(N, 0);
    bool any_closed = false;
    for (Index t = 0; t < M.number_of_triangles(); ++t) any_closed |= M.triangle_is_closed(t);
    if (!any_closed) return state;
    const std::size_t rows = std::size_t(m_n[1]) * m_n[2];
    std::vector<std::vector<std::pair<double, double>>> crossings(rows); // intervals of abscissae
    std::vector<std::uint8_t> degenerate(rows, 0);
    using P2 = Epick::Point_2;
    for (Index t = 0; t < M.number_of_triangles(); ++t) {
      if (!M.triangle_is_closed(t)) continue;
      const auto& tri = M.triangles[t];
      const Point3 &a = M.points[tri[0]], &b = M.points[tri[1]], &c = M.points[tri[2]];
      const P2 A(a[1], a[2]), B(b[1], b[2]), C(c[1], c[2]);
      auto range = [&](int axis) {
        const double lo = (std::min)({a[axis], b[axis], c[axis]}), hi = (std::max)({a[axis], b[axis], c[axis]});
        const int first = (std::max)(0, int(std::ceil((lo - m_lo[axis]) / m_s)) - 1);
        const int last = (std::min)(m_n[axis] - 1, int(std::floor((hi - m_lo[axis]) / m_s)) + 1);
        return std::make_pair(first, last);
      };
      const auto [j0, j1] = range(1);
      const auto [k0, k1] = range(2);
      const CGAL::Orientation whole = CGAL::orientation(A, B, C);
      for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j) {
          const std::size_t row = std::size_t(k) * m_n[1] + j;
          if (degenerate[row]) continue;
          const P2 p(m_lo[1] + m_s * j, m_lo[2] + m_s * k);
          const CGAL::Orientation o0 = CGAL::orientation(B, C, p), o1 = CGAL::orientation(C, A, p),
                                  o2 = CGAL::orientation(A, B, p);
          if (o0 == CGAL::COLLINEAR || o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR) {
            // On the projection of an edge (or a flat triangle): exact parity is unclear here.
            if ((o0 == CGAL::COLLINEAR || o0 == whole) && (o1 == CGAL::COLLINEAR || o1 == whole) &&
                (o2 == CGAL::COLLINEAR || o2 == whole))
              degenerate[row] = 1;
            continue;
          }
          if (o0 != o1 || o1 != o2) continue; // the row misses the triangle
          // The row crosses the triangle's interior: an interval of its abscissa, by
          // barycentric coordinates in interval arithmetic (wide for a nearly flat projection).
          CGAL::Protect_FPU_rounding<true> guard;
          const Interval wa = area2(b, c, p), wb = area2(c, a, p), wc = area2(a, b, p), w = wa + wb + wc;
          Interval x(-HUGE_VAL, HUGE_VAL);
          if (CGAL::certainly(w != 0)) x = (wa * a[0] + wb * b[0] + wc * c[0]) / w;
          crossings[row].push_back({x.inf(), x.sup()});
        }
    }
    for (std::size_t row = 0; row < rows; ++row) {
      const std::size_t base = row * m_n[0];
      if (degenerate[row]) {
        std::fill(state.begin() + base, state.begin() + base + m_n[0], 2);
        continue;
      }
      const auto& xs = crossings[row];
      for (int i = 0; i < m_n[0]; ++i) {
        const double x = m_lo[0] + m_s * i;
        std::size_t left = 0;
        bool near = false;
        for (const auto& [lo, hi] : xs) {
          if (hi < x - m_tol) ++left;
          else if (lo <= x + m_tol) near = true;
        }
        state[base + i] = near ? 2 : (left % 2 == 1 ? 1 : 0);
      }
    }
    return state;
  }

  static Interval area2(const Point3& u, const Point3& v, const Epick::Point_2& p)
  {
    return (Interval(v[1]) - u[1]) * (Interval(p.y()) - u[2]) - (Interval(v[2]) - u[2]) * (Interval(p.x()) - u[1]);
  }

  Point3 m_lo{};
  double m_s = 0, m_tol = 0;
  std::pair<Point3, Point3> m_box;     // of the mesh's vertices
  std::array<int, 3> m_n{};
  std::vector<std::uint8_t> m_inside;  // grid point inside a closed component (exact parity)
  std::vector<double> m_radius;        // inside: a lower bound of its distance to the surface
  std::vector<Point3> m_closest;       // the surface point closest to it (rounded)
  std::vector<Inner_ball> m_balls;
};

/// Certifies boxes inside int(P + Q) (file comment).
class Interior_certificate
{
public:
  /// `resolution`: grid points along the longest side of each mesh's grid.
  /// Its distance grids are made in parallel if asked, and shared among the ranks of `comm`
  /// (collective) if not null.
  Interior_certificate(const Mesh_data& P, const Mesh_data& Q, int resolution, double tolerance, bool parallel,
                       Communicator* comm)
  {
    const auto bp = mesh_box(P), bq = mesh_box(Q);
    // A ball inside X fits in X's box: its radius is at most half the box's smallest side.
    auto max_radius = [](const std::pair<Point3, Point3>& b) {
      return 0.5 * (std::min)({b.second[0] - b.first[0], b.second[1] - b.first[1], b.second[2] - b.first[2]});
    };
    auto grown = [](std::pair<Point3, Point3> b, double r) {
      for (int c = 0; c < 3; ++c) { b.first[c] -= r; b.second[c] += r; }
      return b;
    };
    const auto gp = grown(bp, max_radius(bq)), gq = grown(bq, max_radius(bp));
    m_p.emplace(P, gp.first, gp.second, resolution, tolerance, max_balls, parallel, comm);
    m_q.emplace(Q, gq.first, gq.second, resolution, tolerance, max_balls, parallel, comm);
  }

  /// The balls that last certified a query, on each side, tried first by the next query
  /// given the same hint (neighbouring queries are often certified by the same ball). The
  /// answer does not depend on it.
  struct Hint
  {
    std::array<std::uint32_t, 2> last = {0, 0};
  };

  /// Is every point within distance rho of c inside int(P + Q)?
  bool certifies(const Point3& c, double rho, Hint* hint = nullptr) const
  {
    return certifies(c, rho, m_p->balls(), *m_q, hint ? &hint->last[0] : nullptr) ||
           certifies(c, rho, m_q->balls(), *m_p, hint ? &hint->last[1] : nullptr);
  }

  bool can_certify() const { return !m_p->balls().empty() || !m_q->balls().empty(); }

  /// The largest radius of a ball inside P or Q (0 if none).
  double largest_ball() const
  {
    double r = 0;
    for (const auto* g : {&*m_p, &*m_q})
      if (!g->balls().empty()) r = (std::max)(r, g->balls().front().r);
    return r;
  }

private:
  /// Does a ball of `balls` certify the query, `last` (if given, the index of the ball tried
  /// first) updated to it?
  static bool certifies(const Point3& c, double rho, const std::vector<Inner_ball>& balls, const Distance_grid& other,
                        std::uint32_t* last)
  {
    auto holds = [&](const Inner_ball& b) {
      return other.closer_than({c[0] - b.c[0], c[1] - b.c[1], c[2] - b.c[2]}, b.r - rho);
    };
    if (last && *last < balls.size() && balls[*last].r > rho && holds(balls[*last])) return true;
    for (std::size_t i = 0; i < balls.size(); ++i) { // by decreasing radius
      if (balls[i].r <= rho) return false;
      if (!holds(balls[i])) continue;
      if (last) *last = std::uint32_t(i);
      return true;
    }
    return false;
  }

  static constexpr std::size_t max_balls = 256;
  std::optional<Distance_grid> m_p, m_q;
};

/// The candidates' leaf cells of size h and the certified ones.
class Octree_filter
{
public:
  using Key = std::uint64_t;

  /// Leaf cells of size h over the box [lo, hi] of the candidates. Disabled (certifies
  /// nothing) when h is too small for 21-bit cell coordinates or for the double accuracy.
  Octree_filter(const Interior_certificate& cert, const Point3& lo, const Point3& hi, double h, double tolerance)
    : m_cert(&cert), m_h(h), m_tol(tolerance)
  {
    for (int c = 0; c < 3; ++c) m_origin[c] = lo[c] - h;
    double extent = 0;
    for (int c = 0; c < 3; ++c) extent = (std::max)(extent, hi[c] - lo[c] + 2 * h);
    m_enabled = cert.can_certify() && h > 0 && extent / h < double(1 << 20) && tolerance < 1e-3 * h;
  }

  bool enabled() const { return m_enabled; }

  /// The leaf of x, unless x is within the rounding margin of a cell face (then no leaf:
  /// the candidate is always tested).
  std::optional<Key> leaf(const Point3& x) const
  {
    if (!m_enabled) return std::nullopt;
    std::array<Key, 3> cell;
    for (int c = 0; c < 3; ++c) {
      const double f = grid(x[c], c);
      const double floor = std::floor(f);
      const double margin = m_tol / m_h;
      if (!in_grid(floor) || f - floor < margin || floor + 1 - f < margin) return std::nullopt;
      cell[c] = Key(floor);
    }
    return key(cell[0], cell[1], cell[2]);
  }

  /// Certifies the given leaves (sorted, unique), top-down over the octree levels, in
  /// parallel if asked, shared among the ranks of `comm` (collective) if not null.
  /// @pre `alive` is sorted and holds no key twice
  void certify(std::vector<Key> alive, bool parallel, Communicator* comm)
  {
    CGAL_precondition(std::adjacent_find(alive.begin(), alive.end(), std::greater_equal<Key>()) == alive.end());
    m_leaves = alive.size();
    m_certified.clear();
    if (!m_enabled || alive.empty()) return;
    Key all = 0;
    for (Key k : alive) all |= k;
    int top = 0; // the level of the root, the one node holding every leaf
    while (node(all, top) != 0) ++top;
    for (int level = top; level >= 0 && !alive.empty(); --level) {
      // The nodes of the level, in the order of the leaves: a node's key is a prefix of its
      // leaves' keys, so they come sorted, and equal nodes consecutive.
      std::vector<Key> unique;
      for (Key k : alive)
        if (unique.empty() || unique.back() != node(k, level)) unique.push_back(node(k, level));
      const double size = m_h * double(Key(1) << level);
      // The candidates of a leaf are in it up to the leaf margin; centres are rounded.
      const double rho = 0.5 * std::sqrt(3.0) * (size + 2 * m_tol) * (1 + 1e-9) + m_tol;
      const std::vector<std::uint8_t> ok = map_ranges<std::uint8_t>(unique.size(), parallel, comm,
        [&](std::size_t first, std::size_t last, std::vector<std::uint8_t>& out) {
          Interior_certificate::Hint hint;
          for (std::size_t i = first; i < last; ++i) {
            Point3 c;
            for (int a = 0; a < 3; ++a) c[a] = m_origin[a] + size * (double(coordinate(unique[i], a)) + 0.5);
            out.push_back(m_cert->certifies(c, rho, &hint));
          }
        });
      std::vector<Key> next;
      std::size_t u = 0;
      for (Key k : alive) {
        while (unique[u] != node(k, level)) ++u;
        (ok[u] ? m_certified : next).push_back(k);
      }
      alive.swap(next);
    }
    std::sort(m_certified.begin(), m_certified.end());
  }

  bool certified(const Point3& x) const { return bool(certified_leaf(x)); }

  /// Is every leaf cell that the box [lo, hi], grown by the rounding margin, meets certified?
  /// Then the box is inside the sum. (False for boxes over more than 512 cells.)
  bool certifies_box(const Point3& lo, const Point3& hi) const
  {
    if (!m_enabled || m_certified.empty()) return false;
    std::array<Key, 3> first, last;
    for (int c = 0; c < 3; ++c) {
      const double a = std::floor(grid(lo[c] - m_tol, c)), b = std::floor(grid(hi[c] + m_tol, c));
      if (!(in_grid(a) && in_grid(b) && b - a < 8)) return false;
      first[c] = Key(a);
      last[c] = Key(b);
    }
    for (Key i = first[0]; i <= last[0]; ++i)
      for (Key j = first[1]; j <= last[1]; ++j)
        for (Key k = first[2]; k <= last[2]; ++k)
          if (!std::binary_search(m_certified.begin(), m_certified.end(), key(i, j, k))) return false;
    return true;
  }

  /// Is the ball of centre c and radius rho (doubles, within the rounding margin) inside the
  /// sum? The certificate's own test, where no leaf is needed.
  bool certifies_ball(const Point3& c, double rho, Interior_certificate::Hint* hint = nullptr) const
  { return m_enabled && m_cert->certifies(c, rho * (1 + 1e-9) + 2 * m_tol, hint); }

  /// The leaf of x if it is certified (a convex cell inside the sum).
  std::optional<Key> certified_leaf(const Point3& x) const
  {
    const std::optional<Key> k = leaf(x);
    if (k && std::binary_search(m_certified.begin(), m_certified.end(), *k)) return k;
    return std::nullopt;
  }

  std::size_t number_of_leaves() const { return m_leaves; }
  std::size_t number_of_certified_leaves() const { return m_certified.size(); }

private:
  // A cell's key interleaves the bits of its three 21-bit coordinates (Morton order): bit b
  // of coordinate c is bit 3b + c of the key. So the key of a cell's parent is the key
  // shifted by 3 bits, and the cells of a node have consecutive keys.
  static Key key(Key i, Key j, Key k) { return spread(i) | (spread(j) << 1) | (spread(k) << 2); }
  static Key coordinate(Key key, int c) { return compact(key >> c); }
  /// The 21 low bits of x moved to the bits 0, 3, 6, ..., 60.
  static Key spread(Key x)
  {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffff;
    x = (x | x << 16) & 0x1f0000ff0000ff;
    x = (x | x << 8) & 0x100f00f00f00f00f;
    x = (x | x << 4) & 0x10c30c30c30c30c3;
    return (x | x << 2) & 0x1249249249249249;
  }
  /// The inverse of spread: the bits 0, 3, 6, ..., 60 of x as a 21-bit number.
  static Key compact(Key x)
  {
    x &= 0x1249249249249249;
    x = (x ^ (x >> 2)) & 0x10c30c30c30c30c3;
    x = (x ^ (x >> 4)) & 0x100f00f00f00f00f;
    x = (x ^ (x >> 8)) & 0x1f0000ff0000ff;
    x = (x ^ (x >> 16)) & 0x1f00000000ffff;
    return (x ^ (x >> 32)) & 0x1fffff;
  }
  static bool in_grid(double cell) { return cell >= 0 && cell < double(1 << 21); }
  /// Coordinate x along axis c in units of leaf cells from the grid's origin.
  double grid(double x, int c) const { return (x - m_origin[c]) / m_h; }
  /// The key of the node of `level` (0: the leaves) that holds the leaf.
  static Key node(Key leaf, int level) { return leaf >> (3 * level); }

  const Interior_certificate* m_cert;
  Point3 m_origin{};
  double m_h, m_tol;
  bool m_enabled = false;
  std::vector<Key> m_certified;
  std::size_t m_leaves = 0;
};

/// The octree filter's settings: a tolerance far above the rounding errors of the doubles
/// of a sum of P and Q at covering distance d, and the box of the sum.
struct Octree_settings
{
  Point3 lo, hi;
  double tolerance;
  Octree_settings(const Mesh_data& mp, const Mesh_data& mq, double d)
  {
    const auto bp = mesh_box(mp), bq = mesh_box(mq);
    double scale = d;
    for (int c = 0; c < 3; ++c) {
      lo[c] = bp.first[c] + bq.first[c];
      hi[c] = bp.second[c] + bq.second[c];
      scale = (std::max)({scale, std::abs(bp.first[c]), std::abs(bp.second[c]), std::abs(bq.first[c]),
                          std::abs(bq.second[c]), std::abs(lo[c]), std::abs(hi[c])});
    }
    tolerance = 1e-9 * scale;
  }
  /// Grids of about candidates / 8 points each (between 12^3 and 64^3): their set-up costs
  /// about as much as testing a tenth of the candidates would.
  static int certificate_resolution(std::size_t candidates)
  { return int(std::clamp(std::cbrt(double(candidates) / 8), 12.0, 64.0)); }
};

/// The octree filter of one level: the leaves holding the candidates of `pairs`, of size d
/// as in the paper but small enough for the certificate's balls, certified. Empty if it
/// cannot certify anything. In parallel if asked, shared among the ranks of `comm`
/// (collective) if not null.
inline std::optional<Octree_filter> make_level_octree(const Interior_certificate& certificate,
                                                      const Octree_settings& settings, const Candidate_pairs& pairs,
                                                      const Mesh_sampling& sp, const Mesh_sampling& sq, double d,
                                                      bool parallel, Communicator* comm)
{
  const double leaf = std::clamp(certificate.largest_ball() / 4, d / 8, d);
  std::optional<Octree_filter> octree(std::in_place, certificate, settings.lo, settings.hi, leaf, settings.tolerance);
  if (!octree->enabled() || pairs.pairs.empty()) return std::nullopt;
  // The leaves holding candidates, by chunks of pairs.
  std::vector<Octree_filter::Key> all = map_ranges<Octree_filter::Key>(pairs.pairs.size(), parallel, comm,
    [&](std::size_t first, std::size_t last, std::vector<Octree_filter::Key>& out) {
      Pair_candidates candidates;
      for (std::size_t i = first; i < last; ++i) {
        candidates.load(sp, sq, pairs.pairs[i], true);
        const std::size_t before = out.size();
        candidates.for_each([&](std::size_t ip, std::size_t iq) {
          if (auto k = octree->leaf(candidates.position(ip, iq))) out.push_back(*k);
        });
        std::sort(out.begin() + before, out.end());
        out.erase(std::unique(out.begin() + before, out.end()), out.end());
      }
    });
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  octree->certify(std::move(all), parallel, comm);
  return octree;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_OCTREE_FILTER_H
