// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::measure_boundary_coverage(): how well a point set covers a surface made of
// shells (e.g. the exact boundary of a Minkowski sum, outer boundary and voids), shell by
// shell. Independent of how the surface and the points were computed.

#ifndef CGAL_PMSUM_MEASURE_BOUNDARY_COVERAGE_H
#define CGAL_PMSUM_MEASURE_BOUNDARY_COVERAGE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumCoverage
/// One connected boundary surface (triangle soup).
struct Shell
{
  std::vector<std::array<double, 3>> points;          ///< the vertices
  std::vector<std::array<std::size_t, 3>> triangles;  ///< the triangles, as indices into `points`
  bool is_void = false; ///< bounds a void (hole) of the solid rather than its outside
};

/// \ingroup PkgPointMinkowskiSumCoverage
/// Coverage of one shell, as measured by measure_boundary_coverage().
struct Shell_coverage
{
  bool is_void = false;         ///< the shell's Shell::is_void
  std::size_t triangles = 0;    ///< number of triangles of the shell
  std::size_t samples = 0;      ///< points of the shell the distance was measured at
  double worst_distance = 0;    ///< largest distance from a sample to the nearest point
  std::size_t touched = 0;      ///< samples that have a point closer than d
  /// Tells whether the samples are covered within `d`.
  /// \param d a covering distance
  /// \returns `worst_distance < d`
  bool covered(double d) const { return worst_distance < d; }
};

namespace internal {
/// The points as Epick points, and a kd-tree over them.
struct Point_search
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Traits = CGAL::Search_traits_3<K>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  std::vector<K::Point_3> points;
  Search::Tree tree;
  template <class PointRange>
  explicit Point_search(const PointRange& range)
  {
    for (const auto& p : range)
      points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    tree.insert(points.begin(), points.end());
  }
};

/// Calls visit(x) on the points of the closed lattice of spacing at most `spacing` on the
/// triangle `t` of shell `s` (its vertices and edges included).
template <class Visit>
void for_each_lattice_point(const Shell& s, const std::array<std::size_t, 3>& t, double spacing, Visit&& visit)
{
  using K = Point_search::K;
  const K::Point_3 a(s.points[t[0]][0], s.points[t[0]][1], s.points[t[0]][2]);
  const K::Point_3 b(s.points[t[1]][0], s.points[t[1]][1], s.points[t[1]][2]);
  const K::Point_3 e(s.points[t[2]][0], s.points[t[2]][1], s.points[t[2]][2]);
  const double longest = std::sqrt((std::max)({CGAL::squared_distance(a, b), CGAL::squared_distance(b, e),
                                               CGAL::squared_distance(e, a)}));
  const int n = (std::max)(1, int(std::ceil(longest / spacing)));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) visit(a + (double(i) / n) * (b - a) + (double(j) / n) * (e - a));
}
} // namespace internal

/// \ingroup PkgPointMinkowskiSumCoverage
/// Measures how well `points` cover each shell: samples every triangle of every shell with
/// the closed lattice of spacing at most `spacing` (vertices and edges included) and finds,
/// per shell, the largest distance from a sample to the nearest point of `points`, and how
/// many samples have a point closer than `d`.
///
/// The distance is measured at the samples only: the largest distance from the shell to
/// `points` may exceed Shell_coverage::worst_distance by less than `spacing`.
///
/// \tparam PointRange a range of points with `x()`, `y()` and `z()` convertible with
///         `CGAL::to_double()` (e.g. `std::vector<Kernel::Point_3>`)
/// \param shells the surface, e.g. Nef_minkowski_sum_reference::shells()
/// \param points the points to measure, e.g. the output of point_minkowski_sum()
/// \param d the covering distance that Shell_coverage::touched counts
/// \param spacing the largest spacing of the samples on each triangle
/// \returns one Shell_coverage per shell, in the order of `shells` (a worst distance of
///          infinity if `points` is empty)
/// \pre `spacing > 0`
template <class PointRange>
std::vector<Shell_coverage> measure_boundary_coverage(const std::vector<Shell>& shells, const PointRange& points,
                                                     double d, double spacing)
{
  using K = internal::Point_search::K;
  using Search = internal::Point_search::Search;
  const internal::Point_search index(points);
  const auto& pts = index.points;
  const auto& tree = index.tree;

  std::vector<Shell_coverage> out;
  for (const Shell& s : shells) {
    Shell_coverage c;
    c.is_void = s.is_void;
    c.triangles = s.triangles.size();
    auto visit = [&](const K::Point_3& x) {
      ++c.samples;
      double dist = std::numeric_limits<double>::infinity();
      if (!pts.empty()) {
        Search search(tree, x, 1);
        dist = std::sqrt(search.begin()->second);
      }
      c.worst_distance = (std::max)(c.worst_distance, dist);
      c.touched += (dist < d);
    };
    for (const auto& t : s.triangles) internal::for_each_lattice_point(s, t, spacing, visit);
    out.push_back(c);
  }
  return out;
}

/// \ingroup PkgPointMinkowskiSumCoverage
/// Computes the smallest distance between two of `points`, to check the `d/2` separation
/// of a (d/2, d)-net for instance.
///
/// \tparam PointRange as for measure_boundary_coverage()
/// \param points the points
/// \returns the smallest distance between two points of `points` (rounded to double
///          first), 0 if two are equal, infinity for fewer than two points
template <class PointRange>
double measure_point_spacing(const PointRange& points)
{
  using Search = internal::Point_search::Search;
  const internal::Point_search index(points);
  double best = std::numeric_limits<double>::infinity();
  if (index.points.size() < 2) return best;
  for (const auto& x : index.points) {
    Search search(index.tree, x, 2); // x itself, then its nearest other point
    auto it = search.begin();
    ++it;
    best = (std::min)(best, std::sqrt(it->second));
  }
  return best;
}

/// \ingroup PkgPointMinkowskiSumCoverage
/// Computes the total area of the shells.
/// \param shells the shells
/// \returns the sum of the areas of their triangles
inline double shells_area(const std::vector<Shell>& shells)
{
  double area = 0;
  for (const Shell& s : shells)
    for (const auto& t : s.triangles) {
      const auto &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
  return area;
}

/// \ingroup PkgPointMinkowskiSumCoverage
/// Computes the number of points of an ideal d-covering of a surface of area `area`: the
/// hexagonal covering, one point per hexagon of circumradius d (area 2.598 d^2), to compare
/// an output's size with.
/// \param area the area of the surface, e.g. shells_area()
/// \param d the covering distance
/// \returns `area / (1.5 * sqrt(3) * d * d)` (not rounded)
/// \pre `d > 0`
inline double ideal_covering_size(double area, double d) { return area / (1.5 * std::sqrt(3.0) * d * d); }

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_MEASURE_BOUNDARY_COVERAGE_H
