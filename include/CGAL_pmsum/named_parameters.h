// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters specific to CGAL_pmsum, usable like CGAL's own:
//
//   CGAL::parameters::use_normal_filter(false).negate_first_mesh(true).vertex_point_map(vpm)
//
// CGAL 5.5 has no way to add member functions to CGAL::Named_function_parameters, so the
// package parameters return a class derived from it, which also offers every CGAL parameter
// as a member returning that class: once a chain starts with one of ours, CGAL's and ours
// follow in any order (`use_cd_filter(true).callback(f).statistics(s)`). A chain that starts
// with one of CGAL's (`CGAL::parameters::callback(f)`) is CGAL's own class and cannot take
// ours after it: start it with one of ours.
//
// Which pack takes what: the algorithm's parameters go in the first mesh's pack (np_p); the
// second pack (np_q) takes only that mesh's `vertex_point_map` and `treat_as_surface`. An
// algorithm parameter in np_q is a compile-time error (internal/sum_input.h).

#ifndef CGAL_PMSUM_NAMED_PARAMETERS_H
#define CGAL_PMSUM_NAMED_PARAMETERS_H

#include <CGAL_pmsum/Communicator.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>

namespace CGAL {
namespace Pmsum {
namespace internal_np {
enum use_normal_filter_t { use_normal_filter };
enum use_cd_filter_t { use_cd_filter };
enum use_octree_filter_t { use_octree_filter };
enum use_covering_net_t { use_covering_net };
enum use_trim_points_t { use_trim_points };
enum search_islands_t { search_islands };
enum negate_first_mesh_t { negate_first_mesh };
enum statistics_t { statistics };
enum treat_as_surface_t { treat_as_surface };
enum maximum_number_of_candidates_t { maximum_number_of_candidates };
enum check_overlaps_t { check_overlaps };
enum merge_flat_regions_t { merge_flat_regions };
enum roadmap_neighbors_t { roadmap_neighbors };
enum mesh_statistics_t { mesh_statistics };
enum communicator_t { communicator };
} // namespace internal_np

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// Named parameter pack that also offers the CGAL_pmsum parameters, and CGAL's, as member
/// functions (see the file comment). Made by the functions of `CGAL::parameters` below.
/// \tparam T the type of the last parameter's value
/// \tparam Tag the last parameter's tag
/// \tparam Base the rest of the chain
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// CGAL's pack, the base class
  using Nfp = CGAL::Named_function_parameters<T, Tag, Base>;
  /// A chain of one parameter.
  /// \param v its value
  explicit Named_parameters(const T& v) : Nfp(v) {}
  /// The parameter `v` in front of the chain `b`.
  /// \param v its value
  /// \param b the rest of the chain
  Named_parameters(const T& v, const Base& b) : Nfp(v, b) {}

  /// Run the normal filter (default `true`). It removes only pairs whose sum cannot be a
  /// boundary point; turning it off makes the computation much slower, never more exact.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::use_normal_filter_t, Named_parameters>
  use_normal_filter(bool b) const { return {b, *this}; }

  /// Treat every component of this mesh as a surface, closed or not (default `false`): the
  /// sum is then taken with the surface itself, not with the solid it bounds. (Used for
  /// erosion: the boundary of surface(P) + ball is the set at distance r from the surface.)
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::treat_as_surface_t, Named_parameters>
  treat_as_surface(bool b) const { return {b, *this}; }

  /// Fill `s` (a CGAL::Pmsum::Statistics) with counters and timings of the run.
  /// \tparam S `CGAL::Pmsum::Statistics` (another type is a compile-time error)
  /// \param s the statistics to fill
  /// \returns this chain with the parameter added
  template <class S>
  Named_parameters<S*, internal_np::statistics_t, Named_parameters>
  statistics(S& s) const { return {&s, *this}; }

