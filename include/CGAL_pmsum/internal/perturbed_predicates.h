// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact perturbed predicates of the collision tests, in one place for their users: the
// CD filter (cd_filter.h, whose segment search, segment_search.h, evaluates the same
// predicates along segments of translations) and the swept-robot test of the planner
// (swept_cd.h).
//
// A point of a predicate has a position and moves by shift * delta, delta an infinitesimal
// perturbation e v_1 + e^2 v_2 + ... (a chain of directions that each user chooses, ending
// with the three axes). The orientation of four such points is affine in delta (the delta
// parts of its columns are parallel, so no product of two survives): its sign is the sign at
// delta = 0 if that is not zero, else the sign of the first non-zero g.v_i, g its gradient.
// Every evaluation is exact (exact_sign.h). With the axes in the chain no evaluated
// predicate is zero, so every configuration is generic and
//  - a segment crosses a triangle iff it crosses the triangle's plane and the three
//    orientations of the segment with the triangle's edges agree;
//  - two triangles cross iff an edge of one crosses the other;
//  - a point is inside a closed mesh iff a ray from it crosses an odd number of triangles.
// Also here: the meshes with their AABB trees (Tree_mesh) and the two tree traversals.

#ifndef CGAL_PMSUM_INTERNAL_PERTURBED_PREDICATES_H
#define CGAL_PMSUM_INTERNAL_PERTURBED_PREDICATES_H

#include <CGAL_pmsum/internal/bvh.h>
#include <CGAL_pmsum/internal/exact_sign.h>
#include <CGAL_pmsum/internal/mesh_data.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

/// AABB tree primitive: one triangle of a mesh, by index.
struct Triangle_primitive
{
  using Id = Index;
  using Point = Epick::Point_3;
  using Datum = Epick::Triangle_3;
  using Input = std::vector<std::pair<Index, Datum>>::const_iterator;

  Triangle_primitive(Input it) : m_id(it->first), m_triangle(it->second) {}
  Id id() const { return m_id; }
  const Datum& datum() const { return m_triangle; }
  Point reference_point() const { return m_triangle[0]; }

private:
  Id m_id;
  Datum m_triangle;
};

using Triangle_tree = CGAL::AABB_tree<CGAL::AABB_traits<Epick, Triangle_primitive>>;

/// A mesh with its trees, in a given frame (its coordinates, or their negation).
struct Tree_mesh
{
  const Mesh_data* mesh;
  std::vector<std::array<double, 3>> base; // coordinates in this frame
  std::vector<std::pair<Index, Epick::Triangle_3>> triangles;
  Triangle_tree tree;                      // triangles, for the rays of point-in-solid tests
  // Hierarchy of the triangles and bare edges, for surface crossings: item i < number of
  // triangles is triangle i, item number_of_triangles() + k is bare edge bare_edges[k].
  Bvh items;
  std::vector<Vec3<Interval>> normals;     // (b - a) x (c - a) of each triangle, enclosed
  CGAL::Bbox_3 closed_box;                 // bounding box of the closed components
  bool has_closed = false;
  // Ray direction of the point-in-solid test. Any direction works: a triangle parallel to
  // it is skipped, and for every other triangle the perturbed predicates are not zero.
  static constexpr std::array<double, 3> ray = {1.0, 0.7548776662466927, 0.5698402909980532};

  Tree_mesh(const Mesh_data& m, bool reflect) : mesh(&m)
  {
    for (const auto& p : m.points)
      base.push_back(reflect ? std::array<double, 3>{-p[0], -p[1], -p[2]} : p);
    auto pt = [&](Index v) { return Epick::Point_3(base[v][0], base[v][1], base[v][2]); };
    for (Index t = 0; t < m.number_of_triangles(); ++t) {
      const auto& tri = m.triangles[t];
      triangles.emplace_back(t, Epick::Triangle_3(pt(tri[0]), pt(tri[1]), pt(tri[2])));
      if (m.triangle_is_closed(t)) {
        closed_box += triangles.back().second.bbox();
        has_closed = true;
      }
    }
    {
      CGAL::Protect_FPU_rounding<true> guard;
      for (const auto& tri : m.triangles) normals.push_back(triangle_normal<Interval>(base[tri[0]], base[tri[1]], base[tri[2]]));
    }
    std::vector<CGAL::Bbox_3> boxes;
    for (const auto& t : triangles) boxes.push_back(t.second.bbox());
    for (Index e : m.bare_edges) boxes.push_back(edge_box(e));
    items = Bvh(boxes);
    if (triangles.empty()) return; // a polyline: bare edges only
    tree.insert(triangles.cbegin(), triangles.cend());
    tree.build();
  }

