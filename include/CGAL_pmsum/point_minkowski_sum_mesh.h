// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_minkowski_sum_mesh(): a closed, 2-manifold, outward-oriented triangle mesh of
// the boundary of P + Q without self-intersections, whose vertices are output points of
// point_minkowski_sum() (each exactly on the boundary). The points (the default (d/2, d)-net)
// are joined by CGAL's advancing-front surface reconstruction; the result is checked, and if a
// check fails the sum is recomputed with a smaller covering distance. A mesh that fails every
// check is never returned: Mesh_reconstruction_failed is thrown instead.

#ifndef CGAL_PMSUM_POINT_MINKOWSKI_SUM_MESH_H
#define CGAL_PMSUM_POINT_MINKOWSKI_SUM_MESH_H

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumMesh
/// No valid mesh could be made from the points, even with the smaller covering distances
/// tried. Constructed from its message, as `std::runtime_error`.
class Mesh_reconstruction_failed : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// \ingroup PkgPointMinkowskiSumMesh
/// What check_mesh() found in a triangle mesh.
struct Mesh_checks
{
  bool closed = false;                 ///< no border edge
  bool manifold = false;               ///< every edge on two faces, every vertex a disk (a valid halfedge mesh)
  bool self_intersection_free = false; ///< `CGAL::Polygon_mesh_processing::does_self_intersect()` is false
  bool bounds_a_volume = false;        ///< outer shells oriented outward, voids inward
  std::size_t shells = 0;              ///< connected components
  std::size_t void_shells = 0;         ///< of them, boundaries of voids (inside an odd number of others)

  /// \returns whether the mesh is closed, manifold, free of self-intersections and bounds a volume
  bool valid() const { return closed && manifold && self_intersection_free && bounds_a_volume; }
};

/// \ingroup PkgPointMinkowskiSumMesh
/// Counters and seconds of point_minkowski_sum_mesh().
struct Mesh_statistics
{
  Statistics sum;              ///< the last point_minkowski_sum() run
  double covering_distance = 0;///< the `d` of that run (`d`, or smaller after refinements)
  int refinements = 0;         ///< how many times `d` was halved because a check failed
  std::size_t vertices = 0;    ///< vertices of the mesh (output points of the sum)
  std::size_t triangles = 0;   ///< triangles of the mesh
  Mesh_checks checks;          ///< the checks of the mesh returned
  double seconds_sum = 0;      ///< all runs of the sum
  double seconds_mesh = 0;     ///< all reconstructions and checks
};

/// \ingroup PkgPointMinkowskiSumMesh
/// Checks a triangle mesh: closed, manifold, free of self-intersections, bounding a volume
/// (CGAL::Polygon_mesh_processing), and counts its shells and voids.
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point map
/// \param mesh the mesh to check
/// \returns what was found; `bounds_a_volume`, `shells` and `void_shells` only for a closed
///          manifold mesh without self-intersections
template <class TriangleMesh>
Mesh_checks check_mesh(const TriangleMesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Mesh_checks c;
  c.closed = CGAL::is_closed(mesh);
  c.manifold = CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh);
  if (!c.closed || !c.manifold) return c;
  c.self_intersection_free = !PMP::does_self_intersect(mesh);
  if (!c.self_intersection_free) return c;
  auto volume_id = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  std::vector<std::size_t> nesting;
  std::vector<bool> outward;
  PMP::volume_connected_components(mesh, volume_id,
                                   CGAL::parameters::nesting_levels(std::ref(nesting))
                                     .is_cc_outward_oriented(std::ref(outward)));
  c.shells = nesting.size();
  c.bounds_a_volume = true;
  for (std::size_t i = 0; i < nesting.size(); ++i) {
    const bool is_void = nesting[i] % 2 == 1;
    c.void_shells += is_void;
    c.bounds_a_volume = c.bounds_a_volume && outward[i] != is_void;
  }
  return c;
}

namespace internal {

/// Joins `points` (with their positions in double) by advancing-front reconstruction into
/// `mesh`, oriented to bound a volume. Returns the checks of the mesh made.
template <class TriangleMesh, class Point>
Mesh_checks reconstruct_mesh(const std::vector<Point>& points, TriangleMesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Epick::Point_3> positions;
  positions.reserve(points.size());
  for (const Point& p : points)
    positions.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL::advancing_front_surface_reconstruction(positions.begin(), positions.end(), std::back_inserter(triangles));
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(triangles.size());
  for (const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  std::vector<Point> soup_points(points); // orient_polygon_soup may duplicate non-manifold vertices
  clear(mesh);
  if (!PMP::orient_polygon_soup(soup_points, polygons) || !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    return Mesh_checks{}; // not orientable, or not a manifold mesh
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, mesh);
  Mesh_checks c = check_mesh(mesh);
  if (c.closed && c.manifold && c.self_intersection_free && !c.bounds_a_volume) {
    PMP::orient_to_bound_a_volume(mesh);
    c = check_mesh(mesh);
  }
  return c;
}

} // namespace internal
} // namespace Pmsum

