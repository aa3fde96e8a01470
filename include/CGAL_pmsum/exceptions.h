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

/// Input the algorithm cannot handle: empty mesh, non-triangle or degenerate face,
/// coordinate that is not finite or not a double, inward orientation, d <= 0, ...
class Invalid_input : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

/// A run refused for its size before the work is done: the base of the two errors below.
class Too_large : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// The candidate count exceeds the limit set with `maximum_number_of_candidates()`.
class Too_many_candidates : public Too_large
{
public:
  Too_many_candidates(std::size_t candidates, std::size_t limit)
    : Too_many_candidates(candidates, limit, "the normal filter leaves " + std::to_string(candidates) +
                                               " candidate points, more than the limit of " + std::to_string(limit)) {}
  Too_many_candidates(std::size_t candidates, std::size_t limit, const std::string& what)
    : Too_large(what), candidates(candidates), limit(limit) {}
  std::size_t candidates, limit;
};

/// Without the normal filter: the (feature pair, direction) records to store exceed the
/// limit set with `maximum_number_of_candidates()` (checked before they are stored).
class Too_many_feature_pairs : public Too_many_candidates
{
public:
  using Too_many_candidates::Too_many_candidates;
};

/// `d` is so small that a feature would need more subdivisions than the sample lattice
/// holds (2^20 along an edge).
class Covering_distance_too_small : public Too_large
{
public:
  using Too_large::Too_large;
};

/// The progress callback returned false.
class Operation_cancelled : public std::runtime_error
{
public:
  Operation_cancelled() : std::runtime_error("point_minkowski_sum was cancelled by its callback") {}
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_EXCEPTIONS_H
