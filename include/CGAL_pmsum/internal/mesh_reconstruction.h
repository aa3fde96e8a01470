// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh stage of point_minkowski_sum_mesh(): output points with their outward normals are
// joined into triangles by CGAL's advancing-front surface reconstruction, the triangles
// made into an oriented halfedge mesh, and the mesh checked (check_mesh.h).
//
// The normals choose among the reconstruction's candidate triangles: a triangle is refused
// when it makes more than 80 degrees with the outward normal of one of its vertices (oriented
// by the sum of the three). Such a triangle joins the two sides of a thin part or of a narrow
// passage, or the outside of a shell to a void: points close together on surfaces that face
// away from each other. The normal of a point inside a convolution facet is the facet's; on a
// convolution edge or vertex (a possible crease or corner) it is not unique and not used. A
// vertex plus an edge that makes no crease with it (a point on the border of a face, inside a
// flat region of the sum) still tells the side it is on: a triangle is refused where two
// corners are on sides back to back (the two sides of a wall thinner than d, whose points on
// such borders carried no normal, and the advancing front joined the wall's outer face to the
// inner face of a hollow box across it). That side is not a normal for the 80-degree test:
// where parts of a mesh touch, the point may be on a crease of features it does not come from.
// A triangle with a point d or farther from its three corners is refused too: it could not be
// shown within d of the points (mesh_distance_bound()), and such triangles bridge concave
// corners, where the crease points carry no normal.
// The reconstruction leaves holes at sharp corners, and along the rims of parts thinner than
// about three times the point spacing: they are closed by triangulating each hole's border,
// or, where the hole is too wide for that, with the points the reconstruction left inside it
// (mesh_hole_filling.h).
// Where a filled hole crosses the triangles beside it, those are cut away with their
// neighbourhood and the hole filled again. Only the triangles that fill holes can cross
// another: the advancing front's are facets of one 3D Delaunay triangulation of the points'
// double positions (CGAL's, exact predicates), which meet only in shared corners and sides;
// so the crossings are searched among the filling triangles and those whose boxes meet
// theirs (searching all took 10-30% of the reconstruction on the suite's rows). Shells
// smaller than d (bubbles closed on a few points beside a crease) are removed. Where the
// result still fails a check, point_minkowski_sum_mesh() tries the same points plane by plane
// (plane_triangulation.h), through the same repairs and checks (mesh_from_triangles()), then
// refines.

#ifndef CGAL_PMSUM_INTERNAL_MESH_RECONSTRUCTION_H
#define CGAL_PMSUM_INTERNAL_MESH_RECONSTRUCTION_H

#include <CGAL_pmsum/check_mesh.h>
#include <CGAL_pmsum/internal/mesh_hole_filling.h>
#include <CGAL_pmsum/measure_mesh_distance.h>

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <iterator>
#include <set>
#include <thread>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <limits>
#include <numeric>
#include <optional>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// The largest distance from a point of the triangle abc to the nearest of its corners: the
/// circumradius if no angle is obtuse; else, with the obtuse angle at c, the larger distance
/// from a or b to where the perpendicular bisector of its side with c meets ab.
inline double corner_covering_radius(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                     const std::array<double, 3>& c)
{
  auto sq = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]) + (u[2] - v[2]) * (u[2] - v[2]);
  };
  // squared sides, the longest (opposite the largest angle) as s2
  std::array<double, 3> s = {sq(b, c), sq(c, a), sq(a, b)};
  std::sort(s.begin(), s.end());
  const double s0 = s[0], s1 = s[1], s2 = s[2];
  if (s2 <= s0 + s1) { // no obtuse angle: the circumradius, from 16 area^2 (Heron)
    const double area16 = 4 * s0 * s1 - (s0 + s1 - s2) * (s0 + s1 - s2);
    return area16 > 0 ? std::sqrt(s0 * s1 * s2 / area16) : std::sqrt(s2) / 2;
  }
  // obtuse: from the corner between sides 1 and 2 (angle opposite side 0), along side 2, to
  // the bisector of side 1: side1 / (2 cos), cos = (s1 + s2 - s0) / (2 sqrt(s1 s2)); alike for side 0
  return (std::max)(s1 * std::sqrt(s2) / (s1 + s2 - s0), s0 * std::sqrt(s2) / (s0 + s2 - s1));
}

/// What the normal of a face through a point tells the advancing front
/// (Normal_consistent_priority): nothing (a point on a crease or a corner, where the normal is
/// not unique, or on a trim curve), only the side of the sum the point is on (a point that may
/// be on a crease of features it does not come from, as where parts of a mesh touch), or also
/// its normal.
enum class Normal_use : unsigned char { none, side, normal };