/// \ingroup PkgPointMinkowskiSumMesh
/// Computes a triangle mesh of the boundary of the Minkowski sum `P + Q` (or `-P + Q`): its
/// vertices are output points of point_minkowski_sum() (exactly on the boundary, rounded
/// only if the mesh's kernel is inexact), joined by CGAL's advancing-front surface
/// reconstruction. The mesh returned is closed, 2-manifold, free of self-intersections and
/// bounds a volume (outer shells outward, voids inward): if the reconstruction at `d` fails a
/// check, the sum is recomputed at `d/2`, then `d/4`; if that fails too,
/// `CGAL::Pmsum::Mesh_reconstruction_failed` is thrown and `mesh` is left empty.
///
/// What is measured, not proved: the distance from the mesh to the exact boundary and back
/// (`pmsum validate --mesh`; below `d` both ways on the validation suite).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMeshP, PolygonMeshQ models of `FaceListGraph`
/// \tparam TriangleMesh a model of `MutableFaceGraph` whose point type is constructible from
///         the points of P's geometric traits (e.g. `Surface_mesh<GeomTraits::Point_3>`)
/// \tparam NamedParametersP, NamedParametersQ named parameter packs
/// \param P the first mesh
/// \param Q the second mesh
/// \param d covering distance of the vertices
/// \param mesh the output (cleared first)
/// \param np_p as for point_minkowski_sum(), and `mesh_statistics` (a
///        `CGAL::Pmsum::Mesh_statistics&` to fill); `use_covering_net(false)` is not allowed
/// \param np_q as for point_minkowski_sum()
/// \pre the preconditions of point_minkowski_sum(); violations throw `CGAL::Pmsum::Invalid_input`
/// \throws CGAL::Pmsum::Mesh_reconstruction_failed if no valid mesh was made
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMeshP, class PolygonMeshQ, class TriangleMesh,
          class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersQ = parameters::Default_named_parameters>
void point_minkowski_sum_mesh(const PolygonMeshP& P, const PolygonMeshQ& Q, double d, TriangleMesh& mesh,
                              const NamedParametersP& np_p = parameters::default_values(),
                              const NamedParametersQ& np_q = parameters::default_values())
{
  namespace in = Pmsum::internal;
  static_assert(!in::has_any_parameter<NamedParametersP, Pmsum::internal_np::use_covering_net_t,
                                       Pmsum::internal_np::roadmap_neighbors_t>(),
                "CGAL_pmsum: point_minkowski_sum_mesh() meshes the covering net; use_covering_net and "
                "roadmap_neighbors are not parameters of it");
  using Point = typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;
  Pmsum::Mesh_statistics local;
  Pmsum::Mesh_statistics& ms =
    *parameters::choose_parameter(parameters::get_parameter(np_p, Pmsum::internal_np::mesh_statistics), &local);
  ms = Pmsum::Mesh_statistics();
  using GT = typename GetGeomTraits<PolygonMeshP, NamedParametersP>::type;
  const int max_refinements = 2;
  for (int level = 0; level <= max_refinements; ++level) {
    const double dl = d / double(1 << level);
    const auto t_sum = in::Clock::now();
    std::vector<typename GT::Point_3> sum_points;
    auto out = std::back_inserter(sum_points);
    Pmsum::Statistics local_stats;
    in::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(P, Q, dl, np_p, np_q,
                                                                                      local_stats);
    in::run_pipeline<ConcurrencyTag>(sum.mp, sum.mq, dl, sum.options, sum.stats, sum.make_emit(out), sum.start);
    ms.sum = sum.stats;
    const std::vector<Point> points(sum_points.begin(), sum_points.end());
    ms.seconds_sum += in::seconds_since(t_sum);
    const auto t_mesh = in::Clock::now();
    ms.checks = in::reconstruct_mesh(points, mesh);
    ms.seconds_mesh += in::seconds_since(t_mesh);
    ms.covering_distance = dl;
    ms.refinements = level;
    if (ms.checks.valid()) {
      ms.vertices = num_vertices(mesh);
      ms.triangles = num_faces(mesh);
      return;
    }
  }
  clear(mesh);
  const Pmsum::Mesh_checks& c = ms.checks;
  throw Pmsum::Mesh_reconstruction_failed(
    std::string("no valid mesh of the sum's boundary could be made (down to d = ") + std::to_string(d / 4) +
    "): the last reconstruction was " + (c.closed ? "" : "not closed, ") + (c.manifold ? "" : "not manifold, ") +
    (c.closed && c.manifold && !c.self_intersection_free ? "self-intersecting, " : "") +
    (c.self_intersection_free && !c.bounds_a_volume ? "not bounding a volume, " : "") + "so none is returned");
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_MINKOWSKI_SUM_MESH_H
