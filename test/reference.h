// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact reference answers for Minkowski sums whose operands are unions of convex pieces:
// (A1 u A2 u ...) + (B1 u B2 u ...) is the union of the convex hulls of the vertex sums
// Ai + Bj. The tests decide exactly whether an output point is on the boundary of that
// union, and measure how well the output covers it.

#ifndef CGAL_PMSUM_TEST_REFERENCE_H
#define CGAL_PMSUM_TEST_REFERENCE_H

#include "shapes.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace pmsum_shapes {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using IK = CGAL::Exact_predicates_inexact_constructions_kernel;

/// One exact convex polytope (full-dimensional or flat), as its hull's triangles.
struct Exact_convex
{
  std::vector<std::array<EK::Point_3, 3>> facets; // outward, when full-dimensional
  std::vector<EK::Point_3> vertices;
  std::vector<std::array<double, 4>> planes; // rounded unit outward normals and offsets
  bool flat = false;

  explicit Exact_convex(const std::vector<EK::Point_3>& ep)
  {
    CGAL::Surface_mesh<EK::Point_3> hull;
    // coplanar input: convex_hull_3 makes a polygon; keep its triangles (both sides count)
    CGAL::convex_hull_3(ep.begin(), ep.end(), hull);
    for (auto v : hull.vertices()) vertices.push_back(hull.point(v));
    for (auto f : hull.faces()) {
      std::array<EK::Point_3, 3> t;
      int i = 0;
      for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) if (i < 3) t[i++] = hull.point(v);
      facets.push_back(t);
    }
    for (const auto& t : facets) {
      auto dbl = [](const EK::Point_3& p) { return IK::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())); };
      const IK::Point_3 a = dbl(t[0]);
      IK::Vector_3 n = CGAL::cross_product(dbl(t[1]) - a, dbl(t[2]) - a);
      n = n / std::sqrt(n.squared_length());
      planes.push_back({n.x(), n.y(), n.z(), -(n * (a - CGAL::ORIGIN))});
    }
    flat = CGAL::coplanar(vertices[0], vertices[1], vertices[2], vertices.back());
    if (flat) {
      for (std::size_t i = 3; i < vertices.size() && flat; ++i)
        flat = CGAL::coplanar(vertices[0], vertices[1], vertices[2], vertices[i]);
    }
  }

  /// -1 strictly inside, 0 on the boundary, +1 outside (flat pieces: 0 on, +1 off).
  int locate(const EK::Point_3& x) const
  {
    if (flat) {
      if (!CGAL::coplanar(facets[0][0], facets[0][1], facets[0][2], x)) return 1;
      for (const auto& t : facets) {
        // inside the triangle t (coplanar): project to the triangle's plane
        const EK::Plane_3 pl(t[0], t[1], t[2]);
        const auto a = pl.to_2d(t[0]), b = pl.to_2d(t[1]), c = pl.to_2d(t[2]), p = pl.to_2d(x);
        if (CGAL::Triangle_2<EK>(a, b, c).bounded_side(p) != CGAL::ON_UNBOUNDED_SIDE) return 0;
      }
      return 1;
    }
    bool on = false;
    for (const auto& t : facets) {
      const CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2], x);
      if (o == CGAL::POSITIVE) return 1; // outside: on the outer side of an outward facet
      on |= (o == CGAL::COPLANAR);
    }
    return on ? 0 : -1;
  }

  /// For x strictly inside (full-dimensional pieces): its distance to the boundary, the
  /// smallest distance to a facet plane. Nothing otherwise.
  std::optional<double> depth(const EK::Point_3& x) const
  {
    if (flat || locate(x) >= 0) return std::nullopt;
    double m = HUGE_VAL;
    for (const auto& t : facets)
      m = (std::min)(m, std::sqrt(CGAL::to_double(CGAL::squared_distance(EK::Plane_3(t[0], t[1], t[2]), x))));
    return m;
  }
};

/// The union of convex polytopes, given by the vertex sums of every pair of pieces.
struct Reference
{
  struct Exact_box { std::array<EK::FT, 3> min, max; };
  std::vector<Exact_convex> pieces;
  std::vector<Exact_box> boxes; // when every piece is an axis-aligned box: exact interior test

