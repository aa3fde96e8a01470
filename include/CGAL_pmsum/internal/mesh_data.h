// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input stage: a triangle mesh (any CGAL FaceListGraph) is validated and copied into flat
// arrays of exact double coordinates, with the combinatorics the later stages need
// (edges with their incident triangles, vertex stars, connected components, which
// components are closed). The user's descriptors are kept so that every output point can
// name the vertex, edge or face it came from.

#ifndef CGAL_PMSUM_INTERNAL_MESH_DATA_H
#define CGAL_PMSUM_INTERNAL_MESH_DATA_H

#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/exact_sign.h>
#include <CGAL_pmsum/internal/planar_patches.h>
#include <CGAL_pmsum/internal/region_locator.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

using Index = std::uint32_t;
constexpr Index no_index = std::numeric_limits<Index>::max();

/// Flat, validated copy of one input mesh. If the mesh is negated (the contact space
/// -P), coordinates are negated and triangles reversed, so that normals stay outward.
struct Mesh_data
{
  struct Edge
  {
    std::array<Index, 2> v;   // endpoints; v[0] -> v[1] is the orientation of triangle f[0]
    std::array<Index, 2> f;   // incident triangles; f[1] == no_index on a border edge
    bool convex;              // border edges and convex or flat interior edges
    bool flat = false;        // interior edges whose two triangles are coplanar
  };
  struct Component
  {
    bool closed = true;                 // no border edge: bounds a volume
    Index representative_vertex = no_index;
    std::array<double, 3> min{}, max{}; // bounding box of its vertices
  };

  std::vector<std::array<double, 3>> points;
  std::vector<std::array<Index, 3>> triangles;      // outward (counterclockwise seen from outside)
  std::vector<std::array<Index, 3>> triangle_edges; // edge of (t[i], t[(i+1)%3])
  std::vector<Edge> edges;
  std::vector<Index> vertex_edge_offsets, vertex_edges;         // CSR: edges around a vertex
  std::vector<Index> vertex_triangle_offsets, vertex_triangles; // CSR: triangles around a vertex
  std::vector<Index> vertex_component, triangle_component;
  std::vector<Component> components;
  std::vector<Index> bare_edges; // edges without any triangle (polylines: sweep paths)

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_edges() const { return edges.size(); }
  std::size_t number_of_triangles() const { return triangles.size(); }

  bool has_open_component() const
  {
    return std::any_of(components.begin(), components.end(),
                       [](const Component& c) { return !c.closed; });
  }
  bool triangle_is_closed(Index t) const { return components[triangle_component[t]].closed; }
  bool vertex_is_closed(Index v) const { return components[vertex_component[v]].closed; }
  /// Vertices on no edge (unused by any face) are ignored by every stage.
  bool vertex_is_isolated(Index v) const { return vertex_edge_offsets[v] == vertex_edge_offsets[v + 1]; }
  bool edge_is_closed(Index e) const { return vertex_is_closed(edges[e].v[0]); }

  template <class NT> Vec3<NT> point(Index v) const { return to_nt<NT>(points[v]); }

  /// Outward normal (b - a) x (c - a) of triangle t, not normalized.
  template <class NT> Vec3<NT> triangle_normal(Index t) const
  { return internal::triangle_normal<NT>(points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]]); }
  /// Vertex of triangle t that is not on edge e.
  Index opposite_vertex(Index t, Index e) const
  {
    for (int i = 0; i < 3; ++i)
      if (triangle_edges[t][i] == e) return triangles[t][(i + 2) % 3];
    return no_index;
  }
  template <class NT> Vec3<NT> edge_vector(Index e) const
  { return point<NT>(edges[e].v[1]) - point<NT>(edges[e].v[0]); }
};

/// The user's descriptors, indexed like the arrays of Mesh_data.
template <class PolygonMesh>
struct Mesh_descriptors
{
  using GT = boost::graph_traits<PolygonMesh>;
  std::vector<typename GT::vertex_descriptor> vertices;
  std::vector<typename GT::halfedge_descriptor> edges; // halfedge from v[0] to v[1]
  std::vector<typename GT::face_descriptor> faces;        // after a merge: a face of the triangle's flat region

  /// After merge_planar_patches() (else empty), to name the mesh's own features where the
  /// points of the new triangles lie (to_mesh_feature()): for each flat region triangulated
  /// again, its old triangles (the locator's), their halfedges (halfedges[t][i] from corner i
  /// to corner i + 1) and faces; for each triangle and each edge the index of its region, or
  /// no_index where it is the mesh's own (an edge joined along a crease: either region's).
  struct Region
  {
    Region_locator locator;
    std::vector<std::array<typename GT::halfedge_descriptor, 3>> halfedges;
    std::vector<typename GT::face_descriptor> faces;
  };
  std::vector<Region> regions;
  std::vector<Index> region_of_triangle, region_of_edge;
};