/// Priority of the advancing front: CGAL's default (the radius of the smallest Delaunay
/// sphere through the triangle), but infinity (refused) for a triangle that makes an angle of
/// more than 80 degrees with a vertex normal (the triangle oriented by the sum of its vertex
/// normals; only the points whose `use` is Normal_use::normal have one: the others accept any
/// triangle). A triangle is refused too where two of its corners are on sides of the sum back
/// to back (the two sides of a thin wall, see back_to_back(); points whose `use` is not
/// Normal_use::none). Equal radii are frequent (lattice
/// points on flat faces are cospherical), and CGAL breaks such ties by the addresses of its
/// border elements, which depend on what the process allocated before: the radius is scaled
/// by 1 + 2^-40 h, h in [0, 1) a hash of the triangle's vertices, so that the mesh does not.
/// cos(80 degrees): the advancing front accepts a triangle only within 80 degrees of the face
/// normal of each of its corners that has one (Normal_consistent_priority).
constexpr double cos_largest_normal_angle = 0.17364817766693;

struct Normal_consistent_priority
{
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  const std::vector<Vector>* normals; // unit normals of a face through each point
  const std::vector<Normal_use>* use;  // what each point's normal tells
  double d;  // the covering distance of the points
  bool flat; // are the points coplanar (CGAL then adds a vertex)?

  template <class AdvancingFront, class Cell_handle>
  double operator()(const AdvancingFront& adv, Cell_handle& c, const int& index) const
  {
    const double infinity = std::numeric_limits<double>::infinity();
    std::array<typename Cell_handle::value_type::Vertex_handle, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = c->vertex((index + k + 1) & 3);
    // The radius is costly: it is computed only for a triangle that the tests below accept
    // (most Delaunay facets are refused), but first where a vertex may have no id (the
    // infinite vertex, the vertex CGAL adds to a flat point set: an infinite radius there
    // returns before the ids are read, as when it was computed first for every facet;
    // asked again below, it is CGAL's cached value). The same priorities as then, but that
    // CGAL caches the radius as computed from the side of the facet that asked first (the
    // two sides round differently), and the normal test may, within rounding, accept a
    // triangle from one side only: which side asks first can then differ.
    const auto& dt = adv.triangulation_3();
    if ((flat || dt.is_infinite(v[0]) || dt.is_infinite(v[1]) || dt.is_infinite(v[2])) &&
        adv.smallest_radius_delaunay_sphere(c, index) == infinity)
      return infinity;
    std::array<Vector, 3> n;
    for (int k = 0; k < 3; ++k)
      n[k] = (*use)[v[k]->id()] == Normal_use::normal ? (*normals)[v[k]->id()] : CGAL::NULL_VECTOR;
    auto at = [&](int k) { return std::array<double, 3>{v[k]->point().x(), v[k]->point().y(), v[k]->point().z()}; };
    if (corner_covering_radius(at(0), at(1), at(2)) >= d) return infinity;
    Vector t = CGAL::cross_product(v[1]->point() - v[0]->point(), v[2]->point() - v[0]->point());
    if (t * (n[0] + n[1] + n[2]) < 0) t = -t;
    const double length = std::sqrt(t.squared_length());
    for (const Vector& nk : n)
      if (nk != CGAL::NULL_VECTOR && !(t * nk > cos_largest_normal_angle * length)) return infinity;
    if (back_to_back(v[0], v[1]) || back_to_back(v[1], v[2]) || back_to_back(v[2], v[0])) return infinity;
    const double radius = adv.smallest_radius_delaunay_sphere(c, index);
    return radius == infinity ? radius : scaled_radius(radius, v);
  }

  /// Are points a and b on sides of the sum that face away from each other, back to back (the
  /// two sides of a wall): normals more than 160 degrees apart, each point in front of the
  /// other's side? (Sides that face each other, across a gap, may be joined.)
  template <class Vertex_handle>
  bool back_to_back(const Vertex_handle& a, const Vertex_handle& b) const
  {
    const double cos_160 = -0.9396926207859084;
    if ((*use)[a->id()] == Normal_use::none || (*use)[b->id()] == Normal_use::none) return false;
    const Vector& na = (*normals)[a->id()];
    const Vector& nb = (*normals)[b->id()];
    return na * nb < cos_160 && (a->point() - b->point()) * na > 0 && (b->point() - a->point()) * nb > 0;
  }

  /// The radius scaled by 1 + 2^-40 h, h a hash of the triangle's vertices (see above).
  template <class Vertex_handle>
  static double scaled_radius(double radius, const std::array<Vertex_handle, 3>& v)
  {
    std::array<std::uint64_t, 3> id = {std::uint64_t(v[0]->id()), std::uint64_t(v[1]->id()), std::uint64_t(v[2]->id())};
    std::sort(id.begin(), id.end());
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint64_t i : id) h = (h ^ i) * 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
    return radius * (1 + std::ldexp(double(h >> 11), -93)); // (h >> 11) / 2^53 in [0, 1), times 2^-40
  }
};

