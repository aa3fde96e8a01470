// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_offset_mesh(): a checked triangle mesh of the boundary of the offset P + B
// (B a ball from make_icosphere(), or a cube): the offset is the Minkowski sum, so this is
// point_minkowski_sum_mesh() of P and B, with its guarantees.

#ifndef CGAL_PMSUM_POINT_OFFSET_MESH_H
#define CGAL_PMSUM_POINT_OFFSET_MESH_H

#include <CGAL_pmsum/point_minkowski_sum_mesh.h>
#include <CGAL_pmsum/point_offset.h>

namespace CGAL {

/// \ingroup PkgPointMinkowskiSumMesh
/// Computes a triangle mesh of the boundary of the offset `P + B` (e.g. `B` from
/// make_icosphere(), or a cube for an offset in the maximum norm): point_minkowski_sum_mesh()
/// of `P` and `B`, with the same guarantees. Its vertices are exact points of the offset's
/// boundary (with a ball from make_icosphere(), each at a distance between the ball's
/// inradius and `r` from the surface of `P`); the mesh is closed, 2-manifold, outward
/// oriented and free of self-intersections, or `CGAL::Pmsum::Mesh_reconstruction_failed` is
/// thrown.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMesh, StructuringMesh models of `FaceListGraph`
/// \tparam TriangleMesh as for point_minkowski_sum_mesh()
/// \param P the solid to offset
/// \param B the structuring element, e.g. a ball containing the origin
/// \param d covering distance of the vertices
/// \param mesh the output (cleared first)
/// \param np_p named parameters of `P` and of the algorithm, as `np_p` of point_minkowski_sum_mesh()
/// \param np_b named parameters of `B`, as `np_q` of point_minkowski_sum_mesh()
/// \pre the preconditions of point_minkowski_sum_mesh() for `P` and `B`; violations throw
///      `CGAL::Pmsum::Invalid_input`
/// \throws CGAL::Pmsum::Mesh_reconstruction_failed if no valid mesh was made
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh, class StructuringMesh, class TriangleMesh,
          class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersB = parameters::Default_named_parameters>
void point_offset_mesh(const PolygonMesh& P, const StructuringMesh& B, double d, TriangleMesh& mesh,
                       const NamedParametersP& np_p = parameters::default_values(),
                       const NamedParametersB& np_b = parameters::default_values())
{
  point_minkowski_sum_mesh<ConcurrencyTag>(P, B, d, mesh, np_p, np_b);
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_OFFSET_MESH_H