/// Vertex stars, connected components and their closedness, bare edges.
inline void build_stars_and_components(Mesh_data& m, bool as_surface)
{
  // Vertex stars (CSR).
  const std::size_t nv = m.points.size();
  auto build_csr = [nv](auto&& for_each_pair, std::vector<Index>& offsets, std::vector<Index>& list) {
    offsets.assign(nv + 1, 0);
    for_each_pair([&](Index v, Index) { ++offsets[v + 1]; });
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    list.resize(offsets.back());
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for_each_pair([&](Index v, Index x) { list[fill[v]++] = x; });
  };
  build_csr([&](auto&& f) { for (Index e = 0; e < m.edges.size(); ++e) { f(m.edges[e].v[0], e); f(m.edges[e].v[1], e); } },
            m.vertex_edge_offsets, m.vertex_edges);
  build_csr([&](auto&& f) { for (Index t = 0; t < m.triangles.size(); ++t) for (Index v : m.triangles[t]) f(v, t); },
            m.vertex_triangle_offsets, m.vertex_triangles);

  // Connected components (through edges) and whether they are closed.
  std::vector<Index> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](Index v) { while (parent[v] != v) v = parent[v] = parent[parent[v]]; return v; };
  for (const auto& e : m.edges) parent[find(e.v[0])] = find(e.v[1]);
  m.vertex_component.assign(nv, no_index);
  for (Index v = 0; v < nv; ++v) {
    if (m.vertex_edge_offsets[v] == m.vertex_edge_offsets[v + 1]) continue; // isolated vertex
    const Index r = find(v);
    if (m.vertex_component[r] == no_index) {
      m.vertex_component[r] = static_cast<Index>(m.components.size());
      Mesh_data::Component c;
      c.representative_vertex = r;
      c.min = c.max = m.points[r];
      m.components.push_back(c);
    }
    m.vertex_component[v] = m.vertex_component[r];
    Mesh_data::Component& c = m.components[m.vertex_component[v]];
    for (int i = 0; i < 3; ++i) {
      c.min[i] = (std::min)(c.min[i], m.points[v][i]);
      c.max[i] = (std::max)(c.max[i], m.points[v][i]);
    }
  }
  for (const auto& e : m.edges)
    if (e.f[1] == no_index || as_surface) m.components[m.vertex_component[e.v[0]]].closed = false;
  for (const auto& t : m.triangles) m.triangle_component.push_back(m.vertex_component[t[0]]);

  for (Index e = 0; e < m.edges.size(); ++e)
    if (m.edges[e].f[0] == no_index) m.bare_edges.push_back(e);
}

/// Sign of the orientation of (a, b, c, k z) against the plane of a, b, c, where the query
/// point z is `zk / k` (k = 1: a vertex; k = 3: a triangle's centroid, zk the sum of its
/// vertices): positive on the side of (b - a) x (c - a).
inline CGAL::Sign side_of_plane(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                const std::array<double, 3>& c, const std::array<std::array<double, 3>, 3>& zk, int k)
{
  return filtered_sign([&](auto nt) {
    using NT = decltype(nt);
    const Vec3<NT> A = to_nt<NT>(a);
    Vec3<NT> z = to_nt<NT>(zk[0]);
    for (int i = 1; i < k; ++i) z = z + to_nt<NT>(zk[i]);
    return dot(triangle_normal<NT>(a, b, c), z - scaled(A, int_nt<NT>(k)));
  });
}

/// Checks of the closed components of a mesh: their surfaces cross neither themselves nor
/// each other (touching along faces, edges or vertices is fine), and each is oriented as its
/// nesting asks: outward, or inward (a void) inside an odd number of others. Exact.
class Solid_checker
{
public:
  using P3 = std::array<double, 3>;

  /// `name` names the mesh in the errors (solids() reports none).
  explicit Solid_checker(const Mesh_data& m, std::string name = "the mesh")
    : m(m), name(std::move(name)), m_triangles(m.components.size()), m_vertices(m.components.size())
  {
    for (Index t = 0; t < m.number_of_triangles(); ++t) m_triangles[m.triangle_component[t]].push_back(t);
    for (Index v = 0; v < m.number_of_vertices(); ++v)
      if (m.vertex_component[v] != no_index) m_vertices[m.vertex_component[v]].push_back(v);
  }

