// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A check of the mesh stage against the sum itself: are the mesh's voids voids of the sum?
//
// A void shell V of the mesh says that the free space it encloses is cut off from the rest
// of the free space. Where a passage narrower than the point spacing joins a cavity to the
// outside (a hole through a part, narrowed by the other solid to a thin channel), the
// reconstruction can close the passage and leave the wider places of the channel as small
// voids: a closed, manifold mesh without self-intersections, with the wrong number of shells
// (couplingdown plus a small icosahedron at d = 2% of the diagonal: 14 voids the sum does not
// have; at d = 1%, one shell).
//
// Such a void is refuted exactly: if the open segment from a vertex a of V to a vertex b of
// another shell is free (outside the sum; Segment_search::free_ends(), perturbed along the
// axes where it touches the boundary), a and b are on the border of one component of the free
// space, so V does not enclose a component of its own: the sum has no such void, unless b's
// shell lies inside V itself (a solid island in the void: it bounds the same free space, and is
// never taken as b). (The mesh's vertices are output points, on the exact boundary; with an
// exact kernel they are rounded to doubles here, which can only hide a refutation: a rounded
// end inside the sum is not free.)
// A true void is never refuted; a false one is refuted where a tested segment runs along the
// passage: for each vertex of V, its nearest few vertices of another shell are candidates, and
// the nearest candidates are tested first (a few dozen per void).

#ifndef CGAL_PMSUM_INTERNAL_MESH_VOIDS_H
#define CGAL_PMSUM_INTERNAL_MESH_VOIDS_H

#include <CGAL_pmsum/internal/mesh_reconstruction.h>
#include <CGAL_pmsum/internal/segment_search.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <algorithm>
#include <functional>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// The ends of the free parts of the segment from a to b (Segment_search::free_ends(),
/// perturbed along the axes where it touches the boundary). @pre a != b
inline std::vector<Segment_parameter> free_ends_between(Segment_search& search, const Position& a, const Position& b)
{
  auto exact = [](const Position& x) {
    return Exact_point{{Exact_nt(x[0]), Exact_nt(x[1]), Exact_nt(x[2])}, Exact_nt(1)};
  };
  std::vector<Segment_parameter> ends;
  search.free_ends(Translation_segment(exact(a), exact(b)), nullptr, 0, ends);
  return ends;
}

/// Is the open segment from a to b outside the sum (one free part, from 0 to 1)? False if a = b.
inline bool free_segment(Segment_search& search, const Position& a, const Position& b)
{
  if (a == b) return false;
  const std::vector<Segment_parameter> ends = free_ends_between(search, a, b);
  return ends.size() == 2 && CGAL::is_zero(ends[0].num) && compare(ends[1], Segment_parameter::one()) == CGAL::ZERO;
}

/// Is the segment from a to b inside the sum (no free part)? False if a = b.
inline bool inside_segment(Segment_search& search, const Position& a, const Position& b)
{ return a != b && free_ends_between(search, a, b).empty(); }

/// Is a void shell of `mesh` (closed, manifold, without self-intersections, bounding a
/// volume; its vertices on the boundary of the sum) refuted by a free segment to another
/// shell (see the file comment)? At most `tests` segments per void, the shortest from its
/// vertices to their `per_vertex` nearest vertices of another shell. `search`: on the CD
/// filter of the sum.
template <class TriangleMesh>
bool has_false_void(const TriangleMesh& mesh, Segment_search& search, std::size_t tests = 32,
                    std::size_t per_vertex = 4)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto volume_id = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  auto shell_id = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::vector<std::size_t> nesting;
  std::vector<std::vector<std::size_t>> around; // the shells first met going out of each
  PMP::volume_connected_components(mesh, volume_id,
                                   CGAL::parameters::face_connected_component_map(shell_id)
                                     .nesting_levels(std::ref(nesting))
                                     .volume_inclusions(std::ref(around)));
  if (std::none_of(nesting.begin(), nesting.end(), [](std::size_t n) { return n % 2 == 1; })) return false;
  // The vertices, their shells, and a tree of their positions.
  std::vector<Position> at;
  std::vector<std::size_t> shell;
  std::unordered_map<Position, std::size_t, Position_hash> index;
  for (auto v : vertices(mesh)) {
    at.push_back(position(get(CGAL::vertex_point, mesh, v)));
    shell.push_back(get(shell_id, face(halfedge(v, mesh), mesh)));
    index.emplace(at.back(), at.size() - 1);
  }
  std::vector<Point_search::K::Point_3> points;
  for (const Position& x : at) points.emplace_back(x[0], x[1], x[2]);
  const Point_search tree(points);
  // Per void: for each of its vertices, the nearest few vertices of another shell not inside it
  // (among its 16 nearest). More than one: the nearest can lie on the same face of the sum as
  // the void's vertex (a thin channel whose walls carry points at the same places), and a
  // segment along a face is not free; the next one, across the channel, is.
  std::vector<std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>>> candidates(nesting.size());
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (nesting[shell[i]] % 2 == 0) continue;
    const Point_search::Search nearest(tree.tree, points[i], 16);
    std::size_t taken = 0;
    for (const auto& [p, squared] : nearest) {
      const std::size_t j = index.at(Position{p.x(), p.y(), p.z()});
      if (shell[j] == shell[i] || std::count(around[shell[j]].begin(), around[shell[j]].end(), shell[i]) > 0) continue;
      candidates[shell[i]].push_back({squared, {i, j}});
      if (++taken == per_vertex) break;
    }
  }
  for (auto& c : candidates) {
    std::sort(c.begin(), c.end());
    for (std::size_t k = 0; k < c.size() && k < tests; ++k)
      if (free_segment(search, at[c[k].second.first], at[c[k].second.second])) return true;
  }
  return false;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_MESH_VOIDS_H
