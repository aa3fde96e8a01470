// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangles of a mesh grouped into convex planar patches, for the island search
// (island_search.h): a patch is a set of triangles joined through edges whose two triangles
// are exactly coplanar and face the same way, whose union is a convex polygon.
//
// Why: the island search drops a piece of a lattice cell when one pair of items certainly
// crosses on all of it. Where a face of P or of Q is cut into several triangles (a box's
// square faces into two), the crossing sets of the triangle pairs meet along the diagonals,
// and no single triangle pair covers a piece of the cell across such a seam: those pieces
// stay, halving after halving, and their lines are searched. The crossing set of two convex
// planar patches A and B, the translations t at which A + t and B cross (B - A, open), is
// the union of their triangles' crossing sets and the seams between them, and it is convex
// (a Minkowski difference of convex sets): one pair covers what those did together. Every
// translation in it is a collision: A + t and B meet in their relative interiors,
// transversally (an open set of translations), and near such a point the surface of each
// solid is that one plane, the solid on one side, so the interiors overlap.
//
// A patch is grown from a triangle (lowest index first) by the triangles across its border
// edges, while the union stays convex (exact orientations, in the coordinate plane the
// patch's normal is most aligned with). Its corners are kept in order with those where the
// border goes straight on (they are the ends of border edges), so its slabs are those of a
// triangle pair when nothing merges. At most max_corners corners: the crossing set of two
// patches has 2 + (edge directions of A) x (edge directions of B) slabs.

#ifndef CGAL_PMSUM_INTERNAL_CONVEX_PATCHES_H
#define CGAL_PMSUM_INTERNAL_CONVEX_PATCHES_H

#include <CGAL_pmsum/internal/exact_sign.h>
#include <CGAL_pmsum/internal/mesh_data.h>
#include <CGAL_pmsum/internal/planar_patches.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// The convex planar patches of a mesh's triangles (see the file comment).
struct Convex_patches
{
  static constexpr std::size_t max_corners = 6;

  struct Patch
  {
    std::vector<Index> corners;              // in order around the patch
    std::vector<std::array<Index, 2>> edges; // one border edge per direction (from, to)
    std::vector<Index> triangles;            // its triangles; the patch's normal is the first's
  };

  std::vector<Index> of; // the patch of each triangle
  std::vector<Patch> patches;

  /// The patches of the triangles of m, in coordinates `points` (m's, or their negation).
  Convex_patches(const Mesh_data& m, const std::vector<std::array<double, 3>>& points)
  {
    of.assign(m.number_of_triangles(), no_index);
    for (Index t = 0; t < m.number_of_triangles(); ++t)
      if (of[t] == no_index) grow(m, points, t);
  }

private:
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;

  /// The patch that starts with triangle t.
  void grow(const Mesh_data& m, const std::vector<std::array<double, 3>>& points, Index t)
  {
    const Index id = Index(patches.size());
    of[t] = id;
    const auto& tri = m.triangles[t];
    Patch patch{{tri[0], tri[1], tri[2]}, {}, {t}};
    std::vector<Index> owner = {t, t, t}; // the triangle of each border edge (corner i to i + 1)
    auto corners = [&](Index f) -> planar_patches::Corners {
      const auto& c = m.triangles[f];
      return {points[c[0]], points[c[1]], points[c[2]]};
    };
    // The coordinate plane the normal is most aligned with, and the orientation of the
    // patch's triangles there (exact): the sign of the normal's component off that plane.
    const auto axis = planar_patches::projection_axis(points[tri[0]], points[tri[1]], points[tri[2]]);
    const int drop = axis ? axis->first : 0;
    const CGAL::Orientation sense = axis ? axis->second : CGAL::COLLINEAR;
    auto p2 = [&](Index v) { return K::Point_2(points[v][(drop + 1) % 3], points[v][(drop + 2) % 3]); };
    auto turn = [&](Index a, Index b, Index c) { return CGAL::orientation(p2(a), p2(b), p2(c)); };
    auto reflex = [&](Index a, Index b, Index c) { const CGAL::Orientation o = turn(a, b, c); return o != CGAL::COLLINEAR && o != sense; };
    for (bool grown = sense != CGAL::COLLINEAR; grown;) {
      grown = false;
      const std::size_t k = patch.corners.size();
      for (std::size_t i = 0; i < k && k < max_corners && !grown; ++i) {
        const Index a = patch.corners[i], b = patch.corners[(i + 1) % k];
        const Index u = owner[i];
        Index e = no_index;
        for (int j = 0; j < 3; ++j)
          if (m.triangles[u][j] == a) e = m.triangle_edges[u][j];
        const Mesh_data::Edge& edge = m.edges[e];
        const Index w = edge.f[0] == u ? edge.f[1] : edge.f[0];
        if (w == no_index || of[w] != no_index) continue;
        const Index d = m.opposite_vertex(w, e);
        // coplanar, facing the same way, keeping the union convex
        if (!planar_patches::flat_neighbours(corners(u), corners(w), points[d])) continue;
        const Index before = patch.corners[(i + k - 1) % k], after = patch.corners[(i + 2) % k];
        if (reflex(before, a, d) || reflex(d, b, after)) continue;
        of[w] = id;
        patch.triangles.push_back(w);
        patch.corners.insert(patch.corners.begin() + std::ptrdiff_t(i) + 1, d);
        owner[i] = w;
        owner.insert(owner.begin() + std::ptrdiff_t(i) + 1, w);
        grown = true;
      }
    }
    // One border edge per direction (exact; intervals decide nearly every pair of directions).
    auto parallel = [&](const std::array<Index, 2>& e, const std::array<Index, 2>& f) {
      for (int c = 0; c < 3; ++c)
        if (filtered_sign([&](auto nt) {
              using NT = decltype(nt);
              return cross(to_nt<NT>(points[e[1]]) - to_nt<NT>(points[e[0]]), to_nt<NT>(points[f[1]]) - to_nt<NT>(points[f[0]]))[c];
            }) != CGAL::ZERO)
          return false;
      return true;
    };
    const std::size_t k = patch.corners.size();
    for (std::size_t i = 0; i < k; ++i) {
      const std::array<Index, 2> e = {patch.corners[i], patch.corners[(i + 1) % k]};
      if (std::none_of(patch.edges.begin(), patch.edges.end(), [&](const std::array<Index, 2>& f) { return parallel(e, f); }))
        patch.edges.push_back(e);
    }
    patches.push_back(std::move(patch));
  }
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_CONVEX_PATCHES_H