/// Calls f() on a thread of its own and waits for it (what f throws is rethrown here).
/// CGAL's advancing front orders its border by (priority, address of the border element), and
/// many priorities are equal (its constants for the triangles it puts off), so the mesh depends
/// on the order of the addresses malloc returns, that is on what the heap holds. After a
/// parallel stage the main thread's heap holds blocks freed by other threads in an order that
/// varies from run to run: the hooks' mesh was valid in three runs out of five. A new thread
/// allocates from an arena of its own: glibc gives it the arena of a thread that has exited
/// (in this package, only this function's threads exit), else a fresh one while there are
/// fewer than 8 per core. Only the reconstruction has used it: the same mesh in every run,
/// whatever the number of threads. (A user's program whose own threads exit before may hand
/// it an arena in any state; the mesh is checked all the same.)
template <class F>
void on_own_thread(const F& f)
{
  std::exception_ptr failure;
  std::thread([&] {
    try {
      f();
    } catch (...) {
      failure = std::current_exception();
    }
  }).join();
  if (failure) std::rethrow_exception(failure);
}

/// The pairs of triangles of `mesh` that cross (CGAL's self_intersections(); a degenerate
/// triangle f gives (f, f)) among the `suspect` ones and those whose boxes meet theirs: all
/// of them when the other triangles are known not to cross one another.
template <class ConcurrencyTag, class TriangleMesh, class IsSuspect>
std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor,
                      typename boost::graph_traits<TriangleMesh>::face_descriptor>>
crossings_near(const TriangleMesh& mesh, const IsSuspect& suspect)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, face_descriptor>;
  std::vector<Box> suspects, others;
  for (face_descriptor f : faces(mesh))
    (suspect(f) ? suspects : others).emplace_back(CGAL::Polygon_mesh_processing::face_bbox(f, mesh), f);
  std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
  if (suspects.empty()) return pairs;
  std::set<face_descriptor> near;
  for (const Box& b : suspects) near.insert(b.info());
  CGAL::box_intersection_d(suspects.begin(), suspects.end(), others.begin(), others.end(),
                           [&](const Box&, const Box& b) { near.insert(b.info()); });
  const std::vector<face_descriptor> range(near.begin(), near.end());
  CGAL::Polygon_mesh_processing::self_intersections<ConcurrencyTag>(range, mesh, std::back_inserter(pairs));
  return pairs;
}

/// Removes the faces `cut` of `mesh` with `rings` rings of faces around them (the faces around
/// their vertices, repeatedly), leaving holes for fill_holes(). The faces removed are taken
/// out of `suspects` if given.
template <class TriangleMesh>
void remove_faces_with_rings(TriangleMesh& mesh, std::set<typename boost::graph_traits<TriangleMesh>::face_descriptor> cut,
                             int rings, std::set<typename boost::graph_traits<TriangleMesh>::face_descriptor>* suspects)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  for (int r = 0; r < rings; ++r) {
    std::set<face_descriptor> grown = cut;
    for (face_descriptor f : cut)
      for (auto v : vertices_around_face(halfedge(f, mesh), mesh))
        for (face_descriptor g : faces_around_target(halfedge(v, mesh), mesh))
          if (g != boost::graph_traits<TriangleMesh>::null_face()) grown.insert(g);
    cut.swap(grown);
  }
  for (face_descriptor f : cut) {
    CGAL::Euler::remove_face(halfedge(f, mesh), mesh);
    if (suspects) suspects->erase(f);
  }
}

/// Removes the faces of `mesh` that intersect another one, with `rings` rings of faces around
/// them (remove_faces_with_rings()). `suspects`: if given, only these faces may cross another
/// (crossings_near()); the faces removed are taken out of it. Returns whether a face
/// intersected another.
template <class ConcurrencyTag, class TriangleMesh>
bool cut_self_intersections(TriangleMesh& mesh, int rings,
                            std::set<typename boost::graph_traits<TriangleMesh>::face_descriptor>* suspects)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::vector<std::pair<face_descriptor, face_descriptor>> pairs;
  if (suspects) pairs = crossings_near<ConcurrencyTag>(mesh, [&](face_descriptor f) { return suspects->count(f) > 0; });
  else CGAL::Polygon_mesh_processing::self_intersections<ConcurrencyTag>(mesh, std::back_inserter(pairs));
  if (pairs.empty()) return false;
  std::set<face_descriptor> cut;
  for (const auto& fg : pairs) cut.insert({fg.first, fg.second});
  remove_faces_with_rings(mesh, std::move(cut), rings, suspects);
  return true;
}