  /// Throws Invalid_input on two crossing triangles of closed components.
  void check_crossings() const
  {
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, Index>;
    std::vector<Box> boxes;
    for (Index t = 0; t < m.number_of_triangles(); ++t) {
      if (!m.triangle_is_closed(t)) continue;
      CGAL::Bbox_3 b;
      for (Index v : m.triangles[t]) b += CGAL::Bbox_3(m.points[v][0], m.points[v][1], m.points[v][2],
                                                     m.points[v][0], m.points[v][1], m.points[v][2]);
      boxes.emplace_back(b, t);
    }
    // the first crossing pair in the order of (components, faces): the same report whatever
    // order the boxes are visited in
    std::array<Index, 4> first = {no_index, no_index, no_index, no_index};
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
      const Index s = (std::min)(a.info(), b.info()), t = (std::max)(a.info(), b.info());
      const Index cs = m.triangle_component[s], ct = m.triangle_component[t];
      const std::array<Index, 4> key = {(std::min)(cs, ct), (std::max)(cs, ct), s, t};
      if (key < first && triangles_cross(s, t)) first = key;
    });
    if (first[0] == no_index) return;
    const std::string faces = "(faces " + std::to_string(first[2]) + " and " + std::to_string(first[3]) + " cross)";
    if (first[0] == first[1])
      throw Invalid_input(name + " component " + std::to_string(first[0]) + " intersects itself " + faces);
    throw Invalid_input(name + " components " + std::to_string(first[0]) + " and " + std::to_string(first[1]) +
                        " overlap " + faces);
  }

  /// With no crossings: throws Invalid_input unless every closed component has the
  /// orientation its nesting depth asks for (outward at even depth, inward at odd).
  void check_orientations() const
  {
    const std::size_t nc = m.components.size();
    std::vector<CGAL::Sign> volume(nc, CGAL::ZERO);
    for (Index c = 0; c < nc; ++c) {
      if (!m.components[c].closed) continue;
      volume[c] = filtered_sign([&](auto nt) {
        using NT = decltype(nt);
        NT sum(0);
        for (Index t : m_triangles[c]) sum = sum + dot(m.point<NT>(m.triangles[t][0]), m.triangle_normal<NT>(t));
        return sum;
      });
    }
    const std::vector<std::vector<Index>> containers = closed_containers();
    for (Index c = 0; c < nc; ++c) {
      if (!m.components[c].closed || volume[c] == CGAL::ZERO) continue;
      const std::size_t depth = containers[c].size();
      if ((depth % 2 == 0) == (volume[c] == CGAL::POSITIVE)) continue;
      const Index parent = innermost(containers, c);
      const std::string sc = std::to_string(c), sp = std::to_string(parent);
      if (depth == 0)
        throw Invalid_input(name + " is oriented inward (component " + sc + " has a negative volume); reverse "
                            "its face orientation, e.g. with PMP::reverse_face_orientations");
      if (volume[c] == CGAL::POSITIVE)
        throw Invalid_input(name + " components " + sp + " and " + sc + " overlap: " + sc + " lies inside " + sp +
                            " and both are oriented outward (a void must be oriented inward)");
      throw Invalid_input(name + " component " + sc + " is oriented inward inside the void of component " + sp +
                          " (a solid inside a void must be oriented outward)");
    }
  }

  /// Do the relative interiors of triangles s and t meet in a way that makes their solids
  /// overlap: a transversal crossing, or coplanar overlapping faces on the same side?
  bool triangles_cross(Index s, Index t) const
  {
    const std::array<P3, 3> T1 = {pt(m.triangles[s][0]), pt(m.triangles[s][1]), pt(m.triangles[s][2])};
    const std::array<P3, 3> T2 = {pt(m.triangles[t][0]), pt(m.triangles[t][1]), pt(m.triangles[t][2])};
    std::array<CGAL::Sign, 3> s2, s1; // vertices of T2 against T1's plane, and conversely
    for (int i = 0; i < 3; ++i) s2[i] = orientation(T1[0], T1[1], T1[2], T2[i]);
    auto straddles = [](const std::array<CGAL::Sign, 3>& x) {
      return std::count(x.begin(), x.end(), CGAL::POSITIVE) > 0 && std::count(x.begin(), x.end(), CGAL::NEGATIVE) > 0;
    };
    if (s2[0] == CGAL::ZERO && s2[1] == CGAL::ZERO && s2[2] == CGAL::ZERO) {
      // coplanar: same side (normals agree) and interiors overlapping with positive area,
      // i.e. no edge line of either triangle leaves the other on its outer closed side
      const CGAL::Sign same = filtered_sign([&](auto nt) {
        using NT = decltype(nt);
        return dot(triangle_normal<NT>(T1[0], T1[1], T1[2]), triangle_normal<NT>(T2[0], T2[1], T2[2]));
      });
      if (same != CGAL::POSITIVE) return false;
      for (const auto* pair : {&T1, &T2}) {
        const auto& A = *pair;
        const auto& B = (pair == &T1) ? T2 : T1;
        for (int i = 0; i < 3; ++i) {
          bool separates = true;
          for (int j = 0; j < 3 && separates; ++j)
            separates = side_in_plane(A[i], A[(i + 1) % 3], B[j], A.data()) != CGAL::POSITIVE;
          if (separates) return false;
        }
      }
      return true;
    }
    if (!straddles(s2)) return false;
    for (int i = 0; i < 3; ++i) s1[i] = orientation(T2[0], T2[1], T2[2], T1[i]);
    if (!straddles(s1)) return false;
    // Both cross the other's plane: T1 ∩ plane(T2) and T2 ∩ plane(T1) are segments of the
    // same line; their open interiors overlap iff an end of one lies inside the other
    // triangle, or both ends of one are on the other's border (the segments are equal).
    const std::array<Where, 2> e1 = ends(T1, s1, T2), e2 = ends(T2, s2, T1);
    for (const auto& e : {e1, e2}) {
      if (e[0] == INSIDE || e[1] == INSIDE) return true;
      if (e[0] == ON_BORDER && e[1] == ON_BORDER) return true;
    }
    return false;
  }

  /// The solid (or surface) each component is part of, numbered from 0 in the order of the
  /// components: components whose surfaces meet (touch or cross) are one, and a void (a closed
  /// component inside an odd number of others) is one with its innermost container. Each is
  /// connected, so the sum of one with a connected set is connected. Exact.
  std::vector<Index> solids() const
  {
    const std::size_t nc = m.components.size();
    std::vector<Index> root(nc);
    std::iota(root.begin(), root.end(), Index(0));
    auto find = [&](Index c) {
      while (root[c] != c) c = root[c] = root[root[c]];
      return c;
    };
    auto unite = [&](Index a, Index b) {
      a = find(a), b = find(b);
      root[(std::max)(a, b)] = (std::min)(a, b);
    };
    if (nc > 1) {
      using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, Index>;
      using K = CGAL::Exact_predicates_inexact_constructions_kernel;
      auto triangle = [&](Index t) {
        const auto& v = m.triangles[t];
        auto p = [&](int i) { return K::Point_3(pt(v[i])[0], pt(v[i])[1], pt(v[i])[2]); };
        return K::Triangle_3(p(0), p(1), p(2));
      };
      std::vector<Box> boxes;
      for (Index t = 0; t < m.number_of_triangles(); ++t) {
        CGAL::Bbox_3 b;
        for (Index v : m.triangles[t]) b += CGAL::Bbox_3(pt(v)[0], pt(v)[1], pt(v)[2], pt(v)[0], pt(v)[1], pt(v)[2]);
        boxes.emplace_back(b, t);
      }
      // (closed boxes, the default: triangles that only touch have touching boxes)
      CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
        const Index ca = m.triangle_component[a.info()], cb = m.triangle_component[b.info()];
        if (find(ca) != find(cb) && CGAL::do_intersect(triangle(a.info()), triangle(b.info()))) unite(ca, cb);
      });
      const std::vector<std::vector<Index>> containers = closed_containers();
      for (Index c = 0; c < nc; ++c)
        if (containers[c].size() % 2 == 1) unite(c, innermost(containers, c));
    }
    std::vector<Index> solid(nc), number(nc, no_index);
    Index next = 0;
    for (Index c = 0; c < nc; ++c) {
      Index& n = number[find(c)];
      if (n == no_index) n = next++;
      solid[c] = n;
    }
    return solid;
  }

