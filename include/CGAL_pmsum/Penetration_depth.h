// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::Penetration_depth: translational penetration depth of a moving solid P
// against a fixed solid Q (paper section 9.2), from points covering the contact space
// C = boundary of (-P) + Q.
//
// P translated by t overlaps Q iff t is inside (-P) + Q; the shortest translation that
// separates them moves t to the nearest point of C, and its length is the penetration depth
// PD(t). The contact points are exactly on C and cover it within d, so the nearest one gives
// PD within d: PD <= PD' < PD + d. Built once (the point-based sum and a static kd-tree with
// oriented bounds, internal/nearest_point_tree.h, exact: the nearest stored point); then
//   nearest_contact(t)  the nearest contact point (fast: a kd-tree query), and
//   query(t)            exact overlap test (the CD filter of the core) + nearest contact.

#ifndef CGAL_PMSUM_PENETRATION_DEPTH_H
#define CGAL_PMSUM_PENETRATION_DEPTH_H

#include <CGAL_pmsum/internal/nearest_point_tree.h>
#include <CGAL_pmsum/point_minkowski_sum.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <memory>
#include <vector>

namespace CGAL {
namespace Pmsum {

template <class PolygonMeshP, class PolygonMeshQ>
class Penetration_depth
{
public:
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point_3 = Kernel::Point_3;
  using Vector_3 = Kernel::Vector_3;

  struct Result
  {
    bool overlapping = false; ///< P + t and Q overlap (exact); query() only
    double depth = 0;         ///< distance from t to the nearest contact point (0 if not overlapping)
    Vector_3 direction;       ///< unit vector: translate P by depth * direction to separate it
    Point_3 contact;          ///< the nearest contact configuration t + depth * direction
  };

  /// Computes the contact space of P (moving) and Q (fixed) with covering distance d, with
  /// `ConcurrencyTag` as in point_minkowski_sum(). \pre as for point_minkowski_sum()
  template <class ConcurrencyTag = CGAL::Sequential_tag>
  static Penetration_depth make(const PolygonMeshP& P, const PolygonMeshQ& Q, double d)
  {
    internal::check_covering_distance(d);
    const auto start = internal::Clock::now();
    Penetration_depth pd(P, Q, d); // -P and Q, converted and checked once
    Statistics stats;
    internal::run_pipeline<ConcurrencyTag>(
      *pd.m_p, *pd.m_q, d, internal::Pipeline_options{}, stats,
      [&](const internal::Sample& sp, const internal::Sample& sq, const internal::Direction&, const internal::Trim* trim) {
        double c[3];
        for (int i = 0; i < 3; ++i) c[i] = internal::sum_coordinate<double>(*pd.m_p, *pd.m_q, sp, sq, trim, i);
        pd.m_points.emplace_back(c[0], c[1], c[2]);
      },
      start);
    pd.build();
    return pd;
  }

  /// A copy shares the tree and the collision geometry (read-only) but has its own overlap test
  /// state, so that each thread can query its own copy.
  Penetration_depth(const Penetration_depth& other)
    : m_d(other.m_d), m_points(other.m_points), m_tree(other.m_tree), m_p(other.m_p), m_q(other.m_q),
      m_geometry(other.m_geometry), m_filter(std::make_shared<internal::Cd_filter>(m_geometry.get()))
  {}
  Penetration_depth(Penetration_depth&&) = default;
  Penetration_depth& operator=(const Penetration_depth& other)
  {
    if (this != &other) *this = Penetration_depth(other);
    return *this;
  }
  Penetration_depth& operator=(Penetration_depth&&) = default;

  std::size_t number_of_contact_points() const { return m_points.size(); }
  const std::vector<Point_3>& contact_points() const { return m_points; }
  double covering_distance() const { return m_d; }

  /// Nearest contact point to t (whether or not P + t overlaps Q). Thread-safe.
  Result nearest_contact(const Point_3& t) const
  {
    Result r;
    if (m_points.empty()) return r;
    const double q[3] = {t.x(), t.y(), t.z()};
    const auto nearest = m_tree->nearest(q);
    r.contact = m_points[nearest.first];
    r.depth = std::sqrt(nearest.second);
    const Vector_3 v = r.contact - t;
    r.direction = r.depth > 0 ? v / r.depth : Vector_3(0, 0, 0);
    return r;
  }

  /// Exact: do the interiors of P + t and Q overlap? (Not thread-safe: one object, or copy, per thread.)
  bool overlaps(const Point_3& t) { return !m_filter->is_free_at({t.x(), t.y(), t.z()}); }

  /// Penetration depth at t: 0 without overlap, else the nearest contact (within d of PD).
  Result query(const Point_3& t)
  {
    if (!overlaps(t)) {
      Result r;
      r.contact = t;
      r.direction = Vector_3(0, 0, 0);
      return r;
    }
    Result r = nearest_contact(t);
    r.overlapping = true;
    return r;
  }

private:
  Penetration_depth(const PolygonMeshP& P, const PolygonMeshQ& Q, double d) : m_d(d)
  {
    internal::Mesh_descriptors<PolygonMeshP> dp;
    internal::Mesh_descriptors<PolygonMeshQ> dq;
    m_p = std::make_shared<internal::Mesh_data>(
      internal::make_mesh_data(P, get(CGAL::vertex_point, P), true, false, "P", dp));
    m_q = std::make_shared<internal::Mesh_data>(
      internal::make_mesh_data(Q, get(CGAL::vertex_point, Q), false, false, "Q", dq));
  }

  void build()
  {
    m_tree = std::make_shared<internal::Nearest_point_tree>(
      m_points.size(), [this](std::size_t i, int a) { return m_points[i][a]; });
    m_geometry = std::make_shared<internal::Cd_geometry>(*m_p, *m_q);
    m_filter = std::make_shared<internal::Cd_filter>(m_geometry.get());
  }

  double m_d;
  std::vector<Point_3> m_points;
  std::shared_ptr<const internal::Nearest_point_tree> m_tree;
  std::shared_ptr<internal::Mesh_data> m_p, m_q;
  std::shared_ptr<internal::Cd_geometry> m_geometry;
  std::shared_ptr<internal::Cd_filter> m_filter;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_PENETRATION_DEPTH_H
