// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The connected pieces ("parts") of a union of convex polygons of one plane, and which of
// them hold a point: for Face_cover::joins_separate_parts() (face_cover.h), the advancing
// front's check that no face of a plane joins two pieces of the plane's convolution facets
// across a gap. In doubles: polygons and points nearer than a tolerance are taken as meeting,
// so a gap narrower than it is not seen (the check only refuses meshes).

#ifndef CGAL_PMSUM_INTERNAL_PLANE_PARTS_H
#define CGAL_PMSUM_INTERNAL_PLANE_PARTS_H

#include <CGAL/box_intersection_d.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

class Plane_parts
{
public:
  using Point = std::array<double, 2>;
  using Part_list = boost::container::small_vector<std::size_t, 4>; // sorted

  /// The parts of the union of `polygons` (convex, in either orientation; those of no area
  /// left out), polygons nearer than `tolerance` joined.
  Plane_parts(const std::vector<std::vector<Point>>& polygons, double tolerance) : m_tolerance(tolerance)
  {
    for (const std::vector<Point>& corners : polygons) {
      Polygon g{corners, {HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
      double area = 0;
      for (std::size_t k = 0; k < corners.size(); ++k) {
        const Point &a = corners[k], &b = corners[(k + 1) % corners.size()];
        area += a[0] * b[1] - a[1] * b[0];
        g.box = {(std::min)(g.box[0], a[0]), (std::min)(g.box[1], a[1]), (std::max)(g.box[2], a[0]), (std::max)(g.box[3], a[1])};
      }
      if (area == 0) continue;
      if (area < 0) std::reverse(g.corners.begin(), g.corners.end());
      m_polygons.push_back(std::move(g));
    }
    join_meeting_polygons();
    make_grid();
  }

  /// The parts that hold x (within the tolerance), sorted, each once.
  Part_list holding(const Point& x) const
  {
    Part_list out;
    for (std::uint32_t i : near(x))
      if (m_polygons[i].holds(x, m_tolerance)) out.push_back(m_part[i]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  /// The stretches of the segment a b that the polygons cover, as parameters along it (0 at
  /// a, 1 at b), one per polygon it crosses, in no order.
  std::vector<std::pair<double, double>> covered_along(const Point& a, const Point& b) const
  {
    std::vector<std::pair<double, double>> out;
    for (const Polygon& g : m_polygons) {
      double lo = 0, hi = 1;
      for (std::size_t k = 0; k < g.corners.size() && lo < hi; ++k) {
        const Point &c0 = g.corners[k], &c1 = g.corners[(k + 1) % g.corners.size()];
        const double nx = c0[1] - c1[1], ny = c1[0] - c0[0]; // inward (left of c0 c1)
        const double at_a = nx * (a[0] - c0[0]) + ny * (a[1] - c0[1]);
        const double slope = nx * (b[0] - a[0]) + ny * (b[1] - a[1]);
        if (slope > 0) lo = (std::max)(lo, -at_a / slope);
        else if (slope < 0) hi = (std::min)(hi, -at_a / slope);
        else if (at_a < 0) hi = lo;
      }
      if (lo < hi) out.emplace_back(lo, hi);
    }
    return out;
  }

private:
  /// Counterclockwise, with its box (x min, y min, x max, y max).
  struct Polygon
  {
    std::vector<Point> corners;
    std::array<double, 4> box;

    /// Is x within `tolerance` of the polygon?
    bool holds(const Point& x, double tolerance) const
    {
      if (x[0] < box[0] - tolerance || x[1] < box[1] - tolerance || x[0] > box[2] + tolerance || x[1] > box[3] + tolerance)
        return false;
      for (std::size_t k = 0; k < corners.size(); ++k) {
        const Point &a = corners[k], &b = corners[(k + 1) % corners.size()];
        const double ex = b[0] - a[0], ey = b[1] - a[1], length = std::sqrt(ex * ex + ey * ey);
        if (ex * (x[1] - a[1]) - ey * (x[0] - a[0]) < -tolerance * length) return false;
      }
      return true;
    }
    /// Are the two polygons nearer than `tolerance` (no edge direction of either separates
    /// them by more)?
    bool meets(const Polygon& other, double tolerance) const
    {
      for (const Polygon* g : {this, &other})
        for (std::size_t k = 0; k < g->corners.size(); ++k) {
          const Point &a = g->corners[k], &b = g->corners[(k + 1) % g->corners.size()];
          const double nx = b[1] - a[1], ny = a[0] - b[0], length = std::sqrt(nx * nx + ny * ny);
          auto extent = [&](const Polygon& h) {
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            for (const Point& c : h.corners) {
              const double t = (nx * c[0] + ny * c[1]) / length;
              lo = (std::min)(lo, t);
              hi = (std::max)(hi, t);
            }
            return std::make_pair(lo, hi);
          };
          const auto [lo0, hi0] = extent(*this);
          const auto [lo1, hi1] = extent(other);
          if (lo1 > hi0 + tolerance || lo0 > hi1 + tolerance) return false;
        }
      return true;
    }
  };

  /// m_part: union-find over the polygons that meet (their boxes first).
  void join_meeting_polygons()
  {
    const std::size_t n = m_polygons.size();
    m_part.resize(n);
    for (std::size_t i = 0; i < n; ++i) m_part[i] = i;
    auto find = [&](std::size_t i) {
      while (m_part[i] != i) i = m_part[i] = m_part[m_part[i]];
      return i;
    };
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;
    std::vector<Box> boxes;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& b = m_polygons[i].box;
      const double t = m_tolerance;
      boxes.emplace_back(CGAL::Bbox_2(b[0] - t, b[1] - t, b[2] + t, b[3] + t), i);
    }
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
      if (find(a.info()) != find(b.info()) && m_polygons[a.info()].meets(m_polygons[b.info()], m_tolerance))
        m_part[find(a.info())] = find(b.info());
    });
    for (std::size_t i = 0; i < n; ++i) m_part[i] = find(i);
  }

  /// A grid over the polygons' boxes (grown by the tolerance), each cell listing the polygons
  /// whose box meets it, about one per cell.
  void make_grid()
  {
    if (m_polygons.empty()) return;
    Point hi = {-HUGE_VAL, -HUGE_VAL};
    m_lo = {HUGE_VAL, HUGE_VAL};
    for (const Polygon& g : m_polygons)
      for (int a = 0; a < 2; ++a) {
        m_lo[a] = (std::min)(m_lo[a], g.box[a] - m_tolerance);
        hi[a] = (std::max)(hi[a], g.box[a + 2] + m_tolerance);
      }
    const int side = (std::max)(1, (std::min)(256, int(std::sqrt(double(m_polygons.size())))));
    for (int a = 0; a < 2; ++a) {
      m_cells[a] = side;
      m_cell[a] = (hi[a] - m_lo[a]) / side;
      if (!(m_cell[a] > 0)) {
        m_cells[a] = 1;
        m_cell[a] = 1;
      }
    }
    m_in_cell.assign(std::size_t(m_cells[0]) * m_cells[1], {});
    for (std::uint32_t i = 0; i < m_polygons.size(); ++i) {
      const auto& b = m_polygons[i].box;
      const auto [i0, j0] = cell_of({b[0] - m_tolerance, b[1] - m_tolerance});
      const auto [i1, j1] = cell_of({b[2] + m_tolerance, b[3] + m_tolerance});
      for (int ci = i0; ci <= i1; ++ci)
        for (int cj = j0; cj <= j1; ++cj) m_in_cell[std::size_t(cj) * m_cells[0] + ci].push_back(i);
    }
  }

  std::pair<int, int> cell_of(const Point& x) const
  {
    auto index = [&](int a) { return (std::max)(0, (std::min)(m_cells[a] - 1, int(std::floor((x[a] - m_lo[a]) / m_cell[a])))); };
    return {index(0), index(1)};
  }

  /// The polygons whose box may hold x (none off the grid).
  const std::vector<std::uint32_t>& near(const Point& x) const
  {
    static const std::vector<std::uint32_t> none;
    if (m_in_cell.empty() || x[0] < m_lo[0] || x[1] < m_lo[1] || x[0] > m_lo[0] + m_cell[0] * m_cells[0] ||
        x[1] > m_lo[1] + m_cell[1] * m_cells[1])
      return none;
    const auto [i, j] = cell_of(x);
    return m_in_cell[std::size_t(j) * m_cells[0] + i];
  }

  double m_tolerance;
  std::vector<Polygon> m_polygons;
  std::vector<std::size_t> m_part; // of each polygon: a representative polygon's index
  Point m_lo{}, m_cell{1, 1};
  std::array<int, 2> m_cells{0, 0};
  std::vector<std::vector<std::uint32_t>> m_in_cell;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PLANE_PARTS_H
