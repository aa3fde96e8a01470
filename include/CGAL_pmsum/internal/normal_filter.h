// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 2 of the pipeline: the normal filter (paper section 5), decided per feature pair.
//
// By Kaul and Rossignac, a facet of the boundary of P + Q lies on the sum of
//   case 1: a facet f of P and a vertex v of Q (or the reverse) with v locally extreme in
//           the outward direction of f, or
//   case 2: two non-parallel edges of P and Q that are locally extreme in a common
//           direction normal to both.
// We call those the "2D pairs". A boundary point is in the closure of a boundary facet, so
// the lower-dimensional pairs (cases 3 and 4: vertex-edge, edge-vertex, vertex-vertex) are
// kept exactly when they lie in the closure of a kept 2D pair, and every other pair
// (case 5: facet-facet, facet-edge, edge-facet) is dropped. Each kept pair remembers the
// outward directions of the 2D pairs it came from: the CD filter perturbs the candidate
// along them.
//
// Local extremality is decided exactly. For a vertex we test its edges, as the paper does;
// that is necessary, not sufficient (the bottom vertex of a pit passes), so the filter may
// keep a few more pairs than needed but never drops one it must keep. Meshes with borders
// are surfaces: their facets face both ways and their edges need not be convex.

#ifndef CGAL_PMSUM_INTERNAL_NORMAL_FILTER_H
#define CGAL_PMSUM_INTERNAL_NORMAL_FILTER_H

#include <CGAL_pmsum/internal/direction_grid.h>
#include <CGAL_pmsum/internal/parallel.h>
#include <CGAL_pmsum/internal/sampling.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// An outward direction of a candidate, kept symbolically so that it can be evaluated
/// with any number type.
struct Direction
{
  enum Kind : std::uint8_t { FACET_OF_P = 0, FACET_OF_Q = 1, EDGES = 2 };
  Kind kind;
  std::int8_t sign; // +1 or -1
  Index a, b;       // facet a (of P or Q), or edge a of P and edge b of Q

  bool operator==(const Direction& o) const
  { return kind == o.kind && sign == o.sign && a == o.a && b == o.b; }
  bool operator<(const Direction& o) const
  {
    if (kind != o.kind) return kind < o.kind;
    if (a != o.a) return a < o.a;
    if (b != o.b) return b < o.b;
    return sign < o.sign;
  }

  template <class NT>
  Vec3<NT> vector(const Mesh_data& P, const Mesh_data& Q) const
  {
    Vec3<NT> n = kind == FACET_OF_P ? P.triangle_normal<NT>(a)
               : kind == FACET_OF_Q ? Q.triangle_normal<NT>(a)
                                    : cross(P.edge_vector<NT>(a), Q.edge_vector<NT>(b));
    return sign > 0 ? n : Vec3<NT>{-n[0], -n[1], -n[2]};
  }
};

/// A pair of features (one of P, one of Q) whose sample sums are candidates, with the
/// directions [first_direction, first_direction + number_of_directions) of
/// Candidate_pairs::directions.
struct Feature_pair
{
  Feature p, q;
  std::uint32_t first_direction, number_of_directions;
};

struct Candidate_pairs
{
  std::vector<Feature_pair> pairs; // sorted by (p, q): a canonical order
  std::vector<Direction> directions;
};

/// Sign of (w - o) . n for mesh points o, w and a direction.
inline CGAL::Sign side(const Mesh_data& M, Index o, Index w, const Direction& d,
                       const Mesh_data& P, const Mesh_data& Q)
{
  return filtered_sign([&](auto nt) {
    using NT = decltype(nt);
    return dot(M.point<NT>(w) - M.point<NT>(o), d.vector<NT>(P, Q));
  });
}

/// Is vertex v of M locally extreme in direction d (no incident edge goes up; a flat star
/// of a closed mesh must also face d)?
inline bool vertex_is_extreme(const Mesh_data& M, Index v, const Direction& d,
                              const Mesh_data& P, const Mesh_data& Q)
{
  bool all_flat = true;
  for (Index i = M.vertex_edge_offsets[v]; i < M.vertex_edge_offsets[v + 1]; ++i) {
    const auto& e = M.edges[M.vertex_edges[i]];
    const CGAL::Sign s = side(M, v, e.v[0] == v ? e.v[1] : e.v[0], d, P, Q);
    if (s == CGAL::POSITIVE) return false;
    all_flat &= (s == CGAL::ZERO);
  }
  if (!all_flat || !M.vertex_is_closed(v)) return true;
  const Index t = M.vertex_triangles[M.vertex_triangle_offsets[v]];
  return filtered_sign([&](auto nt) {
           using NT = decltype(nt);
           return dot(M.triangle_normal<NT>(t), d.vector<NT>(P, Q));
         }) == CGAL::POSITIVE;
}

