// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_sweep_mesh(): a checked triangle mesh of the boundary of the volume swept by a
// solid P translating along a polyline, P + path: the points of point_sweep() meshed and
// checked as point_minkowski_sum_mesh() does it, with the same guarantees.

#ifndef CGAL_PMSUM_POINT_SWEEP_MESH_H
#define CGAL_PMSUM_POINT_SWEEP_MESH_H

#include <CGAL_pmsum/point_minkowski_sum_mesh.h>

namespace CGAL {

/// \ingroup PkgPointMinkowskiSumMesh
/// Computes a triangle mesh of the boundary of the volume swept by the solid `P` translating
/// along a polyline (`P` + the path), whose vertices are output points of point_sweep()
/// (exactly on the boundary of the swept volume): closed, 2-manifold, outward oriented and
/// free of self-intersections, refined as point_minkowski_sum_mesh() does, or
/// `CGAL::Pmsum::Mesh_reconstruction_failed` is thrown. Every point of the exact boundary is
/// closer than `Mesh_statistics::boundary_to_mesh_bound()` to the mesh, and every point of the
/// mesh closer than `Mesh_statistics::mesh_to_boundary_bound` to the exact boundary.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMesh a model of `FaceListGraph`
/// \tparam PointRange a range of points with `x()`, `y()`, `z()`
/// \tparam TriangleMesh as for point_minkowski_sum_mesh()
/// \param P the moving solid
/// \param path the positions of P's reference point (its origin) along the motion, in order
/// \param d covering distance of the vertices
/// \param mesh the output (cleared first)
/// \param np named parameters of `P` and of the algorithm: those of
///        point_minkowski_sum_mesh() but `negate_first_mesh`
/// \pre the preconditions of point_sweep(), and `use_trim_points` and `search_islands` not
///      false; violations throw `CGAL::Pmsum::Invalid_input`
/// \throws CGAL::Pmsum::Mesh_reconstruction_failed if no valid mesh was made
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh, class PointRange, class TriangleMesh,
          class NamedParameters = parameters::Default_named_parameters>
void point_sweep_mesh(const PolygonMesh& P, const PointRange& path, double d, TriangleMesh& mesh,
                      const NamedParameters& np = parameters::default_values())
{
  namespace in = Pmsum::internal;
  static_assert(!in::has_any_parameter<NamedParameters, Pmsum::internal_np::negate_first_mesh_t>(),
                "CGAL_pmsum: negate_first_mesh is not a parameter of point_sweep_mesh()");
  using GT = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;
  Pmsum::Mesh_statistics local;
  Pmsum::Mesh_statistics& ms = in::start_mesh(np, mesh, local, "point_sweep_mesh()");
  const auto t_input = in::Clock::now();
  Pmsum::Statistics local_stats;
  const in::Sum_settings settings(d, np, local_stats);
  in::Mesh_descriptors<PolygonMesh> desc;
  const in::Mesh_data mp = in::read_mesh(P, np, false, settings.check_overlaps, "P", desc, settings.merge_flat_regions);
  const in::Mesh_data mq = in::make_polyline_data(path, "path");
  in::Pipeline<ConcurrencyTag> pipeline(mp, mq, settings.options, /*coarse_to_fine=*/true);
  ms.seconds_sum += in::seconds_since(t_input);
  in::mesh_levels<GT>(pipeline, mp, mq, d, settings.stats, settings.start, mesh, ms);
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_SWEEP_MESH_H