/// Removes the faces of `mesh` beside its holes (those fill_holes() left open), with `rings`
/// rings of faces around them (remove_faces_with_rings()): where the reconstruction folded,
/// every triangulation of a hole's border may need a side that the faces around already have
/// (a pentagon whose three diagonals from alternate corners are sides elsewhere: the anchor
/// turned at random plus an octahedron at 1%), and the larger hole has more. `suspects` as in
/// cut_self_intersections(). Returns whether `mesh` had a hole.
template <class TriangleMesh>
bool cut_round_holes(TriangleMesh& mesh, int rings,
                     std::set<typename boost::graph_traits<TriangleMesh>::face_descriptor>* suspects)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::set<face_descriptor> cut;
  for (auto h : halfedges(mesh))
    if (is_border(h, mesh)) cut.insert(face(opposite(h, mesh), mesh));
  if (cut.empty()) return false;
  remove_faces_with_rings(mesh, std::move(cut), rings - 1, suspects);
  return true;
}

/// Removes the shells (connected components) of `mesh` whose bounding box has a diagonal
/// shorter than `d`, unless no other shell would remain: bubbles, such as a tetrahedron that
/// the reconstruction closes on four points near a crease, beside the shell they belong to.
/// A shell of the exact boundary that small (a tiny void) is lost with them: its points are
/// then as far from the mesh as the void is from the rest of the boundary, which
/// point_minkowski_sum_mesh() refuses if it is d or more; nearer, only the shell count against
/// the exact boundary's (pmsum validate --mesh) tells.
template <class TriangleMesh>
void remove_bubbles(TriangleMesh& mesh, double d)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t n = PMP::connected_components(mesh, component);
  if (n < 2) return;
  std::vector<CGAL::Bbox_3> boxes(n);
  const auto vpm = get(CGAL::vertex_point, mesh);
  for (auto f : faces(mesh))
    for (auto v : vertices_around_face(halfedge(f, mesh), mesh)) boxes[get(component, f)] += get(vpm, v).bbox();
  std::vector<std::size_t> small;
  for (std::size_t k = 0; k < n; ++k) {
    const CGAL::Bbox_3& b = boxes[k];
    double squared = 0;
    for (int c = 0; c < 3; ++c) squared += (b.max(c) - b.min(c)) * (b.max(c) - b.min(c));
    if (squared < d * d) small.push_back(k);
  }
  if (small.size() < n) PMP::remove_connected_components(mesh, small, component);
}

/// The double positions of `points` (exact or not).
template <class Point>
std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> double_positions(const std::vector<Point>& points)
{
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> positions;
  positions.reserve(points.size());
  for (const Point& p : points)
    positions.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  return positions;
}

/// Do the points lie in one plane (or fewer dimensions)? Exact predicates.
inline bool coplanar_points(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& points)
{
  const auto a = points.begin(), end = points.end();
  if (a == end) return true;
  const auto b = std::find_if(a, end, [&](const auto& p) { return p != *a; });
  if (b == end) return true;
  const auto c = std::find_if(b, end, [&](const auto& p) { return !CGAL::collinear(*a, *b, p); });
  return c == end || std::all_of(c, end, [&](const auto& p) { return CGAL::coplanar(*a, *b, *c, p); });
}

/// The triangles that CGAL's advancing front makes of `positions` (a d-covering), chosen by
/// the unit outward `normals` of a face through each point, as far as `use` says
/// (Normal_consistent_priority).
inline std::vector<std::array<std::size_t, 3>>
advancing_front_triangles(const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& positions,
                          const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3>& normals,
                          const std::vector<Normal_use>& use, double d)
{
  std::vector<std::array<std::size_t, 3>> triangles;
  const bool flat = coplanar_points(positions);
  on_own_thread([&] {
    CGAL::advancing_front_surface_reconstruction(positions.begin(), positions.end(), std::back_inserter(triangles),
                                                 Normal_consistent_priority{&normals, &use, d, flat});
  });
  return triangles;
}

/// The triangles at each point of a triangle soup (point indices): those at point p are
/// at[start[p]] .. at[start[p + 1] - 1], in the order of the triangles.
struct Triangle_stars
{
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  std::vector<std::size_t> start, at;

