// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::check_mesh(): is a triangle mesh closed, 2-manifold, free of self-intersections
// and the boundary of a volume, and how many shells and voids does it have. The checks
// point_minkowski_sum_mesh() makes before it returns a mesh, and that `pmsum validate --mesh`
// reports.

#ifndef CGAL_PMSUM_CHECK_MESH_H
#define CGAL_PMSUM_CHECK_MESH_H

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumMesh
/// What check_mesh() found in a triangle mesh.
struct Mesh_checks
{
  bool closed = false;                 ///< no border edge
  bool manifold = false;               ///< a valid halfedge triangle mesh without non-manifold vertex: every edge on two faces, every vertex a disk
  bool self_intersection_free = false; ///< `CGAL::Polygon_mesh_processing::does_self_intersect()` is false
  bool bounds_a_volume = false;        ///< outer shells oriented outward, voids inward
  std::size_t shells = 0;              ///< connected components
  std::size_t void_shells = 0;         ///< of them, boundaries of voids (inside an odd number of others)
  /// vertices - edges + faces: 2 - 2 g summed over the shells (g: a shell's genus, its handles)
  long euler_characteristic = 0;

  /// \returns whether the mesh is closed, manifold, free of self-intersections and bounds a volume
  bool valid() const { return closed && manifold && self_intersection_free && bounds_a_volume; }
  /// \returns the checks that failed, as a comma-separated list (empty if valid())
  std::string failures() const
  {
    std::string s;
    auto add = [&](bool ok, const char* what) { if (!ok) s += (s.empty() ? "" : ", ") + std::string(what); };
    add(closed, "not closed");
    add(manifold, "not manifold");
    add(!closed || !manifold || self_intersection_free, "self-intersecting");
    add(!self_intersection_free || bounds_a_volume, "not bounding a volume");
    return s;
  }
};

namespace internal {

/// Is there a vertex where two fans of faces meet (more halfedges end at it than go around it)?
template <class TriangleMesh>
bool has_pinched_vertex(const TriangleMesh& mesh)
{
  auto ending = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  for (auto v : vertices(mesh)) put(ending, v, 0);
  for (auto h : halfedges(mesh)) put(ending, target(h, mesh), get(ending, target(h, mesh)) + 1);
  for (auto v : vertices(mesh)) {
    std::size_t around = 0;
    for (auto h : halfedges_around_target(halfedge(v, mesh), mesh)) {
      (void)h;
      ++around;
    }
    if (around != get(ending, v)) return true;
  }
  return false;
}

/// The shells of a closed, manifold mesh without self-intersections: `bounds_a_volume`,
/// `shells`, `void_shells` and `euler_characteristic` of `c`.
template <class TriangleMesh>
void check_shells(const TriangleMesh& mesh, Mesh_checks& c)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto volume_id = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::vector<std::size_t> nesting;
  std::vector<bool> outward;
  PMP::volume_connected_components(mesh, volume_id,
                                   CGAL::parameters::nesting_levels(std::ref(nesting))
                                     .is_cc_outward_oriented(std::ref(outward)));
  c.shells = nesting.size();
  c.euler_characteristic = long(vertices(mesh).size()) - long(edges(mesh).size()) + long(faces(mesh).size());
  c.void_shells = 0;
  c.bounds_a_volume = true;
  for (std::size_t i = 0; i < nesting.size(); ++i) {
    const bool is_void = nesting[i] % 2 == 1;
    c.void_shells += is_void;
    c.bounds_a_volume = c.bounds_a_volume && outward[i] != is_void;
  }
}

/// check_mesh(), told whether the mesh is free of self-intersections when that is already
/// known (`self_intersection_free`), so as not to test it again.
template <class ConcurrencyTag, class TriangleMesh>
Mesh_checks check_mesh_given(const TriangleMesh& mesh, std::optional<bool> self_intersection_free)
{
  Mesh_checks c;
  c.closed = CGAL::is_closed(mesh);
  c.manifold = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh);
  c.manifold = c.manifold && !has_pinched_vertex(mesh);
  if (!c.closed || !c.manifold) return c;
  c.self_intersection_free = self_intersection_free
                               ? *self_intersection_free
                               : !CGAL::Polygon_mesh_processing::does_self_intersect<ConcurrencyTag>(mesh);
  if (c.self_intersection_free) check_shells(mesh, c);
  return c;
}

} // namespace internal

/// \ingroup PkgPointMinkowskiSumMesh
/// Checks a triangle mesh: closed, manifold, free of self-intersections, bounding a volume
/// (CGAL::Polygon_mesh_processing), and counts its shells and voids.
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (the self-intersection test)
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point map
/// \param mesh the mesh to check
/// \returns what was found; `bounds_a_volume`, `shells`, `void_shells` and
///          `euler_characteristic` only for a closed manifold mesh without self-intersections
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh>
Mesh_checks check_mesh(const TriangleMesh& mesh)
{
  return internal::check_mesh_given<ConcurrencyTag>(mesh, std::nullopt);
}

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_CHECK_MESH_H
