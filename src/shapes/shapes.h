// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Procedural models (tests, validation suite, pmsum generate), as polygon soups with exact
// double coordinates,
// and their conversion to any CGAL face graph. Each shape also knows the convex pieces it
// is the union of, so that exact reference answers can be built from them.

#ifndef CGAL_PMSUM_TEST_SHAPES_H
#define CGAL_PMSUM_TEST_SHAPES_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace pmsum_shapes {

using Point = std::array<double, 3>;

struct Box
{
  Point min, max;
};

/// A triangle soup plus the convex pieces (as point sets) whose union it bounds.
struct Soup
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::vector<Point>> convex_pieces; // union of their hulls = the solid (or surface)
  std::vector<Box> boxes;                         // same pieces, when they are boxes

  void append(const Soup& o)
  {
    const std::size_t off = points.size();
    points.insert(points.end(), o.points.begin(), o.points.end());
    for (auto t : o.triangles) triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    convex_pieces.insert(convex_pieces.end(), o.convex_pieces.begin(), o.convex_pieces.end());
    boxes.insert(boxes.end(), o.boxes.begin(), o.boxes.end());
  }
};

/// Outward oriented closed box.
inline Soup box(const Point& lo, const Point& hi)
{
  Soup s;
  for (int i = 0; i < 8; ++i)
    s.points.push_back({(i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1], (i & 4) ? hi[2] : lo[2]});
  // quads (counterclockwise seen from outside), split in two triangles
  const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& f : q) {
    s.triangles.push_back({std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])});
    s.triangles.push_back({std::size_t(f[0]), std::size_t(f[2]), std::size_t(f[3])});
  }
  s.convex_pieces.push_back(s.points);
  s.boxes.push_back({lo, hi});
  return s;
}

/// The box without its top face (z = hi): a surface with a border.
inline Soup open_box(const Point& lo, const Point& hi)
{
  Soup s = box(lo, hi);
  s.triangles.erase(s.triangles.begin() + 2, s.triangles.begin() + 4); // the {4,5,7,6} quad
  s.boxes.clear();
  s.convex_pieces.clear();
  // As a surface, it is the union of its five faces (flat convex pieces).
  const int q[5][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& f : q) s.convex_pieces.push_back({s.points[f[0]], s.points[f[1]], s.points[f[2]], s.points[f[3]]});
  return s;
}

/// Convex hull of points, triangulated, outward.
inline Soup convex_hull(const std::vector<Point>& pts)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> kp;
  for (const auto& p : pts) kp.emplace_back(p[0], p[1], p[2]);
  CGAL::Surface_mesh<K::Point_3> hull;
  CGAL::convex_hull_3(kp.begin(), kp.end(), hull);
  Soup s;
  for (auto v : hull.vertices()) s.points.push_back({hull.point(v).x(), hull.point(v).y(), hull.point(v).z()});
  for (auto f : hull.faces()) {
    std::array<std::size_t, 3> t;
    int i = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) t[i++] = std::size_t(v);
    s.triangles.push_back(t);
  }
  s.convex_pieces.push_back(s.points);
  return s;
}

inline Soup tetrahedron(double a = 1)
{ return convex_hull({{0, 0, 0}, {a, 0, 0}, {0, a, 0}, {0, 0, a}}); }

inline Soup octahedron(double a = 1)
{ return convex_hull({{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}}); }

/// Random convex polytope: hull of n points with coordinates on a 1/1024 grid in [-1, 1].
inline Soup random_convex(int n, unsigned seed)
{
  CGAL::Random rng(seed);
  std::vector<Point> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back({rng.get_int(-1024, 1025) / 1024., rng.get_int(-1024, 1025) / 1024.,
                   rng.get_int(-1024, 1025) / 1024.});
  return convex_hull(pts);
}

