// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Pmsum::Communicator over MPI. Include it only in an MPI program (link MPI::MPI_CXX);
// the rest of the package does not include <mpi.h>.

#ifndef CGAL_PMSUM_MPI_COMMUNICATOR_H
#define CGAL_PMSUM_MPI_COMMUNICATOR_H

#include <CGAL_pmsum/Communicator.h>

#include <mpi.h>

#include <climits>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumSupport
/// The ranks of an MPI communicator (MPI must be initialised; the sum is computed on the
/// thread that calls it, so MPI_THREAD_FUNNELED is enough).
/// \code
/// CGAL::Pmsum::MPI_communicator world(MPI_COMM_WORLD);
/// CGAL::point_minkowski_sum(P, Q, d, out, CGAL::parameters::communicator(&world));
/// \endcode
class MPI_communicator : public Communicator
{
public:
  /// The ranks of `comm` (not duplicated: keep it alive while in use).
  /// \param comm an MPI communicator
  explicit MPI_communicator(MPI_Comm comm) : m_comm(comm)
  {
    MPI_Comm_rank(comm, &m_rank);
    MPI_Comm_size(comm, &m_size);
  }
  /// This process's rank in the communicator.
  /// \returns a number in [0, size())
  int rank() const override { return m_rank; }
  /// The communicator's size.
  /// \returns the number of ranks
  int size() const override { return m_size; }
  /// MPI_Allgather of the sizes, then MPI_Allgatherv of the bytes (up to 2 GiB in all).
  /// \param bytes this rank's message
  /// \returns the messages of ranks 0, 1, ..., size() - 1
  std::vector<std::string> all_gather(const std::string& bytes) override
  {
    // A message too large for MPI's int counts fails on every rank alike (size -1).
    const int mine = bytes.size() > std::size_t(INT_MAX) ? -1 : int(bytes.size());
    const std::size_t n = std::size_t(m_size);
    std::vector<int> sizes(n), offsets(n);
    MPI_Allgather(&mine, 1, MPI_INT, sizes.data(), 1, MPI_INT, m_comm);
    long long total = 0;
    for (int r = 0; r < m_size; ++r) {
      if (sizes[std::size_t(r)] < 0) total = LLONG_MAX;
      if (total == LLONG_MAX) break;
      offsets[std::size_t(r)] = int(total);
      total += sizes[std::size_t(r)];
    }
    if (total > INT_MAX) throw std::length_error("MPI_communicator: messages above 2 GiB");
    std::string all(std::size_t(total), '\0');
    MPI_Allgatherv(bytes.data(), mine, MPI_BYTE, &all[0], sizes.data(), offsets.data(), MPI_BYTE, m_comm);
    std::vector<std::string> out;
    for (int r = 0; r < m_size; ++r) out.push_back(all.substr(std::size_t(offsets[std::size_t(r)]), std::size_t(sizes[std::size_t(r)])));
    return out;
  }

  /// An MPI window of one 64-bit integer on rank 0, updated with MPI_Fetch_and_op (passive
  /// target: rank 0 need not take part). Collective; its close() frees the window
  /// (collective), its destruction alone does not (MPI_Win_free would wait for the others).
  /// \returns this rank's handle to the counter
  std::unique_ptr<Counter> make_counter() override { return std::make_unique<Window_counter>(m_comm); }

private:
  class Window_counter : public Counter
  {
  public:
    explicit Window_counter(MPI_Comm comm)
    {
      int rank = 0;
      MPI_Comm_rank(comm, &rank);
      std::uint64_t* value = nullptr;
      MPI_Win_allocate(MPI_Aint(rank == 0 ? sizeof(std::uint64_t) : 0), int(sizeof(std::uint64_t)), MPI_INFO_NULL, comm,
                       &value, &m_window);
      if (rank == 0) {
        MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, m_window);
        *value = 0;
        MPI_Win_unlock(0, m_window);
      }
      MPI_Barrier(comm);
      MPI_Win_lock_all(0, m_window);
    }
    void close() override
    {
      if (m_window == MPI_WIN_NULL) return;
      MPI_Win_unlock_all(m_window);
      MPI_Win_free(&m_window); // sets it to MPI_WIN_NULL
    }
    std::uint64_t fetch_add(std::uint64_t n) override
    {
      std::uint64_t before = 0;
      MPI_Fetch_and_op(&n, &before, MPI_UINT64_T, 0, 0, MPI_SUM, m_window);
      MPI_Win_flush(0, m_window);
      return before;
    }

  private:
    MPI_Win m_window = MPI_WIN_NULL;
  };

  MPI_Comm m_comm;
  int m_rank = 0, m_size = 1;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_MPI_COMMUNICATOR_H