  /// Throw CGAL::Pmsum::Too_many_candidates before filtering if the normal filter leaves
  /// more candidates than `n` (default: no limit).
  /// \param n the limit
  /// \returns this chain with the parameter added
  Named_parameters<std::size_t, internal_np::maximum_number_of_candidates_t, Named_parameters>
  maximum_number_of_candidates(std::size_t n) const { return {n, *this}; }

  /// Run the collision-detection filter (default `true`). Without it the output is every
  /// candidate that passed the other filters, most of them not on the boundary.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::use_cd_filter_t, Named_parameters>
  use_cd_filter(bool b) const { return {b, *this}; }

  /// Run the octree filter (default `true`): candidates in octree cells certified to lie in
  /// the interior of the sum are not CD-tested. The output is the same either way.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::use_octree_filter_t, Named_parameters>
  use_octree_filter(bool b) const { return {b, *this}; }

  /// Output a (d/2, d)-net of the boundary candidates (default `true`): a d-covering of the
  /// boundary with no two points closer than d/2, whose candidates near an output point are
  /// not CD-tested. `false`: every boundary candidate, as in the paper (many more points).
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::use_covering_net_t, Named_parameters>
  use_covering_net(bool b) const { return {b, *this}; }

  /// Search the trim curves of the convolution facets for boundary points between lattice
  /// points (default `true`): it covers the passages of the sum narrower than the sample
  /// spacing (user manual, section 4). `false` is faster and may leave them uncovered.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::use_trim_points_t, Named_parameters>
  use_trim_points(bool b) const { return {b, *this}; }

  /// With trim points, also search the islands of the convolution facets (default `true`):
  /// visible pieces strictly inside one lattice cell, such as a void of the sum smaller than
  /// the sample spacing (user manual, section 4). `false` is faster (up to 1.7 times in
  /// benchmark/results/trim_points.md) and may leave them uncovered.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::search_islands_t, Named_parameters>
  search_islands(bool b) const { return {b, *this}; }

  /// Compute the boundary of (-P) + Q instead of P + Q (default `false`): the contact space
  /// of a robot P translating among obstacles Q.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::negate_first_mesh_t, Named_parameters>
  negate_first_mesh(bool b) const { return {b, *this}; }

  /// Check that the closed components of P and Q intersect neither themselves nor each
  /// other (default `true`; exact, with boxes first: see the precondition of
  /// point_minkowski_sum()). `false` skips it for input known to be valid; then only the
  /// sign of each mesh's total volume is checked, and overlapping input gives wrong output.
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::check_overlaps_t, Named_parameters>
  check_overlaps(bool b) const { return {b, *this}; }

  /// Triangulate the flat regions of P and Q again first, without the vertices inside them and
  /// inside their straight creases (exact coplanarity and collinearity; the same solids), so
  /// that a tessellated CAD part costs what its uncut faces cost (default `true`). Records
  /// still name the mesh's own features, with exact weights (see Mesh_feature).
  /// \param b `true` or `false`
  /// \returns this chain with the parameter added
  Named_parameters<bool, internal_np::merge_flat_regions_t, Named_parameters>
  merge_flat_regions(bool b) const { return {b, *this}; }

  /// Translational_motion_planner: join each roadmap node to its `k` nearest nodes
  /// (default 12). \pre k >= 1
  /// \param k the number of neighbours
  /// \returns this chain with the parameter added
  Named_parameters<unsigned, internal_np::roadmap_neighbors_t, Named_parameters>
  roadmap_neighbors(unsigned k) const { return {k, *this}; }

  /// point_minkowski_sum_mesh(): fill `s` (a CGAL::Pmsum::Mesh_statistics) with the
  /// reconstruction's counters, checks and seconds.
  /// \tparam S `CGAL::Pmsum::Mesh_statistics`
  /// \param s the statistics to fill
  /// \returns this chain with the parameter added
  template <class S>
  Named_parameters<S*, internal_np::mesh_statistics_t, Named_parameters>
  mesh_statistics(S& s) const { return {&s, *this}; }