/// Ellipsoid with semi-axes a, b, c: hull of a latitude-longitude grid of points, rounded
/// to a 1/4096 grid so that the coordinates stay short.
inline Soup ellipsoid(double a, double b, double c, int slices = 12, int stacks = 6)
{
  std::vector<Point> pts = {{0, 0, c}, {0, 0, -c}};
  const double pi = std::acos(-1.);
  auto r = [](double x) { return std::round(x * 4096) / 4096; };
  for (int i = 1; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const double phi = pi * i / stacks, theta = 2 * pi * j / slices;
      pts.push_back({r(a * std::sin(phi) * std::cos(theta)), r(b * std::sin(phi) * std::sin(theta)),
                     r(c * std::cos(phi))});
    }
  return convex_hull(pts);
}

/// L-shaped prism: [0,2]x[0,1]x[0,1] union [0,1]x[0,2]x[0,1], one closed mesh.
inline Soup l_shape()
{
  Soup s;
  const std::vector<std::array<double, 2>> poly = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const std::size_t n = poly.size();
  for (double z : {0., 1.})
    for (const auto& p : poly) s.points.push_back({p[0], p[1], z});
  for (std::size_t i = 1; i + 1 < n; ++i) { // fans from vertex 0 (the polygon is star-shaped from it)
    s.triangles.push_back({0, i + 1, i});             // bottom, facing down
    s.triangles.push_back({n, n + i, n + i + 1});     // top, facing up
  }
  for (std::size_t i = 0; i < n; ++i) {               // sides
    const std::size_t j = (i + 1) % n;
    s.triangles.push_back({i, j, n + j});
    s.triangles.push_back({i, n + j, n + i});
  }
  for (const Box& b : {Box{{0, 0, 0}, {2, 1, 1}}, Box{{0, 0, 0}, {1, 2, 1}}}) {
    s.boxes.push_back(b);
    s.convex_pieces.push_back(box(b.min, b.max).points);
  }
  return s;
}

/// The paper's blocks (Fig. 6): the black squares of an n x n checkerboard of unit squares,
/// extruded to height h. Blocks touch their diagonal neighbours along vertical edges, so the
/// solid is not a manifold; each block is its own closed component, sharing no vertex.
inline Soup blocks(int n, double h)
{
  Soup s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if ((i + j) % 2 == 0) s.append(box({double(i), double(j), 0}, {double(i + 1), double(j + 1), h}));
  return s;
}

/// Two unit cubes side by side along x with a gap w between them, standing on a floor box
/// 2 + w long and 1/2 thick if `floor` (boxes that touch along faces), else apart (two
/// solids): summed with a convex Q whose extent along x is w - delta, a slot (or a slit) of
/// width delta.
inline Soup slot_blocks(double w, bool floor)
{
  Soup s = box({0, 0, 0}, {1, 1, 1});
  s.append(box({1 + w, 0, 0}, {2 + w, 1, 1}));
  if (floor) s.append(box({0, 0, -0.5}, {2 + w, 1, 0}));
  return s;
}

/// A 4 x 4 x 4 block with a square tunnel 1 x 1 along z through its middle (four boxes that
/// touch along faces).
inline Soup tunnel_block()
{
  Soup s = box({0, 0, 0}, {1.5, 4, 4});
  s.append(box({2.5, 0, 0}, {4, 4, 4}));
  s.append(box({1.5, 0, 0}, {2.5, 1.5, 4}));
  s.append(box({1.5, 2.5, 0}, {2.5, 4, 4}));
  return s;
}

/// A cube of the given side centred at the origin, turned about z by the angle of cosine c
/// and sine sn (c^2 + sn^2 = 1): its extent along x and y is side (c + sn). Then tilted
/// about x by the angle of cosine tc and sine ts, which keeps its extent along x (a small
/// tilt: faces nearly parallel to those of an axis-aligned part, slivers in the sum).
inline Soup turned_cube(double side, double c, double sn, double tc = 1, double ts = 0)
{
  std::vector<Point> pts;
  const double h = side / 2;
  for (double z : {-h, h})
    for (double a : {-h, h})
      for (double b : {-h, h}) {
        const double y = sn * a + c * b;
        pts.push_back({c * a - sn * b, ts == 0 ? y : tc * y - ts * z, ts == 0 ? z : ts * y + tc * z});
      }
  return convex_hull(pts);
}

