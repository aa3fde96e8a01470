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

/// \ingroup PkgPointMinkowskiSumSupport
/// Where a sample of a mesh lies: a vertex, an edge or a face, and its exact position
/// `sum_i weights[i] * point(vertices[i]) / denominator` (unused weights are 0).
///
/// With `merge_flat_regions(true)` (the default), a flat region of the mesh cut into many
/// triangles (coplanar faces with vertices inside the region, or inside the straight creases
/// between regions) is sampled as the same region triangulated again without those vertices
/// (the same solid, much less work). A point there is still named by the mesh's own feature
/// that holds it (the lowest-dimensional one), with `rational_weights` over that feature's
/// vertices.
///
/// \tparam PolygonMesh the type of the mesh (`PolygonMeshP` or `PolygonMeshQ` of
///         point_minkowski_sum()), a model of `FaceGraph`
template <class PolygonMesh>
struct Mesh_feature
{
  using Graph_traits = boost::graph_traits<PolygonMesh>;                     ///< the mesh's graph traits
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;       ///< a vertex of the mesh
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;   ///< a halfedge of the mesh
  using face_descriptor = typename Graph_traits::face_descriptor;           ///< a face of the mesh

  int dimension = -1;            ///< 0: vertex, 1: edge, 2: face
  vertex_descriptor vertex{};    ///< valid if dimension == 0
  halfedge_descriptor halfedge{};///< valid if dimension == 1: from vertices[0] to vertices[1]
  face_descriptor face{};        ///< valid if dimension == 2
  std::array<vertex_descriptor, 3> vertices{}; ///< the vertices `weights` refer to (those of the feature)
  std::array<int, 3> weights{};  ///< integer barycentric weights over `vertices`, summing to `denominator`
  int denominator = 1;           ///< positive denominator of `weights`
  /// Where `weights / denominator` cannot give the point exactly: the exact barycentric
  /// weights over `vertices` (they sum to 1), used instead. Set on trim curves (between lattice
  /// samples, where a visible part of a convolution facet ends: `weights / denominator` then
  /// hold the lattice sample the point was found from), and on flat regions triangulated
  /// again (`merge_flat_regions`, trim points too: `weights / denominator` then round them,
  /// denominator 2^20, nonzero on the feature's vertices only).
  std::optional<std::array<CGAL::Exact_rational, 3>> rational_weights;
};

/// \ingroup PkgPointMinkowskiSumSupport
/// One point of the boundary of `P + Q` (or of `-P + Q`), the record that point_minkowski_sum()
/// writes to an output iterator that accepts it: the point, its outward normal and its
/// provenance, from which exact_point() rebuilds the exact point.
///
/// \tparam PolygonMeshP the type of `P`
/// \tparam PolygonMeshQ the type of `Q`
/// \tparam Kernel the geometric traits of the computation (the kernel of `P`'s points, or the
///         `geom_traits` named parameter)
template <class PolygonMeshP, class PolygonMeshQ, class Kernel>
struct Minkowski_sum_boundary_point
{
  typename Kernel::Point_3 point;   ///< the point (exact with an exact kernel, else rounded)
  typename Kernel::Vector_3 normal; ///< unit outward normal of the boundary there (rounded)
  Mesh_feature<PolygonMeshP> origin_p; ///< the sample of `P` (on `P` itself, also when `negated_p`)
  Mesh_feature<PolygonMeshQ> origin_q; ///< the sample of `Q`
  bool negated_p = false;           ///< point = -sample_p + sample_q rather than sample_p + sample_q
  /// a point on a trim curve (where a visible part of a convolution facet ends), found between
  /// lattice sums; false for a lattice sum sample_p + sample_q
  bool on_trim_curve = false;
};

/// \ingroup PkgPointMinkowskiSumSupport
/// Computes the exact sample of `f` in the exact kernel `EK`.
///
/// \tparam EK an exact kernel, e.g. `CGAL::Exact_predicates_exact_constructions_kernel`
/// \tparam PolygonMesh the type of the mesh `f` lies on
/// \tparam VertexPointMap a readable property map from the mesh's vertices to points whose
///         coordinates convert to `double`
/// \param f where the sample lies
/// \param vpm the vertex point map used for the computation
/// \returns `sum_i w_i * get(vpm, f.vertices[i])`, with `w` the rational weights of `f` if it
///          has them, else `weights / denominator`
/// \pre the coordinates of the points of `vpm` are exactly representable as `double` (which
///      point_minkowski_sum() checks)
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

/// \ingroup PkgPointMinkowskiSumSupport
/// Computes the exact point of a record in the exact kernel `EK` (for checks and exact
/// post-processing).
///
/// \tparam EK an exact kernel, e.g. `CGAL::Exact_predicates_exact_constructions_kernel`
/// \tparam PolygonMeshP, PolygonMeshQ, Kernel the template parameters of the record
/// \tparam VpmP, VpmQ the types of the vertex point maps of `P` and `Q`
/// \param r a record written by point_minkowski_sum() (or another entry point)
/// \param vpm_p the vertex point map of `P` used for the computation
/// \param vpm_q the vertex point map of `Q` used for the computation
/// \returns `exact_sample(r.origin_p) + exact_sample(r.origin_q)`, or
///          `exact_sample(r.origin_q) - exact_sample(r.origin_p)` if `r.negated_p`
/// \pre `vpm_p` and `vpm_q` give the points the computation used (see exact_sample())
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
