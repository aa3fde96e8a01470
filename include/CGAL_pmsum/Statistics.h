// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Counters and timings of one run of CGAL::point_minkowski_sum(), filled when the named
// parameter `statistics(s)` is given.

#ifndef CGAL_PMSUM_STATISTICS_H
#define CGAL_PMSUM_STATISTICS_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumSupport
/// One rank's share of the decisions of a run with a communicator (Statistics::ranks).
struct Rank_statistics
{
  std::size_t pieces = 0;          ///< pieces of feature pairs this rank decided (the unit of work)
  std::size_t candidates = 0;      ///< their candidates (which piece a rank takes varies from run to run)
  std::size_t island_cells = 0;    ///< lattice cells whose islands it searched, or found covered (after the pieces)
  std::size_t cd_queries = 0;      ///< collision tests of candidates made by this rank
  double seconds_deciding = 0;     ///< seconds spent deciding its pieces
  double seconds_exchanging = 0;   ///< seconds spent exchanging decisions (waiting for the others included)
};

/// \ingroup PkgPointMinkowskiSumSupport
/// Counters and timings of one run of point_minkowski_sum() (or of one level of
/// point_minkowski_sum_coarse_to_fine()), filled when the named parameter `statistics(s)` is
/// given. Seconds are wall-clock times.
struct Statistics
{
  /// \var samples_p
  /// number of samples of P (its d/2-covering: vertices, edge and face lattices)
  std::size_t samples_p = 0, samples_q = 0; ///< number of samples of Q
  std::size_t feature_pairs = 0;            ///< feature pairs kept by the normal filter
  std::size_t candidates = 0;               ///< sample pairs p + q kept by the normal filter
  std::size_t octree_leaves = 0;            ///< leaf cells (size d) holding candidates
  std::size_t octree_certified_leaves = 0;  ///< of them, certified interior by the octree filter
  std::size_t candidates_certified = 0;     ///< candidates in certified cells: never CD-tested
  std::size_t candidates_reused = 0;        ///< coarse to fine: decided by the coarser level
  std::size_t candidates_covered = 0;       ///< closer than d/2 to an output point: never CD-tested
  std::size_t candidates_in_patch_pairs = 0; ///< candidates and facet lattice points inside one pair of convex faces' crossing set: never CD-tested
  std::size_t cd_queries = 0;               ///< collision tests of candidates (one per candidate and direction tried)
  std::size_t triangle_pairs = 0;           ///< exact triangle-triangle tests (CD filter and trim search)
  std::size_t containment_tests = 0;        ///< exact point-in-solid tests (CD filter and trim search)
  std::size_t corner_tests = 0;             ///< CD tests of facet lattice points on the facets' edges (trim search)
  std::size_t trim_segments = 0;            ///< segments searched for trim-curve points (lattice edges and island lines)
  std::size_t island_cells = 0;             ///< lattice cells searched for islands (visible pieces inside one cell)
  std::size_t trim_queries = 0;             ///< collision tests of the trim search (corner tests and segment searches)
  std::size_t trim_points = 0;              ///< output points on trim curves (between lattice points)
  std::size_t output_points = 0;            ///< the (d/2, d)-net, or every boundary candidate
  double seconds_setup = 0;                 ///< input checks, sampling resolutions, AABB trees
  double seconds_normal_filter = 0;         ///< normal filter (coarse to fine: first level only, else 0)
  double seconds_octree_filter = 0;         ///< interior certificate and leaf cells
  double seconds_cd_filter = 0;             ///< candidate enumeration and CD filter
  /// With a communicator (named parameter `communicator`): each rank's share of the
  /// decisions, in rank order (the same on every rank); empty without one.
  std::vector<Rank_statistics> ranks;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_STATISTICS_H
