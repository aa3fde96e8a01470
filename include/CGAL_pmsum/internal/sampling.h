// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 1 of the pipeline: deterministic samples with origins.
//
// A triangle t is sampled by the lattice {(i a + j b + k c) / N_t : i + j + k = N_t}. The
// lattice cuts t into N_t^2 copies of t scaled by 1/N_t, and any point of a triangle T is
// closer to one of T's corners than f(T) = circumradius (T not obtuse) or half the longest
// edge (T obtuse). Choosing N_t = ceil(f(t) / radius) makes the closed lattice a
// radius-covering of t. Its interior points are the samples whose origin is the facet.
//
// An edge is sampled at the parameters {k / D : 0 < k < D} for D in {N_e, N_t1, N_t2}: its
// own subdivision N_e = ceil(length / (sqrt(2) radius)) (spacing <= sqrt(2) radius, so that
// the edge-edge grids of the sum are radius-coverings of their parallelograms) and the
// boundary points of the lattices of its incident triangles (so that every closed facet
// lattice is in the sample set). Vertices are samples of their own.
//
// Every sample is stored exactly: vertex indices, integer weights and a denominator.

#ifndef CGAL_PMSUM_INTERNAL_SAMPLING_H
#define CGAL_PMSUM_INTERNAL_SAMPLING_H

#include <CGAL_pmsum/internal/mesh_data.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Largest lattice denominator; keeps every integer of the exact computations below 2^53.
constexpr std::int64_t max_denominator = std::int64_t(1) << 20;

/// A vertex, edge or triangle of a mesh.
struct Feature
{
  int dimension; // 0, 1 or 2
  Index index;
  bool operator==(const Feature& o) const { return dimension == o.dimension && index == o.index; }
  bool operator<(const Feature& o) const
  { return dimension != o.dimension ? dimension < o.dimension : index < o.index; }
};

/// A sample: the point sum_i weights[i] * vertex(vertices[i]) / denominator, exactly.
struct Sample
{
  Feature origin;
  std::array<Index, 3> vertices;
  std::array<std::int32_t, 3> weights;
  std::int32_t denominator;
};

/// Coordinate c of sample s in the number type FT of an output kernel: exact with an exact
/// kernel (the sample is exactly on its feature), rounded otherwise.
template <class FT>
FT sample_coordinate(const Mesh_data& M, const Sample& s, int c)
{
  FT v(0);
  for (int i = 0; i < 3; ++i)
    if (s.weights[i] != 0) v += FT(s.weights[i]) * FT(M.points[s.vertices[i]][c]);
  return v / FT(s.denominator);
}

/// f(T) of the header comment, computed from the edge lengths.
inline double triangle_covering_radius(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                       const std::array<double, 3>& c)
{
  auto sq = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]) + (u[2] - v[2]) * (u[2] - v[2]);
  };
  double l[3] = {sq(b, c), sq(c, a), sq(a, b)};
  std::sort(l, l + 3);
  if (l[2] >= l[0] + l[1]) return std::sqrt(l[2]) / 2; // right or obtuse
  const std::array<double, 3> u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const std::array<double, 3> v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double area2 = std::sqrt(dot(cross(u, v), cross(u, v))); // twice the area
  return std::sqrt(l[0] * l[1] * l[2]) / (2 * area2);            // abc / (4 area)
}

/// Lattice resolutions of one mesh for a covering radius.
class Mesh_sampling
{
public:
  /// With `coarser` (a sampling of the same mesh with a larger radius), every resolution is
  /// rounded up to a multiple of the coarser one, so that every coarser sample is a sample
  /// here too (coarse-to-fine runs reuse the coarser level's decisions).
  Mesh_sampling(const Mesh_data& mesh, double radius, const std::string& name,
                const Mesh_sampling* coarser = nullptr)
    : m_mesh(&mesh)
  {
    // A small safety factor absorbs the rounding of the double computations of f(T).
    auto resolution = [&](double length, std::int32_t multiple_of) {
      double n = (std::max)(1., std::ceil(length * (1 + 1e-9) / radius));
      n = multiple_of * std::ceil(n / multiple_of);
      if (!(n <= double(max_denominator)))
        throw Covering_distance_too_small("d is too small for " + name + ": a feature would need more than " +
                            std::to_string(max_denominator) + " subdivisions");
      return std::int32_t(n);
    };
    for (Index t = 0; t < mesh.number_of_triangles(); ++t) {
      const auto& tri = mesh.triangles[t];
      m_triangle_n.push_back(resolution(triangle_covering_radius(mesh.points[tri[0]], mesh.points[tri[1]],
                                                                 mesh.points[tri[2]]),
                                        coarser ? coarser->m_triangle_n[t] : 1));
    }
    for (Index e = 0; e < mesh.number_of_edges(); ++e) {
      const auto v = mesh.points[mesh.edges[e].v[1]] - mesh.points[mesh.edges[e].v[0]];
      m_edge_n.push_back(resolution(std::sqrt(dot(v, v)) / std::sqrt(2.), coarser ? coarser->m_edge_n[e] : 1));
    }
  }

  /// Is s (a sample of this sampling) also a sample of `coarser` (the sampling this one was
  /// built from)?
  bool is_sample_of(const Sample& s, const Mesh_sampling& coarser) const
  {
    if (s.origin.dimension == 0) return true;
    if (s.origin.dimension == 2) {
      const std::int32_t m = s.denominator / coarser.m_triangle_n[s.origin.index];
      return s.weights[0] % m == 0 && s.weights[1] % m == 0 && s.weights[2] % m == 0;
    }
    bool found = false; // the parameter k / den equal to one of the coarser edge parameters?
    coarser.for_each_edge_denominator(s.origin.index, [&](std::int32_t den) {
      found |= (std::int64_t(s.weights[1]) * den) % s.denominator == 0;
    });
    return found;
  }

