// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
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
#include <stdexcept>
#include <string>
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
  {
    const Vec3<NT> a = point<NT>(triangles[t][0]);
    return cross(point<NT>(triangles[t][1]) - a, point<NT>(triangles[t][2]) - a);
  }
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
  std::vector<typename GT::face_descriptor> faces;
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

/// Copies and checks `pm`. `name` ("P" or "Q") prefixes the error messages. With
/// `as_surface`, closed components count as surfaces too (no volume).
template <class PolygonMesh, class VertexPointMap>
Mesh_data make_mesh_data(const PolygonMesh& pm, VertexPointMap vpm, bool negate, bool as_surface,
                         const std::string& name, Mesh_descriptors<PolygonMesh>& desc)
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

  build_stars_and_components(m, as_surface);

  // Closed components must bound their volume with outward normals (CGAL's convention):
  // the sign of 6 x their total volume, sum of a . ((b - a) x (c - a)), decided exactly.
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

  // Convexity of interior edges: the far vertex of f[1] is not above the plane of f[0].
  for (Index i = 0; i < m.edges.size(); ++i) {
    Mesh_data::Edge& e = m.edges[i];
    if (e.f[1] == no_index) continue;
    const Index far = m.opposite_vertex(e.f[1], i);
    const Index t0 = e.f[0];
    e.convex = filtered_sign([&](auto nt) {
                 using NT = decltype(nt);
                 return dot(m.point<NT>(far) - m.point<NT>(m.triangles[t0][0]),
                            m.triangle_normal<NT>(t0));
               }) != CGAL::POSITIVE;
  }
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