  Reference(const Soup& P, const Soup& Q, bool negate_p = false)
  {
    const EK::FT sign(negate_p ? -1 : 1);
    for (const auto& a : P.convex_pieces)
      for (const auto& b : Q.convex_pieces) {
        std::vector<EK::Point_3> sums; // exact: double sums would round
        for (const auto& p : a)
          for (const auto& q : b)
            sums.emplace_back(sign * p[0] + q[0], sign * p[1] + q[1], sign * p[2] + q[2]);
        pieces.emplace_back(sums);
      }
    if (!negate_p && P.boxes.size() == P.convex_pieces.size() && Q.boxes.size() == Q.convex_pieces.size())
      for (const auto& a : P.boxes)
        for (const auto& b : Q.boxes) {
          Exact_box e;
          for (int c = 0; c < 3; ++c) {
            e.min[c] = EK::FT(a.min[c]) + b.min[c];
            e.max[c] = EK::FT(a.max[c]) + b.max[c];
          }
          boxes.push_back(e);
        }
  }

  /// Is x exactly on the boundary of the union? For unions of boxes the test is complete
  /// (x is interior iff every open octant around x is covered by a box containing x). For
  /// other unions it checks x is in the union and in no piece's interior, which is exact
  /// except on faces where pieces abut without overlapping.
  bool on_boundary(const EK::Point_3& x) const
  {
    if (!boxes.empty()) {
      bool in = false;
      bool covered[8] = {};
      const EK::FT xs[3] = {x.x(), x.y(), x.z()};
      for (const Exact_box& b : boxes) {
        bool inside = true;
        for (int c = 0; c < 3 && inside; ++c) inside = b.min[c] <= xs[c] && xs[c] <= b.max[c];
        if (!inside) continue;
        in = true;
        for (int s = 0; s < 8; ++s) {
          bool cov = true;
          for (int c = 0; c < 3 && cov; ++c)
            cov = (s >> c & 1) ? xs[c] < b.max[c] : xs[c] > b.min[c];
          covered[s] |= cov;
        }
      }
      return in && !std::all_of(covered, covered + 8, [](bool b) { return b; });
    }
    bool in = false;
    for (const auto& p : pieces) {
      const int l = p.locate(x);
      if (l < 0) return false;
      in |= (l == 0);
    }
    return in;
  }

  /// Points on the boundary of the union, at spacing <= `spacing` on every facet of every
  /// piece (inexact positions: these are for measuring coverage, not exactness).
  std::vector<IK::Point_3> boundary_samples(double spacing) const
  {
    std::vector<IK::Point_3> out;
    for (const auto& piece : pieces)
      for (const auto& t : piece.facets) {
        const IK::Point_3 a(CGAL::to_double(t[0].x()), CGAL::to_double(t[0].y()), CGAL::to_double(t[0].z()));
        const IK::Point_3 b(CGAL::to_double(t[1].x()), CGAL::to_double(t[1].y()), CGAL::to_double(t[1].z()));
        const IK::Point_3 c(CGAL::to_double(t[2].x()), CGAL::to_double(t[2].y()), CGAL::to_double(t[2].z()));
        const double longest = std::sqrt((std::max)({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c),
                                                     CGAL::squared_distance(c, a)}));
        const int n = (std::max)(1, int(std::ceil(longest / spacing)));
        for (int i = 0; i <= n; ++i)
          for (int j = 0; i + j <= n; ++j) {
            const double u = double(i) / n, v = double(j) / n;
            const IK::Point_3 x = a + u * (b - a) + v * (c - a);
            if (on_boundary_approx(x)) out.push_back(x);
          }
      }
    return out;
  }

private:
  /// Boundary test for sample points (rounded): not strictly inside any piece by more than
  /// a relative 1e-9, and for boxes, not interior to the union.
  bool on_boundary_approx(const IK::Point_3& x) const
  {
    if (!boxes.empty()) {
      const EK::Point_3 ex(x.x(), x.y(), x.z());
      return on_boundary(ex);
    }
    for (const auto& p : pieces) {
      if (p.flat) continue;
      bool deep = true;
      for (const auto& h : p.planes)
        if (h[0] * x.x() + h[1] * x.y() + h[2] * x.z() + h[3] > -1e-9) { deep = false; break; }
      if (deep) return false;
    }
    return true;
  }
};

/// Largest distance from a sample to the nearest output point (infinity if no output).
inline double coverage_distance(const std::vector<IK::Point_3>& samples, const std::vector<IK::Point_3>& output)
{
  using Traits = CGAL::Search_traits_3<IK>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  if (output.empty()) return std::numeric_limits<double>::infinity();
  Search::Tree tree(output.begin(), output.end());
  double worst = 0;
  for (const auto& s : samples) {
    Search search(tree, s, 1);
    worst = (std::max)(worst, std::sqrt(search.begin()->second));
  }
  return worst;
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_TEST_REFERENCE_H
