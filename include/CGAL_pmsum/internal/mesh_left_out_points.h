// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The last repair of the mesh stage: output points that the reconstruction left out (or that
// a repair cut away) are put back as vertices, each splitting the triangle nearest to it in
// three (a low tent from the triangle to the point). Every point lies on the exact boundary
// and the covering's bound on the boundary's distance to the mesh is d' + e, e the largest
// distance from a point to the mesh (point_minkowski_sum_mesh.h): a point put back no longer
// counts in e, and at a sharp corner that the advancing front cut off, the tent puts the
// corner back. A point on a side of its nearest triangle (up to rounding: a crease point between
// two vertices of the crease) stays out: it is on the mesh, and its tent would be a sliver. A
// tent that crosses the mesh (CGAL's self_intersections()) is taken down again, and none is
// raised that would join the points of two parts of the sum (Sum_parts): the mesh stays as
// valid as it was. A point whose nearest triangle is of another part goes into the nearest
// triangle of its own part within d' (there can be one a little farther: the plates turned
// plus a small cube at 2% left a part's points up to 0.94 d from the mesh beside another
// part's triangles, the exact boundary 1.03 d from the mesh; all put back, 0.69 d).

#ifndef CGAL_PMSUM_INTERNAL_MESH_LEFT_OUT_POINTS_H
#define CGAL_PMSUM_INTERNAL_MESH_LEFT_OUT_POINTS_H

#include <CGAL_pmsum/internal/mesh_reconstruction.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Takes down every tent (`tent_of`: its new vertex -> its point, the point then added to
/// `refused`) with a triangle that crosses another triangle of `mesh` or is degenerate, until
/// none does: a tent taken down brings back a triangle that was not tested against the others.
template <class ConcurrencyTag, class TriangleMesh, class Tents>
void take_down_crossing_tents(TriangleMesh& mesh, Tents& tent_of, std::unordered_set<std::size_t>& refused)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const vertex_descriptor none = boost::graph_traits<TriangleMesh>::null_vertex();
  auto tent_at = [&](face_descriptor f) {
    for (auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      if (tent_of.count(target(h, mesh))) return target(h, mesh);
    return none;
  };
  for (bool crossed = true; crossed && !tent_of.empty();) {
    // Only the tents' triangles can cross (the others did not).
    const auto pairs = crossings_near<ConcurrencyTag>(mesh, [&](face_descriptor f) { return tent_at(f) != none; });
    crossed = !pairs.empty();
    std::set<vertex_descriptor> down; // (ordered: the pairs' order varies with threads, and so would the slots the mesh reuses)
    for (const auto& [a, b] : pairs)
      for (face_descriptor f : {a, b})
        if (const vertex_descriptor v = tent_at(f); v != none) down.insert(v);
    if (crossed && down.empty()) // (the mesh had no crossing: not expected) all of them
      for (const auto& [v, i] : tent_of) down.insert(v);
    for (vertex_descriptor v : down) {
      refused.insert(tent_of.at(v));
      CGAL::Euler::remove_center_vertex(halfedge(v, mesh), mesh);
      tent_of.erase(v);
    }
  }
}

/// Puts the points of `points` at no vertex of `mesh` (closed, manifold, free of
/// self-intersections) back into it where it can (see the file comment), in the points'
/// order, one per triangle a pass (three passes at most); `part[i]` is the part of point i
/// (Sum_parts::of()): a point goes only into a triangle whose corners are of its part, the
/// nearest one (or, if that is of another part, the nearest of its part whose bounding box
/// meets the box of half-side `reach` round the point). The mesh stays closed, manifold and
/// free of self-intersections.
/// Returns how many were put back.
template <class ConcurrencyTag, class TriangleMesh, class Point>
std::size_t insert_left_out_points(const std::vector<Point>& points, const std::vector<std::size_t>& part,
                                   double reach, TriangleMesh& mesh)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto index_at = indices_by_position(points); // of the mesh's vertices
  auto part_of = [&](vertex_descriptor v) {
    const auto it = index_at.find(position(get(CGAL::vertex_point, mesh, v)));
    return it == index_at.end() ? std::size_t(-1) : part[it->second];
  };
  const auto positions = double_positions(points);
  const double on_mesh = rounding_margin_of(positions);
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto at = [&](vertex_descriptor v) {
    const Position x = position(get(CGAL::vertex_point, mesh, v));
    return Epick::Point_3(x[0], x[1], x[2]);
  };
  std::unordered_set<std::size_t> refused; // points whose tent was taken down, of another part, or on a side
  std::size_t put_back = 0;
  // Passes: a triangle takes one point a pass, the points that shared it wait for the next.
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<std::size_t> left_out = points_at_no_vertex(points, mesh);
    left_out.erase(std::remove_if(left_out.begin(), left_out.end(), [&](std::size_t i) { return refused.count(i) > 0; }),
                   left_out.end());
    if (left_out.empty()) break;
    const std::vector<face_descriptor> face_of(faces(mesh).begin(), faces(mesh).end()); // to_shell()'s order
    const Shell_triangle_tree tree({to_shell(mesh)});
    std::vector<char> used(face_of.size(), 0);
    std::unordered_map<vertex_descriptor, std::size_t> tent_of; // new vertex -> point
    bool waiting = false;
    auto corners = [&](std::size_t k) {
      const auto h = halfedge(face_of[k], mesh);
      return std::array<vertex_descriptor, 3>{source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)};
    };
    auto of_part = [&](std::size_t k, std::size_t p) {
      const auto c = corners(k);
      return part_of(c[0]) == p && part_of(c[1]) == p && part_of(c[2]) == p;
    };
    for (std::size_t i : left_out) {
      // The nearest triangle; if it is of another part, the nearest of the point's own part
      // within `reach` (a part's points beside another part's triangles).
      std::size_t k = tree.nearest(positions[i]);
      bool same_part = of_part(k, part[i]);
      if (!same_part)
        if (const std::size_t j = tree.nearest_within(positions[i], reach, [&](std::size_t t) { return of_part(t, part[i]); });
            j < face_of.size()) {
          k = j;
          same_part = true;
        }
      const std::array<vertex_descriptor, 3> corner = corners(k);
      bool on_a_side = false;
      for (int c = 0; c < 3; ++c) {
        // (a point on a side, up to rounding, such as a crease point between two of the
        // crease's vertices, is on the mesh already: its tent would have a triangle with three
        // collinear corners)
        on_a_side = on_a_side || CGAL::squared_distance(positions[i], Epick::Segment_3(at(corner[c]), at(corner[(c + 1) % 3]))) <=
                                   on_mesh * on_mesh;
      }
      if (!same_part || on_a_side) refused.insert(i);
      else if (used[k]) waiting = true;
      else {
        used[k] = 1;
        const auto spoke = CGAL::Euler::add_center_vertex(halfedge(face_of[k], mesh), mesh);
        put(CGAL::vertex_point, mesh, target(spoke, mesh), points[i]);
        tent_of.emplace(target(spoke, mesh), i);
      }
    }
    take_down_crossing_tents<ConcurrencyTag>(mesh, tent_of, refused);
    put_back += tent_of.size();
    if (!waiting) break;
  }
  return put_back;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_MESH_LEFT_OUT_POINTS_H
