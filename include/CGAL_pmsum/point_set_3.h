// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::insert_into_point_set(): the records of point_minkowski_sum() (and of the
// other entry points that write records) into a CGAL::Point_set_3, with their normals and
// their provenance as properties, ready for CGAL's point set processing, reconstruction and
// I/O (CGAL::IO::write_point_set writes the integer properties to PLY).

#ifndef CGAL_PMSUM_POINT_SET_3_H
#define CGAL_PMSUM_POINT_SET_3_H

#include <CGAL_pmsum/Minkowski_sum_boundary_point.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/number_utils.h>

#include <type_traits>

namespace CGAL {
namespace Pmsum {
namespace internal {
template <class Record>
struct Record_meshes;
template <class PolygonMeshP, class PolygonMeshQ, class Kernel>
struct Record_meshes<Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, Kernel>>
{
  using P = PolygonMeshP;
  using Q = PolygonMeshQ;
};
} // namespace internal

/// \ingroup PkgPointMinkowskiSumPointSet
/// The provenance properties that insert_into_point_set() adds to a point set.
/// \tparam Point, Vector the point set's point and vector types
/// \tparam PolygonMeshP, PolygonMeshQ the mesh types of the records
template <class Point, class Vector, class PolygonMeshP, class PolygonMeshQ>
struct Point_set_provenance
{
  /// the point set type
  using Point_set = CGAL::Point_set_3<Point, Vector>;
  /// property "origin_p": where the sample of P lies (Mesh_feature: vertex, edge or face, weights)
  typename Point_set::template Property_map<Mesh_feature<PolygonMeshP>> origin_p;
  /// property "origin_q": where the sample of Q lies
  typename Point_set::template Property_map<Mesh_feature<PolygonMeshQ>> origin_q;
  /// property "origin_p_dimension": 0 vertex, 1 edge, 2 face (written to PLY)
  typename Point_set::template Property_map<int> origin_p_dimension;
  /// property "origin_q_dimension": 0 vertex, 1 edge, 2 face (written to PLY)
  typename Point_set::template Property_map<int> origin_q_dimension;
  /// property "on_trim_curve": 1 for a point on a trim curve, 0 for a lattice sum (written to PLY)
  typename Point_set::template Property_map<int> on_trim_curve;
};

/// \ingroup PkgPointMinkowskiSumPointSet
/// Inserts the records into `point_set`: each record's point, its unit outward normal (the
/// normal map is added if missing), and its provenance in the properties "origin_p",
/// "origin_q" (the records' `Mesh_feature`s), "origin_p_dimension", "origin_q_dimension" and
/// "on_trim_curve" (added if missing). Points of another kernel are converted through `double`.
///
/// \tparam RecordRange a range of `Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, K>`
/// \tparam Point, Vector the point set's point and vector types
/// \param records the records, e.g. the output of point_minkowski_sum()
/// \param point_set the point set to extend (its existing points and properties are kept)
/// \returns the provenance property maps
/// \pre if `point_set` already has a property of one of these names, it has the type above
template <class RecordRange, class Point, class Vector>
auto insert_into_point_set(const RecordRange& records, CGAL::Point_set_3<Point, Vector>& point_set)
{
  using Record = typename std::decay<decltype(*std::begin(records))>::type;
  using MeshP = typename internal::Record_meshes<Record>::P;
  using MeshQ = typename internal::Record_meshes<Record>::Q;
  Point_set_provenance<Point, Vector, MeshP, MeshQ> maps;
  maps.origin_p = point_set.template add_property_map<Mesh_feature<MeshP>>("origin_p").first;
  maps.origin_q = point_set.template add_property_map<Mesh_feature<MeshQ>>("origin_q").first;
  maps.origin_p_dimension = point_set.template add_property_map<int>("origin_p_dimension", -1).first;
  maps.origin_q_dimension = point_set.template add_property_map<int>("origin_q_dimension", -1).first;
  maps.on_trim_curve = point_set.template add_property_map<int>("on_trim_curve", 0).first;
  point_set.add_normal_map();
  for (const Record& r : records) {
    const auto i = point_set.insert(
      Point(CGAL::to_double(r.point.x()), CGAL::to_double(r.point.y()), CGAL::to_double(r.point.z())),
      Vector(CGAL::to_double(r.normal.x()), CGAL::to_double(r.normal.y()), CGAL::to_double(r.normal.z())));
    put(maps.origin_p, *i, r.origin_p);
    put(maps.origin_q, *i, r.origin_q);
    put(maps.origin_p_dimension, *i, r.origin_p.dimension);
    put(maps.origin_q_dimension, *i, r.origin_q.dimension);
    put(maps.on_trim_curve, *i, int(r.on_trim_curve));
  }
  return maps;
}

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_POINT_SET_3_H
