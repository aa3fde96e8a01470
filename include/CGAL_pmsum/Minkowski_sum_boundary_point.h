// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rich output record of CGAL::point_minkowski_sum(): a boundary point with its outward
// normal and its provenance (which vertex, edge or face of P and of Q produced it, with the
// exact barycentric weights of the two samples).

#ifndef CGAL_PMSUM_MINKOWSKI_SUM_BOUNDARY_POINT_H
#define CGAL_PMSUM_MINKOWSKI_SUM_BOUNDARY_POINT_H

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <CGAL/Exact_rational.h>
#include <CGAL/number_utils.h>

#include <array>
#include <optional>
#include <stdexcept>

namespace CGAL {
namespace Pmsum {

/// Where a sample of a mesh lies: a vertex, an edge or a face, and its exact position
/// `sum_i weights[i] * point(vertices[i]) / denominator` (unused weights are 0).
template <class PolygonMesh>
struct Mesh_feature
{
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;

  int dimension = -1;            ///< 0: vertex, 1: edge, 2: face
  vertex_descriptor vertex{};    ///< valid if dimension == 0
  halfedge_descriptor halfedge{};///< valid if dimension == 1: from vertices[0] to vertices[1]
  face_descriptor face{};        ///< valid if dimension == 2
  std::array<vertex_descriptor, 3> vertices{};
  std::array<int, 3> weights{};
  int denominator = 1;
  /// Points on trim curves (between lattice samples, where a visible part of a convolution
  /// facet ends): the exact barycentric weights over `vertices` (they sum to 1), used instead
  /// of `weights / denominator`, which then hold the lattice sample the point was found from.
  std::optional<std::array<CGAL::Exact_rational, 3>> rational_weights;
};

/// One point of the boundary of P + Q (or of -P + Q).
template <class PolygonMeshP, class PolygonMeshQ, class Kernel>
struct Minkowski_sum_boundary_point
{
  typename Kernel::Point_3 point;   ///< the point (exact with an exact kernel, else rounded)
  typename Kernel::Vector_3 normal; ///< unit outward normal of the boundary there (rounded)
  Mesh_feature<PolygonMeshP> origin_p;
  Mesh_feature<PolygonMeshQ> origin_q;
  bool negated_p = false;           ///< point = -sample_p + sample_q rather than sample_p + sample_q
};

/// The exact sample of `f` in the exact kernel `EK`, with `vpm` the vertex point map used
/// for the computation.
template <class EK, class PolygonMesh, class VertexPointMap>
typename EK::Point_3 exact_sample(const Mesh_feature<PolygonMesh>& f, VertexPointMap vpm)
{
  using FT = typename EK::FT;
  FT c[3] = {FT(0), FT(0), FT(0)};
  for (int i = 0; i < 3; ++i) {
    const FT w = f.rational_weights ? FT((*f.rational_weights)[i]) : FT(f.weights[i]) / FT(f.denominator);
    if (CGAL::is_zero(w)) continue;
    const auto& p = get(vpm, f.vertices[i]);
    c[0] += w * FT(CGAL::to_double(p.x()));
    c[1] += w * FT(CGAL::to_double(p.y()));
    c[2] += w * FT(CGAL::to_double(p.z()));
  }
  return typename EK::Point_3(c[0], c[1], c[2]);
}

/// The exact point of a record in the exact kernel `EK` (for checks and exact
/// post-processing). `vpm_p` and `vpm_q` are the vertex point maps of the computation.
template <class EK, class PolygonMeshP, class PolygonMeshQ, class Kernel, class VpmP, class VpmQ>
typename EK::Point_3 exact_point(const Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, Kernel>& r,
                                 VpmP vpm_p, VpmQ vpm_q)
{
  const auto p = exact_sample<EK>(r.origin_p, vpm_p);
  const auto q = exact_sample<EK>(r.origin_q, vpm_q);
  return r.negated_p ? q + (CGAL::ORIGIN - p) : q + (p - CGAL::ORIGIN);
}

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_MINKOWSKI_SUM_BOUNDARY_POINT_H
