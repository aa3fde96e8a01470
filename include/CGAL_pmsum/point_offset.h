// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_offset(), CGAL::point_erosion(), CGAL::make_icosphere(): offsetting and
// erosion with points (paper section 9.2, "Modeling"):
//   point_offset(P, B, d, out)   points covering the boundary of P + B (B: a ball, a cube, ...)
//   point_erosion(P, B, d, out)  points covering the boundary of P - B = {x : B + x inside P}
//   make_icosphere(r, e, mesh)   a polyhedral ball of radius r, within relative error e
//
// Erosion without a complement mesh: for B containing the origin in its interior, the
// boundary of (-B) + surface(P) is the set of x where B + x touches the surface of P without
// crossing it; the part of it inside P is exactly the boundary of the erosion.

#ifndef CGAL_PMSUM_POINT_OFFSET_H
#define CGAL_PMSUM_POINT_OFFSET_H

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <boost/property_map/function_property_map.hpp>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace CGAL {

/// \ingroup PkgPointMinkowskiSumOffset
/// Fills `out` with a geodesic sphere of radius `r` centred at the origin: an icosahedron
/// subdivided until its inradius (distance from the centre to its nearest facet plane) is
/// at least (1 - relative_error) r. Vertices lie on the sphere (rounded to double), so the
/// polyhedron B satisfies ball(inradius) inside B inside ball(r): P + B lies between the
/// offsets of P at distances inradius and r.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with an internal vertex point map
/// \param r the radius, > 0
/// \param relative_error how far below `r` the inradius may be, in (0, 1)
/// \param out the mesh to fill (cleared first)
/// \returns the inradius (a lower bound)
/// \pre `r > 0` and finite, `0 < relative_error < 1`; violations throw `CGAL::Pmsum::Invalid_input`
/// \throws CGAL::Pmsum::Too_large if the ball would need more than 2^22 faces (`relative_error`
///         below about 1e-6)
template <class PolygonMesh>
double make_icosphere(double r, double relative_error, PolygonMesh& out)
{
  if (!(r > 0) || !std::isfinite(r) || !(relative_error > 0 && relative_error < 1))
    throw Pmsum::Invalid_input("make_icosphere needs r > 0 and 0 < relative_error < 1");
  using P3 = std::array<double, 3>;
  const double t = (1 + std::sqrt(5.)) / 2;
  std::vector<P3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                       {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                                               {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                               {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
                                               {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  auto project = [r](P3 p) {
    const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    return P3{p[0] * r / n, p[1] * r / n, p[2] * r / n};
  };
  for (auto& p : v) p = project(p);
  // inradius: smallest distance from the origin to a facet plane (with a rounding margin)
  auto inradius = [&]() {
    double m = r;
    for (const auto& tri : f) {
      const P3 &a = v[tri[0]], &b = v[tri[1]], &c = v[tri[2]];
      const P3 u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const P3 n = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      m = (std::min)(m, (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / len);
    }
    return m * (1 - 1e-12);
  };
  const std::size_t max_faces = std::size_t(1) << 22;
  while (inradius() < (1 - relative_error) * r) {
    if (4 * f.size() > max_faces)
      throw Pmsum::Too_large("a ball within the relative error asked for would need more than " +
                      std::to_string(max_faces) + " faces; allow a larger error");
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto middle = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(project({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2}));
      return mid[key] = v.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> g;
    for (const auto& tri : f) {
      const std::size_t ab = middle(tri[0], tri[1]), bc = middle(tri[1], tri[2]), ca = middle(tri[2], tri[0]);
      g.push_back({tri[0], ab, ca});
      g.push_back({tri[1], bc, ab});
      g.push_back({tri[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  using Point = typename boost::property_traits<typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vd;
  clear(out);
  for (const auto& p : v) vd.push_back(add_vertex(Point(p[0], p[1], p[2]), out));
  for (const auto& tri : f) CGAL::Euler::add_face(std::array{vd[tri[0]], vd[tri[1]], vd[tri[2]]}, out);
  return inradius();
}

/// \ingroup PkgPointMinkowskiSumOffset
/// Computes points covering the boundary of the offset `P + B` (e.g. `B` from
/// make_icosphere(), or a cube for an offset in the maximum norm): point_minkowski_sum()
/// of `P` and `B`, with the same guarantees: every point exactly on the boundary of `P + B`,
/// covering it within `d`.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMesh, StructuringMesh models of `FaceListGraph`
/// \tparam OutputIterator receives `Point_3`, or records, as for point_minkowski_sum()
/// \param P the solid (or surface) to offset
/// \param B the structuring element, e.g. a ball containing the origin
/// \param d covering distance
/// \param out where the points go
/// \param np_p named parameters of `P` and of the algorithm, as `np_p` of point_minkowski_sum()
/// \param np_b named parameters of `B`, as `np_q` of point_minkowski_sum()
/// \returns the output iterator past the last point written
/// \pre the preconditions of point_minkowski_sum() for `P` and `B`; violations throw
///      `CGAL::Pmsum::Invalid_input` before anything is written.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh, class StructuringMesh, class OutputIterator,
          class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersB = parameters::Default_named_parameters>
OutputIterator point_offset(const PolygonMesh& P, const StructuringMesh& B, double d, OutputIterator out,
                            const NamedParametersP& np_p = parameters::default_values(),
                            const NamedParametersB& np_b = parameters::default_values())
{
  return point_minkowski_sum<ConcurrencyTag>(P, B, d, out, np_p, np_b);
}

/// \ingroup PkgPointMinkowskiSumOffset
/// Computes points covering the boundary of the erosion of the solid `P` by `B`,
/// `{x : B + x inside P}`: the points of the boundary of `(-B) + surface(P)` that lie inside
/// `P`. Every point is exactly on the boundary of the erosion; by default they form a
/// (d/2, d)-net of it (`use_covering_net(false)`: every such point).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMesh, StructuringMesh models of `FaceListGraph`
/// \tparam OutputIterator receives `Point_3` of the geometric traits of `P`
/// \param P the closed solid to erode
/// \param B the structuring element
/// \param d covering distance
/// \param out where the points go
/// \param np_p named parameters of `P` (`vertex_point_map`, `geom_traits`) and of the algorithm
///        (those of point_minkowski_sum(); `negate_first_mesh` and `treat_as_surface` are implied)
/// \param np_b named parameters of `B` (`vertex_point_map`)
/// \returns the output iterator past the last point written
/// \pre `B` contains the origin in its interior; `P` is a closed triangle mesh bounding a
///      volume; the other preconditions of point_minkowski_sum(). Violations of the checked
///      ones throw `CGAL::Pmsum::Invalid_input`.
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh, class StructuringMesh, class OutputIterator,
          class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersB = parameters::Default_named_parameters>
OutputIterator point_erosion(const PolygonMesh& P, const StructuringMesh& B, double d, OutputIterator out,
                             const NamedParametersP& np_p = parameters::default_values(),
                             const NamedParametersB& np_b = parameters::default_values())
{
  namespace in = Pmsum::internal;
  static_assert(!in::has_algorithm_parameter<NamedParametersB>(),
                "CGAL_pmsum: np_b takes only B's vertex_point_map; pass the algorithm's parameters in np_p");
  static_assert(!in::has_any_parameter<NamedParametersP, Pmsum::internal_np::negate_first_mesh_t,
                                       Pmsum::internal_np::treat_as_surface_t, Pmsum::internal_np::roadmap_neighbors_t,
                                       Pmsum::internal_np::mesh_statistics_t>(),
                "CGAL_pmsum: point_erosion() implies negate_first_mesh and treat_as_surface, and takes no "
                "roadmap_neighbors or mesh_statistics");
  using GT = typename GetGeomTraits<PolygonMesh, NamedParametersP>::type;
  using Point = typename GT::Point_3;
  Pmsum::Statistics local_stats;
  in::Sum_settings settings(d, np_p, local_stats, in::Negation::always);
  if (!CGAL::is_closed(P)) throw Pmsum::Invalid_input("point_erosion needs a closed mesh P");
  const auto vpm = in::vertex_point_map_of(P, np_p);
  { // P is a solid: check it as one (the sum below takes its surface as a surface)
    in::Mesh_descriptors<PolygonMesh> desc;
    in::make_mesh_data(P, vpm, false, false, "P", desc, settings.check_overlaps);
  }
  in::Mesh_descriptors<PolygonMesh> desc_p;
  const in::Mesh_data surface =
    in::make_mesh_data(P, vpm, false, true, "P", desc_p, settings.check_overlaps, settings.merge_flat_regions);
  in::Mesh_descriptors<StructuringMesh> desc_b;
  const in::Mesh_data minus_b = in::read_mesh(B, np_b, true, settings.check_overlaps, "B", desc_b, settings.merge_flat_regions);
  // Every boundary candidate: the net is taken after the part inside P is chosen (a net of
  // the whole boundary could cover a point inside P by one outside).
  const bool net = settings.options.use_covering_net;
  settings.options.use_covering_net = false;
  std::vector<Point> boundary;
  auto boundary_out = std::back_inserter(boundary);
  in::run_pipeline<ConcurrencyTag>(minus_b, surface, d, settings.options, settings.stats,
                                   in::make_point_emit<GT>(minus_b, surface, boundary_out), settings.start);
  // Each point is at distance at least the inradius of B from the surface of P, so the
  // (exact-predicate) side test of its rounded position cannot err.
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  CGAL::Surface_mesh<Epick::Point_3> copy;
  using vertex_descriptor = typename boost::graph_traits<PolygonMesh>::vertex_descriptor;
  auto to_double = [&](vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Epick::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  CGAL::copy_face_graph(P, copy, CGAL::parameters::vertex_point_map(
                                   boost::make_function_property_map<vertex_descriptor, Epick::Point_3>(to_double)));
  const CGAL::Side_of_triangle_mesh<CGAL::Surface_mesh<Epick::Point_3>, Epick> side(copy);
  std::vector<std::size_t> inside;
  std::vector<in::Point3> positions;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const in::Point3 x = {CGAL::to_double(boundary[i].x()), CGAL::to_double(boundary[i].y()),
                          CGAL::to_double(boundary[i].z())};
    if (side(Epick::Point_3(x[0], x[1], x[2])) == CGAL::ON_BOUNDED_SIDE) {
      inside.push_back(i);
      positions.push_back(x);
    }
  }
  if (!net) {
    for (std::size_t i : inside) *out++ = boundary[i];
    return out;
  }
  for (std::size_t k : in::greedy_net(positions, d)) *out++ = boundary[inside[k]];
  return out;
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_OFFSET_H