/// Converts a soup to a face graph (Surface_mesh, Polyhedron_3, ...).
template <class Mesh>
Mesh to_mesh(const Soup& s)
{
  using P = typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<P> pts;
  for (const auto& p : s.points) pts.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> polys;
  for (const auto& t : s.triangles) polys.push_back({t[0], t[1], t[2]});
  Mesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, m);
  return m;
}

/// Each triangle cut in four at its edges' midpoints (exact in binary floating point), `times`
/// times: the same solid, with vertices inside its flat faces and on its creases.
inline Soup subdivided(Soup s, int times = 1)
{
  for (int k = 0; k < times; ++k) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, added] = midpoint.emplace(key, s.points.size());
      if (added)
        s.points.push_back({(s.points[a][0] + s.points[b][0]) / 2, (s.points[a][1] + s.points[b][1]) / 2,
                            (s.points[a][2] + s.points[b][2]) / 2});
      return it->second;
    };
    std::vector<std::array<std::size_t, 3>> triangles;
    for (const auto& t : s.triangles) {
      const std::size_t a = mid(t[0], t[1]), b = mid(t[1], t[2]), c = mid(t[2], t[0]);
      triangles.push_back({t[0], a, c});
      triangles.push_back({a, t[1], b});
      triangles.push_back({c, b, t[2]});
      triangles.push_back({a, b, c});
    }
    s.triangles = std::move(triangles);
  }
  return s;
}

/// Scales a soup (and its pieces) by a factor and translates it.
inline Soup transformed(Soup s, double scale, const Point& shift = {0, 0, 0})
{
  auto f = [&](Point& p) { for (int c = 0; c < 3; ++c) p[c] = p[c] * scale + shift[c]; };
  for (auto& p : s.points) f(p);
  for (auto& piece : s.convex_pieces) for (auto& p : piece) f(p);
  for (auto& b : s.boxes) { f(b.min); f(b.max); }
  return s;
}

/// Turns a soup by the rotation of the integer quaternion q = (a, b, c, e) and scales it by
/// N / 2^k, N = a^2 + b^2 + c^2 + e^2 and 2^k the smallest power of two >= N: the matrix is
/// M / 2^k with M integer, so a soup with small dyadic coordinates keeps exact coordinates,
/// coplanar faces stay coplanar and touching faces keep touching. The default (2, 1, 1, 1)
/// turns about the axis (1, 1, 1) by about 44.4 degrees and scales by 7/8. Its pieces are no
/// longer axis-aligned boxes.
/// @pre q is not zero.
inline Soup rotated(Soup s, const std::array<int, 4>& q = {2, 1, 1, 1})
{
  const long a = q[0], b = q[1], c = q[2], e = q[3];
  const long M[3][3] = {{a * a + b * b - c * c - e * e, 2 * (b * c - a * e), 2 * (b * e + a * c)},
                        {2 * (b * c + a * e), a * a - b * b + c * c - e * e, 2 * (c * e - a * b)},
                        {2 * (b * e - a * c), 2 * (c * e + a * b), a * a - b * b - c * c + e * e}};
  double scale = 1;
  while (scale < double(a * a + b * b + c * c + e * e)) scale *= 2;
  auto f = [&](Point& p) {
    Point r{};
    for (int i = 0; i < 3; ++i) r[i] = (M[i][0] * p[0] + M[i][1] * p[1] + M[i][2] * p[2]) / scale;
    p = r;
  };
  for (auto& p : s.points) f(p);
  for (auto& piece : s.convex_pieces) for (auto& p : piece) f(p);
  s.boxes.clear();
  return s;
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_TEST_SHAPES_H