  /// @pre every index of `triangles` is below `points`
  Triangle_stars(const Triangles& triangles, std::size_t points) : start(points + 1, 0), at(3 * triangles.size())
  {
    for (const auto& t : triangles)
      for (std::size_t p : t) ++start[p + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::size_t> filled(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < triangles.size(); ++f)
      for (std::size_t p : triangles[f]) at[filled[p]++] = f;
  }

  /// The triangle across side i of triangle f, from its corner i to the next: the first other
  /// one at that side's first corner with its second; `triangles.size()` if there is none.
  /// `another`, if given, tells whether a third triangle has that side too.
  std::size_t across(const Triangles& triangles, std::size_t f, int i, bool* another = nullptr) const
  {
    const std::size_t a = triangles[f][std::size_t(i)], b = triangles[f][std::size_t(i + 1) % 3];
    std::size_t found = triangles.size();
    if (another) *another = false;
    for (std::size_t k = start[a]; k < start[a + 1]; ++k) {
      const auto& t = triangles[at[k]];
      if (at[k] == f || std::count(t.begin(), t.end(), b) == 0) continue;
      if (found == triangles.size()) found = at[k];
      else if (another) *another = true;
      if (!another) break;
    }
    return found;
  }
};

/// Removes, at each point where `triangles` (point indices) make several fans (triangles
/// joined by their sides through the point), every fan but the one with the most triangles
/// (the first of them if equal), until every point has one fan: the places left are holes
/// for fill_holes(). Plane by plane, two planes' triangles may touch at a crease point only
/// (CGAL's 3torus, whose quadrilaterals are a millionth out of plane, plus a tetrahedron:
/// five such points at d = 1.5% of the diagonal, where orient_manifold_triangles() refused
/// the whole level).
inline void keep_one_fan_per_point(std::vector<std::array<std::size_t, 3>>& triangles)
{
  for (bool removed = true; removed;) {
    removed = false;
    std::size_t points = 0;
    for (const auto& t : triangles) points = (std::max)(points, *std::max_element(t.begin(), t.end()) + 1);
    const Triangle_stars stars(triangles, points);
    std::vector<bool> gone(triangles.size(), false);
    std::vector<std::size_t> fan(triangles.size()); // the fan of each triangle at the point p
    for (std::size_t p = 0; p < points; ++p) {
      const std::size_t first = stars.start[p], last = stars.start[p + 1];
      if (last - first < 2) continue;
      for (std::size_t k = first; k < last; ++k) fan[stars.at[k]] = k - first;
      // join the triangles at p that share a side through p (union of fans, smallest label)
      for (bool joined = true; joined;) {
        joined = false;
        for (std::size_t k = first; k < last; ++k)
          for (std::size_t l = k + 1; l < last; ++l) {
            const auto &a = triangles[stars.at[k]], &b = triangles[stars.at[l]];
            bool side = false;
            for (std::size_t q : a) side = side || (q != p && std::count(b.begin(), b.end(), q) > 0);
            std::size_t &fa = fan[stars.at[k]], &fb = fan[stars.at[l]];
            if (side && fa != fb) {
              fa = fb = (std::min)(fa, fb);
              joined = true;
            }
          }
      }
      std::vector<std::size_t> size(last - first, 0);
      for (std::size_t k = first; k < last; ++k) ++size[fan[stars.at[k]]];
      const std::size_t kept = std::size_t(std::max_element(size.begin(), size.end()) - size.begin());
      for (std::size_t k = first; k < last; ++k)
        if (fan[stars.at[k]] != kept) removed = gone[stars.at[k]] = true;
    }
    std::size_t j = 0;
    for (std::size_t f = 0; f < triangles.size(); ++f)
      if (!gone[f]) triangles[j++] = triangles[f];
    triangles.resize(j);
  }
}

/// Orients `triangles` (point indices) consistently if they form an orientable 2-manifold
/// (with or without border), as CGAL's orient_polygon_soup() would (each edge-connected
/// component keeps the orientation of its first triangle; a triangle turned is reversed):
/// true if they do; false (`triangles` then partly turned) if a triangle repeats a point, an
/// edge borders more than two triangles, the triangles at a point are not one fan (joined
/// by their edges through it), or no orientation agrees along every edge. This is what
/// orient_polygon_soup() and is_polygon_soup_a_polygon_mesh() tell together, in linear time
/// (together they took 0.37 s on 87k triangles).
inline bool orient_manifold_triangles(std::vector<std::array<std::size_t, 3>>& triangles)
{
  const std::size_t n = triangles.size();
  std::size_t points = 0;
  for (const auto& T : triangles) {
    if (T[0] == T[1] || T[1] == T[2] || T[2] == T[0]) return false;
    points = (std::max)(points, *std::max_element(T.begin(), T.end()) + 1);
  }
  const Triangle_stars stars(triangles, points);
  const auto& start = stars.start;
  const auto& at = stars.at;
  // The other triangle at each side (side i of t from its corner i to the next), or n.
  std::vector<std::array<std::size_t, 3>> beyond(n);
  for (std::size_t t = 0; t < n; ++t)
    for (int i = 0; i < 3; ++i) {
      bool third = false;
      beyond[t][std::size_t(i)] = stars.across(triangles, t, i, &third);
      if (third) return false;
    }
  auto across = [&](std::size_t t, std::size_t a, std::size_t b) { // the other triangle of side ab of t, or n
    const auto& T = triangles[t];
    for (std::size_t i = 0; i < 3; ++i)
      if ((T[i] == a && T[(i + 1) % 3] == b) || (T[i] == b && T[(i + 1) % 3] == a)) return beyond[t][i];
    return n;
  };
  auto runs = [&](std::size_t t, std::size_t a, std::size_t b) { // does triangle t run from a to b?
    const auto& T = triangles[t];
    return (T[0] == a && T[1] == b) || (T[1] == a && T[2] == b) || (T[2] == a && T[0] == b);
  };
  // Orientation: from the first triangle of each component, a neighbour that runs along a
  // shared edge the same way is reversed.
  std::vector<bool> oriented(n, false);
  std::vector<std::size_t> stack;
  for (std::size_t s = 0; s < n; ++s) {
    if (oriented[s]) continue;
    oriented[s] = true;
    stack.assign(1, s);
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const std::size_t a = triangles[t][i], b = triangles[t][(i + 1) % 3], u = across(t, a, b);
        if (u == n) continue;
        const bool same_way = runs(u, a, b);
        if (oriented[u]) {
          if (same_way) return false;
          continue;
        }
        if (same_way) { // (x, y, z) -> (z, y, x): sides 0 and 1 swap
          std::reverse(triangles[u].begin(), triangles[u].end());
          std::swap(beyond[u][0], beyond[u][1]);
        }
        oriented[u] = true;
        stack.push_back(u);
      }
    }
  }
  // One fan per point: the triangles at p, joined across their edges through p.
  std::vector<std::size_t> seen(n, 0); // p + 1: reached from the first triangle at p
  for (std::size_t p = 0; p + 1 < start.size(); ++p) {
    if (start[p] == start[p + 1]) continue;
    std::size_t reached = 1;
    seen[at[start[p]]] = p + 1;
    stack.assign(1, at[start[p]]);
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      for (std::size_t q : triangles[t]) {
        if (q == p) continue;
        const std::size_t u = across(t, p, q);
        if (u == n || seen[u] == p + 1) continue;
        seen[u] = p + 1;
        ++reached;
        stack.push_back(u);
      }
    }
    if (reached != start[p + 1] - start[p]) return false;
  }
  return true;
}