  const Mesh_data& mesh() const { return *m_mesh; }
  std::int32_t triangle_resolution(Index t) const { return m_triangle_n[t]; }

  /// Appends the samples whose origin is `f` (interior of f only) to `out`.
  void samples(Feature f, std::vector<Sample>& out) const
  {
    if (f.dimension == 0) {
      out.push_back({f, {f.index, f.index, f.index}, {1, 0, 0}, 1});
    } else if (f.dimension == 1) {
      const auto& e = m_mesh->edges[f.index];
      for_each_edge_parameter(f.index, [&](std::int32_t k, std::int32_t den) {
        out.push_back({f, {e.v[0], e.v[1], e.v[1]}, {den - k, k, 0}, den});
      });
    } else {
      triangle_samples(f.index, 0, m_triangle_n[f.index], out);
    }
  }

  /// Appends the samples interior to triangle t whose first weight i lies in [first, last)
  /// (the rows of its lattice, trim_points.h), in the order of samples().
  void triangle_samples(Index t, std::int32_t first, std::int32_t last, std::vector<Sample>& out) const
  {
    const std::int32_t n = m_triangle_n[t];
    const auto& tri = m_mesh->triangles[t];
    for (std::int32_t i = (std::max)(first, 1); i < (std::min)(last, n); ++i)
      for (std::int32_t j = 1; i + j < n; ++j)
        out.push_back({Feature{2, t}, tri, {i, j, n - i - j}, n});
  }

  /// Number of samples whose origin is `f`.
  std::size_t number_of_samples(Feature f) const
  {
    if (f.dimension == 0) return 1;
    if (f.dimension == 1) {
      // The distinct fractions k/a, k/b, k/c in (0, 1) (for_each_edge_parameter), counted by
      // inclusion-exclusion: those of both a and b are the k/gcd(a, b). O(1), not O(samples):
      // the refusal of a d too small counts the candidates of every pair first.
      const auto& edge = m_mesh->edges[f.index];
      const std::int64_t a = m_edge_n[f.index], b = edge.f[0] == no_index ? 1 : m_triangle_n[edge.f[0]],
                         c = edge.f[1] == no_index ? 1 : m_triangle_n[edge.f[1]];
      return std::size_t(a + b + c - std::gcd(a, b) - std::gcd(a, c) - std::gcd(b, c) + std::gcd(std::gcd(a, b), c) - 1);
    }
    const std::size_t n = std::size_t(m_triangle_n[f.index]);
    return n < 3 ? 0 : (n - 1) * (n - 2) / 2;
  }

  /// Total number of samples of the mesh.
  std::size_t number_of_samples() const
  {
    std::size_t count = 0;
    for (Index v = 0; v < m_mesh->number_of_vertices(); ++v) count += !m_mesh->vertex_is_isolated(v);
    for (Index e = 0; e < m_mesh->number_of_edges(); ++e) count += number_of_samples(Feature{1, e});
    for (Index t = 0; t < m_mesh->number_of_triangles(); ++t) count += number_of_samples(Feature{2, t});
    return count;
  }

  /// The parameters k / den of edge e's samples with 0 / 1 and 1 / 1 added, increasing.
  std::vector<std::pair<std::int32_t, std::int32_t>> closed_edge_parameters(Index e) const
  {
    std::vector<std::pair<std::int32_t, std::int32_t>> r = {{0, 1}, {1, 1}};
    for_each_edge_parameter(e, [&](std::int32_t k, std::int32_t den) { r.emplace_back(k, den); });
    std::sort(r.begin(), r.end(), [](const auto& a, const auto& b) {
      return std::int64_t(a.first) * b.second < std::int64_t(b.first) * a.second;
    });
    return r;
  }

private:
  /// Calls f(k, den) for the distinct parameters k/den in (0, 1) of edge e (see header).
  template <class F>
  void for_each_edge_denominator(Index e, const F& f) const
  {
    const auto& edge = m_mesh->edges[e];
    f(m_edge_n[e]);
    if (edge.f[0] != no_index) f(m_triangle_n[edge.f[0]]);
    if (edge.f[1] != no_index) f(m_triangle_n[edge.f[1]]);
  }

  template <class F>
  void for_each_edge_parameter(Index e, const F& f) const
  {
    const auto& edge = m_mesh->edges[e];
    std::int32_t dens[3] = {m_edge_n[e], edge.f[0] == no_index ? 1 : m_triangle_n[edge.f[0]],
                            edge.f[1] == no_index ? 1 : m_triangle_n[edge.f[1]]};
    for (int i = 0; i < 3; ++i) {
      const std::int32_t den = dens[i];
      bool repeated = false;
      for (int j = 0; j < i; ++j) repeated |= (dens[j] == den);
      if (repeated) continue;
      for (std::int32_t k = 1; k < den; ++k) {
        bool seen = false; // k/den equal to a parameter of an earlier denominator?
        for (int j = 0; j < i && !seen; ++j)
          seen = (std::int64_t(k) * dens[j]) % den == 0;
        if (!seen) f(k, den);
      }
    }
  }

  const Mesh_data* m_mesh;
  std::vector<std::int32_t> m_triangle_n, m_edge_n;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_SAMPLING_H
