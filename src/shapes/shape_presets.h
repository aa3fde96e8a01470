// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named procedural models of the validation suite (pmsum generate NAME, and the tests that
// reuse the cached exact boundaries in data/exact/). Changing a preset changes the exact
// sums cached for it: rerun benchmark/validation/make_exact_cache.sh.

#ifndef CGAL_PMSUM_SHAPE_PRESETS_H
#define CGAL_PMSUM_SHAPE_PRESETS_H

#include "suite_shapes.h"
#include "planning_scenes.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <stdexcept>
#include <string>

namespace pmsum_shapes {

inline const std::map<std::string, std::function<Soup()>>& shape_presets()
{
  static const std::map<std::string, std::function<Soup()>> presets = {
    {"cube", [] { return box({0, 0, 0}, {1, 1, 1}); }},
    {"cube-0.95", [] { return box({0, 0, 0}, {0.95, 0.95, 0.95}); }},
    {"cube-small", [] { return box({-0.25, -0.25, -0.25}, {0.25, 0.25, 0.25}); }},
    {"cube-large", [] { return box({-0.75, -0.75, -0.75}, {0.75, 0.75, 0.75}); }},
    {"tetrahedron", [] { return tetrahedron(0.5); }},
    {"octahedron", [] { return octahedron(0.25); }},
    {"ellipsoid", [] { return ellipsoid(0.2, 0.15, 0.1); }},
    {"l-shape", [] { return l_shape(); }},
    {"blocks", [] { return blocks(3, 0.5); }},
    {"open-cube", [] { return open_box({0, 0, 0}, {1, 1, 1}); }},
    {"hook-a", [] { return hooks_pair().first; }},
    {"hook-b", [] { return hooks_pair().second; }},
    {"grate-a", [] { return grate(4, 4, 1, 0.5, 0.25); }},
    {"grate-b", [] { return grate(3, 5, 0.75, 0.25, 0.125); }},
    {"frame", [] { return frame(3, 1, 0.5, 0.5); }},
    {"knot", [] { return torus_knot(2, 3, 2, 1, 0.3, 32, 5); }},
    {"hollow-box", [] { return hollow_box_with_windows(4, 0.5, 1); }},   // + cube-large: easy void
    {"plates", [] { return separated_plates(4, 0.5, 0.25); }},            // + cube-small: difficult void
    {"pocket", [] { return pocket_scene().obstacle; }},     // motion planning, robot: cube
    {"slot-room", [] { return slot_scene().obstacle; }},    // motion planning, robot: cube
    // narrow passages (issue 12), each 1/2000 wide: a tunnel, a slot, a slit; slivers (a cube
    // tilted by 0.01 rad, faces nearly parallel to the slot's); the tunnel also rotated
    {"tunnel", [] { return tunnel_block(); }},
    {"tunnel-cube", [] { return turned_cube((1 - 1. / 2000) / 1.4, 0.8, 0.6); }},
    {"tunnel-rotated", [] { return rotated(tunnel_block()); }},
    {"tunnel-cube-rotated", [] { return rotated(turned_cube((1 - 1. / 2000) / 1.4, 0.8, 0.6)); }},
    {"slot", [] { return slot_blocks(0.5, true); }},
    {"slit", [] { return slot_blocks(0.5, false); }},
    {"slot-cube", [] { return turned_cube((0.5 - 1. / 2000) / 1.4, 0.8, 0.6); }},
    {"slot-cube-tilted", [] { return turned_cube((0.5 - 1. / 2000) / 1.4, 0.8, 0.6, std::cos(0.01), std::sin(0.01)); }},
  };
  return presets;
}

inline Soup shape_preset(const std::string& name)
{
  const auto& p = shape_presets();
  const auto it = p.find(name);
  if (it == p.end()) throw std::invalid_argument("unknown shape '" + name + "'");
  return it->second();
}

/// Writes a soup as OFF with exact (round-trip) coordinates.
inline void write_off(const Soup& s, std::ostream& o)
{
  o << std::setprecision(17) << "OFF\n" << s.points.size() << ' ' << s.triangles.size() << " 0\n";
  for (const auto& p : s.points) o << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : s.triangles) o << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_SHAPE_PRESETS_H
