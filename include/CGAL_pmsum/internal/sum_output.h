// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The output function of every entry point: the pipeline's emit(p, q, direction, trim) turned
// into a point of the geometric traits (output_point), and, where the output iterator takes
// them, into a record with its normal and provenance (make_emit).

#ifndef CGAL_PMSUM_INTERNAL_SUM_OUTPUT_H
#define CGAL_PMSUM_INTERNAL_SUM_OUTPUT_H

#include <CGAL_pmsum/Minkowski_sum_boundary_point.h>
#include <CGAL_pmsum/internal/pipeline.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <iterator>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Does `*out = r` compile? Then the output iterator receives records, else points.
template <class OutputIterator, class Record, class = void>
struct Accepts_record : std::false_type {};
template <class OutputIterator, class Record>
struct Accepts_record<OutputIterator, Record,
                      std::void_t<decltype(*std::declval<OutputIterator&>() = std::declval<const Record&>())>>
  : std::true_type {};

/// The value type an output iterator writes: its value_type, or its container's (a
/// back_inserter's is void), or void if it tells neither.
template <class OutputIterator, class = void>
struct Iterator_value { using type = void; };
template <class OutputIterator>
struct Iterator_value<OutputIterator, std::void_t<typename std::iterator_traits<OutputIterator>::value_type>>
{ using type = typename std::iterator_traits<OutputIterator>::value_type; };
template <class OutputIterator, class = void>
struct Container_value { using type = void; };
template <class OutputIterator>
struct Container_value<OutputIterator, std::void_t<typename OutputIterator::container_type>>
{ using type = typename OutputIterator::container_type::value_type; };
template <class OutputIterator>
using Written_t = std::conditional_t<std::is_void<typename Iterator_value<OutputIterator>::type>::value,
                                     typename Container_value<OutputIterator>::type,
                                     typename Iterator_value<OutputIterator>::type>;

/// Is T a Minkowski_sum_boundary_point, and of which kernel?
template <class T>
struct Record_traits : std::false_type {};
template <class P, class Q, class K>
struct Record_traits<Minkowski_sum_boundary_point<P, Q, K>> : std::true_type { using Kernel = K; };

/// Names in f the feature of the mesh that holds x (exact), a point of region `region` of a
/// flat region triangulated again: its lowest-dimensional feature among the region's old
/// triangles (region_locator.h), with x's exact weights over its vertices (the feature's
/// first; weights / denominator round them). Returns false (f unchanged) if no old triangle
/// holds x.
template <class PolygonMesh>
bool name_old_feature(Mesh_feature<PolygonMesh>& f, const Mesh_descriptors<PolygonMesh>& desc, const Mesh_data& M,
                      Index region, const std::array<CGAL::Exact_rational, 3>& x)
{
  const auto& r = desc.regions[region];
  const auto found = r.locator.locate(M.points, x);
  if (!found) return false;
  const auto& [t, w] = *found;
  int nonzero = 0, first = 0;
  for (int i = 0; i < 3; ++i) nonzero += CGAL::sign(w[i]) != CGAL::ZERO;
  f.dimension = nonzero - 1;
  // The corner listed first: the vertex; the edge's first end (its third corner has weight 0).
  for (int i = 0; i < 3; ++i) {
    const bool zero = CGAL::sign(w[i]) == CGAL::ZERO;
    if ((f.dimension == 0 && !zero) || (f.dimension == 1 && zero)) first = f.dimension == 0 ? i : (i + 1) % 3;
  }
  const auto& corners = r.locator.triangles()[t];
  if (f.dimension == 0) f.vertex = desc.vertices[corners[first]];
  else if (f.dimension == 1) f.halfedge = r.halfedges[t][first];
  else f.face = r.faces[t];
  // Rounded weights: those of the feature's vertices at least 1 (and summing to the
  // denominator), the others 0, like a lattice sample's.
  constexpr int scale = 1 << 20;
  std::array<CGAL::Exact_rational, 3> rotated;
  int left = scale;
  for (int i = 0; i < 3; ++i) {
    const int k = (first + i) % 3;
    f.vertices[i] = desc.vertices[corners[k]];
    rotated[i] = w[k];
    if (i < f.dimension) {
      const long rounded = std::lround(CGAL::to_double(w[k]) * scale);
      f.weights[i] = int((std::max)(1L, (std::min)(rounded, long(left - (f.dimension - i)))));
    } else {
      f.weights[i] = i == f.dimension ? left : 0;
    }
    left -= f.weights[i];
  }
  f.denominator = scale;
  f.rational_weights = rotated;
  return true;
}

