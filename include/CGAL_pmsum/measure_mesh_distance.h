// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::measure_mesh_distance(): the distance between a triangle mesh and a surface
// made of shells (e.g. the exact boundary of a Minkowski sum), both ways, measured at lattice
// samples of both; and euler_characteristic() of such a surface, to compare the topology. What
// `pmsum validate --mesh` reports for point_minkowski_sum_mesh().

#ifndef CGAL_PMSUM_MEASURE_MESH_DISTANCE_H
#define CGAL_PMSUM_MEASURE_MESH_DISTANCE_H

#include <CGAL_pmsum/measure_boundary_coverage.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumCoverage
/// The distances measured by measure_mesh_distance().
struct Mesh_distance
{
  double mesh_to_surface = 0;       ///< largest distance from a sample of the mesh to the surface
  double surface_to_mesh = 0;       ///< largest distance from a sample of the surface to the mesh
  std::size_t mesh_samples = 0;     ///< samples of the mesh
  std::size_t surface_samples = 0;  ///< samples of the surface
};

namespace internal {

/// The triangles of shells (as `Point_search::K` triangles), in the shells' order, in an AABB
/// tree for distance queries. Not copied: the tree refers to the triangles.
class Shell_triangle_tree
{
public:
  using K = Point_search::K;

  explicit Shell_triangle_tree(const std::vector<Shell>& shells)
  {
    for (const Shell& s : shells) add(s);
    build();
  }
  explicit Shell_triangle_tree(const Shell& s)
  {
    add(s);
    build();
  }
  Shell_triangle_tree(const Shell_triangle_tree&) = delete;
  Shell_triangle_tree& operator=(const Shell_triangle_tree&) = delete;

  bool empty() const { return m_triangles.empty(); }
  /// @pre !empty()
  double squared_distance(const K::Point_3& x) const { return m_tree.squared_distance(x); }
  /// The index (in the shells' order) of the first triangle nearest to x (the tree's answer
  /// among equally near ones varies from run to run). @pre !empty()
  std::size_t nearest(const K::Point_3& x) const
  {
    const double r = std::sqrt(m_tree.squared_distance(x)) * (1 + 1e-9) + std::numeric_limits<double>::min();
    const std::size_t best = nearest_within(x, r, [](std::size_t) { return true; });
    return best < m_triangles.size() ? best : std::size_t(m_tree.closest_point_and_primitive(x).second - m_triangles.cbegin());
  }
  /// The index of the first triangle nearest to x among those whose bounding box meets the
  /// box of half-side r round x and for which accept(i) is true; the number of triangles if
  /// there is none.
  template <class Accept>
  std::size_t nearest_within(const K::Point_3& x, double r, const Accept& accept) const
  {
    std::vector<Triangles::const_iterator> near;
    if (!empty())
      m_tree.all_intersected_primitives(CGAL::Bbox_3(x.x() - r, x.y() - r, x.z() - r, x.x() + r, x.y() + r, x.z() + r),
                                        std::back_inserter(near));
    std::size_t best = m_triangles.size();
    double best_squared = std::numeric_limits<double>::infinity();
    for (const auto& t : near) {
      const std::size_t i = std::size_t(t - m_triangles.cbegin());
      if (!accept(i)) continue;
      const double squared = CGAL::squared_distance(x, *t);
      if (squared < best_squared || (squared == best_squared && i < best)) {
        best_squared = squared;
        best = i;
      }
    }
    return best;
  }
  /// Calls f(i) with the index (in the shells' order) of each triangle that s meets, except
  /// those for which skip(i) is true: they are not tested (a triangle known to touch s only at
  /// its source, whose exact test would be degenerate). @pre !empty()
  template <class F, class Skip>
  void for_each_met(const K::Segment_3& s, F&& f, const Skip& skip) const
  {
    Met_traversal<F, Skip> traversal{m_tree.traits(), m_triangles.cbegin(), f, skip};
    m_tree.traversal(s, traversal);
  }

private:
  using Triangles = std::vector<K::Triangle_3>;
  using Traits = CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>;
  using Tree = CGAL::AABB_tree<Traits>;

  void add(const Shell& s)
  {
    for (const auto& t : s.triangles) {
      auto p = [&](int i) { return K::Point_3(s.points[t[i]][0], s.points[t[i]][1], s.points[t[i]][2]); };
      m_triangles.emplace_back(p(0), p(1), p(2));
    }
  }
  void build()
  {
    if (!m_triangles.empty()) m_tree.rebuild(m_triangles.begin(), m_triangles.end()); // (its kd-tree for distances: at the first)
  }

  // The traversal of for_each_met(): AABB_tree's listing of the primitives a query meets,
  // with the skipped ones left out before their test.
  template <class F, class Skip>
  struct Met_traversal
  {
    const Traits& traits;
    Triangles::const_iterator first;
    F& f;
    const Skip& skip;
    bool go_further() const { return true; }
    void intersection(const K::Segment_3& s, const Traits::Primitive& t)
    {
      const std::size_t i = std::size_t(t.id() - first);
      if (!skip(i) && traits.do_intersect_object()(s, t)) f(i);
    }
    bool do_intersect(const K::Segment_3& s, const CGAL::AABB_node<Traits>& node) const
    { return traits.do_intersect_object()(s, node.bbox()); }
  };