private:
  const P3& pt(Index v) const { return m.points[v]; }

  /// For each component, the closed components that contain it (none for an open one).
  std::vector<std::vector<Index>> closed_containers() const
  {
    const std::size_t nc = m.components.size();
    std::vector<std::vector<Index>> containers(nc);
    for (Index a = 0; a < nc; ++a)
      for (Index b = 0; b < nc; ++b)
        if (a != b && m.components[a].closed && m.components[b].closed && box_inside(b, a) && inside(b, a))
          containers[b].push_back(a);
    return containers;
  }

  /// The innermost of the containers of c: the one with the most containers itself.
  static Index innermost(const std::vector<std::vector<Index>>& containers, Index c)
  {
    Index parent = no_index;
    for (Index a : containers[c])
      if (parent == no_index || containers[a].size() > containers[parent].size()) parent = a;
    return parent;
  }

  bool box_inside(Index b, Index a) const
  {
    const auto &A = m.components[a], &B = m.components[b];
    for (int i = 0; i < 3; ++i)
      if (B.min[i] < A.min[i] || B.max[i] > A.max[i]) return false;
    return true;
  }

  static CGAL::Sign orientation(const P3& a, const P3& b, const P3& c, const P3& d)
  {
    return side_of_plane(a, b, c, {d, d, d}, 1);
  }

  /// Sign of (b - a) x (x - a) . n: x left of a -> b seen from n's side (x in the plane).
  static CGAL::Sign side_in_plane(const P3& a, const P3& b, const P3& x, const P3* tri)
  {
    return filtered_sign([&](auto nt) {
      using NT = decltype(nt);
      return dot(triangle_normal<NT>(tri[0], tri[1], tri[2]), triangle_normal<NT>(a, b, x));
    });
  }

  enum Where { OUTSIDE, ON_BORDER, INSIDE };

  /// Where x (in the plane of T) lies relative to triangle T.
  static Where in_triangle(const P3& x, const std::array<P3, 3>& T)
  {
    bool zero = false;
    for (int i = 0; i < 3; ++i) {
      const CGAL::Sign s = side_in_plane(T[i], T[(i + 1) % 3], x, T.data());
      if (s == CGAL::NEGATIVE) return OUTSIDE;
      zero |= (s == CGAL::ZERO);
    }
    return zero ? ON_BORDER : INSIDE;
  }

  /// Where the segment u v, crossing the plane of T at one point, crosses it relative to T.
  static Where segment_through(const P3& u, const P3& v, const std::array<P3, 3>& T)
  {
    CGAL::Sign first = CGAL::ZERO;
    bool zero = false;
    for (int i = 0; i < 3; ++i) {
      const CGAL::Sign s = orientation(u, v, T[i], T[(i + 1) % 3]);
      if (s == CGAL::ZERO) { zero = true; continue; }
      if (first == CGAL::ZERO) first = s;
      else if (s != first) return OUTSIDE;
    }
    return zero ? ON_BORDER : INSIDE;
  }

  /// The two ends of T1 ∩ plane(T2) (T1 crossing it strictly), each located relative to T2.
  static std::array<Where, 2> ends(const std::array<P3, 3>& T1, const std::array<CGAL::Sign, 3>& s,
                                   const std::array<P3, 3>& T2)
  {
    std::array<Where, 2> w{};
    int k = 0;
    for (int i = 0; i < 3 && k < 2; ++i) {
      const int j = (i + 1) % 3;
      if (s[i] == CGAL::ZERO) w[k++] = in_triangle(T1[i], T2);
      else if (s[j] != CGAL::ZERO && s[i] != s[j]) w[k++] = segment_through(T1[i], T1[j], T2);
    }
    return w;
  }

  /// Is closed component b inside closed component a (their surfaces do not cross)? Decided
  /// by a vertex of b off a's surface (or a triangle centroid if there is none), by the
  /// parity of a ray's crossings with a's triangles; rays that meet an edge or a vertex of
  /// a, or lie in a triangle's plane, are replaced by another.
  bool inside(Index b, Index a) const
  {
    const std::vector<Index>& ta = m_triangles[a];
    auto classify = [&](const std::array<P3, 3>& zk, int k) -> int { // -1: on a's surface
      for (Index t : ta) {
        const auto& tri = m.triangles[t];
        if (side_of_plane(pt(tri[0]), pt(tri[1]), pt(tri[2]), zk, k) != CGAL::ZERO) continue;
        bool zero = false, out = false;
        for (int i = 0; i < 3 && !out; ++i) {
          const CGAL::Sign si = filtered_sign([&](auto nt) {
            using NT = decltype(nt);
            const Vec3<NT> n = triangle_normal<NT>(pt(tri[0]), pt(tri[1]), pt(tri[2]));
            const Vec3<NT> pa = scaled(to_nt<NT>(pt(tri[i])), int_nt<NT>(k)), pb = scaled(to_nt<NT>(pt(tri[(i + 1) % 3])), int_nt<NT>(k));
            Vec3<NT> z = to_nt<NT>(zk[0]);
            for (int j = 1; j < k; ++j) z = z + to_nt<NT>(zk[j]);
            return dot(n, cross(pb - pa, z - pa));
          });
          out = (si == CGAL::NEGATIVE);
          zero |= (si == CGAL::ZERO);
        }
        if (!out) return -1;
      }
      // ray parity along pseudo-random directions until one is generic
      std::uint64_t seed = 0x9E3779B97F4A7C15ull;
      for (int attempt = 0; attempt < 64; ++attempt) {
        P3 w;
        for (double& c : w) {
          seed = seed * 6364136223846793005ull + 1442695040888963407ull;
          c = double(std::int64_t(seed >> 11) - (std::int64_t(1) << 52)) / double(std::int64_t(1) << 52);
        }
        bool odd = false, degenerate = false;
        for (Index t : ta) {
          const auto& tri = m.triangles[t];
          const P3 &A = pt(tri[0]), &B = pt(tri[1]), &C = pt(tri[2]);
          const CGAL::Sign toward = filtered_sign([&](auto nt) {
            using NT = decltype(nt);
            return dot(to_nt<NT>(w), triangle_normal<NT>(A, B, C));
          });
          const CGAL::Sign side = side_of_plane(A, B, C, zk, k);
          if (toward == CGAL::ZERO) continue; // parallel to the plane, z off it: never meets
          if (side != -toward) continue;      // z must be behind the plane as seen along w
          // the line z + s w passes through the triangle iff det[w, P - z, Q - z] agree
          CGAL::Sign first = CGAL::ZERO;
          bool miss = false, zero = false;
          for (int i = 0; i < 3 && !miss; ++i) {
            const P3 &p = pt(tri[i]), &q = pt(tri[(i + 1) % 3]);
            const CGAL::Sign si = filtered_sign([&](auto nt) {
              using NT = decltype(nt);
              Vec3<NT> z = to_nt<NT>(zk[0]);
              for (int j = 1; j < k; ++j) z = z + to_nt<NT>(zk[j]);
              const NT K = int_nt<NT>(k);
              return dot(to_nt<NT>(w), cross(scaled(to_nt<NT>(p), K) - z, scaled(to_nt<NT>(q), K) - z));
            });
            if (si == CGAL::ZERO) { zero = true; continue; }
            if (first == CGAL::ZERO) first = si;
            else if (si != first) miss = true;
          }
          if (miss) continue;
          if (zero) { degenerate = true; break; }
          odd = !odd;
        }
        if (!degenerate) return odd ? 1 : 0;
      }
      return -1; // not reached for a point off the surface (a generic ray exists)
    };
    for (Index v : m_vertices[b]) {
      const int r = classify({pt(v), pt(v), pt(v)}, 1);
      if (r >= 0) return r == 1;
    }
    for (Index t : m_triangles[b]) {
      const auto& tri = m.triangles[t];
      const int r = classify({pt(tri[0]), pt(tri[1]), pt(tri[2])}, 3);
      if (r >= 0) return r == 1;
    }
    return true; // b's surface lies on a's: the same shell (the crossing test allowed it)
  }

  const Mesh_data& m;
  const std::string name;
  std::vector<std::vector<Index>> m_triangles, m_vertices; // of each component
};