  /// Is item i (of `items`) a bare edge? Then it is edge bare_edges[i - number of triangles].
  bool is_edge(Index i) const { return i >= triangles.size(); }
  Index edge(Index i) const { return mesh->bare_edges[i - triangles.size()]; }

  /// Bounding box of the segment of edge e, in this frame.
  CGAL::Bbox_3 edge_box(Index e) const
  {
    const auto& a = base[mesh->edges[e].v[0]];
    const auto& b = base[mesh->edges[e].v[1]];
    return CGAL::Bbox_3(a[0], a[1], a[2], a[0], a[1], a[2]) + CGAL::Bbox_3(b[0], b[1], b[2], b[0], b[1], b[2]);
  }

};

/// AABB tree traversal along a ray from `origin` in direction `dir` (node boxes grown by
/// `margin`, for conservative double slab tests): on_primitive(id) for every triangle whose
/// box the ray meets.
template <class F>
struct Ray_traversal
{
  std::array<double, 3> origin, dir;
  double margin;
  F on_primitive;
  bool go_further() const { return true; }
  bool hits(const CGAL::Bbox_3& b) const
  {
    double tmin = 0, tmax = HUGE_VAL;
    for (int c = 0; c < 3; ++c) {
      const double lo = b.min(c) - margin, hi = b.max(c) + margin;
      if (dir[c] == 0) { if (origin[c] < lo || origin[c] > hi) return false; continue; }
      double t1 = (lo - origin[c]) / dir[c], t2 = (hi - origin[c]) / dir[c];
      if (t1 > t2) std::swap(t1, t2);
      tmin = (std::max)(tmin, t1); tmax = (std::min)(tmax, t2);
    }
    return tmin <= tmax;
  }
  template <class Query, class Primitive>
  void intersection(const Query&, const Primitive& p) { if (hits(p.datum().bbox())) on_primitive(p.id()); }
  template <class Query, class Node>
  bool do_intersect(const Query&, const Node& node) const { return hits(node.bbox()); }
};
template <class F> Ray_traversal(std::array<double, 3>, std::array<double, 3>, double, F) -> Ray_traversal<F>;

/// AABB tree traversal of the primitives whose boxes overlap `box`: on_primitive(id) for
/// each, until it returns true.
template <class F>
struct Box_traversal
{
  CGAL::Bbox_3 box;
  F on_primitive;
  bool stop = false;
  bool go_further() const { return !stop; }
  template <class Query, class Primitive>
  void intersection(const Query&, const Primitive& p)
  { if (CGAL::do_overlap(box, p.datum().bbox())) stop = on_primitive(p.id()); }
  template <class Query, class Node>
  bool do_intersect(const Query&, const Node& node) const { return CGAL::do_overlap(box, node.bbox()); }
};
template <class F> Box_traversal(CGAL::Bbox_3, F) -> Box_traversal<F>;

/// The gradient of orient3d(a, b, c, d) = det[b - a, c - a, d - a] in delta when point i
/// moves by shift[i] * delta: (sb - sa) u2 x u3 + (sc - sa) u3 x u1 + (sd - sa) u1 x u2,
/// u1 = b - a, u2 = c - a, u3 = d - a at any one delta (it is the same for all).
template <class NT>
Vec3<NT> orientation_gradient(const std::array<Vec3<NT>, 4>& p, const std::array<int, 4>& shift)
{
  const Vec3<NT> u1 = p[1] - p[0], u2 = p[2] - p[0], u3 = p[3] - p[0];
  Vec3<NT> g = {NT(0), NT(0), NT(0)};
  if (shift[1] != shift[0]) g = g + scaled(cross(u2, u3), NT(shift[1] - shift[0]));
  if (shift[2] != shift[0]) g = g + scaled(cross(u3, u1), NT(shift[2] - shift[0]));
  if (shift[3] != shift[0]) g = g + scaled(cross(u1, u2), NT(shift[3] - shift[0]));
  return g;
}