/// Is edge e of M locally extreme in direction d, assumed orthogonal to e?
inline bool edge_is_extreme(const Mesh_data& M, Index e, const Direction& d,
                            const Mesh_data& P, const Mesh_data& Q)
{
  const auto& edge = M.edges[e];
  const bool closed = M.edge_is_closed(e);
  if (closed && !edge.convex) return false;
  bool all_flat = true;
  for (Index t : edge.f) {
    if (t == no_index) continue;
    const CGAL::Sign s = side(M, edge.v[0], M.opposite_vertex(t, e), d, P, Q);
    if (s == CGAL::POSITIVE) return false;
    all_flat &= (s == CGAL::ZERO);
  }
  if (!all_flat || !closed) return true;
  return filtered_sign([&](auto nt) {
           using NT = decltype(nt);
           return dot(M.triangle_normal<NT>(edge.f[0]), d.vector<NT>(P, Q));
         }) == CGAL::POSITIVE;
}

/// The outward normals at which edge e of mesh E and vertex v of mesh V are both locally
/// extreme: those of e's wedge (between its two triangles' normals) that leave every edge of
/// v's star below v. If they are a wedge of positive angle, e + v is a crease of the sum's
/// boundary where it is on it, between two faces whose normals are the wedge's ends
/// (returned, not normalized): two triangles of E moved by v, or one and a strip of e plus an
/// edge of V. Double arithmetic: it only chooses points and planes for a mesh.
inline std::optional<std::array<Vec3<double>, 2>> crease_wedge(const Mesh_data& E, Index e, const Mesh_data& V, Index v)
{
  const auto& edge = E.edges[e];
  if (edge.f[1] == no_index || !edge.convex) return std::nullopt;
  const Vec3<double> n0 = E.triangle_normal<double>(edge.f[0]), n1 = E.triangle_normal<double>(edge.f[1]);
  const Vec3<double> dn = n1 - n0;
  double lo = 0, hi = 1; // the wedge n0 + t (n1 - n0), t in [lo, hi]
  for (Index i = V.vertex_edge_offsets[v]; i < V.vertex_edge_offsets[v + 1] && lo < hi; ++i) {
    const auto& f = V.edges[V.vertex_edges[i]];
    const Vec3<double> u = V.points[f.v[0] == v ? f.v[1] : f.v[0]] - V.points[v];
    const double a = dot(n0, u), b = dot(dn, u); // a + t b <= 0
    if (b > 0) hi = (std::min)(hi, -a / b);
    else if (b < 0) lo = (std::max)(lo, -a / b);
    else if (a > 0) return std::nullopt;
  }
  if (!(lo < hi)) return std::nullopt;
  auto at = [&](double t) { return n0 + Vec3<double>{t * dn[0], t * dn[1], t * dn[2]}; };
  return std::array<Vec3<double>, 2>{at(lo), at(hi)};
}

/// Calls f(wedge, E, e) for each crease_wedge() of the sum of sample features fp of P and fq
/// of Q (e: the edge, of mesh E): an edge and a vertex (one), or two vertices (every edge at
/// either with the other vertex); none for features of higher dimensions.
template <class F>
void for_each_crease_wedge(Feature fp, Feature fq, const Mesh_data& P, const Mesh_data& Q, F&& f)
{
  if (fp.dimension + fq.dimension > 1) return;
  auto edges_and_vertex = [&](Feature a, Feature v, const Mesh_data& E, const Mesh_data& V) {
    auto one = [&](Index e) {
      if (const auto w = crease_wedge(E, e, V, v.index)) f(*w, E, e);
    };
    if (a.dimension == 1) one(a.index);
    else
      for (Index i = E.vertex_edge_offsets[a.index]; i < E.vertex_edge_offsets[a.index + 1]; ++i) one(E.vertex_edges[i]);
  };
  if (fq.dimension == 0) edges_and_vertex(fp, fq, P, Q);
  if (fp.dimension == 0) edges_and_vertex(fq, fp, Q, P);
}

