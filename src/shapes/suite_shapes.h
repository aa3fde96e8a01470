// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Procedural models for the validation suite: hooks, grates, frames of high genus, shells
// with windows (easy hole), separated plates (difficult hole) and torus knots.
//
// All coordinates are exact small dyadic doubles (as long as the parameters are), closed
// components are outward oriented. The box-built shapes are unions of boxes with pairwise
// disjoint interiors (they may touch along faces, edges or vertices), each box being its
// own closed component of the soup (see Soup::append), and `boxes` / `convex_pieces` list
// them one entry per box.

#ifndef CGAL_PMSUM_SUITE_SHAPES_H
#define CGAL_PMSUM_SUITE_SHAPES_H

#include "shapes.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace pmsum_shapes {

namespace suite_internal {

// Box from min and max in the permuted axes: local coordinate i goes to axis ax[i].
inline Soup box_axes(const std::array<int, 3>& ax, const Point& lo, const Point& hi)
{
  Point a{}, b{};
  for (int i = 0; i < 3; ++i) { a[ax[i]] = lo[i]; b[ax[i]] = hi[i]; }
  return box(a, b);
}

// A rectangle [u0,u1]x[v0,v1] with the centered window [a0,a1]x[b0,b1] removed, times
// [w0,w1], as 4 boxes (two full strips, two side pieces); ax maps (u, v, w) to axes.
inline void slab_with_window(Soup& s, const std::array<int, 3>& ax, double u0, double u1, double v0,
                             double v1, double a0, double a1, double b0, double b1, double w0, double w1)
{
  s.append(box_axes(ax, {u0, v0, w0}, {u1, b0, w1}));
  s.append(box_axes(ax, {u0, b1, w0}, {u1, v1, w1}));
  s.append(box_axes(ax, {u0, b0, w0}, {a0, b1, w1}));
  s.append(box_axes(ax, {a1, b0, w0}, {u1, b1, w1}));
}

} // namespace suite_internal

/// J/U-like hook in the xz-plane, y in [0, s/4]: a bottom bar [0,s]x[0,s/4] (in x,z), a
/// shank [0,s/4]x[s/4,2s] on the left and an upturned tip [3s/4,s]x[s/4,3s/4] on the right.
/// The opening (the cup) is x in (s/4, 3s/4), z > s/4. 3 boxes, 36 triangles.
inline Soup hook(double s = 1)
{
  Soup h;
  const double t = 0.25 * s;
  h.append(box({0, 0, 0}, {s, t, t}));                    // bottom bar
  h.append(box({0, 0, t}, {t, t, 2 * s}));                // shank
  h.append(box({0.75 * s, 0, t}, {s, t, 0.75 * s}));      // tip
  return h;
}

/// Two hooks (s = 1) interlocked as in the paper's Fig. 9: the first is hook(); the second is
/// the same hook rotated 90 degrees about z (lying in the yz-plane, thickness 1/4 in x), built
/// directly with swapped axes, and hung into the first one's cup: its bottom bar
/// x in [3/8,5/8], z in [3/8,5/8], y in [-3/8,5/8] crosses the first hook's opening (which is
/// x in (1/4,3/4), z > 1/4) with a clearance of 1/8 on every side, its shank and tip lying on
/// either side of the first hook (y < -1/8 and y > 3/8). The two hooks are disjoint.
inline std::pair<Soup, Soup> hooks_pair()
{
  Soup b;
  const double x0 = 0.375, x1 = 0.625, y0 = -0.375, z0 = 0.375, t = 0.25;
  b.append(box({x0, y0, z0}, {x1, y0 + 1, z0 + t}));                 // bottom bar, along y
  b.append(box({x0, y0, z0 + t}, {x1, y0 + t, z0 + 2}));             // shank
  b.append(box({x0, y0 + 0.75, z0 + t}, {x1, y0 + 1, z0 + 0.75}));   // tip
  return {hook(1), b};
}

