// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_sweep(): points covering the boundary of the volume swept by a solid P
// translating along a polyline (paper Fig. 11): the Minkowski sum P + path, with the path a
// mesh of edges only. Every point is exactly on the boundary of the swept volume; together
// they cover it within d (same guarantees as point_minkowski_sum()).

#ifndef CGAL_PMSUM_POINT_SWEEP_H
#define CGAL_PMSUM_POINT_SWEEP_H

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <vector>

namespace CGAL {

/// \ingroup PkgPointMinkowskiSumSweep
/// Computes points covering the boundary of the volume swept by the solid `P` translating
/// along a polyline: the Minkowski sum of `P` and the path. Every point is exactly on the
/// boundary of the swept volume; together they cover it within `d` (the guarantees of
/// point_minkowski_sum()).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMesh a model of `FaceListGraph`
/// \tparam PointRange a range of points with `x()`, `y()`, `z()`
/// \tparam OutputIterator receives `Point_3` of the geometric traits of `P`
/// \param P the moving solid
/// \param path the positions of P's reference point (its origin) along the motion, in order
/// \param d covering distance
/// \param out where the points go
/// \param np named parameters of `P` (`vertex_point_map`, `geom_traits`) and of the
///        algorithm: those of point_minkowski_sum() but `negate_first_mesh`
/// \returns the output iterator past the last point written
/// \pre `d > 0`; `P` as for point_minkowski_sum(); `path` has at least two points, no two
///      equal consecutive points, coordinates exactly representable as `double`. Violations
///      throw `CGAL::Pmsum::Invalid_input` before anything is written.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh, class PointRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator point_sweep(const PolygonMesh& P, const PointRange& path, double d, OutputIterator out,
                           const NamedParameters& np = parameters::default_values())
{
  namespace in = Pmsum::internal;
  static_assert(!in::has_any_parameter<NamedParameters, Pmsum::internal_np::negate_first_mesh_t,
                                       Pmsum::internal_np::roadmap_neighbors_t, Pmsum::internal_np::mesh_statistics_t>(),
                "CGAL_pmsum: negate_first_mesh, roadmap_neighbors and mesh_statistics are not parameters of point_sweep()");
  using GT = typename GetGeomTraits<PolygonMesh, NamedParameters>::type;
  Pmsum::Statistics local_stats;
  const in::Sum_settings settings(d, np, local_stats);
  in::Mesh_descriptors<PolygonMesh> desc;
  const in::Mesh_data mp = in::read_mesh(P, np, false, settings.check_overlaps, "P", desc, settings.merge_flat_regions);
  const in::Mesh_data mq = in::make_polyline_data(path, "path");
  in::run_pipeline<ConcurrencyTag>(mp, mq, d, settings.options, settings.stats, in::make_point_emit<GT>(mp, mq, out),
                                   settings.start);
  return out;
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_SWEEP_H