/// Where the triangles given to mesh_from_triangles() come from.
enum class Triangles_from : std::uint8_t
{
  /// facets of one Delaunay triangulation of the points' double positions (the advancing
  /// front's): no two of them cross (they meet in a shared corner or side, or not at all)
  one_delaunay_triangulation,
  /// anywhere (plane by plane): any two may cross
  anywhere
};

/// Closes `mesh`, whose faces cross none of one another but (if given) those of `suspects`
/// (all of them if null), and orients it to bound a volume: holes closed (those left open cut
/// round and closed again), crossings cut and closed again, bubbles removed. Returns the
/// mesh's checks. `points`: the d-covering whose points fill_holes() may put in.
template <class ConcurrencyTag, class TriangleMesh, class Point>
Mesh_checks close_mesh(const std::vector<Point>& points, double d,
                       std::set<typename boost::graph_traits<TriangleMesh>::face_descriptor>* suspects, TriangleMesh& mesh)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::set<face_descriptor> filled;
  std::set<face_descriptor>* fillings = suspects ? suspects : &filled;
  fill_holes(mesh, 3 * d, std::inserter(*fillings, fillings->end()), points);
  // Where a filled hole crosses the triangles beside it (a fold left by the reconstruction),
  // or a hole is left open, cut the crossing triangles, or those beside the hole, with a
  // growing neighbourhood and fill again. The last search that found no crossing, on the mesh
  // as it is, answers that check.
  std::optional<bool> self_intersection_free;
  for (int rings = 1; rings <= 3; ++rings) {
    const bool holes = cut_round_holes(mesh, rings, fillings);
    if (!cut_self_intersections<ConcurrencyTag>(mesh, rings, suspects) && !holes) {
      self_intersection_free = true;
      break;
    }
    fill_holes(mesh, 3 * d, std::inserter(*fillings, fillings->end()), points);
  }
  remove_bubbles(mesh, d); // (removing shells makes no crossing)
  Mesh_checks c = check_mesh_given<ConcurrencyTag>(mesh, self_intersection_free);
  if (c.self_intersection_free && !c.bounds_a_volume) {
    CGAL::Polygon_mesh_processing::orient_to_bound_a_volume(mesh);
    check_shells(mesh, c); // reorienting changes no position: the other checks stand
  }
  return c;
}

/// The normal of face f of `mesh` (a triangle), twice its area long, from its corners' positions
/// rounded to doubles.
template <class TriangleMesh>
CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3
face_normal(const TriangleMesh& mesh, typename boost::graph_traits<TriangleMesh>::face_descriptor f)
{
  const auto h = halfedge(f, mesh);
  const std::array<Position, 3> x = {position(get(CGAL::vertex_point, mesh, source(h, mesh))),
                                     position(get(CGAL::vertex_point, mesh, target(h, mesh))),
                                     position(get(CGAL::vertex_point, mesh, target(next(h, mesh), mesh)))};
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  auto side = [&](int k) { return Vector(x[k][0] - x[0][0], x[k][1] - x[0][1], x[k][2] - x[0][2]); };
  return CGAL::cross_product(side(1), side(2));
}

