// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input stage of every entry point (sum, offset, erosion, sweep, penetration depth,
// planner): the named parameters read and checked at compile time, the covering distance
// checked, the statistics reset, the meshes copied and checked (mesh_data.h).

#ifndef CGAL_PMSUM_INTERNAL_SUM_INPUT_H
#define CGAL_PMSUM_INTERNAL_SUM_INPUT_H

#include <CGAL_pmsum/Minkowski_sum_boundary_point.h>
#include <CGAL_pmsum/Statistics.h>
#include <CGAL_pmsum/internal/mesh_data.h>
#include <CGAL_pmsum/internal/pipeline.h>
#include <CGAL_pmsum/internal/sum_output.h>
#include <CGAL_pmsum/named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Does the pack NP hold the parameter Tag?
template <class NP, class Tag>
constexpr bool has_parameter()
{
  using Found = std::decay_t<decltype(parameters::get_parameter(std::declval<const NP&>(), Tag{}))>;
  return !std::is_same<Found, CGAL::internal_np::Param_not_found>::value;
}

/// Does NP hold one of the parameters Tags? (Entry points reject those they would ignore.)
template <class NP, class... Tags>
constexpr bool has_any_parameter()
{ return (has_parameter<NP, Tags>() || ...); }

/// Does NP hold a parameter of the algorithm (one that only the first pack, np_p, takes)?
template <class NP>
constexpr bool has_algorithm_parameter()
{
  return has_parameter<NP, internal_np::use_normal_filter_t>() || has_parameter<NP, internal_np::use_cd_filter_t>() ||
         has_parameter<NP, internal_np::use_octree_filter_t>() || has_parameter<NP, internal_np::use_covering_net_t>() ||
         has_parameter<NP, internal_np::use_trim_points_t>() || has_parameter<NP, internal_np::search_islands_t>() ||
         has_parameter<NP, internal_np::negate_first_mesh_t>() || has_parameter<NP, internal_np::statistics_t>() ||
         has_parameter<NP, internal_np::maximum_number_of_candidates_t>() ||
         has_parameter<NP, internal_np::check_overlaps_t>() || has_parameter<NP, internal_np::roadmap_neighbors_t>() ||
         has_parameter<NP, internal_np::merge_flat_regions_t>() ||
         has_parameter<NP, internal_np::mesh_statistics_t>() || has_parameter<NP, internal_np::communicator_t>() ||
         has_parameter<NP, CGAL::internal_np::callback_t>();
}

/// The vertex point map of `pm`: the pack's `vertex_point_map`, else the mesh's own.
template <class PolygonMesh, class NP>
auto vertex_point_map_of(const PolygonMesh& pm, const NP& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, pm));
}

/// Copies and checks the mesh `pm` with its pack's `vertex_point_map` and `treat_as_surface`
/// (with `merge_flat`, the user's `merge_flat_regions`: its flat regions triangulated again,
/// planar_patches.h).
template <class PolygonMesh, class NP>
Mesh_data read_mesh(const PolygonMesh& pm, const NP& np, bool negate, bool check_overlaps, const std::string& name,
                    Mesh_descriptors<PolygonMesh>& desc, bool merge_flat)
{
  const bool as_surface =
    parameters::choose_parameter(parameters::get_parameter(np, internal_np::treat_as_surface), false);
  return make_mesh_data(pm, vertex_point_map_of(pm, np), negate, as_surface, name, desc, check_overlaps, merge_flat);
}

/// The statistics to fill: the pack's `statistics`, else `local`.
template <class NP>
Statistics& statistics_of(const NP& np, Statistics& local)
{
  auto* s = parameters::choose_parameter(parameters::get_parameter(np, internal_np::statistics), &local);
  constexpr bool ok = std::is_same<decltype(s), Statistics*>::value;
  static_assert(ok, "CGAL_pmsum: statistics() takes a CGAL::Pmsum::Statistics");
  if constexpr (ok) return *s;
  else return local; // (only the static_assert's message)
}