/// Grate: bars_x bars along x (width bar_width in y, at y = j*pitch) in the layer
/// z in [0, thickness], and on top of them bars_y bars along y (width bar_width in x, at
/// x = i*pitch) in the layer z in [thickness, 2*thickness]. Each bar spans the other layer's
/// bars exactly. Requires 0 < bar_width < pitch (for holes). bars_x + bars_y boxes.
inline Soup grate(int bars_x, int bars_y, double pitch, double bar_width, double thickness)
{
  Soup s;
  const double len_x = (bars_y - 1) * pitch + bar_width; // extent in x (spans the y bars)
  const double len_y = (bars_x - 1) * pitch + bar_width; // extent in y
  for (int j = 0; j < bars_x; ++j)
    s.append(box({0, j * pitch, 0}, {len_x, j * pitch + bar_width, thickness}));
  for (int i = 0; i < bars_y; ++i)
    s.append(box({i * pitch, 0, thickness}, {i * pitch + bar_width, len_y, 2 * thickness}));
  return s;
}

/// Square plate of side holes*hole + (holes+1)*bar and given thickness (z in [0, thickness])
/// with holes x holes square through-holes of side `hole`, separated by bars of width `bar`
/// (genus holes^2). Partition: holes+1 full-width strips along x, and in each of the `holes`
/// hole rows, holes+1 short boxes between the holes. (holes+1)^2 + holes boxes.
inline Soup frame(int holes, double hole, double bar, double thickness)
{
  Soup s;
  const double step = hole + bar, size = holes * hole + (holes + 1) * bar;
  for (int k = 0; k <= holes; ++k)
    s.append(box({0, k * step, 0}, {size, k * step + bar, thickness}));
  for (int k = 0; k < holes; ++k)
    for (int i = 0; i <= holes; ++i)
      s.append(box({i * step, k * step + bar, 0}, {i * step + bar, (k + 1) * step, thickness}));
  return s;
}

/// Closed cube shell [0,outer]^3 with cavity [wall, outer-wall]^3, each of its six walls
/// pierced by a centered square window of side `window` (requires 0 < window < outer - 2*wall).
/// Walls: z-walls full [0,outer]^2, y-walls [0,outer] x [wall,outer-wall] (in x,z), x-walls
/// [wall,outer-wall]^2 (in y,z); each is 4 boxes around its window: 24 boxes, 288 triangles.
/// Summed with a centered cube of half-side c, window/2 < c < outer/2 - wall, the windows
/// close and the cavity becomes the enclosed void [wall+c, outer-wall-c]^3 ("easy hole").
inline Soup hollow_box_with_windows(double outer, double wall, double window)
{
  using suite_internal::slab_with_window;
  Soup s;
  const double o = outer, w = wall, a0 = (o - window) / 2, a1 = (o + window) / 2;
  // z-walls: (u, v, w) = (x, y, z)
  slab_with_window(s, {0, 1, 2}, 0, o, 0, o, a0, a1, a0, a1, 0, w);
  slab_with_window(s, {0, 1, 2}, 0, o, 0, o, a0, a1, a0, a1, o - w, o);
  // y-walls: (u, v, w) = (x, z, y)
  slab_with_window(s, {0, 2, 1}, 0, o, w, o - w, a0, a1, a0, a1, 0, w);
  slab_with_window(s, {0, 2, 1}, 0, o, w, o - w, a0, a1, a0, a1, o - w, o);
  // x-walls: (u, v, w) = (y, z, x)
  slab_with_window(s, {1, 2, 0}, w, o - w, w, o - w, a0, a1, a0, a1, 0, w);
  slab_with_window(s, {1, 2, 0}, w, o - w, w, o - w, a0, a1, a0, a1, o - w, o);
  return s;
}

