// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Errors reported by CGAL_pmsum. The library never prints: it throws one of these, with a
// message that says what is wrong and where.

#ifndef CGAL_PMSUM_EXCEPTIONS_H
#define CGAL_PMSUM_EXCEPTIONS_H

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumSupport
/// Input the algorithm cannot handle, such as an empty mesh, a non-triangle or degenerate face,
/// a coordinate that is not finite or not a double, a wrong orientation, or `d <= 0`.
/// The entry points throw it when a checked precondition fails, before writing anything;
/// Nef_minkowski_sum_reference throws it for a mesh with a border or an invalid file.
/// Constructed from its message, as `std::invalid_argument`.
class Invalid_input : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// \ingroup PkgPointMinkowskiSumSupport
/// A run refused for its size before the work is done: the base of Too_many_candidates and
/// Covering_distance_too_small. Constructed from its message, as `std::runtime_error`.
class Too_large : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// \ingroup PkgPointMinkowskiSumSupport
/// The candidate count exceeds the limit set with `maximum_number_of_candidates()`.
class Too_many_candidates : public Too_large
{
public:
  /// Constructs the error with a message that gives both numbers.
  /// \param candidates the number of candidates
  /// \param limit the limit they exceed
  Too_many_candidates(std::size_t candidates, std::size_t limit)
    : Too_many_candidates(candidates, limit, "the normal filter leaves " + std::to_string(candidates) +
                                               " candidate points, more than the limit of " + std::to_string(limit)) {}
  /// Constructs the error with the message `what`.
  /// \param candidates the number of candidates
  /// \param limit the limit they exceed
  /// \param what the message
  Too_many_candidates(std::size_t candidates, std::size_t limit, const std::string& what)
    : Too_large(what), candidates(candidates), limit(limit) {}
  /// \var candidates
  /// the number of candidates (Too_many_feature_pairs: of (feature pair, direction) records)
  std::size_t candidates, limit; ///< the limit set with `maximum_number_of_candidates()`
};

/// \ingroup PkgPointMinkowskiSumSupport
/// Without the normal filter: the (feature pair, direction) records to store exceed the
/// limit set with `maximum_number_of_candidates()` (checked before they are stored).
/// It has the constructors of Too_many_candidates; `candidates` is the number of records.
class Too_many_feature_pairs : public Too_many_candidates
{
public:
  /// \cond
  using Too_many_candidates::Too_many_candidates;
  /// \endcond
};

/// \ingroup PkgPointMinkowskiSumSupport
/// `d` is so small that a feature would need more subdivisions than the sample lattice
/// holds (2^20 along an edge). Constructed from its message, as `std::runtime_error`.
class Covering_distance_too_small : public Too_large
{
public:
  using Too_large::Too_large;
};

/// \ingroup PkgPointMinkowskiSumSupport
/// The progress callback (named parameter `callback`) returned false.
class Operation_cancelled : public std::runtime_error
{
public:
  /// Constructs the error with the message "point_minkowski_sum was cancelled by its callback".
  Operation_cancelled() : std::runtime_error("point_minkowski_sum was cancelled by its callback") {}
};

/// \ingroup PkgPointMinkowskiSumSupport
/// With a communicator (named parameter `communicator`): another rank failed, and this one
/// stops with it. The failing rank throws its own exception.
class Rank_failed : public std::runtime_error
{
public:
  /// Constructs the error with the message "rank R: WHAT".
  /// \param rank the rank that failed
  /// \param what its exception's message
  Rank_failed(int rank, const std::string& what)
    : std::runtime_error("rank " + std::to_string(rank) + ": " + what), m_rank(rank) {}
  /// The rank that failed.
  /// \returns its rank
  int rank() const { return m_rank; }

private:
  int m_rank;
};

/// \ingroup PkgPointMinkowskiSumMesh
/// point_minkowski_sum_mesh() could make no valid mesh from the points, even with the smaller
/// covering distances it tried. Constructed from its message, as `std::runtime_error`.
class Mesh_reconstruction_failed : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_EXCEPTIONS_H