/// Convexity of interior edges: the far vertex of f[1] is not above the plane of f[0] (flat: on it).
inline void mark_convex_edges(Mesh_data& m)
{
  for (Index i = 0; i < m.edges.size(); ++i) {
    Mesh_data::Edge& e = m.edges[i];
    if (e.f[1] == no_index) continue;
    const Index far = m.opposite_vertex(e.f[1], i);
    const Index t0 = e.f[0];
    const CGAL::Sign far_side = filtered_sign([&](auto nt) {
      using NT = decltype(nt);
      return dot(m.point<NT>(far) - m.point<NT>(m.triangles[t0][0]), m.triangle_normal<NT>(t0));
    });
    e.convex = far_side != CGAL::POSITIVE;
    e.flat = far_side == CGAL::ZERO;
  }
}

/// Exact double value of a kernel coordinate, or an Invalid_input error.
template <class FT>
double exact_double(const FT& x, const std::string& where)
{
  const double d = CGAL::to_double(x);
  if (!std::isfinite(d))
    throw Invalid_input(where + " has a coordinate that is not finite (NaN or infinity)");
  if (!(FT(d) == x))
    throw Invalid_input(where + " has a coordinate that is not a double; CGAL_pmsum needs "
                        "coordinates exactly representable as double");
  return d;
}

