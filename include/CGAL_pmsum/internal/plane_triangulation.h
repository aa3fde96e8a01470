// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh stage's second way of joining the output points into triangles: plane by plane.
// The boundary of a sum of polyhedra is made of planar faces, and every output point lies on
// one (inside a convolution facet: it has that facet's normal) or on several (on a crease or
// a trim curve). The points are grouped by the plane they lie on (the plane of the
// convolution facet each point was decided on; a point also joins every plane near it that
// it lies on), each plane's points are triangulated in the plane
// (constrained 2D Delaunay, the crease rows as constraints), and a triangle is kept when it
// is on that plane's face of the boundary: just outside the plane (along its outward normal)
// the sum is free, just inside it collides (the exact CD test at a point), and the whole
// triangle lies in the union of the plane's convolution facets (face_cover.h: no hole of
// the face smaller than the points' spacing, such as a tunnel's mouth, under it). A
// triangle never leaves its plane, so it never bridges a narrow passage, the two sides of
// a thin part or two shells. Creases come out
// where the planes' triangles share the crease points; what is left open (a face too thin to
// hold a point, the far lip of a passage whose points the net left out) is for fill_holes(),
// and no_face_over_empty_space() and no_face_over_hole() refuse a mesh where that closed a
// hole over a passage or over a face's hole. (no_face_joining_parts() is the advancing
// front's check of the same kind: no face across a slit in a plane.)
//
// Grouping by plane compares the points' double normals and offsets within a tolerance of
// about a billionth of the model's size: it chooses the triangles, it decides nothing about
// the boundary (the CD test does, exactly, and check_mesh() checks the result).

#ifndef CGAL_PMSUM_INTERNAL_PLANE_TRIANGULATION_H
#define CGAL_PMSUM_INTERNAL_PLANE_TRIANGULATION_H

#include <CGAL_pmsum/internal/face_cover.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// A plane of output points: unit outward normal, offset (normal . x) and the points on it.
struct Point_plane
{
  CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3 normal;
  double offset;
  std::vector<std::size_t> points;
};

/// More planes of the points than their facets' normals: (point, outward normal) pairs, such
/// as the two faces that meet at a point on a crease (crease_wedge()), of which a face
/// narrower than the points' spacing may have no point of its own.
using Crease_planes = std::vector<std::pair<std::size_t, CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>>;