/// The perturbed predicates (see the file comment), for a user `Derived` (CRTP) whose
/// points are of type `Point`, with a member `int shift`. Derived provides:
///  - `template <class NT> Vec3<NT> position(const Point&)`: the position at delta = 0, for
///    NT = Interval (an enclosure) and NT = Exact_nt (exact, possibly times one positive
///    factor common to all points);
///  - `template <class NT> Vec3<NT> frame_position(const Point&)`: the same, or the position
///    in any other one configuration of all points (only differences enter gradients, which
///    do not depend on it), where cheaper;
///  - `template <class G> CGAL::Sign perturbation_sign(const G& g)`: the sign of the first
///    non-zero g(nt).v_i over its chain (g a generic callable, as in filtered_sign());
///  - `Point fixed_point(const std::array<double, 3>& x)`: a point of a static mesh at x.
/// It may provide `unperturbed_orientation(a, b, c, d, value)` and
/// `orientation_gradient_of<NT>(a, b, c, d)`, hiding the ones here, where it has cheaper
/// exact evaluations of the orientation at delta = 0 and of its gradient.
template <class Derived, class Point>
class Perturbed_predicates
{
public:
  /// Sign of orient3d(a, b, c, d) = det[b - a, c - a, d - a], perturbed.
  CGAL::Sign orientation(const Point& a, const Point& b, const Point& c, const Point& d)
  {
    const auto value = [&](auto nt) {
      using NT = decltype(nt);
      const Vec3<NT> pa = self().template position<NT>(a);
      return dot(self().template position<NT>(d) - pa,
                 cross(self().template position<NT>(b) - pa, self().template position<NT>(c) - pa));
    };
    const CGAL::Sign s0 = self().unperturbed_orientation(a, b, c, d, value);
    if (s0 != CGAL::ZERO) return s0;
    return self().perturbation_sign([&](auto nt) { return self().template orientation_gradient_of<decltype(nt)>(a, b, c, d); });
  }

  /// The gradient of orient3d(a, b, c, d) in delta, in NT.
  template <class NT>
  Vec3<NT> orientation_gradient_of(const Point& a, const Point& b, const Point& c, const Point& d)
  {
    return orientation_gradient<NT>({self().template frame_position<NT>(a), self().template frame_position<NT>(b),
                                     self().template frame_position<NT>(c), self().template frame_position<NT>(d)},
                                    {a.shift, b.shift, c.shift, d.shift});
  }

  /// Do the triangles A and B cross? `known`: the sides of A's points w.r.t. B's plane
  /// (orientation(B[0], B[1], B[2], A[i])) and of B's w.r.t. A's, where already known (ZERO
  /// where not: orientation() never returns it).
  bool triangles_cross(const std::array<Point, 3>& A, const std::array<Point, 3>& B,
                       const std::array<std::array<CGAL::Sign, 3>, 2>& known = {})
  {
    std::array<CGAL::Sign, 3> sa = known[0], sb = known[1]; // sides of A's points w.r.t. B's plane, and reverse
    for (int i = 0; i < 3; ++i)
      if (sa[i] == CGAL::ZERO) sa[i] = orientation(B[0], B[1], B[2], A[i]);
    if (sa[0] == sa[1] && sa[1] == sa[2]) return false;
    for (int i = 0; i < 3; ++i)
      if (sb[i] == CGAL::ZERO) sb[i] = orientation(A[0], A[1], A[2], B[i]);
    if (sb[0] == sb[1] && sb[1] == sb[2]) return false;
    return edge_crosses(A, sa, B) || edge_crosses(B, sb, A);
  }

  /// Does the segment `seg` cross the interior of triangle T?
  bool segment_crosses(const std::array<Point, 2>& seg, const std::array<Point, 3>& T)
  {
    if (orientation(T[0], T[1], T[2], seg[0]) == orientation(T[0], T[1], T[2], seg[1])) return false;
    const CGAL::Sign o1 = orientation(seg[0], seg[1], T[0], T[1]);
    return o1 == orientation(seg[0], seg[1], T[1], T[2]) && o1 == orientation(seg[0], seg[1], T[2], T[0]);
  }