/// Without the solid checks: the sign of the closed components' total volume.
inline void check_total_orientation(const Mesh_data& m, const std::string& name)
{
  const bool any_closed = std::any_of(m.components.begin(), m.components.end(),
                                      [](const Mesh_data::Component& c) { return c.closed; });
  const CGAL::Sign volume = filtered_sign([&](auto nt) {
    using NT = decltype(nt);
    NT sum(0);
    for (Index t = 0; t < m.triangles.size(); ++t)
      if (m.triangle_is_closed(t)) sum = sum + dot(m.point<NT>(m.triangles[t][0]), m.triangle_normal<NT>(t));
    return sum;
  });
  if (any_closed && volume == CGAL::NEGATIVE)
    throw Invalid_input(name + " is oriented inward (negative volume); reverse its face "
                        "orientation, e.g. with PMP::reverse_face_orientations");
}

/// Replaces the triangles of `m` by those of `merged` (same vertices, same solid): the edges
/// are rebuilt from them (the mesh's edges that are left keep their halfedges, in their order;
/// a new edge and a new triangle get their region, whose old triangles `desc` keeps), and each
/// triangle gets the face that `merged.source` names (a new triangle's only stands for its
/// region: its records are located among the region's own, Mesh_descriptors::regions). Leaves `m` and `desc` as
/// they are, and returns false, if a new edge joins two vertices that an edge of the mesh
/// elsewhere joins too.
template <class PolygonMesh>
bool adopt_merged_triangles(Mesh_data& m, Mesh_descriptors<PolygonMesh>& desc, const PolygonMesh& pm,
                            const Planar_merge& merged)
{
  std::vector<std::uint64_t> used;
  for (const auto& t : merged.triangles) for (int i = 0; i < 3; ++i) used.push_back(edge_key(t[i], t[(i + 1) % 3]));
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());

  // Edges: the old ones still used, in their order, then the new ones.
  std::vector<Mesh_data::Edge> edges;
  Mesh_descriptors<PolygonMesh> d;
  std::unordered_map<std::uint64_t, Index> edge_of;
  for (Index e = 0; e < m.edges.size(); ++e) {
    const std::uint64_t k = edge_key(m.edges[e].v[0], m.edges[e].v[1]);
    if (!std::binary_search(used.begin(), used.end(), k)) continue;
    edge_of.emplace(k, Index(edges.size()));
    edges.push_back({m.edges[e].v, {no_index, no_index}, true});
    d.edges.push_back(desc.edges[e]);
    d.region_of_edge.push_back(no_index);
  }
  // The regions' old triangles, with their halfedges and faces.
  for (const auto& region : merged.regions) {
    std::vector<std::array<Index, 3>> old;
    std::vector<std::array<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor, 3>> halfedges;
    std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> faces;
    for (std::uint32_t t : region) {
      old.push_back(m.triangles[t]);
      faces.push_back(desc.faces[t]);
      halfedges.emplace_back();
      for (int i = 0; i < 3; ++i) {
        const Index e = m.triangle_edges[t][i];
        halfedges.back()[i] = m.edges[e].v[0] == m.triangles[t][i] ? desc.edges[e] : opposite(desc.edges[e], pm);
      }
    }
    d.regions.push_back({Region_locator(m.points, std::move(old)), std::move(halfedges), std::move(faces)});
  }
  std::vector<std::array<Index, 3>> triangle_edges(merged.triangles.size());
  for (Index t = 0; t < merged.triangles.size(); ++t) {
    d.faces.push_back(desc.faces[merged.source[t]]);
    d.region_of_triangle.push_back(merged.region_of[t] == Planar_merge::kept ? no_index : Index(merged.region_of[t]));
    for (int i = 0; i < 3; ++i) {
      const Index a = merged.triangles[t][i], b = merged.triangles[t][(i + 1) % 3];
      const auto [it, added] = edge_of.emplace(edge_key(a, b), Index(edges.size()));
      if (added) {
        edges.push_back({{a, b}, {no_index, no_index}, true});
        d.edges.push_back(desc.edges.front()); // not an edge of the mesh: region_of_edge says where it is
        d.region_of_edge.push_back(d.region_of_triangle.back());
      }
      Mesh_data::Edge& e = edges[it->second];
      Index& slot = e.v[0] == a ? e.f[0] : e.f[1];
      if (slot != no_index) return false;
      slot = t;
      triangle_edges[t][i] = it->second;
    }
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    Mesh_data::Edge& e = edges[i];
    if (e.f[0] != no_index) continue;
    if (d.region_of_edge[i] != no_index) return false; // a diagonal is never on a border
    std::swap(e.v[0], e.v[1]);
    std::swap(e.f[0], e.f[1]);
    d.edges[i] = opposite(d.edges[i], pm);
  }
  m.triangles = merged.triangles;
  m.triangle_edges = std::move(triangle_edges);
  m.edges = std::move(edges);
  d.vertices = std::move(desc.vertices);
  desc = std::move(d);
  return true;
}