/// Groups `positions` by plane: one plane per distinct (normal, offset) of the points
/// (`normals`: the normal of the convolution facet each point was decided on, and the normals
/// of `more`; equal within `tolerance`, relative to 1 for the normal and to `scale` for the
/// offset); a point also joins the planes of the points within 2 d of it that it lies on
/// (within tolerance * scale), and so on along crease rows (a point on a crease is on two
/// faces or more).
inline std::vector<Point_plane>
point_planes(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& positions,
             const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>& normals,
             const Crease_planes& more, double d)
{
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  const double tolerance = 1e-9;
  double scale = d;
  for (const auto& p : positions) scale = (std::max)({scale, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
  auto offset = [&](std::size_t i, const Vector& n) { return (positions[i] - CGAL::ORIGIN) * n; };
  // Planes in cells of a grid over (normal, offset / scale), 1e-6 wide: a plane's equal lies
  // in its cell or in one beside it.
  using Key = std::array<std::int64_t, 4>;
  auto key = [&](const Vector& n, double c) {
    return Key{std::llround(n.x() * 1e6), std::llround(n.y() * 1e6), std::llround(n.z() * 1e6),
               std::llround(c / scale * 1e6)};
  };
  std::map<Key, std::vector<std::size_t>> cells;
  std::vector<Point_plane> planes;
  std::vector<std::vector<std::size_t>> joined(positions.size()); // planes of a point
  auto same = [&](const Point_plane& a, const Vector& n, double c) {
    return std::abs(a.normal.x() - n.x()) <= tolerance && std::abs(a.normal.y() - n.y()) <= tolerance &&
           std::abs(a.normal.z() - n.z()) <= tolerance && std::abs(a.offset - c) <= tolerance * scale;
  };
  auto place = [&](std::size_t i, const Vector& normal) {
    const Vector n = normal / std::sqrt(normal.squared_length());
    const double c = offset(i, n);
    const Key k = key(n, c);
    std::size_t found = std::size_t(-1);
    for (int m = 0; m < 81 && found == std::size_t(-1); ++m) {
      Key nk = k;
      for (int a = 0, r = m; a < 4; ++a, r /= 3) nk[a] += r % 3 - 1;
      const auto cell = cells.find(nk);
      if (cell == cells.end()) continue;
      for (std::size_t j : cell->second)
        if (same(planes[j], n, c)) found = j;
    }
    if (found == std::size_t(-1)) {
      found = planes.size();
      planes.push_back(Point_plane{n, c, {}});
      cells[k].push_back(found);
    }
    if (std::find(joined[i].begin(), joined[i].end(), found) != joined[i].end()) return;
    planes[found].points.push_back(i);
    joined[i].push_back(found);
  };
  for (std::size_t i = 0; i < positions.size(); ++i) place(i, normals[i]);
  for (const auto& [i, n] : more) place(i, n);
  // The points join the planes of the points within two cells (2 d wide) of theirs that they
  // lie on, spreading along crease rows: a plane known near a point it joins is asked of the
  // points near that one (a face narrower than d may have points of its own only at its ends).
  using Cell = std::array<std::int64_t, 3>;
  auto cell_of = [&](std::size_t i) {
    const auto& p = positions[i];
    return Cell{std::int64_t(std::floor(p.x() / (2 * d))), std::int64_t(std::floor(p.y() / (2 * d))),
                std::int64_t(std::floor(p.z() / (2 * d)))};
  };
  std::map<Cell, std::vector<std::size_t>> near;     // cell -> planes of its points
  std::map<Cell, std::vector<std::size_t>> points_in; // cell -> its points
  std::vector<Cell> changed;                         // cells whose planes were not yet asked around
  auto add_near = [&](const Cell& c, std::size_t j) {
    std::vector<std::size_t>& known = near[c];
    if (std::find(known.begin(), known.end(), j) != known.end()) return;
    known.push_back(j);
    changed.push_back(c);
  };
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (std::size_t j : joined[i]) add_near(cell_of(i), j);
    points_in[cell_of(i)].push_back(i);
  }
  while (!changed.empty()) {
    const Cell c = changed.back();
    changed.pop_back();
    const std::vector<std::size_t> known = near[c];
    for (int m = 0; m < 125; ++m) {
      const auto cell = points_in.find(Cell{c[0] + m % 5 - 2, c[1] + m / 5 % 5 - 2, c[2] + m / 25 - 2});
      if (cell == points_in.end()) continue;
      for (std::size_t i : cell->second)
        for (std::size_t j : known) {
          if (std::find(joined[i].begin(), joined[i].end(), j) != joined[i].end()) continue;
          if (!(std::abs(offset(i, planes[j].normal) - planes[j].offset) <= tolerance * scale)) continue;
          joined[i].push_back(j);
          planes[j].points.push_back(i);
          add_near(cell->first, j);
        }
    }
  }
  return planes;
}

/// The triangles t of `candidates` (corners: indices below `points`) for which keep(t) holds,
/// in their order; or, at the first side that three kept triangles share (no manifold mesh has
/// it), those kept so far. keep() runs first on the triangles with a side that three or more
/// candidates share, the only ones that can make such a side: where one is made, after few
/// calls of keep().
template <class Keep>
std::vector<std::array<std::size_t, 3>> kept_triangles(const std::vector<std::array<std::size_t, 3>>& candidates,
                                                       std::size_t points, const Keep& keep)
{
  auto side_key = [&](const std::array<std::size_t, 3>& t, int e) {
    const auto [a, b] = std::minmax(t[std::size_t(e)], t[std::size_t(e + 1) % 3]);
    return std::uint64_t(a) * points + b;
  };
  std::unordered_map<std::uint64_t, int> at_side; // candidates at each side, then kept ones
  for (const auto& t : candidates)
    for (int e = 0; e < 3; ++e) ++at_side[side_key(t, e)];
  std::vector<char> shares(candidates.size(), 0), kept(candidates.size(), 0);
  for (std::size_t k = 0; k < candidates.size(); ++k)
    for (int e = 0; e < 3; ++e) shares[k] |= at_side[side_key(candidates[k], e)] >= 3;
  for (auto& [side, count] : at_side) count = 0;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (!shares[k] || !(kept[k] = keep(k))) continue;
    bool third = false;
    for (int e = 0; e < 3; ++e) third |= ++at_side[side_key(candidates[k], e)] == 3;
    if (!third) continue;
    for (std::size_t m = 0; m <= k; ++m)
      if (kept[m]) triangles.push_back(candidates[m]);
    return triangles;
  }
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (shares[k] ? kept[k] : keep(k)) triangles.push_back(candidates[k]);
  return triangles;
}