  /// Compute the sum together with the other ranks of `c` (default `nullptr`: this process
  /// alone). Every rank calls the same function with the same input; the ranks share the decisions
  /// of the candidates, and every rank gets the whole output, identical to one process's
  /// (see CGAL::Pmsum::Communicator, and CGAL::Pmsum::MPI_communicator for MPI).
  /// \param c the ranks, or `nullptr`
  /// \returns this chain with the parameter added
  Named_parameters<Communicator*, internal_np::communicator_t, Named_parameters>
  communicator(Communicator* c) const { return {c, *this}; }

#ifndef DOXYGEN_RUNNING
  // Every CGAL named parameter, returning this class so that ours may follow it.
#define CGAL_add_named_parameter(X, Y, Z)                                                  \
  template <class K>                                                                       \
  Named_parameters<K, CGAL::internal_np::X, Named_parameters> Z(const K& k) const         \
  { return {k, *this}; }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#endif
};

} // namespace Pmsum

namespace parameters {

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::use_normal_filter
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::use_normal_filter_t>
use_normal_filter(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::use_normal_filter_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::use_cd_filter
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::use_cd_filter_t>
use_cd_filter(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::use_cd_filter_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::use_octree_filter
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::use_octree_filter_t>
use_octree_filter(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::use_octree_filter_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::use_covering_net
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::use_covering_net_t>
use_covering_net(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::use_covering_net_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::use_trim_points
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::use_trim_points_t>
use_trim_points(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::use_trim_points_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::search_islands
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::search_islands_t>
search_islands(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::search_islands_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::negate_first_mesh
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::negate_first_mesh_t>
negate_first_mesh(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::negate_first_mesh_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::check_overlaps
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::check_overlaps_t>
check_overlaps(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::check_overlaps_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::merge_flat_regions
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::merge_flat_regions_t>
merge_flat_regions(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::merge_flat_regions_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::treat_as_surface
inline Pmsum::Named_parameters<bool, Pmsum::internal_np::treat_as_surface_t>
treat_as_surface(bool b) { return Pmsum::Named_parameters<bool, Pmsum::internal_np::treat_as_surface_t>(b); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::statistics
template <class S>
Pmsum::Named_parameters<S*, Pmsum::internal_np::statistics_t>
statistics(S& s) { return Pmsum::Named_parameters<S*, Pmsum::internal_np::statistics_t>(&s); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::maximum_number_of_candidates
inline Pmsum::Named_parameters<std::size_t, Pmsum::internal_np::maximum_number_of_candidates_t>
maximum_number_of_candidates(std::size_t n)
{ return Pmsum::Named_parameters<std::size_t, Pmsum::internal_np::maximum_number_of_candidates_t>(n); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::roadmap_neighbors
inline Pmsum::Named_parameters<unsigned, Pmsum::internal_np::roadmap_neighbors_t>
roadmap_neighbors(unsigned k) { return Pmsum::Named_parameters<unsigned, Pmsum::internal_np::roadmap_neighbors_t>(k); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::mesh_statistics
template <class S>
Pmsum::Named_parameters<S*, Pmsum::internal_np::mesh_statistics_t>
mesh_statistics(S& s) { return Pmsum::Named_parameters<S*, Pmsum::internal_np::mesh_statistics_t>(&s); }

/// \ingroup PkgPointMinkowskiSumNamedParameters
/// \copydoc CGAL::Pmsum::Named_parameters::communicator
inline Pmsum::Named_parameters<Pmsum::Communicator*, Pmsum::internal_np::communicator_t>
communicator(Pmsum::Communicator* c)
{ return Pmsum::Named_parameters<Pmsum::Communicator*, Pmsum::internal_np::communicator_t>(c); }

} // namespace parameters
} // namespace CGAL

#endif // CGAL_PMSUM_NAMED_PARAMETERS_H
