// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input stage: flat regions cut into many triangles (a mesh exported from another tool, a
// Minkowski sum's own mesh, a remeshed CAD model) are triangulated again without the
// vertices inside them, before anything is sampled. The solid is the same; what changes is
// the number of convolution facets, and with it the cost of every later stage: the exact
// boundary tests grow with the pairs of triangles that meet, and a flat square face cut into
// a thousand triangles makes a thousand times more pairs than its two triangles do.
//
// A region (a "patch") is a set of triangles joined through edges whose two triangles are
// exactly coplanar and face the same way. A vertex of a patch is removed when the triangles
// around it are one closed fan, all in the patch; a vertex on the border between two patches
// is removed when it lies strictly between its two border neighbours on a line (exactly) and
// both patches are triangulated again. A patch is triangulated again (constrained
// Delaunay, in the coordinate plane its normal is most aligned with) on its border edges,
// and the new triangles are kept only if they tile exactly the region the old ones tiled:
// the same border, no added vertex, the count Euler asks for, the same area (all decided
// exactly), and, for a patch that only loses crease vertices, only if they do not ask for
// more lattice points than the old ones (long thin triangles can: Merger::lattice_weight()).
// Any doubt keeps the patch as it was (and the border vertices it shares).

#ifndef CGAL_PMSUM_INTERNAL_PLANAR_PATCHES_H
#define CGAL_PMSUM_INTERNAL_PLANAR_PATCHES_H

#include <CGAL_pmsum/internal/exact_sign.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Triangles of a mesh after merge_planar_patches(), and where each came from.
struct Planar_merge
{
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> source;  // for each triangle, the old one it is (kept), or its region's first
  /// The old triangles of each region triangulated again, and for each new triangle the
  /// index of its region there, or `kept` (an old triangle kept as it was).
  std::vector<std::vector<std::uint32_t>> regions;
  std::vector<std::uint32_t> region_of;
  static constexpr std::uint32_t kept = std::numeric_limits<std::uint32_t>::max();
  std::size_t removed_vertices = 0;
};

/// The key of the edge between vertices a and b, whichever way it runs.
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b)
{ return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b); }

namespace planar_patches {

/// The coordinate axis the normal of triangle abc is most aligned with (rounded), and the
/// sign of the exact normal's component on it, if not zero: abc then projects to the other
/// two axes' plane without degeneracy, and so does every triangle of its plane.
inline std::optional<std::pair<int, CGAL::Sign>> projection_axis(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                          const std::array<double, 3>& c)
{
  const Vec3<double> n = triangle_normal<double>(a, b, c);
  int k = 0;
  for (int i = 1; i < 3; ++i) if (std::abs(n[i]) > std::abs(n[k])) k = i;
  const CGAL::Sign sign = filtered_sign([&](auto nt) { return triangle_normal<decltype(nt)>(a, b, c)[k]; });
  if (sign == CGAL::ZERO) return std::nullopt;
  return std::make_pair(k, sign);
}

using Corners = std::array<std::array<double, 3>, 3>;

/// Are two triangles that share an edge exactly coplanar, facing the same way (the dot
/// product of their normals is positive; false if either is degenerate)? `far`: the corner
/// of t off the shared edge.
inline bool flat_neighbours(const Corners& s, const Corners& t, const std::array<double, 3>& far)
{
  auto normal = [](const Corners& c, auto nt) { return triangle_normal<decltype(nt)>(c[0], c[1], c[2]); };
  const bool coplanar = filtered_sign([&](auto nt) {
    using NT = decltype(nt);
    return dot(to_nt<NT>(far) - to_nt<NT>(s[0]), normal(s, nt));
  }) == CGAL::ZERO;
  return coplanar && filtered_sign([&](auto nt) { return dot(normal(s, nt), normal(t, nt)); }) == CGAL::POSITIVE;
}

using Id = std::uint32_t;
constexpr Id none = std::numeric_limits<Id>::max();

/// Half-edge h = 3 t + i of triangle t goes from corner i to corner i + 1; its twin is the
/// half-edge of the other triangle on that edge (none on a border edge).
inline std::vector<Id> twins(const std::vector<std::array<Id, 3>>& T)
{
  std::vector<std::pair<std::uint64_t, Id>> keyed;
  keyed.reserve(3 * T.size());
  for (Id t = 0; t < T.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      keyed.push_back({edge_key(T[t][i], T[t][(i + 1) % 3]), 3 * t + i});
    }
  std::sort(keyed.begin(), keyed.end());
  std::vector<Id> twin(3 * T.size(), none);
  for (std::size_t i = 0; i + 1 < keyed.size(); ++i)
    if (keyed[i].first == keyed[i + 1].first &&
        (i + 2 == keyed.size() || keyed[i + 2].first != keyed[i].first) &&
        (i == 0 || keyed[i - 1].first != keyed[i].first)) {
      twin[keyed[i].second] = keyed[i + 1].second;
      twin[keyed[i + 1].second] = keyed[i].second;
    }
  return twin;
}

struct Merger
{
  const std::vector<std::array<double, 3>>& P;
  const std::vector<std::array<Id, 3>>& T;
  std::vector<Id> twin, patch;

