// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact collision test of a robot P translating along a segment among obstacles Q (the
// local planner of Translational_motion_planner.h).
//
// The question. C = (-P) + Q is the set of translations t where P + t meets Q; a path is
// free when it never enters int(C), i.e. when it stays in the regular free space
// R^3 \ int(C) = closure of the strictly free translations (contact is allowed, sliding along
// an obstacle too). For a segment s = [a, b] we decide exactly, with a symbolic
// perturbation, whether
//     (P + s + delta) and Q are disjoint,  delta = e v_1 + e^2 v_2 + ... + e^k e_z,
// e > 0 infinitesimal, for a chain of directions (v_1, ..., then the three axes) chosen by the
// caller (the outward normals of the contact configurations at the ends). If it holds, every
// t in s is a limit of strictly free translations, so s meets no point of int(C): the segment
// is free. If s meets int(C), so does s + delta (int(C) is open): the test never accepts a
// colliding segment. It may reject a segment that only slides in contact when no single
// infinitesimal translation frees all of it (e.g. sliding in a corner that the chain's first
// direction does not open); the planner then uses other edges.
//
// How. P + s = union of P + a + lambda (b - a), lambda in [0, 1] (the swept robot). Its
// boundary is contained in the "pieces": the triangles of P + a, of P + b, and the
// parallelograms e + s of the edges e of P not parallel to b - a (two triangles each); every
// piece lies in P + s. (A point y of the boundary is x + a + lambda (b - a) with lambda
// minimal; then x is on the boundary of P, and either lambda is 0 or 1, or x is on an edge, or
// x is inside a face containing b - a, whose sweep is covered by the face at a, at b and its
// edges' parallelograms.) Every predicate is an orientation determinant of four points of
// the form base + shift * delta (base: a vertex of Q, or a vertex of P plus a or b, exactly),
// which is affine in delta; its sign is that of the first non-zero term of
// (D(0), g.v_1, g.v_2, ...), computed exactly by the predicates that the CD filter of the
// core uses too (perturbed_predicates.h). With the axes at the end of the chain no needed
// predicate is zero, so the configuration is generic and
//     (P + s + delta) meets Q  <=>  a piece crosses a triangle of Q,
//                                   or a vertex of each component of Q is in P + s + delta
//                                      (the segment q - delta - s meets P),
//                                   or a vertex of a component of P + a + delta is inside Q.
// A segment with a == b is the point test of a single translation.

#ifndef CGAL_PMSUM_INTERNAL_SWEPT_CD_H
#define CGAL_PMSUM_INTERNAL_SWEPT_CD_H

#include <CGAL_pmsum/internal/perturbed_predicates.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Counters of the segment tests.
struct Swept_cd_statistics
{
  std::size_t segment_tests = 0;    // is_free() calls with a != b
  std::size_t point_tests = 0;      // is_free() calls with a == b
  std::size_t triangle_pairs = 0;   // exact piece-triangle tests
  std::size_t containment_tests = 0;
};

/// The point *p + tsign * (*t) (t may be null), moved by shift * delta.
struct Swept_point
{
  const std::array<double, 3>* p;
  const std::array<double, 3>* t;
  int tsign;
  int shift;
};

/// Exact test "P moved along [a, b], perturbed by delta, misses Q" (see the file comment).
/// Holds its own AABB trees of P and Q; one object per thread.
class Swept_cd : Perturbed_predicates<Swept_cd, Swept_point>
{
  friend class Perturbed_predicates<Swept_cd, Swept_point>;

public:
  using Point = std::array<double, 3>;

