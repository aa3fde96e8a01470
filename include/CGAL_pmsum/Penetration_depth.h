// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Penetration_depth: translational penetration depth of a moving solid P
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

/// \ingroup PkgPointMinkowskiSumPenetrationDepth
/// Translational penetration depth of a moving solid `P` against a fixed solid `Q`, from
/// points covering the contact space, the boundary of `-P + Q`: the depth returned is within
/// `d` of the exact one, and overlap itself is decided exactly. Made by make().
///
/// \tparam PolygonMeshP, PolygonMeshQ models of `FaceListGraph`
template <class PolygonMeshP, class PolygonMeshQ>
class Penetration_depth
{
public:
  /// the kernel of the queries and answers
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  /// a translation of P, or a contact point
  using Point_3 = Kernel::Point_3;
  /// a direction
  using Vector_3 = Kernel::Vector_3;

  /// The answer to a query at a translation `t`.
  struct Result
  {
    bool overlapping = false; ///< P + t and Q overlap (exact); query() only
    double depth = 0;         ///< distance from t to the nearest contact point (0 if not overlapping)
    Vector_3 direction;       ///< unit vector: translate P by depth * direction to separate it
    Point_3 contact;          ///< the nearest contact configuration t + depth * direction
  };

  /// Computes the contact space of `P` (moving) and `Q` (fixed) with covering distance `d`.
  ///
  /// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`, as in point_minkowski_sum()
  /// \param P the moving solid
  /// \param Q the fixed solid
  /// \param d covering distance of the contact points
  /// \param np_p named parameters of `P` and of the algorithm: those of point_minkowski_sum()
  ///        (`statistics` receives the contact space's; `negate_first_mesh` is implied)
  /// \param np_q named parameters of `Q` (`vertex_point_map`)
  /// \returns the penetration depth object, ready for queries
  /// \pre as for point_minkowski_sum(); violations throw `CGAL::Pmsum::Invalid_input`
  template <class ConcurrencyTag = CGAL::Sequential_tag, class NamedParametersP = parameters::Default_named_parameters,
            class NamedParametersQ = parameters::Default_named_parameters>
  static Penetration_depth make(const PolygonMeshP& P, const PolygonMeshQ& Q, double d,
                                const NamedParametersP& np_p = parameters::default_values(),
                                const NamedParametersQ& np_q = parameters::default_values())
  {
    namespace in = Pmsum::internal;
    static_assert(!in::has_any_parameter<NamedParametersP, Pmsum::internal_np::negate_first_mesh_t,
                                         Pmsum::internal_np::roadmap_neighbors_t, Pmsum::internal_np::mesh_statistics_t>(),
                  "CGAL_pmsum: Penetration_depth implies negate_first_mesh and takes no roadmap_neighbors or "
                  "mesh_statistics");
    Pmsum::Statistics local_stats;
    in::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(
      P, Q, d, np_p, np_q, local_stats, in::Negation::always);
    Penetration_depth pd(d, std::move(sum.mp), std::move(sum.mq));
    auto out = std::back_inserter(pd.m_points);
    in::run_pipeline<ConcurrencyTag>(*pd.m_p, *pd.m_q, d, sum.options, sum.stats,
                                     in::make_point_emit<Kernel>(*pd.m_p, *pd.m_q, out), sum.start);
    pd.build();
    return pd;
  }

  /// A copy shares the tree and the collision geometry (read-only) but has its own overlap test
  /// state, so that each thread can query its own copy.
  /// \param other the object to copy
  Penetration_depth(const Penetration_depth& other)
    : m_d(other.m_d), m_points(other.m_points), m_tree(other.m_tree), m_p(other.m_p), m_q(other.m_q),
      m_geometry(other.m_geometry), m_filter(std::make_shared<Pmsum::internal::Cd_filter>(m_geometry.get()))
  {}
  /// Moves `other` (which is left empty).
  Penetration_depth(Penetration_depth&&) = default;
  /// As the copy constructor.
  /// \param other the object to copy
  /// \returns `*this`
  Penetration_depth& operator=(const Penetration_depth& other)
  {
    if (this != &other) *this = Penetration_depth(other);
    return *this;
  }
  /// Moves.
  /// \returns `*this`
  Penetration_depth& operator=(Penetration_depth&&) = default;

  /// \returns the number of contact points
  std::size_t number_of_contact_points() const { return m_points.size(); }
  /// \returns the contact points (exactly on the contact space, rounded to double)
  const std::vector<Point_3>& contact_points() const { return m_points; }
  /// \returns the covering distance `d` given to make()
  double covering_distance() const { return m_d; }

  /// Nearest contact point to t (whether or not P + t overlaps Q). Thread-safe.
  /// \param t a translation of P
  /// \returns `depth`, `direction` and `contact` of the nearest contact point (`overlapping` is false)
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
  /// \param t a translation of P
  /// \returns whether P + t and Q overlap
  bool overlaps(const Point_3& t) { return !m_filter->is_free_at({t.x(), t.y(), t.z()}); }

  /// Penetration depth at t: 0 without overlap, else the nearest contact (within d of PD).
  /// Not thread-safe, as overlaps().
  /// \param t a translation of P
  /// \returns the depth, the separating direction and the contact point; `overlapping` tells
  ///          whether P + t and Q overlap (exact)
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
  Penetration_depth(double d, Pmsum::internal::Mesh_data minus_p, Pmsum::internal::Mesh_data q)
    : m_d(d), m_p(std::make_shared<Pmsum::internal::Mesh_data>(std::move(minus_p))),
      m_q(std::make_shared<Pmsum::internal::Mesh_data>(std::move(q)))
  {}

  void build()
  {
    m_tree = std::make_shared<Pmsum::internal::Nearest_point_tree>(
      m_points.size(), [this](std::size_t i, int a) { return m_points[i][a]; });
    m_geometry = std::make_shared<Pmsum::internal::Cd_geometry>(*m_p, *m_q);
    m_filter = std::make_shared<Pmsum::internal::Cd_filter>(m_geometry.get());
  }

  double m_d;
  std::vector<Point_3> m_points;
  std::shared_ptr<const Pmsum::internal::Nearest_point_tree> m_tree;
  std::shared_ptr<Pmsum::internal::Mesh_data> m_p, m_q;
  std::shared_ptr<Pmsum::internal::Cd_geometry> m_geometry;
  std::shared_ptr<Pmsum::internal::Cd_filter> m_filter;
};

} // namespace CGAL

#endif // CGAL_PMSUM_PENETRATION_DEPTH_H