  Merger(const std::vector<std::array<double, 3>>& points, const std::vector<std::array<Id, 3>>& triangles)
    : P(points), T(triangles), twin(twins(triangles))
  {
    find_patches();
  }

  Corners corners(Id t) const { return {P[T[t][0]], P[T[t][1]], P[T[t][2]]}; }
  Id head(Id h) const { return T[h / 3][(h % 3 + 1) % 3]; }
  Id tail(Id h) const { return T[h / 3][h % 3]; }
  bool patch_border(Id h) const { return twin[h] == none || patch[twin[h] / 3] != patch[h / 3]; }

  /// patch[t]: the smallest triangle of t's patch.
  void find_patches()
  {
    patch.resize(T.size());
    std::iota(patch.begin(), patch.end(), Id(0));
    auto find = [&](Id t) { while (patch[t] != t) t = patch[t] = patch[patch[t]]; return t; };
    for (Id h = 0; h < twin.size(); ++h) {
      if (twin[h] == none || twin[h] < h) continue;
      const Id t0 = h / 3, t1 = twin[h] / 3;
      const Id far = T[t1][(twin[h] % 3 + 2) % 3];
      if (flat_neighbours(corners(t0), corners(t1), P[far])) {
        const Id a = find(t0), b = find(t1);
        patch[std::max(a, b)] = std::min(a, b);
      }
    }
    for (Id t = 0; t < T.size(); ++t) patch[t] = find(t);
  }

  /// Are the triangles around a vertex one closed fan? `out`: the half-edges leaving it, none
  /// of them on a border.
  bool one_fan(const std::vector<Id>& out) const
  {
    // Walk the fan: the half-edge leaving v after h is the one after twin(h), turning around v.
    std::size_t steps = 0;
    Id h = out.front();
    do {
      const Id back = twin[h]; // head(back) == v
      h = 3 * (back / 3) + (back % 3 + 1) % 3;
      ++steps;
    } while (h != out.front() && steps <= out.size());
    return h == out.front() && steps == out.size();
  }

  /// If the vertex v (half-edges leaving it: `out`) is between two patches, on two of their
  /// border edges that are collinear with it, on one closed fan: those two patches.
  std::optional<std::pair<Id, Id>> on_straight_crease(Id v, const std::vector<Id>& out) const
  {
    Id a = none, b = none;
    std::vector<Id> ends;
    for (Id h : out) {
      if (twin[h] == none) return std::nullopt;
      const Id p = patch[h / 3];
      if (a == none || a == p) a = p;
      else if (b == none || b == p) b = p;
      else return std::nullopt;
      if (patch_border(h)) ends.push_back(head(h));
    }
    if (b == none || ends.size() != 2 || !one_fan(out)) return std::nullopt;
    const auto arm = [&](auto nt, Id e) { using NT = decltype(nt); return to_nt<NT>(P[e]) - to_nt<NT>(P[v]); };
    for (int c = 0; c < 3; ++c)
      if (filtered_sign([&](auto nt) { return cross(arm(nt, ends[0]), arm(nt, ends[1]))[c]; }) != CGAL::ZERO)
        return std::nullopt;
    if (filtered_sign([&](auto nt) { return dot(arm(nt, ends[0]), arm(nt, ends[1])); }) != CGAL::NEGATIVE)
      return std::nullopt;
    return std::make_pair(a, b);
  }