  /// P: the robot (not negated); Q: the obstacles. Both outlive this object.
  Swept_cd(const Mesh_data& P, const Mesh_data& Q) : m_p(P, false), m_q(Q, false)
  {
    for (const Tree_mesh* tm : {&m_p, &m_q})
      for (const auto& x : tm->base) m_scale = (std::max)({m_scale, std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
  }

  const Swept_cd_statistics& statistics() const { return m_stats; }

  /// Is (P + [a, b] + delta) disjoint from Q, delta = e chain[0] + e^2 chain[1] + ... + the
  /// axes? The chain's vectors need not be unit nor non-zero (zero ones are skipped).
  bool is_free(const Point& a, const Point& b, const std::vector<Point>& chain)
  {
    m_chain.clear();
    for (const Point& v : chain)
      if (v[0] != 0 || v[1] != 0 || v[2] != 0) m_chain.push_back(v);
    for (int c = 0; c < 3; ++c) {
      Point e = {0, 0, 0};
      e[c] = 1;
      m_chain.push_back(e);
    }
    m_a = a;
    m_b = b;
    const bool moving = (a != b);
    ++(moving ? m_stats.segment_tests : m_stats.point_tests);
    const double ts = (std::max)({m_scale, std::abs(a[0]), std::abs(a[1]), std::abs(a[2]),
                                  std::abs(b[0]), std::abs(b[1]), std::abs(b[2])});
    m_margin = 4e-6 * ts;

    const Mesh_data& P = *m_p.mesh;
    const Mesh_data& Q = *m_q.mesh;
    // 1. Pieces of the swept robot against the triangles of Q.
    for (Index t = 0; t < P.number_of_triangles(); ++t) {
      const auto& tr = P.triangles[t];
      for (const Point* off : {&m_a, &m_b}) {
        if (off == &m_b && !moving) break;
        const std::array<Swept_point, 3> A = {robot(tr[0], off), robot(tr[1], off), robot(tr[2], off)};
        if (piece_hits_q(A)) return false;
      }
    }
    if (moving) {
      for (Index e = 0; e < P.number_of_edges(); ++e) {
        const Index v0 = P.edges[e].v[0], v1 = P.edges[e].v[1];
        if (parallel_to_motion(v0, v1)) continue;
        const std::array<Swept_point, 3> A1 = {robot(v0, &m_a), robot(v1, &m_a), robot(v1, &m_b)};
        const std::array<Swept_point, 3> A2 = {robot(v0, &m_a), robot(v1, &m_b), robot(v0, &m_b)};
        if (piece_hits_q(A1) || piece_hits_q(A2)) return false;
      }
    }
    // 2. A component of Q inside the swept robot: the segment q - delta - [a, b] meets P.
    for (const auto& c : Q.components) {
      const Point& q = m_q.base[c.representative_vertex];
      const Swept_point za{&q, &m_a, -1, -1}, zb{&q, &m_b, -1, -1};
      if (moving) {
        bool hit = false;
        const CGAL::Bbox_3 box = conservative_box(std::array<Swept_point, 2>{za, zb});
        Box_traversal traversal{box, [&](Index s) {
                                  ++m_stats.triangle_pairs;
                                  return hit = segment_crosses({za, zb}, triangle(m_p, s, nullptr, 0));
                                }};
        if (CGAL::do_overlap(box, m_p.tree.bbox())) m_p.tree.traversal(box, traversal);
        if (hit) return false;
      }
      if (inside(m_p, za)) return false;
    }
    // 3. A component of the swept robot inside Q: a vertex of P + a + delta inside Q.
    for (const auto& c : P.components) {
      const Swept_point z{&m_p.base[c.representative_vertex], &m_a, +1, +1};
      if (inside(m_q, z)) return false;
    }
    return true;
  }

private:
  Swept_point robot(Index v, const Point* off) const { return {&m_p.base[v], off, +1, +1}; }

  std::array<Swept_point, 3> triangle(const Tree_mesh& m, Index s, const Point* off, int shift) const
  {
    const auto& tr = m.mesh->triangles[s];
    return {Swept_point{&m.base[tr[0]], off, 1, shift}, Swept_point{&m.base[tr[1]], off, 1, shift},
            Swept_point{&m.base[tr[2]], off, 1, shift}};
  }

  // ----- the points of the perturbed predicates (perturbed_predicates.h) ----------------
  template <class NT>
  static Vec3<NT> position(const Swept_point& x)
  {
    const Vec3<NT> p = to_nt<NT>(*x.p);
    if (!x.t) return p;
    const Vec3<NT> t = to_nt<NT>(*x.t);
    return x.tsign > 0 ? p + t : p - t;
  }
  template <class NT>
  static Vec3<NT> frame_position(const Swept_point& x) { return position<NT>(x); }
  static Swept_point fixed_point(const Point& x) { return {&x, nullptr, 1, 0}; }

  /// Sign of the first non-zero g.v over the chain (its last vectors: the axes).
  template <class G>
  CGAL::Sign perturbation_sign(const G& g)
  {
    for (const Point& v : m_chain) {
      const CGAL::Sign s = filtered_sign([&](auto nt) {
        using NT = decltype(nt);
        return dot(g(nt), to_nt<NT>(v));
      });
      if (s != CGAL::ZERO) return s;
    }
    throw std::logic_error("CGAL_pmsum: a perturbed predicate of the segment test is identically zero");
  }

  /// Is the edge (v0, v1) of P parallel to b - a (exactly)?
  bool parallel_to_motion(Index v0, Index v1) const
  {
    for (int c = 0; c < 3; ++c)
      if (filtered_sign([&](auto nt) {
            using NT = decltype(nt);
            const Vec3<NT> e = to_nt<NT>(m_p.base[v1]) - to_nt<NT>(m_p.base[v0]);
            return cross(e, to_nt<NT>(m_b) - to_nt<NT>(m_a))[c];
          }) != CGAL::ZERO)
        return false;
    return true;
  }

  /// Closed box containing the points (exact positions; delta is infinitesimal), widened by
  /// one step outward.
  template <std::size_t N>
  CGAL::Bbox_3 conservative_box(const std::array<Swept_point, N>& pts) const
  {
    CGAL::Protect_FPU_rounding<true> guard;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (const Swept_point& x : pts) {
      const Vec3<Interval> v = position<Interval>(x);
      for (int c = 0; c < 3; ++c) {
        lo[c] = (std::min)(lo[c], v[c].inf());
        hi[c] = (std::max)(hi[c], v[c].sup());
      }
    }
    return CGAL::Bbox_3(std::nextafter(lo[0], -HUGE_VAL), std::nextafter(lo[1], -HUGE_VAL), std::nextafter(lo[2], -HUGE_VAL),
                        std::nextafter(hi[0], HUGE_VAL), std::nextafter(hi[1], HUGE_VAL), std::nextafter(hi[2], HUGE_VAL));
  }

  /// Does the piece A (robot points) cross a triangle of Q?
  bool piece_hits_q(const std::array<Swept_point, 3>& A)
  {
    const CGAL::Bbox_3 box = conservative_box(A);
    if (!CGAL::do_overlap(box, m_q.tree.bbox())) return false;
    bool hit = false;
    Box_traversal traversal{box, [&](Index s) {
                              ++m_stats.triangle_pairs;
                              return hit = triangles_cross(A, triangle(m_q, s, nullptr, 0));
                            }};
    m_q.tree.traversal(box, traversal);
    return hit;
  }

  bool inside(const Tree_mesh& solid, const Swept_point& z)
  {
    if (!may_be_inside(solid, z)) return false;
    ++m_stats.containment_tests;
    return ray_parity(solid, z, m_margin);
  }

  Tree_mesh m_p, m_q;
  double m_scale = 1, m_margin = 0;
  Point m_a{}, m_b{};
  std::vector<Point> m_chain;
  Swept_cd_statistics m_stats;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_SWEPT_CD_H