/// The triangles of the planes of `positions` (point_planes(), with `more`), oriented by the planes'
/// outward normals, that lie on the boundary: is_free_at(x) (x a double point) says whether
/// the sum is free at x. Each plane's points are triangulated in the plane (constrained
/// Delaunay, the crease rows as constraints); a triangle is kept when its centroid and a
/// point just inside each of its corners (d / 2^20 from it) are on the plane's face: the sum
/// is free at d / 2^30 outside the plane and not at d / 2^30 inside, and the triangle (its
/// corners d / 2^20 inwards) lies in the union of the plane's convolution facets (`cover`).
/// Triangles of nearly
/// collinear points (area below 1e-10 of their longest edge squared: crease points rounded
/// off their line) are left out. Stops at the first side that three kept triangles share
/// (kept_triangles(), the exact tests as keep()): mesh_from_triangles() refuses the triangles
/// so far as it would all of them. On curved models, whose many small planes overlap round
/// their creases, a level that fails so fails after a few of its tests, and one that passes
/// keeps the same triangles in the same order. (CGAL's anchor turned + an octahedron 1/32 of
/// its size at 1%, refused at every level: with the tests in the planes' order, 148,820
/// triangles were tested at d/2 before a third was kept, 17.5 s; the whole `pmsum mesh`
/// 285 -> 127 s with this order.)
template <class IsFreeAt>
std::vector<std::array<std::size_t, 3>>
plane_triangles(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& positions,
                const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>& normals,
                const Crease_planes& more, double d, IsFreeAt&& is_free_at, Face_cover& cover)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  struct Point_id { std::size_t i = std::size_t(-1); }; // none: a crossing of two crease rows
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<Point_id, K>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
  // x on the plane's face: free just outside (d / 2^30 along the outward normal n), not just
  // inside. (Nearer than the passages and parts the covering resolves, and far above the
  // rounding of x; farther, the test would take the plane beyond a crease between two planes
  // at a small angle for their face.)
  auto on_face = [&](const K::Point_3& x, const K::Vector_3& n) {
    const double t = std::ldexp(d, -30);
    const K::Point_3 out = x + t * n, in = x - t * n;
    return is_free_at(std::array<double, 3>{out.x(), out.y(), out.z()}) &&
           !is_free_at(std::array<double, 3>{in.x(), in.y(), in.z()});
  };
  auto coordinates = [](const K::Point_3& x) { return std::array<double, 3>{x.x(), x.y(), x.z()}; };
  // The candidates (oriented triangles, with their planes) in the order of the planes; the
  // exact tests (on_face) run on them last (kept_triangles()).
  std::vector<std::array<std::size_t, 3>> candidates;
  std::vector<std::size_t> plane_of;
  const std::vector<Point_plane> planes = point_planes(positions, normals, more, d);
  std::vector<std::vector<std::size_t>> planes_of(positions.size());
  for (std::size_t j = 0; j < planes.size(); ++j)
    for (std::size_t i : planes[j].points) planes_of[i].push_back(j);
  // Are the three corners of a triangle of plane j on one other plane too? The triangle then
  // lies along the crease row of the two (a sliver), on the face of neither. CGAL's 3torus,
  // whose quadrilaterals are a millionth out of plane, plus a tetrahedron gives pairs of
  // planes 3e-6 apart along its creases; at d = 1.5% of the diagonal, such a sliver 0.005 d
  // wide, kept by the tests at its centroid, lay over a triangle of the nearly coplanar plane
  // beside it (three triangles at one side: the level refused).
  auto on_another_plane = [&](const std::array<std::size_t, 3>& t, std::size_t j) {
    for (std::size_t k : planes_of[t[0]])
      if (k != j && std::count(planes_of[t[1]].begin(), planes_of[t[1]].end(), k) > 0 &&
          std::count(planes_of[t[2]].begin(), planes_of[t[2]].end(), k) > 0)
        return true;
    return false;
  };
  for (std::size_t j = 0; j < planes.size(); ++j) {
    const Point_plane& plane = planes[j];
    if (plane.points.size() < 3) continue;
    // In the plane: drop the coordinate along which the normal is largest (exact), keeping
    // the cyclic order, so that a counterclockwise triangle has a normal of that sign there.
    const K::Vector_3& n = plane.normal;
    const int drop = std::abs(n.x()) >= std::abs(n.y()) && std::abs(n.x()) >= std::abs(n.z()) ? 0
                     : std::abs(n.y()) >= std::abs(n.z())                                  ? 1
                                                                                             : 2;
    const bool flip = n[drop] < 0;
    cover.set_plane({n.x(), n.y(), n.z()}, plane.offset, drop);
    Cdt cdt;
    std::map<std::size_t, typename Cdt::Vertex_handle> vertex_of;
    for (std::size_t i : plane.points) {
      const auto v = cdt.insert(K::Point_2(positions[i][(drop + 1) % 3], positions[i][(drop + 2) % 3]));
      v->info().i = i;
      vertex_of[i] = v;
    }
    // Crease rows: the points on this plane and another one, in order along their line;
    // consecutive ones closer than 2 d are joined by a constrained edge, so that both planes'
    // triangles meet along the row (and none crosses it).
    std::map<std::size_t, std::vector<std::size_t>> rows; // other plane -> its points here
    for (std::size_t i : plane.points)
      for (std::size_t k : planes_of[i])
        if (k != j) rows[k].push_back(i);
    for (auto& [k, row] : rows) {
      const K::Vector_3 along = CGAL::cross_product(n, planes[k].normal);
      auto at = [&](std::size_t i) { return (positions[i] - CGAL::ORIGIN) * along; };
      std::sort(row.begin(), row.end(), [&](std::size_t a, std::size_t b) { return at(a) < at(b); });
      for (std::size_t r = 1; r < row.size(); ++r)
        if (vertex_of[row[r - 1]] != vertex_of[row[r]] && // (equal points are one vertex)
            CGAL::squared_distance(positions[row[r - 1]], positions[row[r]]) < 4 * d * d)
          cdt.insert_constraint(vertex_of[row[r - 1]], vertex_of[row[r]]);
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      std::array<std::size_t, 3> t = {f->vertex(0)->info().i, f->vertex(1)->info().i, f->vertex(2)->info().i};
      if (std::count(t.begin(), t.end(), std::size_t(-1))) continue;
      const K::Point_3 &a = positions[t[0]], &b = positions[t[1]], &c = positions[t[2]];
      const double area = std::sqrt(CGAL::cross_product(b - a, c - a).squared_length());
      const double longest =
        (std::max)({(b - a).squared_length(), (c - b).squared_length(), (a - c).squared_length()});
      if (!(area > 1e-10 * longest)) continue;
      if (on_another_plane(t, j)) continue;
      if (!cover.covers({coordinates(a), coordinates(b), coordinates(c)}, std::ldexp(d, -20))) continue;
      if (flip) std::swap(t[1], t[2]);
      candidates.push_back(t);
      plane_of.push_back(j);
    }
  }
  // The centroid, then a point just inside the triangle at each corner: a triangle from a
  // crease point across a face's missing strip (the mouth of a passage whose far lip has no
  // point) has its centroid on the face, not its corner at that point.
  return kept_triangles(candidates, positions.size(), [&](std::size_t k) {
    const K::Point_3 &a = positions[candidates[k][0]], &b = positions[candidates[k][1]], &c = positions[candidates[k][2]];
    const K::Vector_3& n = planes[plane_of[k]].normal;
    const K::Point_3 centroid = CGAL::centroid(a, b, c);
    auto near_corner = [&](const K::Point_3& v) {
      const K::Vector_3 u = centroid - v;
      return v + (std::ldexp(d, -20) / std::sqrt(u.squared_length())) * u;
    };
    return on_face(centroid, n) && on_face(near_corner(a), n) && on_face(near_corner(b), n) && on_face(near_corner(c), n);
  });
}