  /// The triangles that tile a patch (triangles `old`) without its `inner` removable inner
  /// vertices and its border vertices marked in `gone` (each between two collinear border
  /// edges), outward; nothing if they cannot be shown to tile the same region, or if they
  /// only drop border vertices and ask for more lattice points (lattice_weight()).
  std::optional<std::vector<std::array<Id, 3>>> retriangulate(const std::vector<Id>& old, std::size_t inner,
                                                              const std::vector<char>& gone) const
  {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Triangulation_vertex_base_with_info_2<Id, K>;
    using Fb = CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K>>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

    const auto axis = projection_axis(P[T[old.front()][0]], P[T[old.front()][1]], P[T[old.front()][2]]);
    if (!axis) return std::nullopt;
    const auto [k, nk] = *axis;
    const int u = (k + 1) % 3, w = (k + 2) % 3;

    // Border half-edges (those through a vertex that goes joined into one), their vertices,
    // and the CDT on them.
    std::vector<std::pair<Id, Id>> border, through;
    for (Id t : old)
      for (int i = 0; i < 3; ++i)
        if (patch_border(3 * t + i))
          (gone[T[t][i]] ? through : border).push_back({T[t][i], T[t][(i + 1) % 3]});
    std::sort(through.begin(), through.end());
    std::size_t joined = through.size();
    for (auto& e : border)
      for (std::size_t steps = 0; gone[e.second]; ++steps) {
        const auto next = std::lower_bound(through.begin(), through.end(), std::make_pair(e.second, Id(0)));
        if (next == through.end() || next->first != e.second || steps > through.size()) return std::nullopt;
        e.second = next->second;
        --joined;
      }
    if (joined != 0) return std::nullopt; // a vertex that goes on a border loop of its own
    std::vector<Id> corners;
    for (const auto& e : border) { corners.push_back(e.first); corners.push_back(e.second); }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handle(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
      handle[i] = cdt.insert(K::Point_2(P[corners[i]][u], P[corners[i]][w]));
      if (cdt.number_of_vertices() != i + 1) return std::nullopt; // two corners project together
      handle[i]->info() = corners[i];
    }
    auto vertex = [&](Id v) { return handle[std::lower_bound(corners.begin(), corners.end(), v) - corners.begin()]; };
    for (const auto& e : border) cdt.insert_constraint(vertex(e.first), vertex(e.second));
    if (cdt.number_of_vertices() != corners.size()) return std::nullopt; // crossing border edges

    // Faces inside: an odd number of border crossings from the infinite face (breadth first
    // over the crossings, so that each face gets its smallest count).
    for (auto f : cdt.all_face_handles()) f->info() = -1;
    std::deque<std::pair<Cdt::Face_handle, int>> across{{cdt.infinite_face(), 0}};
    std::vector<Cdt::Face_handle> stack;
    while (!across.empty()) {
      const auto [start, level] = across.front();
      across.pop_front();
      if (start->info() != -1) continue;
      start->info() = level;
      stack.push_back(start);
      while (!stack.empty()) {
        const Cdt::Face_handle f = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i) {
          const Cdt::Face_handle g = f->neighbor(i);
          if (g->info() != -1) continue;
          if (cdt.is_constrained({f, i})) { across.push_back({g, level + 1}); continue; }
          g->info() = level;
          stack.push_back(g);
        }
      }
    }

    std::vector<std::array<Id, 3>> fresh;
    for (auto f : cdt.finite_face_handles()) {
      if (f->info() % 2 == 0) continue;
      std::array<Id, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      if (nk == CGAL::NEGATIVE) std::swap(t[1], t[2]);
      fresh.push_back(t);
    }
    if (fresh.size() + 2 * inner + through.size() != old.size()) return std::nullopt; // Euler

    // Same border, same orientation; same area (in the projection, exactly).
    std::set<std::pair<Id, Id>> fresh_edges;
    for (const auto& t : fresh) for (int i = 0; i < 3; ++i) fresh_edges.insert({t[i], t[(i + 1) % 3]});
    for (const auto& e : border) if (!fresh_edges.count(e)) return std::nullopt;
    const auto area2 = [&](auto nt, const auto& tris) {
      using NT = decltype(nt);
      NT sum(0);
      for (const auto& t : tris) {
        const NT ax(P[t[0]][u]), ay(P[t[0]][w]);
        sum = sum + (NT(P[t[1]][u]) - ax) * (NT(P[t[2]][w]) - ay) - (NT(P[t[1]][w]) - ay) * (NT(P[t[2]][u]) - ax);
      }
      return sum;
    };
    std::vector<std::array<Id, 3>> old_triangles;
    for (Id t : old) old_triangles.push_back(T[t]);
    if (filtered_sign([&](auto nt) { return area2(nt, old_triangles) - area2(nt, fresh); }) != CGAL::ZERO)
      return std::nullopt;
    // A patch that only loses crease vertices (no inner one: not cut into many triangles) is
    // kept if its new triangles ask for more lattice points (equal weights rounded apart: merged).
    if (inner == 0 && lattice_weight(fresh) > lattice_weight(old_triangles) * (1 + 1e-9)) return std::nullopt;
    return fresh;
  }

  /// About how many lattice points the triangles get at a small sampling radius r, times
  /// 8 r^2: the sum of their longest edges squared (a triangle's lattice divides its edges
  /// into about (longest edge / 2r) parts, sampling.h). The long thin triangles that replace
  /// the fans of removed crease vertices can ask for more than those fans. (Not asked of a
  /// patch cut into many triangles: there the far fewer pairs of triangles pay for more points.)
  double lattice_weight(const std::vector<std::array<Id, 3>>& tris) const
  {
    double sum = 0;
    for (const auto& t : tris) {
      double longest = 0;
      for (int i = 0; i < 3; ++i) {
        const Vec3<double> e = to_nt<double>(P[t[(i + 1) % 3]]) - to_nt<double>(P[t[i]]);
        longest = (std::max)(longest, dot(e, e));
      }
      sum += longest;
    }
    return sum;
  }
};

} // namespace planar_patches

