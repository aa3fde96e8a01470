// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Motion-planning problems built from boxes (tests, example, benchmark, pmsum generate):
// the robot is the unit cube [0, 1]^3, the obstacles are unions of touching boxes, so that
// the exact configuration obstacle is the union of the boxes [B.min - 1, B.max] (the robot's
// reference point is its corner (0, 0, 0)).
//
//   pocket(g)  the paper's Fig. 12(b) kind: the robot sits in a pocket with clearance g on
//              every side, under a lid; to take it out it must slide sideways (clearance g
//              in y and z) to the chimney, then rise through it (clearance g in x and y).
//   slot(g)    a closed room split by a wall; the wall has a square slot 1 + g wide, the
//              only way from the start (one side) to the goal (other side).

#ifndef CGAL_PMSUM_PLANNING_SCENES_H
#define CGAL_PMSUM_PLANNING_SCENES_H

#include "shapes.h"

#include <string>
#include <vector>

namespace pmsum_shapes {

struct Planning_scene
{
  std::string name;
  Soup robot, obstacle;  // obstacle.boxes: the boxes it is the union of
  Point start, goal;
  double gap;
};

inline Soup union_of_boxes(const std::vector<Box>& boxes)
{
  Soup s;
  for (const Box& b : boxes) s.append(box(b.min, b.max));
  return s;
}

/// Robot in a pocket under a lid, clearance g (a power of two keeps every coordinate exact).
inline Planning_scene pocket_scene(double g = 1. / 16)
{
  const double w = 1 + g, H = 1 + g, T = 0.25, c = 0.25;
  std::vector<Box> b = {
    {{-T, -T, -T}, {2 * w + T, w + T, 0}},     // floor
    {{-T, -T, 0}, {0, w + T, H + c}},          // wall x-
    {{2 * w, -T, 0}, {2 * w + T, w + T, H + c}}, // wall x+
    {{0, -T, 0}, {2 * w, 0, H + c}},           // wall y-
    {{0, w, 0}, {2 * w, w + T, H + c}},        // wall y+
    {{0, 0, H}, {w, w, H + c}},                // lid over the robot; the chimney is x in [w, 2w]
  };
  Planning_scene s;
  s.name = "pocket";
  s.robot = box({0, 0, 0}, {1, 1, 1});
  s.obstacle = union_of_boxes(b);
  s.start = {g / 2, g / 2, g / 2};
  s.goal = {2 * w + T + 0.5, g / 2, H + c + 0.5};
  s.gap = g;
  return s;
}

/// Room split by a wall with a slot 1 + g wide.
inline Planning_scene slot_scene(double g = 1. / 16)
{
  const double X0 = -1.25, X1 = 1.75, Y = 1, T = 0.125, s2 = (1 + g) / 2;
  std::vector<Box> b = {
    // room: six slabs
    {{X0 - T, -Y - T, -Y - T}, {X0, Y + T, Y + T}},
    {{X1, -Y - T, -Y - T}, {X1 + T, Y + T, Y + T}},
    {{X0, -Y - T, -Y - T}, {X1, -Y, Y + T}},
    {{X0, Y, -Y - T}, {X1, Y + T, Y + T}},
    {{X0, -Y, -Y - T}, {X1, Y, -Y}},
    {{X0, -Y, Y}, {X1, Y, Y + T}},
    // dividing wall x in [0, 0.5] with the slot |y|, |z| < s2
    {{0, -Y, -Y}, {0.5, -s2, Y}},
    {{0, s2, -Y}, {0.5, Y, Y}},
    {{0, -s2, -Y}, {0.5, s2, -s2}},
    {{0, -s2, s2}, {0.5, s2, Y}},
  };
  Planning_scene s;
  s.name = "slot";
  s.robot = box({0, 0, 0}, {1, 1, 1});
  s.obstacle = union_of_boxes(b);
  s.start = {-1.125, -0.875, -0.125}; // strictly free (no contact), like the pocket's
  s.goal = {0.625, -0.125, -0.875};
  s.gap = g;
  return s;
}

} // namespace pmsum_shapes

#endif // CGAL_PMSUM_PLANNING_SCENES_H