/// Fills the public Mesh_feature of a sample s of M, or of side `side`'s part of the trim
/// point of `trim` (s: that side's sample of its first corner). In a flat region triangulated
/// again (merge_flat_regions), the feature is the mesh's own that holds the point.
template <class PolygonMesh>
Mesh_feature<PolygonMesh> to_mesh_feature(const Sample& s, const Mesh_descriptors<PolygonMesh>& desc, const Mesh_data& M,
                                          const Trim* trim = nullptr, int side = 0)
{
  using Q = CGAL::Exact_rational;
  Mesh_feature<PolygonMesh> f;
  const Feature o = trim ? (side == 0 ? trim->origin_p : trim->origin_q) : s.origin;
  const std::vector<Index>& region_of = o.dimension == 1 ? desc.region_of_edge : desc.region_of_triangle;
  const Index region = o.dimension > 0 && !region_of.empty() ? region_of[o.index] : no_index;
  if (region != no_index) {
    std::array<Q, 3> w, x = {Q(0), Q(0), Q(0)};
    if (trim) w = trim_weights(s, *trim, side);
    else for (int i = 0; i < 3; ++i) w[i] = Q(s.weights[i]) / Q(s.denominator);
    for (int i = 0; i < 3; ++i)
      if (CGAL::sign(w[i]) != CGAL::ZERO)
        for (int c = 0; c < 3; ++c) x[c] += w[i] * Q(M.points[s.vertices[i]][c]);
    if (name_old_feature(f, desc, M, region, x)) return f;
    f.dimension = 2; // (never: a face of the region)
    f.face = desc.regions[region].faces.front();
  } else {
    f.dimension = o.dimension;
    if (f.dimension == 0) f.vertex = desc.vertices[o.index];
    else if (f.dimension == 1) f.halfedge = desc.edges[o.index];
    else f.face = desc.faces[o.index];
  }
  for (int i = 0; i < 3; ++i) {
    f.vertices[i] = desc.vertices[s.vertices[i]];
    f.weights[i] = s.weights[i];
  }
  f.denominator = s.denominator;
  if (trim) f.rational_weights = trim_weights(s, *trim, side);
  return f;
}

/// The output point sp + sq (moved along the trim segment of `trim`), in GT: exact with an
/// exact number type, rounded with double.
template <class GT>
typename GT::Point_3 output_point(const Mesh_data& mp, const Mesh_data& mq, const Sample& sp, const Sample& sq,
                                  const Trim* trim)
{
  using FT = typename GT::FT;
  return typename GT::Point_3(sum_coordinate<FT>(mp, mq, sp, sq, trim, 0), sum_coordinate<FT>(mp, mq, sp, sq, trim, 1),
                              sum_coordinate<FT>(mp, mq, sp, sq, trim, 2));
}

/// The unit outward normal of the boundary at an output point (rounded).
template <class GT>
typename GT::Vector_3 output_normal(const Mesh_data& mp, const Mesh_data& mq, const Direction& direction)
{
  const auto n = direction.template vector<double>(mp, mq);
  const double len = std::sqrt(dot(n, n));
  return typename GT::Vector_3(n[0] / len, n[1] / len, n[2] / len);
}

/// emit(p, q, direction, trim) for the pipeline: writes a `Record` to `out` if it takes them,
/// else a point of the record's geometric traits.
template <class Record, class PolygonMeshP, class PolygonMeshQ, class OutputIterator>
auto make_emit(const Mesh_data& mp, const Mesh_data& mq, const Mesh_descriptors<PolygonMeshP>& desc_p,
               const Mesh_descriptors<PolygonMeshQ>& desc_q, bool negate_p, OutputIterator& out)
{
  using GT = typename Record_traits<Record>::Kernel;
  constexpr bool records = Accepts_record<OutputIterator, Record>::value;
  constexpr bool other_records = !records && Record_traits<Written_t<OutputIterator>>::value;
  static_assert(!other_records,
                "CGAL_pmsum: the output records must be Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, K> "
                "with the meshes' types and K the geometric traits of P (its vertex point map's kernel, or "
                "geom_traits)");
  return [&mp, &mq, &desc_p, &desc_q, negate_p, &out](const Sample& sp, const Sample& sq, const Direction& direction,
                                                      const Trim* trim) {
    if constexpr (records) {
      *out++ = Record{output_point<GT>(mp, mq, sp, sq, trim), output_normal<GT>(mp, mq, direction),
                      to_mesh_feature(sp, desc_p, mp, trim, 0), to_mesh_feature(sq, desc_q, mq, trim, 1), negate_p,
                      trim != nullptr};
    } else if constexpr (!other_records) { // (else only the static_assert's message)
      *out++ = output_point<GT>(mp, mq, sp, sq, trim);
    }
  };
}

/// emit(p, q, direction, trim) writing points of GT only (Q is not a mesh: a sweep's path).
template <class GT, class OutputIterator>
auto make_point_emit(const Mesh_data& mp, const Mesh_data& mq, OutputIterator& out)
{
  constexpr bool records = Record_traits<Written_t<OutputIterator>>::value;
  static_assert(!records, "CGAL_pmsum: this entry point writes points (Point_3), not records");
  return [&mp, &mq, &out](const Sample& sp, const Sample& sq, const Direction&, const Trim* trim) {
    if constexpr (!records) *out++ = output_point<GT>(mp, mq, sp, sq, trim);
  };
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_SUM_OUTPUT_H