/// Copies and checks `pm`. `name` ("P" or "Q") prefixes the error messages. With
/// `as_surface`, closed components count as surfaces too (no volume). With `check_solids`,
/// closed components must not cross themselves or each other, and each must be oriented
/// as its nesting asks (see Solid_checker); without, only the total volume's sign is checked.
/// With `merge_flat`, flat regions cut into many triangles are triangulated again first (off
/// here, the mesh as given, for the internal uses and tests; the public functions pass their
/// `merge_flat_regions`, on by default, through read_mesh()).
template <class PolygonMesh, class VertexPointMap>
Mesh_data make_mesh_data(const PolygonMesh& pm, VertexPointMap vpm, bool negate, bool as_surface,
                         const std::string& name, Mesh_descriptors<PolygonMesh>& desc, bool check_solids = true,
                         bool merge_flat = false)
{
  using GT = boost::graph_traits<PolygonMesh>;
  using halfedge_descriptor = typename GT::halfedge_descriptor;

  Mesh_data m;
  if (faces(pm).empty())
    throw Invalid_input(name + " has no faces");

  auto vindex = get(CGAL::dynamic_vertex_property_t<Index>(), pm);
  auto hindex = get(CGAL::dynamic_halfedge_property_t<Index>(), pm);
  const double sign = negate ? -1. : 1.;
  for (auto v : vertices(pm)) {
    put(vindex, v, static_cast<Index>(desc.vertices.size()));
    const std::string where = name + " vertex " + std::to_string(desc.vertices.size());
    const auto& p = get(vpm, v);
    m.points.push_back({sign * exact_double(p.x(), where), sign * exact_double(p.y(), where),
                        sign * exact_double(p.z(), where)});
    desc.vertices.push_back(v);
  }
  for (auto e : edges(pm)) {
    const halfedge_descriptor h = halfedge(e, pm);
    put(hindex, h, static_cast<Index>(m.edges.size()));
    put(hindex, opposite(h, pm), static_cast<Index>(m.edges.size()));
    m.edges.push_back({{get(vindex, source(h, pm)), get(vindex, target(h, pm))},
                       {no_index, no_index}, true});
    desc.edges.push_back(h);
  }
  for (auto f : faces(pm)) {
    const Index t = static_cast<Index>(m.triangles.size());
    const halfedge_descriptor h0 = halfedge(f, pm);
    if (next(next(next(h0, pm), pm), pm) != h0)
      throw Invalid_input(name + " face " + std::to_string(t) + " is not a triangle (" +
                          std::to_string(CGAL::halfedges_around_face(h0, pm).size()) +
                          " vertices); triangulate the mesh first");
    const std::array<halfedge_descriptor, 3> h = {h0, next(h0, pm), next(next(h0, pm), pm)};
    std::array<Index, 3> tri, tedges;
    for (int i = 0; i < 3; ++i) { tri[i] = get(vindex, source(h[i], pm)); tedges[i] = get(hindex, h[i]); }
    if (negate) { // reverse the orientation: (v0, v2, v1); edges (v0v2, v2v1, v1v0)
      tri = {tri[0], tri[2], tri[1]};
      tedges = {tedges[2], tedges[1], tedges[0]};
    }
    for (int i = 0; i < 3; ++i) {
      Mesh_data::Edge& e = m.edges[tedges[i]];
      const bool forward = (e.v[0] == tri[i]);
      Index& slot = forward ? e.f[0] : e.f[1];
      if (slot != no_index)
        throw Invalid_input(name + " is not consistently oriented around edge " +
                            std::to_string(tedges[i]));
      slot = t;
    }
    m.triangles.push_back(tri);
    m.triangle_edges.push_back(tedges);
    desc.faces.push_back(f);
  }

  // Border edges keep their single triangle in f[0] (so f[1] == no_index marks the border);
  // edges without any triangle cannot occur in a face graph without isolated edges.
  for (std::size_t i = 0; i < m.edges.size(); ++i) {
    Mesh_data::Edge& e = m.edges[i];
    if (e.f[0] == no_index) {
      std::swap(e.v[0], e.v[1]);
      std::swap(e.f[0], e.f[1]);
      desc.edges[i] = opposite(desc.edges[i], pm);
    }
    if (e.f[0] == no_index)
      throw Invalid_input(name + " edge " + std::to_string(i) + " has no incident face");
  }

  // Degenerate triangles (zero area, decided exactly).
  for (Index t = 0; t < m.triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) {
      if (filtered_sign([&](auto nt) { return m.triangle_normal<decltype(nt)>(t)[c]; }) != CGAL::ZERO)
        break;
      if (c == 2)
        throw Invalid_input(name + " face " + std::to_string(t) +
                            " is degenerate (its three vertices are collinear)");
    }
  }

  // Flat regions cut into many triangles: the same region with fewer (planar_patches.h).
  if (merge_flat)
    if (const auto merged = merge_planar_patches(m.points, m.triangles))
      adopt_merged_triangles(m, desc, pm, *merged);

  build_stars_and_components(m, as_surface);

  // Closed components must bound their volume with outward normals (CGAL's convention):
  // the sign of 6 x their volume, sum of a . ((b - a) x (c - a)), decided exactly, for each
  // (voids inward) after the crossing tests, or else for all together.
  if (check_solids) {
    const Solid_checker checker(m, name);
    checker.check_crossings();
    checker.check_orientations();
  } else {
    check_total_orientation(m, name);
  }
  mark_convex_edges(m);
  return m;
}


/// A polyline as a mesh without triangles (a sweep path): vertices and edges only.
template <class PointRange>
Mesh_data make_polyline_data(const PointRange& path, const std::string& name)
{
  Mesh_data m;
  for (const auto& p : path) {
    const std::string where = name + " point " + std::to_string(m.points.size());
    m.points.push_back({exact_double(p.x(), where), exact_double(p.y(), where), exact_double(p.z(), where)});
  }
  if (m.points.size() < 2) throw Invalid_input(name + " needs at least two points");
  for (Index i = 0; i + 1 < m.points.size(); ++i) {
    if (m.points[i] == m.points[i + 1])
      throw Invalid_input(name + " has two equal consecutive points (" + std::to_string(i) + ")");
    m.edges.push_back({{i, i + 1}, {no_index, no_index}, true});
  }
  build_stars_and_components(m, true);
  return m;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_MESH_DATA_H