enum class Negation { from_parameters, always };

/// The algorithm's settings, read from the first pack (np_p): pipeline options, negation,
/// overlap checks, the statistics to fill (reset here) and the clock, started after `d` is
/// checked. Every entry point starts with one.
struct Sum_settings
{
  template <class NamedParameters>
  Sum_settings(double d, const NamedParameters& np, Statistics& local_stats, Negation negation = Negation::from_parameters)
    : stats(statistics_of(np, local_stats))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    options.use_normal_filter = choose_parameter(get_parameter(np, internal_np::use_normal_filter), true);
    options.use_cd_filter = choose_parameter(get_parameter(np, internal_np::use_cd_filter), true);
    options.use_octree_filter = choose_parameter(get_parameter(np, internal_np::use_octree_filter), true);
    options.use_covering_net = choose_parameter(get_parameter(np, internal_np::use_covering_net), true);
    options.use_trim_points = choose_parameter(get_parameter(np, internal_np::use_trim_points), true);
    options.search_islands = choose_parameter(get_parameter(np, internal_np::search_islands), true);
    options.max_candidates =
      choose_parameter(get_parameter(np, internal_np::maximum_number_of_candidates), std::size_t(-1));
    options.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
    options.communicator = choose_parameter(get_parameter(np, internal_np::communicator), static_cast<Communicator*>(nullptr));
    negate_p = negation == Negation::always || choose_parameter(get_parameter(np, internal_np::negate_first_mesh), false);
    check_overlaps = choose_parameter(get_parameter(np, internal_np::check_overlaps), true);
    merge_flat_regions = choose_parameter(get_parameter(np, internal_np::merge_flat_regions), true);
    stats = Statistics();
    check_covering_distance(d);
    start = Clock::now();
  }

  Statistics& stats;
  Pipeline_options options;
  bool negate_p = false;
  bool check_overlaps = true;
  bool merge_flat_regions = true;
  Clock::time_point start;
};

/// The input stage of a sum of two meshes: the settings, then P (or -P) and Q copied and
/// checked; make_emit() gives the output function for its records.
template <class PolygonMeshP, class PolygonMeshQ, class NamedParametersP, class NamedParametersQ>
struct Prepared_sum : Sum_settings
{
  static_assert(!has_algorithm_parameter<NamedParametersQ>() &&
                  !has_parameter<NamedParametersQ, CGAL::internal_np::geom_traits_t>(),
                "CGAL_pmsum: the second pack (np_q) takes only Q's vertex_point_map and treat_as_surface; "
                "pass the algorithm's parameters in the first pack (np_p)");
  using GT = typename GetGeomTraits<PolygonMeshP, NamedParametersP>::type;
  using Record = Minkowski_sum_boundary_point<PolygonMeshP, PolygonMeshQ, GT>;

  Prepared_sum(const PolygonMeshP& P, const PolygonMeshQ& Q, double d, const NamedParametersP& np_p,
               const NamedParametersQ& np_q, Statistics& local_stats, Negation negation = Negation::from_parameters)
    : Sum_settings(d, np_p, local_stats, negation),
      mp(read_mesh(P, np_p, negate_p, check_overlaps, "P", desc_p, merge_flat_regions)),
      mq(read_mesh(Q, np_q, false, check_overlaps, "Q", desc_q, merge_flat_regions))
  {}

  /// The pipeline's emit function writing records (or points) to `out` (sum_output.h).
  template <class OutputIterator>
  auto make_emit(OutputIterator& out) const
  { return internal::make_emit<Record>(mp, mq, desc_p, desc_q, negate_p, out); }

  Mesh_descriptors<PolygonMeshP> desc_p;
  Mesh_descriptors<PolygonMeshQ> desc_q;
  Mesh_data mp, mq;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_SUM_INPUT_H
