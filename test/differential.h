// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Random small solids for the differential test against CGAL's exact Nef Minkowski sum: one
// seed gives one case (P, Q, d, contact space or not). Kinds, by seed:
//   convex         random convex hulls;
//   union          an exact union of 2-3 overlapping random hulls made into one solid (Nef),
//                  its rational vertices rounded to double (the rounded mesh is the input);
//   boxes on boxes boxes on a half-unit grid stacked on a base (one solid, exact), summed
//                  with a box: large coplanar and touching faces;
//   void           a hull minus a smaller hull strictly inside it: a solid with a void;
//   touching       two boxes as separate components touching along a face or an edge.
// Each is turned by a random non-round rotation (exact: see rotated()) half the time; P is
// negated (the contact space -P + Q) a quarter of the time; d is 2% to 6% of the sum's
// diagonal. Includes Nef: only for the translation unit that already compiles it.

#ifndef CGAL_PMSUM_TEST_DIFFERENTIAL_H
#define CGAL_PMSUM_TEST_DIFFERENTIAL_H

#include "test_support.h"

#include "../src/cli_input.h"

#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace pmsum_shapes {

struct Differential_case
{
  unsigned seed = 0;
  std::string kind;
  Soup P, Q;
  double d = 0;
  bool negate = false;
  std::array<int, 4> rotation{1, 0, 0, 0}; // identity when not turned
};

namespace differential {

using Nef = CGAL::Nef_polyhedron_3<EK>;

/// Hull of n random points of a 1/64 grid in the cube of half side r about c.
inline Soup random_hull(CGAL::Random& rng, int n, double r, const Point& c)
{
  std::vector<Point> pts;
  const int k = int(r * 64);
  for (int i = 0; i < n; ++i)
    pts.push_back({c[0] + rng.get_int(-k, k + 1) / 64., c[1] + rng.get_int(-k, k + 1) / 64.,
                   c[2] + rng.get_int(-k, k + 1) / 64.});
  return convex_hull(pts);
}

inline Nef to_nef(const Soup& s)
{
  CGAL::Surface_mesh<EK::Point_3> m;
  std::vector<EK::Point_3> pts;
  for (const auto& p : s.points) pts.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> polys;
  for (const auto& t : s.triangles) polys.push_back({t[0], t[1], t[2]});
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, m);
  return Nef(m);
}

/// The solid's boundary, triangulated, coordinates rounded to double (exact when they are
/// doubles, as for unions of boxes on a grid and differences of nested hulls).
inline Soup to_soup(const Nef& nef)
{
  std::vector<EK::Point_3> pts;
  std::vector<std::vector<std::size_t>> polys;
  CGAL::convert_nef_polyhedron_to_polygon_soup(nef, pts, polys, /*triangulate_all_faces=*/true);
  std::vector<IK::Point_3> points;
  for (const auto& p : pts) points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  // solids touching along an edge: split there, as pmsum's reader does
  pmsum_cli::split_non_manifold_edges(points, polys);
  Soup s;
  for (const auto& p : points) s.points.push_back({p.x(), p.y(), p.z()});
  for (const auto& f : polys) s.triangles.push_back({f[0], f[1], f[2]});
  return s;
}

inline Soup random_union(CGAL::Random& rng)
{
  Nef u;
  const int n = rng.get_int(2, 4);
  for (int i = 0; i < n; ++i) {
    const Point c{rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6), rng.get_double(-0.6, 0.6)};
    u += to_nef(random_hull(rng, rng.get_int(5, 12), 0.75, {std::round(c[0] * 64) / 64, std::round(c[1] * 64) / 64,
                                                             std::round(c[2] * 64) / 64}));
  }
  return to_soup(u.regularization());
}

inline Soup boxes_on_boxes(CGAL::Random& rng)
{
  auto half = [&](int lo, int hi) { return rng.get_int(lo, hi + 1) / 2.; };
  const double w = half(2, 6), h = half(1, 3);
  Nef u = to_nef(box({0, 0, 0}, {w, w, h}));
  const int n = rng.get_int(1, 4);
  for (int i = 0; i < n; ++i) {
    const double x = half(-1, int(2 * w)), y = half(-1, int(2 * w));
    u += to_nef(box({x, y, h}, {x + half(1, 4), y + half(1, 4), h + half(1, 3)}));
  }
  return to_soup(u.regularization());
}