/// Triangulates again, without their inner vertices and the vertices inside the straight
/// creases between them, the flat regions of a consistently oriented triangle mesh without degenerate triangles (see the top of this file). Nothing
/// if no region changes. The removed vertices are on no new triangle.
inline std::optional<Planar_merge> merge_planar_patches(const std::vector<std::array<double, 3>>& points,
                                                        const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  using planar_patches::Id;
  const planar_patches::Merger m(points, triangles);

  // The half-edges leaving each vertex (CSR).
  std::vector<Id> offsets(points.size() + 1, 0), out(3 * triangles.size());
  for (const auto& t : triangles) for (Id v : t) ++offsets[v + 1];
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  {
    std::vector<Id> fill(offsets.begin(), offsets.end() - 1);
    for (Id h = 0; h < out.size(); ++h) out[fill[m.tail(h)]++] = h;
  }

  // Per patch: how many inner vertices go; an inner vertex that cannot go keeps it whole.
  // Vertices on a straight crease between two patches go too, if both patches change.
  const std::size_t nt = triangles.size();
  std::vector<std::size_t> inner(nt, 0), creases(nt, 0);
  std::vector<char> blocked(nt, 0), gone(points.size(), 0);
  std::vector<std::pair<Id, std::pair<Id, Id>>> crease_vertices;
  for (Id v = 0; v < points.size(); ++v) {
    if (offsets[v] == offsets[v + 1]) continue;
    const std::vector<Id> around(out.begin() + offsets[v], out.begin() + offsets[v + 1]);
    const Id p = m.patch[around.front() / 3];
    bool inside = true;
    for (Id h : around)
      if (m.patch[h / 3] != p || m.patch_border(h) || m.patch_border(3 * (h / 3) + (h % 3 + 2) % 3)) inside = false;
    if (inside) {
      if (m.one_fan(around)) ++inner[p];
      else blocked[p] = 1;
    } else if (const auto ab = m.on_straight_crease(v, around)) {
      crease_vertices.push_back({v, *ab});
    }
  }
  for (const auto& [v, ab] : crease_vertices)
    if (!blocked[ab.first] && !blocked[ab.second]) {
      gone[v] = 1;
      ++creases[ab.first];
      ++creases[ab.second];
    }

  std::vector<std::vector<Id>> members(nt);
  for (Id t = 0; t < nt; ++t) members[m.patch[t]].push_back(t);

  // Retriangulate the patches that change; where one fails, its crease vertices stay, and the
  // patches on their other side are done again.
  std::vector<std::optional<std::vector<std::array<Id, 3>>>> fresh(nt);
  std::vector<char> dirty(nt, 0);
  for (Id p = 0; p < nt; ++p) dirty[p] = !blocked[p] && (inner[p] > 0 || creases[p] > 0);
  for (bool again = true; again;) {
    for (Id p = 0; p < nt; ++p)
      if (dirty[p]) {
        fresh[p] = inner[p] > 0 || creases[p] > 0 ? m.retriangulate(members[p], inner[p], gone) : std::nullopt;
        dirty[p] = 0;
      }
    again = false;
    for (const auto& [v, ab] : crease_vertices)
      if (gone[v] && (!fresh[ab.first] || !fresh[ab.second])) {
        gone[v] = 0;
        for (Id p : {ab.first, ab.second}) { --creases[p]; dirty[p] = 1; }
        again = true;
      }
  }

  Planar_merge result;
  for (Id p = 0; p < nt; ++p) if (fresh[p]) result.removed_vertices += inner[p];
  for (const auto& c : crease_vertices) result.removed_vertices += gone[c.first];
  if (result.removed_vertices == 0) return std::nullopt;

  for (Id t = 0; t < triangles.size(); ++t) {
    const Id p = m.patch[t];
    if (!fresh[p]) {
      result.triangles.push_back(triangles[t]);
      result.source.push_back(t);
      result.region_of.push_back(Planar_merge::kept);
    } else if (p == t) { // the patch's first triangle stands for its region
      for (const auto& n : *fresh[p]) {
        result.triangles.push_back(n);
        result.source.push_back(t);
        result.region_of.push_back(std::uint32_t(result.regions.size()));
      }
      result.regions.push_back(members[p]);
    }
  }
  return result;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PLANAR_PATCHES_H