/// The double positions of the corners of face f of `mesh`; none if f is not a triangle.
template <class TriangleMesh>
std::optional<std::array<std::array<double, 3>, 3>>
face_corners(const TriangleMesh& mesh, typename boost::graph_traits<TriangleMesh>::face_descriptor f)
{
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::array<std::array<double, 3>, 3> x{};
  int k = 0;
  for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) {
    if (k == 3) return std::nullopt;
    const auto& p = get(vpm, v);
    x[k++] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  if (k != 3) return std::nullopt;
  return x;
}

/// Is no face of `mesh` over empty space: at its centroid c, is the sum free just outside
/// (c + t n, t = d / 2^30) and still free at c - t n for every t = d / 2^30, d / 2^24, ...,
/// d / 2 (inward, no solid within d/2)? Such a face closes a hole over a passage or a
/// tunnel's mouth. A face of a plane has the solid just inside; one that fill_holes() put
/// across a convex crease has its centroid inside the solid, across a concave one the solid
/// within d/2 inside.
template <class TriangleMesh, class IsFreeAt>
bool no_face_over_empty_space(const TriangleMesh& mesh, double d, IsFreeAt&& is_free_at)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto free_at = [&](const K::Point_3& x) { return is_free_at(std::array<double, 3>{x.x(), x.y(), x.z()}); };
  for (auto f : faces(mesh)) {
    const auto x = face_corners(mesh, f);
    if (!x) return false;
    std::array<K::Point_3, 3> p;
    for (int i = 0; i < 3; ++i) p[i] = K::Point_3((*x)[i][0], (*x)[i][1], (*x)[i][2]);
    K::Vector_3 n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    if (n == CGAL::NULL_VECTOR) return false;
    n = n / std::sqrt(n.squared_length());
    const K::Point_3 c = CGAL::centroid(p[0], p[1], p[2]);
    if (!free_at(c + std::ldexp(d, -30) * n)) continue;
    bool solid_inside = false;
    for (int e : {30, 24, 18, 12, 8, 4, 2, 1})
      if ((solid_inside = !free_at(c - std::ldexp(d, -e) * n))) break;
    if (!solid_inside) return false;
  }
  return true;
}

