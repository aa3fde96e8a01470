// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The communicator interface of a sum computed by several processes (named parameter
// `communicator`): all-gather of bytes, and a counter shared by the ranks. The package holds
// no MPI symbol; CGAL_pmsum/MPI_communicator.h implements it over an MPI_Comm.

#ifndef CGAL_PMSUM_COMMUNICATOR_H
#define CGAL_PMSUM_COMMUNICATOR_H

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumSupport
/// The processes (ranks) that compute one sum together, given to an entry point with the
/// named parameter `communicator(&c)`. Every rank calls the entry point with the same
/// meshes, `d` and parameters (a fingerprint of the candidates is compared: different inputs
/// throw `Invalid_input` on every rank); the ranks take the pieces of feature pairs to decide
/// from a shared counter (make_counter()), and every rank returns the whole output, the same
/// as one process's, point for point. A failure during the decisions on one rank ends every rank (the others throw `Rank_failed`); one
/// before them (e.g. out of memory while reading) is not shared: end every rank then.
/// Implement it over your transport (CGAL::Pmsum::MPI_communicator for MPI).
class Communicator
{
public:
  virtual ~Communicator() = default;
  /// This process's rank.
  /// \returns a number in [0, size())
  virtual int rank() const = 0;
  /// The number of ranks.
  /// \returns the number of ranks, at least 1
  virtual int size() const = 0;
  /// Collective: every rank passes its bytes and receives every rank's, in rank order.
  /// \param bytes this rank's message (any size, possibly empty)
  /// \returns the messages of ranks 0, 1, ..., size() - 1
  virtual std::vector<std::string> all_gather(const std::string& bytes) = 0;

  /// A counter shared by the ranks (make_counter()): the ranks take the pieces of each wave
  /// from it, so that a rank that finishes early takes more.
  class Counter
  {
  public:
    /// Not collective: a rank that leaves on an exception of its own destroys its counter
    /// alone (and its program then ends every rank, e.g. with MPI_Abort).
    virtual ~Counter() = default;
    /// Adds `n` to the counter, atomically with respect to every rank.
    /// \param n the increment
    /// \returns the counter's value before the addition
    virtual std::uint64_t fetch_add(std::uint64_t n) = 0;
    /// Collective: every rank is done with the counter, which may release what it holds
    /// across the ranks (fetch_add() must not be called after it). A counter destroyed
    /// without it keeps that until the transport ends (MPI_communicator: until MPI_Finalize).
    virtual void close() {}
  };
  /// Collective: a new counter, at 0 on every rank when this returns.
  /// \returns this rank's handle to the counter
  virtual std::unique_ptr<Counter> make_counter() = 0;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_COMMUNICATOR_H