/// The faces of `mesh` (oriented outward; their indices in the order of faces(mesh)) turned
/// against the faces of the sum their corners lie on: every corner a point with a face normal
/// (`normal_at(position(p))`: a unit vector, or none), each more than 100 degrees from the
/// face's normal (the advancing front's test, Normal_consistent_priority, mirrored). The
/// advancing front accepted such a face facing the other way, or a filling or a point put back
/// made it, and orienting the mesh as a whole turned it over: the mesh folds there. A right
/// mesh has none: it lies within d of the boundary, facing out where its corners' faces do
/// (none on the 22 rows of the mesh table). Found by sweep.py's turned inputs (P turned by a
/// seed's rotation; benchmark/mesh/hard/README.md), at 2% and 1% of the diagonal:
/// - the L-shape (seed 41), -P plus a small cube: chords under a convex crease of 68 degrees,
///   from points of one face to points of the other, faced into the solid (-0.73, -0.71 and
///   -0.73 of their corners' normals), a tube under the crease; every other check passed it,
///   with a handle too many (Euler characteristic 0 against 2);
/// - cross (seed 53) plus star: a chord across a crease of 84 degrees turned over, a wrinkle
///   beside the crease (the topology right).
/// Such faces are made again round (remesh_around()), as second sheets are; where that does not
/// remove them, the mesh as it was goes on to the other checks. The tents of the
/// points put back (insert_left_out_points()) are not asked: mesh_levels() looks for folds
/// before. The plates (seed 53) plus a small cube had a tent whose third triangle lay back on
/// the other two, 3e-16 out of their plane (no crossing in doubles), a wrinkle of no thickness
/// that holds its point; taking such tents down (tried) left the plates turned by seed 7 with
/// a part of the boundary 1.1 d from the mesh.
template <class TriangleMesh, class NormalAt>
std::vector<std::size_t> faces_against_their_corners(const TriangleMesh& mesh, const NormalAt& normal_at)
{
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::vector<std::size_t> against_corners;
  std::size_t index = 0;
  for (auto f : faces(mesh)) {
    const Vector t = face_normal(mesh, f);
    const double length = std::sqrt(t.squared_length());
    bool against = true;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) {
      const std::optional<Vector> n = normal_at(position(get(vpm, v)));
      against = n && t * *n < -cos_largest_normal_angle * length;
      if (!against) break;
    }
    if (against) against_corners.push_back(index);
    ++index;
  }
  return against_corners;
}

/// Makes `triangles` (indices into `points`, a d-covering) into `mesh`, oriented to bound a
/// volume (close_mesh()). Returns the mesh's checks; the mesh is left empty if the triangles
/// do not form an oriented manifold.
/// Triangles_from::one_delaunay_triangulation with points of double coordinates (the
/// positions triangulated): only the triangles that fill holes, and those whose boxes meet
/// theirs, are searched for crossings; else all of them.
template <class ConcurrencyTag, class TriangleMesh, class Point>
Mesh_checks mesh_from_triangles(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3>>& triangles,
                                Triangles_from from, double d, TriangleMesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  std::vector<std::array<std::size_t, 3>> polygons(triangles);
  clear(mesh);
  keep_one_fan_per_point(polygons);
  if (!orient_manifold_triangles(polygons)) return Mesh_checks{}; // not orientable, or not a manifold mesh
  std::vector<Point> soup_points(points);
  PMP::remove_isolated_points_in_polygon_soup(soup_points, polygons); // points the triangles left out
  PMP::polygon_soup_to_polygon_mesh(soup_points, polygons, mesh);
  // The faces that may cross another: those that fill holes, if the others cross none.
  const bool delaunay = from == Triangles_from::one_delaunay_triangulation &&
                        std::is_same<typename CGAL::Kernel_traits<Point>::Kernel::FT, double>::value;
  std::set<face_descriptor> filled;
  return close_mesh<ConcurrencyTag>(points, d, delaunay ? &filled : nullptr, mesh);
}

/// Cuts the faces `cut` of `mesh` (closed, no two faces crossing) with a ring of faces
/// round them out of it, and closes it again (close_mesh(); only the new faces may cross
/// another). Returns the mesh's checks.
template <class ConcurrencyTag, class TriangleMesh, class Point>
Mesh_checks remesh_around(const std::vector<Point>& points,
                          std::set<typename boost::graph_traits<TriangleMesh>::face_descriptor> cut, double d,
                          TriangleMesh& mesh)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  remove_faces_with_rings(mesh, std::move(cut), 1, nullptr);
  std::set<face_descriptor> filled;
  return close_mesh<ConcurrencyTag>(points, d, &filled, mesh);
}

/// The index of the point at each position (the first of those there), to tell which point
/// each vertex of a mesh is (its part, its normal).
template <class Point>
std::unordered_map<Position, std::size_t, Position_hash> indices_by_position(const std::vector<Point>& points)
{
  std::unordered_map<Position, std::size_t, Position_hash> index_at;
  for (std::size_t i = 0; i < points.size(); ++i) index_at.emplace(position(points[i]), i);
  return index_at;
}