inline Soup with_void(CGAL::Random& rng)
{
  const Soup outer = random_hull(rng, rng.get_int(10, 20), 1, {0, 0, 0});
  // a small hull about the centre of a box known to lie inside: the outer hull contains the
  // hull of its vertices' centroid neighbourhood only if it is large enough; test exactly
  Nef o = to_nef(outer);
  for (int attempt = 0; attempt < 20; ++attempt) {
    const Nef inner = to_nef(random_hull(rng, rng.get_int(4, 10), 0.25, {0, 0, 0}));
    if ((inner - o).is_empty()) return to_soup((o - inner).regularization());
  }
  return outer; // no inner hull fits: a plain hull
}

inline Soup touching_boxes(CGAL::Random& rng)
{
  auto half = [&](int lo, int hi) { return rng.get_int(lo, hi + 1) / 2.; };
  const Point size{half(1, 4), half(1, 4), half(1, 4)};
  Soup s = box({0, 0, 0}, size);
  const bool along_edge = rng.get_bool();
  Point lo{size[0], along_edge ? size[1] : half(-1, 1), 0};
  s.append(box(lo, {lo[0] + half(1, 4), lo[1] + half(1, 4), half(1, 4)}));
  return s;
}

/// A random quaternion with small integer components that is not a multiple of a round one.
inline std::array<int, 4> random_rotation(CGAL::Random& rng)
{
  for (;;) {
    std::array<int, 4> q;
    int nonzero = 0;
    for (int& c : q) nonzero += (c = rng.get_int(-3, 4)) != 0;
    if (nonzero >= 3) return q;
  }
}

inline double diagonal(const Soup& P, const Soup& Q)
{
  double s = 0;
  for (int c = 0; c < 3; ++c) {
    double extent = 0;
    for (const Soup* m : {&P, &Q}) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (const auto& p : m->points) lo = (std::min)(lo, p[c]), hi = (std::max)(hi, p[c]);
      extent += hi - lo;
    }
    s += extent * extent;
  }
  return std::sqrt(s);
}

} // namespace differential

inline Differential_case make_differential_case(unsigned seed)
{
  namespace df = differential;
  CGAL::Random rng(seed);
  Differential_case c;
  c.seed = seed;
  switch (seed % 5) {
  case 0:
    c.kind = "convex";
    c.P = df::random_hull(rng, rng.get_int(5, 20), 1, {0, 0, 0});
    c.Q = df::random_hull(rng, rng.get_int(4, 12), 0.5, {0, 0, 0});
    break;
  case 1:
    c.kind = "union";
    c.P = df::random_union(rng);
    c.Q = df::random_hull(rng, rng.get_int(4, 10), 0.4, {0, 0, 0});
    break;
  case 2:
    c.kind = "boxes on boxes";
    c.P = df::boxes_on_boxes(rng);
    c.Q = box({0, 0, 0}, {rng.get_int(1, 4) / 2., rng.get_int(1, 4) / 2., rng.get_int(1, 4) / 2.});
    break;
  case 3:
    c.kind = "void";
    c.P = df::with_void(rng);
    c.Q = df::random_hull(rng, rng.get_int(4, 8), 0.125, {0, 0, 0});
    break;
  default:
    c.kind = "touching";
    c.P = df::touching_boxes(rng);
    c.Q = df::random_hull(rng, rng.get_int(4, 10), 0.5, {0, 0, 0});
    break;
  }
  if (rng.get_bool()) {
    c.rotation = df::random_rotation(rng);
    c.P = rotated(c.P, c.rotation);
    c.Q = rotated(c.Q, c.rotation);
  }
  c.negate = rng.get_int(0, 4) == 0;
  c.d = rng.get_double(0.02, 0.06) * df::diagonal(c.P, c.Q);
  return c;
}

/// Writes a soup as OFF with every coordinate round-tripping exactly.
inline void write_off(const Soup& s, const std::string& path)
{
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << s.points.size() << ' ' << s.triangles.size() << " 0\n";
  for (const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_TEST_DIFFERENTIAL_H