/// Does `holds` hold for every face of `mesh` that lies in the plane of some convolution
/// facets (its corners, that plane selected in `cover`)? False if a face is not a triangle
/// or has no normal.
template <class TriangleMesh, class Holds>
bool every_face_in_a_facet_plane(const TriangleMesh& mesh, Face_cover& cover, const Holds& holds)
{
  using Corners = std::array<std::array<double, 3>, 3>;
  struct Face { std::array<std::int64_t, 4> key; std::array<double, 4> plane; Corners corners; };
  std::vector<Face> by_plane;
  by_plane.reserve(faces(mesh).size());
  for (auto f : faces(mesh)) {
    const std::optional<Corners> x = face_corners(mesh, f);
    if (!x) return false;
    Vec3<double> n = cross((*x)[1] - (*x)[0], (*x)[2] - (*x)[0]);
    const double length = std::sqrt(dot(n, n));
    if (!(length > 0)) return false;
    n = scaled(n, 1 / length);
    const double c = dot(n, (*x)[0]);
    by_plane.push_back({{std::llround(n[0] * 1e6), std::llround(n[1] * 1e6), std::llround(n[2] * 1e6), std::llround(c * 1e6)},
                        {n[0], n[1], n[2], c}, *x});
  }
  std::stable_sort(by_plane.begin(), by_plane.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  for (std::size_t i = 0, next; i < by_plane.size(); i = next) {
    for (next = i + 1; next < by_plane.size() && by_plane[next].key == by_plane[i].key; ++next) {}
    const auto& [n0, n1, n2, c] = by_plane[i].plane;
    const int drop = std::abs(n0) >= std::abs(n1) && std::abs(n0) >= std::abs(n2) ? 0 : std::abs(n1) >= std::abs(n2) ? 1 : 2;
    if (!cover.set_plane({n0, n1, n2}, c, drop)) continue;
    for (std::size_t j = i; j < next; ++j)
      if (!holds(by_plane[j].corners)) return false;
  }
  return true;
}

/// Does every face of `mesh` that lies in the plane of some convolution facets lie in their
/// union (Face_cover::covers(), corners moved d / 2^20 inwards)? A face that fill_holes() put
/// over a hole in a face, such as the mouth of a tunnel narrower than the points' spacing,
/// does not, while every point test on it can land on the face.
template <class TriangleMesh>
bool no_face_over_hole(const TriangleMesh& mesh, double d, Face_cover& cover)
{
  return every_face_in_a_facet_plane(mesh, cover, [&](const std::array<std::array<double, 3>, 3>& corners) {
    return cover.covers(corners, std::ldexp(d, -20));
  });
}

/// Does no face of `mesh` that lies in the plane of some convolution facets join two parts
/// of their union that do not meet (Face_cover::joins_separate_parts()) over a slit: free
/// space d / 2 under the middle of a gap it crosses, along the face's normal (`free_at`: the
/// exact test at a point)? The advancing front may lay such faces over the mouth of a slit
/// narrower than the points' spacing, from the points on one lip to those on the other, and
/// then the slit's other mouths make a tunnel: a handle the sum does not have (blocks + cube
/// 0.95 at d = 1.1% of the diagonal). A face over a recess less than d / 2 deep is not over a
/// slit: it cuts a corner of the face, or crosses a seam. CGAL's cheese plus an octahedron
/// 1/64 as wide, at d = 1.5%: a plane whose two parts meet, in the model, only through a wall
/// 0.025 d wide at the inner corner of an L round a pit; faces across that corner pass over
/// the sum's corner there, up to between d / 4 and d / 2 above it, and every level was refused
/// for one of them (exit 6 after 12 minutes; now the first level, 4 s). (Where a gap's
/// middle is on a crease of the sum, as on a side along the sum's edge, the point tested lies
/// on the boundary, which is free: the face is refused, as every such face was before.)
template <class TriangleMesh, class FreeAt>
bool no_face_joining_parts(const TriangleMesh& mesh, double d, Face_cover& cover, const FreeAt& free_at)
{
  return every_face_in_a_facet_plane(mesh, cover, [&](const std::array<std::array<double, 3>, 3>& corners) {
    if (!cover.joins_separate_parts(corners)) return true;
    const std::vector<std::array<double, 3>> gaps = cover.gaps_between_parts(corners);
    Vec3<double> n = cross(corners[1] - corners[0], corners[2] - corners[0]); // outward
    n = scaled(n, d / 2 / std::sqrt(dot(n, n)));
    return !gaps.empty() && std::none_of(gaps.begin(), gaps.end(), [&](const std::array<double, 3>& g) { return free_at(g - n); });
  });
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PLANE_TRIANGULATION_H