/// Is the sum of sample features fp of P and fq of Q on a crease of the sum along a sharp edge
/// (its triangles' normals more than 20 degrees apart), or a vertex sum at an end of one? The
/// edge's wedge, not the crease's: a strip of the edge plus an edge of the other mesh splits
/// it into creases that may be far less sharp (one nearly flat), and both are needed.
inline bool on_sharp_crease(Feature fp, Feature fq, const Mesh_data& P, const Mesh_data& Q)
{
  bool sharp = false;
  for_each_crease_wedge(fp, fq, P, Q, [&](const std::array<Vec3<double>, 2>&, const Mesh_data& E, Index e) {
    const Vec3<double> a = E.triangle_normal<double>(E.edges[e].f[0]), b = E.triangle_normal<double>(E.edges[e].f[1]);
    const double cos_20 = 0.9396926207859084;
    sharp = sharp || dot(a, b) < cos_20 * std::sqrt(dot(a, a) * dot(b, b));
  });
  return sharp;
}

/// Hash key of a feature pair.
struct Pair_key
{
  std::uint64_t p, q;
  static Pair_key of(Feature a, Feature b)
  { return {(std::uint64_t(a.dimension) << 32) | a.index, (std::uint64_t(b.dimension) << 32) | b.index}; }
  Feature p_feature() const { return {int(p >> 32), Index(p & 0xffffffffu)}; }
  Feature q_feature() const { return {int(q >> 32), Index(q & 0xffffffffu)}; }
  bool operator==(const Pair_key& o) const { return p == o.p && q == o.q; }
  bool operator<(const Pair_key& o) const { return p != o.p ? p < o.p : q < o.q; }
};

/// The closure of a feature: itself, its edges and its vertices.
inline std::vector<Feature> closure(const Mesh_data& M, Feature f)
{
  std::vector<Feature> out{f};
  if (f.dimension == 2) {
    for (Index e : M.triangle_edges[f.index]) out.push_back({1, e});
    for (Index v : M.triangles[f.index]) out.push_back({0, v});
  } else if (f.dimension == 1) {
    for (Index v : M.edges[f.index].v) out.push_back({0, v});
  }
  return out;
}

/// Outward facet directions of triangle t of M (both orientations on a surface).
inline void facet_directions(const Mesh_data& M, Direction::Kind kind, Index t, std::vector<Direction>& out)
{
  out.push_back({kind, 1, t, 0});
  if (!M.triangle_is_closed(t)) out.push_back({kind, -1, t, 0});
}