  Triangles m_triangles;
  Tree m_tree;
};

/// The largest distance from the points that `for_each_point(f)` passes to `f` (as
/// `Point_search::K::Point_3`) to the triangles of `to`: infinity if `to` has none.
template <class ForEachPoint>
double largest_distance_to(const std::vector<Shell>& to, const ForEachPoint& for_each_point)
{
  const Shell_triangle_tree tree(to);
  if (tree.empty()) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for_each_point([&](const Shell_triangle_tree::K::Point_3& x) { worst = (std::max)(worst, tree.squared_distance(x)); });
  return std::sqrt(worst);
}

/// The largest distance from the lattice samples of `from` to the triangles of `to`;
/// `samples` counts the samples.
inline double largest_distance(const std::vector<Shell>& from, const std::vector<Shell>& to, double spacing,
                               std::size_t& samples)
{
  samples = 0;
  return largest_distance_to(to, [&](const auto& f) {
    for (const Shell& s : from)
      for (const auto& t : s.triangles)
        for_each_lattice_point(s, t, spacing, [&](const Point_search::K::Point_3& x) {
          ++samples;
          f(x);
        });
  });
}

/// A triangle mesh as one shell (positions rounded to double).
template <class TriangleMesh>
Shell to_shell(const TriangleMesh& mesh)
{
  Shell s;
  const auto vpm = get(CGAL::vertex_point, mesh);
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
  for (auto v : vertices(mesh)) {
    put(index, v, s.points.size());
    const auto& p = get(vpm, v);
    s.points.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  for (auto f : faces(mesh)) {
    const auto h = halfedge(f, mesh);
    s.triangles.push_back({get(index, source(h, mesh)), get(index, target(h, mesh)),
                           get(index, target(next(h, mesh), mesh))});
  }
  return s;
}

} // namespace internal

/// \ingroup PkgPointMinkowskiSumCoverage
/// The Euler characteristic (vertices - edges + triangles) of a surface given shell by shell,
/// such as Nef_minkowski_sum_reference::shells(), to compare with a mesh's
/// (Mesh_checks::euler_characteristic): equal shell counts do not tell a handle too many.
///
/// Combinatorial: from the triangles' vertex indices, each shell's vertices counted once.
/// \param shells the surface
/// \returns the sum over the shells of 2 - 2 g (g: the shell's genus), or nothing if a shell
///          is not a closed, consistently oriented 2-manifold (an edge on other than two of its
///          triangles, or a vertex whose triangles are not one fan: the boundary of solids
///          that touch along an edge or at a vertex, for instance)
inline std::optional<long> euler_characteristic(const std::vector<Shell>& shells)
{
  long chi = 0;
  for (const Shell& s : shells) {
    std::map<std::pair<std::size_t, std::size_t>, int> edges; // (smaller, larger) -> triangles on it
    std::vector<std::map<std::size_t, std::size_t>> fan(s.points.size()); // at v: b -> c for each triangle (v, b, c)
    for (const auto& t : s.triangles)
      for (int i = 0; i < 3; ++i) {
        const std::size_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        ++edges[{(std::min)(a, b), (std::max)(a, b)}];
        if (!fan[a].emplace(b, c).second) return std::nullopt; // two triangles turn the same way at a
      }
    for (const auto& e : edges)
      if (e.second != 2) return std::nullopt;
    long used = 0;
    for (const auto& around : fan) {
      if (around.empty()) continue;
      ++used;
      const std::size_t first = around.begin()->first;
      std::size_t at = first, steps = 0;
      do {
        const auto next = around.find(at);
        if (next == around.end()) return std::nullopt;
        at = next->second;
        ++steps;
      } while (at != first && steps <= around.size());
      if (steps != around.size()) return std::nullopt; // (more than one fan)
    }
    chi += used - long(edges.size()) + long(s.triangles.size());
  }
  return chi;
}

/// \ingroup PkgPointMinkowskiSumCoverage
/// Measures the distance between a triangle mesh and a surface in both directions (the two
/// one-sided Hausdorff distances): the largest distance from a sample of one to the other's
/// triangles, sampling the triangles of each with the closed lattice of spacing at most
/// `spacing` (as measure_boundary_coverage()).
///
/// Measured at the samples only: each true one-sided distance may exceed the measured one by
/// less than `spacing`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex point map
/// \param shells the surface, e.g. Nef_minkowski_sum_reference::shells()
/// \param mesh the triangle mesh, e.g. of point_minkowski_sum_mesh()
/// \param spacing the largest spacing of the samples on each triangle
/// \returns both distances (infinity if the mesh or the surface is empty)
/// \pre `spacing > 0`, `mesh` is a triangle mesh
template <class TriangleMesh>
Mesh_distance measure_mesh_distance(const std::vector<Shell>& shells, const TriangleMesh& mesh, double spacing)
{
  CGAL_precondition(spacing > 0);
  const std::vector<Shell> mesh_shell = {internal::to_shell(mesh)};
  Mesh_distance m;
  m.mesh_to_surface = internal::largest_distance(mesh_shell, shells, spacing, m.mesh_samples);
  m.surface_to_mesh = internal::largest_distance(shells, mesh_shell, spacing, m.surface_samples);
  return m;
}

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_MEASURE_MESH_DISTANCE_H