  /// Can z be inside the closed components of `solid` (its box meets theirs)?
  bool may_be_inside(const Tree_mesh& solid, const Point& z)
  {
    if (!solid.has_closed) return false;
    const Vec3<Interval> x = box(z);
    const CGAL::Bbox_3& cb = solid.closed_box;
    for (int c = 0; c < 3; ++c)
      if (x[c].sup() < cb.min(c) || x[c].inf() > cb.max(c)) return false;
    return true;
  }

  /// Is z inside the closed components of `solid`? Parity of the crossings of the ray from
  /// z along solid.ray (tree nodes grown by `margin` for the double slab tests).
  bool ray_parity(const Tree_mesh& solid, const Point& z, double margin)
  {
    const Vec3<Interval> x = box(z);
    std::array<double, 3> origin;
    for (int c = 0; c < 3; ++c) origin[c] = 0.5 * (x[c].inf() + x[c].sup());
    bool odd = false;
    Ray_traversal traversal{origin, solid.ray, margin, [&](Index s) {
                              if (solid.mesh->triangle_is_closed(s) && ray_crosses(solid, s, z)) odd = !odd;
                            }};
    solid.tree.traversal(0, traversal);
    return odd;
  }

  /// Exact sign of orient3d(a, b, c, d) at delta = 0, `value` its generic expression.
  template <class F>
  CGAL::Sign unperturbed_orientation(const Point&, const Point&, const Point&, const Point&, const F& value)
  { return filtered_sign(value); }

private:
  Derived& self() { return static_cast<Derived&>(*this); }

  Vec3<Interval> box(const Point& z)
  {
    CGAL::Protect_FPU_rounding<true> guard;
    return self().template position<Interval>(z);
  }

  /// Does an edge of triangle E, whose vertices lie on sides `side` of the plane of T, cross
  /// the interior of T?
  bool edge_crosses(const std::array<Point, 3>& E, const std::array<CGAL::Sign, 3>& side, const std::array<Point, 3>& T)
  {
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (side[i] == side[j]) continue;
      const CGAL::Sign o1 = orientation(E[i], E[j], T[0], T[1]);
      const CGAL::Sign o2 = orientation(E[i], E[j], T[1], T[2]);
      if (o1 != o2) continue;
      if (orientation(E[i], E[j], T[2], T[0]) == o1) return true;
    }
    return false;
  }

  /// Does the ray z + s w, s > 0, w = solid.ray, cross triangle s of `solid`?
  bool ray_crosses(const Tree_mesh& solid, Index s, const Point& z)
  {
    const auto& tri = solid.mesh->triangles[s];
    const std::array<Point, 3> T = {self().fixed_point(solid.base[tri[0]]), self().fixed_point(solid.base[tri[1]]),
                                    self().fixed_point(solid.base[tri[2]])};
    const std::array<double, 3>& w = solid.ray;
    const CGAL::Sign toward = filtered_sign([&](auto nt) {
      using NT = decltype(nt);
      return dot(to_nt<NT>(w), triangle_normal<NT>(solid.base[tri[0]], solid.base[tri[1]], solid.base[tri[2]]));
    });
    if (toward == CGAL::ZERO) return false; // ray parallel to the plane, z (perturbed) not on it
    if (orientation(T[0], T[1], T[2], z) != -toward) return false; // z must be behind the plane
    // The line z + s w must pass through the triangle: det[w, a - z, b - z] of equal signs.
    CGAL::Sign first = CGAL::ZERO;
    for (int i = 0; i < 3; ++i) {
      const Point& a = T[i];
      const Point& b = T[(i + 1) % 3];
      CGAL::Sign si = filtered_sign([&](auto nt) {
        using NT = decltype(nt);
        const Vec3<NT> pz = self().template position<NT>(z);
        return dot(to_nt<NT>(w), cross(self().template position<NT>(a) - pz, self().template position<NT>(b) - pz));
      });
      if (si == CGAL::ZERO) // f(z) = w.(a x b) + z.(w x (b - a)): g = shift * w x (b - a)
        si = self().perturbation_sign([&](auto nt) {
          using NT = decltype(nt);
          return scaled(cross(to_nt<NT>(w), self().template frame_position<NT>(b) - self().template frame_position<NT>(a)),
                        NT(z.shift));
        });
      if (i == 0) first = si;
      else if (si != first) return false;
    }
    return true;
  }
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PERTURBED_PREDICATES_H