/// The kept feature pairs. Without the normal filter every feature pair is kept; pairs the
/// filter would have dropped get the facet directions around their features. The tests run
/// by chunks of facets and edges, in parallel if asked, shared among the ranks of `comm`
/// (collective) if not null; the result is sorted, hence the same.
/// Without the normal filter, throws Too_many_feature_pairs before allocating them if the
/// (pair, direction) records to store would be more than `max_records`.
inline Candidate_pairs candidate_feature_pairs(const Mesh_data& P, const Mesh_data& Q, bool use_normal_filter,
                                               bool parallel = false,
                                               std::size_t max_records = std::size_t(-1),
                                               Communicator* comm = nullptr)
{
  if (!use_normal_filter) {
    // Each pair (a, b) stores the facet directions around a and those around b (at most).
    auto count = [](const Mesh_data& M, std::size_t& features, std::size_t& directions) {
      auto around_triangle = [&](Index t) { return M.triangle_is_closed(t) ? 1 : 2; };
      features = directions = 0;
      for (Index v = 0; v < M.number_of_vertices(); ++v) {
        if (M.vertex_is_isolated(v)) continue;
        ++features;
        for (Index i = M.vertex_triangle_offsets[v]; i < M.vertex_triangle_offsets[v + 1]; ++i)
          directions += around_triangle(M.vertex_triangles[i]);
      }
      for (const auto& e : M.edges) {
        ++features;
        for (Index t : e.f) if (t != no_index) directions += around_triangle(t);
      }
      for (Index t = 0; t < M.number_of_triangles(); ++t) { ++features; directions += around_triangle(t); }
    };
    std::size_t fp, dp, fq, dq;
    count(P, fp, dp);
    count(Q, fq, dq);
    const long double records = (long double)(fq) * dp + (long double)(fp) * dq; // no overflow
    if (records > (long double)(max_records)) {
      const std::size_t n = records >= (long double)(std::size_t(-1)) ? std::size_t(-1) : std::size_t(records);
      throw Too_many_feature_pairs(n, max_records,
                                "without the normal filter, the " + std::to_string(fp) + " x " + std::to_string(fq) +
                                  " feature pairs need up to " + std::to_string(n) +
                                  " (pair, direction) records, more than the limit of " + std::to_string(max_records));
    }
  }
  // Kept (pair, direction) records, per chunk of the loops below; sorted and merged at the end.
  struct Kept
  {
    Pair_key first;
    Direction second;
    bool operator==(const Kept& o) const { return first == o.first && second == o.second; }
  };
  auto keep_closure = [&](std::vector<Kept>& kept, Feature fp, Feature fq, const Direction& d) {
    for (Feature a : closure(P, fp))
      for (Feature b : closure(Q, fq)) kept.push_back({Pair_key::of(a, b), d});
  };
  constexpr std::size_t chunks = 64;

  // The direction grid limits the exact tests to pairs that may be extreme in a common
  // cell of directions (see direction_grid.h); the kept pairs are the same as with all pairs.
  const Direction_grid grid;
  using V = Direction_grid::V;
  auto diff = [](const Mesh_data& M, Index a, Index b) { return M.points[b] - M.points[a]; };
  // cells where vertex v may be extreme: no incident edge is up for every direction of the cell
  auto vertex_cells = [&](const Mesh_data& M) {
    std::vector<std::vector<Index>> by_cell(grid.size());
    for (Index v = 0; v < M.number_of_vertices(); ++v) {
      if (M.vertex_is_isolated(v)) continue;
      for (int c = 0; c < grid.size(); ++c) {
        bool possible = true;
        for (Index i = M.vertex_edge_offsets[v]; i < M.vertex_edge_offsets[v + 1] && possible; ++i) {
          const auto& e = M.edges[M.vertex_edges[i]];
          possible = !grid.strictly_positive(c, diff(M, v, e.v[0] == v ? e.v[1] : e.v[0]));
        }
        if (possible) by_cell[c].push_back(v);
      }
    }
    return by_cell;
  };
  // cells where edge e may be extreme: they meet the circle orthogonal to e, and no far
  // vertex is up for every direction of the cell
  auto edge_cells = [&](const Mesh_data& M) {
    std::vector<std::vector<Index>> cells(M.number_of_edges());
    for (Index e = 0; e < M.number_of_edges(); ++e) {
      const auto& edge = M.edges[e];
      if (M.edge_is_closed(e) && !edge.convex) continue;
      const V ev = diff(M, edge.v[0], edge.v[1]);
      for (int c = 0; c < grid.size(); ++c) {
        bool possible = grid.meets_plane(c, ev);
        for (Index t : edge.f)
          if (possible && t != no_index) possible = !grid.strictly_positive(c, diff(M, edge.v[0], M.opposite_vertex(t, e)));
        if (possible) cells[e].push_back(Index(c));
      }
    }
    return cells;
  };
  // The vertices to test for a facet direction: those of its cell (all of them in the
  // unlikely case that the double normal underflows to zero).
  auto candidates = [&](const std::vector<std::vector<Index>>& by_cell, const Direction& d, const Mesh_data& M) {
    const auto n = d.vector<double>(P, Q);
    if (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]) > 0 && std::isfinite(n[0] + n[1] + n[2]))
      return by_cell[grid.cell_of(n)];
    std::vector<Index> all;
    for (Index v = 0; v < M.number_of_vertices(); ++v)
      if (!M.vertex_is_isolated(v)) all.push_back(v);
    return all;
  };

  // Case 1: facet of P and vertex of Q, vertex of P and facet of Q.
  const auto q_vertices = vertex_cells(Q);
  const auto p_vertices = vertex_cells(P);
  auto kept_by_chunk = map_chunks<Kept>(2 * chunks, parallel, comm, [&](std::size_t job, std::vector<Kept>& kept) {
    const bool p_facets = job < chunks;
    const Mesh_data &F = p_facets ? P : Q, &V = p_facets ? Q : P;
    const auto [first, last] = chunk_range(job % chunks, chunks, F.number_of_triangles());
    std::vector<Direction> dirs;
    for (Index t = Index(first); t < Index(last); ++t) {
      dirs.clear();
      facet_directions(F, p_facets ? Direction::FACET_OF_P : Direction::FACET_OF_Q, t, dirs);
      for (const Direction& d : dirs)
        for (Index v : candidates(p_facets ? q_vertices : p_vertices, d, V))
          if (vertex_is_extreme(V, v, d, P, Q)) {
            if (p_facets) keep_closure(kept, {2, t}, {0, v}, d);
            else keep_closure(kept, {0, v}, {2, t}, d);
          }
    }
  });
  // Case 2: non-parallel edges extreme in a common normal direction.
  const auto p_edges = edge_cells(P), q_edges = edge_cells(Q);
  std::vector<std::vector<Index>> q_edges_by_cell(grid.size());
  for (Index b = 0; b < Q.number_of_edges(); ++b)
    for (Index c : q_edges[b]) q_edges_by_cell[c].push_back(b);
  auto edge_pairs = map_chunks<Kept>(chunks, parallel, comm, [&](std::size_t chunk, std::vector<Kept>& kept) {
    std::vector<Index> seen(Q.number_of_edges(), no_index); // last edge of P that paired with b
    const auto [first, last] = chunk_range(chunk, chunks, P.number_of_edges());
    for (Index a = Index(first); a < Index(last); ++a) {
      for (Index c : p_edges[a])
        for (Index b : q_edges_by_cell[c]) {
          if (seen[b] == a) continue;
          seen[b] = a;
          const Direction plus{Direction::EDGES, 1, a, b};
          bool is_parallel = true;
          for (int k = 0; k < 3 && is_parallel; ++k)
            is_parallel = filtered_sign([&](auto nt) { return plus.vector<decltype(nt)>(P, Q)[k]; }) == CGAL::ZERO;
          if (is_parallel) continue;
          for (std::int8_t sgn : {1, -1}) {
            const Direction d{Direction::EDGES, sgn, a, b};
            if (edge_is_extreme(P, a, d, P, Q) && edge_is_extreme(Q, b, d, P, Q))
              keep_closure(kept, {1, a}, {1, b}, d);
          }
        }
    }
  });
  for (auto& k : edge_pairs) kept_by_chunk.push_back(std::move(k));
  std::vector<Kept> kept = concatenate(std::move(kept_by_chunk));
  auto by_pair_then_direction = [](const Kept& x, const Kept& y) {
    return x.first == y.first ? x.second < y.second : x.first < y.first;
  };
  std::sort(kept.begin(), kept.end(), by_pair_then_direction);
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());

  if (!use_normal_filter) {
    auto around = [](const Mesh_data& M, Direction::Kind kind, Feature f, std::vector<Direction>& out) {
      if (f.dimension == 2) return facet_directions(M, kind, f.index, out);
      if (f.dimension == 1) {
        for (Index t : M.edges[f.index].f) if (t != no_index) facet_directions(M, kind, t, out);
        return;
      }
      for (Index i = M.vertex_triangle_offsets[f.index]; i < M.vertex_triangle_offsets[f.index + 1]; ++i)
        facet_directions(M, kind, M.vertex_triangles[i], out);
    };
    auto all_features = [](const Mesh_data& M) {
      std::vector<Feature> fs;
      for (Index v = 0; v < M.number_of_vertices(); ++v)
        if (!M.vertex_is_isolated(v)) fs.push_back({0, v});
      for (Index e = 0; e < M.number_of_edges(); ++e) fs.push_back({1, e});
      for (Index t = 0; t < M.number_of_triangles(); ++t) fs.push_back({2, t});
      return fs;
    };
    const std::vector<Feature> fp_all = all_features(P), fq_all = all_features(Q);
    std::vector<Kept> others;
    std::vector<Direction> d;
    for (Feature a : fp_all)
      for (Feature b : fq_all) {
        const Pair_key key = Pair_key::of(a, b);
        const auto it = std::lower_bound(kept.begin(), kept.end(), key,
                                         [](const Kept& k, const Pair_key& x) { return k.first < x; });
        if (it != kept.end() && it->first == key) continue;
        d.clear();
        around(P, Direction::FACET_OF_P, a, d);
        around(Q, Direction::FACET_OF_Q, b, d);
        for (const Direction& x : d) others.push_back({key, x});
      }
    kept.insert(kept.end(), others.begin(), others.end());
    std::sort(kept.begin(), kept.end(), by_pair_then_direction);
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  }

  Candidate_pairs out;
  out.directions.reserve(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (i == 0 || !(kept[i].first == kept[i - 1].first))
      out.pairs.push_back({kept[i].first.p_feature(), kept[i].first.q_feature(), std::uint32_t(i), 0});
    ++out.pairs.back().number_of_directions;
    out.directions.push_back(kept[i].second);
  }
  return out;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_NORMAL_FILTER_H
