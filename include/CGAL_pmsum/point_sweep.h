// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::point_sweep(): points covering the boundary of the volume swept by a solid P
// translating along a polyline (paper Fig. 11): the Minkowski sum P + path, with the path a
// mesh of edges only. Every point is exactly on the boundary of the swept volume; together
// they cover it within d (same guarantees as point_minkowski_sum()).

#ifndef CGAL_PMSUM_POINT_SWEEP_H
#define CGAL_PMSUM_POINT_SWEEP_H

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <vector>

namespace CGAL {
namespace Pmsum {

/// \param path the positions of P's reference point (its origin) along the motion, in order:
///        a range of points with x(), y(), z() exactly representable as double
/// \pre d > 0; P as for point_minkowski_sum(); path has at least two points and no two
///      equal consecutive points. Violations throw Invalid_input.
/// The output iterator receives points of P's kernel.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh, class PointRange, class OutputIterator>
OutputIterator point_sweep(const PolygonMesh& P, const PointRange& path, double d, OutputIterator out,
                           Statistics* statistics = nullptr)
{
  namespace in = internal;
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::const_type>::value_type;
  using FT = typename CGAL::Kernel_traits<Point>::Kernel::FT;
  internal::check_covering_distance(d);
  const auto start = in::Clock::now();
  in::Mesh_descriptors<PolygonMesh> desc;
  const in::Mesh_data mp = in::make_mesh_data(P, get(CGAL::vertex_point, P), false, false, "P", desc);
  const in::Mesh_data mq = in::make_polyline_data(path, "path");
  Statistics local;
  Statistics& stats = statistics ? *statistics : local;
  stats = Statistics();
  in::run_pipeline<ConcurrencyTag>(mp, mq, d, in::Pipeline_options{}, stats,
                                   [&](const in::Sample& sp, const in::Sample& sq, const in::Direction&, const in::Trim* trim) {
                                     *out++ = Point(in::sum_coordinate<FT>(mp, mq, sp, sq, trim, 0),
                                                    in::sum_coordinate<FT>(mp, mq, sp, sq, trim, 1),
                                                    in::sum_coordinate<FT>(mp, mq, sp, sq, trim, 2));
                                   },
                                   start);
  return out;
}

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_POINT_SWEEP_H