/// The six walls of the hollow cube [0,size]^3 as six separate boxes of thickness `plate`,
/// each shrunk in its two in-plane directions to [plate+gap, size-plate-gap], so that two
/// neighbouring walls are `gap` apart along both axes across every edge of the cube (they
/// do not touch). 6 boxes, 72 triangles. Requires gap > 0 and size > 2*(plate+gap).
///
/// Summed with the centered cube [-c,c]^3 ("difficult hole", paper sec. 6.2): the gaps close
/// iff 2c > gap (c > gap is enough), and the inside is then the enclosed void
/// [plate+c, size-plate-c]^3 provided size > 2*(plate+c). Each void corner, e.g.
/// (plate+c, plate+c, plate+c), is the intersection of the offset inner faces of three
/// different plates (x = plate+c, y = plate+c, z = plate+c); it would be a vertex sum only if
/// plate+gap-c == plate+c, i.e. gap == 2c, which 2c > gap excludes. (With the other common
/// convention, where the walls span [g, size-g] and g = plate+gap, this reads g != plate,
/// g != plate+2c.) E.g. size 4, plate 1/2, gap 1/4, c 1/4 or 1/2.
inline Soup separated_plates(double size, double plate, double gap)
{
  using suite_internal::box_axes;
  Soup s;
  const double a = plate + gap, b = size - plate - gap;
  for (const std::array<int, 3>& ax : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{1, 2, 0},
                                       std::array<int, 3>{2, 0, 1}}) { // (u, v, normal axis)
    s.append(box_axes(ax, {a, a, 0}, {b, b, plate}));
    s.append(box_axes(ax, {a, a, size - plate}, {b, b, size}));
  }
  return s;
}

/// Closed tube of radius `tube` (polygonal section with `sides` vertices) around the (p,q)
/// torus knot c(t) = ((R + r cos qt) cos pt, (R + r cos qt) sin pt, r sin qt), t in [0, 2pi),
/// sampled at `segments` points. The section is placed in the Frenet frame (N, B), which is
/// periodic (torus knots have nonzero curvature) so the tube closes up without twist
/// mismatch. Coordinates are rounded to multiples of 1/1024. Outward oriented, one closed
/// component of 2*segments*sides triangles, genus 1. Valid (no self-intersection) e.g. for
/// (2,3,2,1,0.3,96,6) and (2,3,2,1,0.3,40,6): the strands stay >= 1.6 apart and the radius
/// of curvature is >= 1.4. convex_pieces and boxes stay empty.
inline Soup torus_knot(int p = 2, int q = 3, double R = 2, double r = 1, double tube = 0.3,
                       int segments = 96, int sides = 6)
{
  Soup s;
  const double pi = std::acos(-1.);
  auto rnd = [](double x) { return std::round(x * 1024) / 1024; };
  using V = std::array<double, 3>;
  auto cross = [](const V& u, const V& v) {
    return V{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  auto dot = [](const V& u, const V& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  auto unit = [&](const V& u) {
    const double l = std::sqrt(dot(u, u));
    return V{u[0] / l, u[1] / l, u[2] / l};
  };
  for (int i = 0; i < segments; ++i) {
    const double t = 2 * pi * i / segments, th = q * t, ph = p * t;
    const double ct = std::cos(th), st = std::sin(th), cp = std::cos(ph), sp = std::sin(ph);
    const double rho = R + r * ct;
    const V c{rho * cp, rho * sp, r * st};
    const V d1{-r * q * st * cp - rho * p * sp, -r * q * st * sp + rho * p * cp, r * q * ct};
    const V d2{-r * q * q * ct * cp + 2 * r * p * q * st * sp - rho * p * p * cp,
               -r * q * q * ct * sp - 2 * r * p * q * st * cp - rho * p * p * sp, -r * q * q * st};
    const V T = unit(d1);
    const V B = unit(cross(d1, d2));
    const V N = cross(B, T);
    for (int k = 0; k < sides; ++k) {
      const double a = 2 * pi * k / sides, ca = std::cos(a), sa = std::sin(a);
      s.points.push_back({rnd(c[0] + tube * (ca * N[0] + sa * B[0])),
                          rnd(c[1] + tube * (ca * N[1] + sa * B[1])),
                          rnd(c[2] + tube * (ca * N[2] + sa * B[2]))});
    }
  }
  auto id = [&](int i, int k) { return std::size_t((i % segments) * sides + (k % sides)); };
  for (int i = 0; i < segments; ++i)
    for (int k = 0; k < sides; ++k) {
      // (T, angle) parametrization gives inward normals, hence the order (i,k), (i,k+1), (i+1,k+1).
      s.triangles.push_back({id(i, k), id(i, k + 1), id(i + 1, k + 1)});
      s.triangles.push_back({id(i, k), id(i + 1, k + 1), id(i + 1, k)});
    }
  return s;
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_SUITE_SHAPES_H