/// The margin added to a distance measured on positions rounded to doubles, for that rounding
/// and the distance's: 256 units in the last place of the largest coordinate.
inline double rounding_margin(double largest_coordinate)
{
  return 256 * std::numeric_limits<double>::epsilon() * largest_coordinate;
}

/// rounding_margin() for the largest coordinate of `positions` (points of doubles, or arrays
/// of three).
template <class Range>
double rounding_margin_of(const Range& positions)
{
  double largest = 0;
  for (const auto& x : positions) largest = (std::max)({largest, std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
  return rounding_margin(largest);
}

/// The largest distance from `points` to the triangles of `mesh` (0 if every point is a
/// vertex; infinity if the mesh has no triangle), plus rounding_margin() if not 0 (the
/// positions are rounded to doubles alike for both). Only the points at no vertex are searched for.
template <class Point, class TriangleMesh>
double largest_distance_to_mesh(const std::vector<Point>& points, const TriangleMesh& mesh)
{
  if (faces(mesh).empty()) return std::numeric_limits<double>::infinity();
  std::vector<Point_search::K::Point_3> away;
  for (std::size_t i : points_at_no_vertex(points, mesh)) {
    const Position x = position(points[i]);
    away.emplace_back(x[0], x[1], x[2]);
  }
  if (away.empty()) return 0;
  const double e = largest_distance_to({to_shell(mesh)}, [&](const auto& f) {
    for (const auto& x : away) f(x);
  });
  return e > 0 ? e + rounding_margin_of(away) : e;
}

/// A bound of the largest distance from a point of `mesh` to the nearest of `points`, made
/// below `limit` where it can be: each triangle, split in four as long as needed (six times
/// at most), is closer than (largest distance from a corner to the points) + (its
/// corner_covering_radius()) to them. Returns the largest bound (0 for a mesh without
/// triangles), or a value >= `limit` as soon as a triangle's cannot be brought below it.
/// The mesh's vertices being points, a triangle needs no split and no search while its
/// corner covering radius is below `limit`. With rounding_margin().
template <class Point, class TriangleMesh>
double mesh_distance_bound(const TriangleMesh& mesh, const std::vector<Point>& points, double limit)
{
  using V = std::array<double, 3>;
  const Shell s = to_shell(mesh);
  const double margin = rounding_margin_of(s.points);
  std::optional<Point_search> search; // built on the first triangle that needs it
  auto distance = [&](const V& x) {
    if (!search) search.emplace(points);
    if (search->points.empty()) return std::numeric_limits<double>::infinity();
    const Point_search::Search nearest(search->tree, Point_search::K::Point_3(x[0], x[1], x[2]), 1);
    return std::sqrt(nearest.begin()->second);
  };
  std::vector<double> at_vertex(s.points.size(), -1); // -1: not searched yet
  auto vertex_distance = [&](std::size_t v) {
    if (at_vertex[v] < 0) at_vertex[v] = distance(s.points[v]);
    return at_vertex[v];
  };
  auto mid = [](const V& u, const V& v) { return V{(u[0] + v[0]) / 2, (u[1] + v[1]) / 2, (u[2] + v[2]) / 2}; };
  // the bound of triangle t with its corners' distances e, split `depth` more times at most
  std::function<double(const std::array<V, 3>&, const std::array<double, 3>&, int)> bound =
    [&](const std::array<V, 3>& t, const std::array<double, 3>& e, int depth) {
      const double corners = (std::max)({e[0], e[1], e[2]}) + margin;
      const double b = corners + corner_covering_radius(t[0], t[1], t[2]);
      if (b < limit || corners >= limit || depth == 0) return b;
      const std::array<V, 3> m = {mid(t[1], t[2]), mid(t[2], t[0]), mid(t[0], t[1])};
      const std::array<double, 3> em = {distance(m[0]), distance(m[1]), distance(m[2])};
      double worst = bound({m[0], m[1], m[2]}, em, depth - 1);
      for (int i = 0; i < 3 && worst < limit; ++i)
        worst = (std::max)(worst, bound({t[i], m[(i + 2) % 3], m[(i + 1) % 3]}, {e[i], em[(i + 2) % 3], em[(i + 1) % 3]},
                                        depth - 1));
      return worst;
    };
  double worst = 0;
  for (const auto& tri : s.triangles) {
    const std::array<V, 3> t = {s.points[tri[0]], s.points[tri[1]], s.points[tri[2]]};
    const double r = corner_covering_radius(t[0], t[1], t[2]) + margin;
    const double b = r < limit ? r : bound(t, {vertex_distance(tri[0]), vertex_distance(tri[1]), vertex_distance(tri[2])}, 6);
    worst = (std::max)(worst, b);
    if (worst >= limit) break;
  }
  return worst;
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_MESH_RECONSTRUCTION_H
