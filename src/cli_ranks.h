// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's ranks. Built with CGAL_PMSUM_WITH_MPI and started by mpirun, every rank runs the
// same command: each reads the inputs and decides its share of the sum (named parameter
// `communicator`); rank 0 alone writes the outputs, shows progress and prints errors. A
// failure on one rank (an input it cannot read, an exception) ends every rank: the steps
// that can fail on one rank alone run in agreed(). Otherwise (or started without mpirun)
// the tool is one process and nothing here does anything.

#ifndef CGAL_PMSUM_CLI_RANKS_H
#define CGAL_PMSUM_CLI_RANKS_H

#include <CGAL_pmsum/Communicator.h>
#include <CGAL_pmsum/exceptions.h>

#ifdef CGAL_PMSUM_WITH_MPI
#include <CGAL_pmsum/MPI_communicator.h>
#endif

#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace pmsum_cli {

namespace ranks_internal {
/// The communicator of the ranks, set by Ranks_session (nullptr: one process).
inline CGAL::Pmsum::Communicator*& world()
{
  static CGAL::Pmsum::Communicator* c = nullptr;
  return c;
}
} // namespace ranks_internal

/// The ranks of this run, or nullptr for one process.
inline CGAL::Pmsum::Communicator* world_communicator() { return ranks_internal::world(); }
inline int process_rank() { return world_communicator() ? world_communicator()->rank() : 0; }
/// Does this process write the outputs, the progress and the messages (rank 0)?
inline bool is_main_rank() { return process_rank() == 0; }

/// Where errors go: std::cerr on rank 0, nowhere on the other ranks.
inline std::ostream& error_stream()
{
  static std::ostream nowhere(nullptr);
  return is_main_rank() ? std::cerr : nowhere;
}

/// Lives as long as main(): starts MPI when the process was started by an MPI launcher with
/// more than one rank (and the tool was built with MPI), and ends it.
class Ranks_session
{
public:
  Ranks_session(int& argc, char**& argv)
  {
#ifdef CGAL_PMSUM_WITH_MPI
    // Started by mpirun (Open MPI, MPICH's Hydra or a PMIx launcher)?
    if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE") && !std::getenv("PMIX_RANK")) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    m_started = true;
    m_world = std::make_unique<CGAL::Pmsum::MPI_communicator>(MPI_COMM_WORLD);
    if (m_world->size() > 1) ranks_internal::world() = m_world.get();
#else
    (void)argc;
    (void)argv;
#endif
  }
  Ranks_session(const Ranks_session&) = delete;
  Ranks_session& operator=(const Ranks_session&) = delete;
  ~Ranks_session()
  {
    ranks_internal::world() = nullptr;
#ifdef CGAL_PMSUM_WITH_MPI
    m_world.reset();
    if (m_started) MPI_Finalize();
#endif
  }

private:
  std::unique_ptr<CGAL::Pmsum::Communicator> m_world;
  bool m_started = false;
};

/// Runs step() on every rank; if it fails on any rank, every rank throws: a failing rank its
/// own exception, the others CGAL::Pmsum::Rank_failed with the first failing rank's message.
template <class Step>
auto agreed(Step&& step) -> decltype(step())
{
  CGAL::Pmsum::Communicator* c = world_communicator();
  if (!c) return step();
  std::exception_ptr failure;
  std::string message;
  using Result = decltype(step());
  std::optional<Result> result;
  try {
    result.emplace(step());
  } catch (const std::exception& e) {
    failure = std::current_exception();
    message = e.what();
  } catch (...) {
    failure = std::current_exception();
    message = "unknown error";
  }
  const std::vector<std::string> all = c->all_gather(failure ? "1" + message : "0");
  if (failure) std::rethrow_exception(failure);
  for (int r = 0; r < int(all.size()); ++r)
    if (!all[std::size_t(r)].empty() && all[std::size_t(r)][0] == '1') throw CGAL::Pmsum::Rank_failed(r, all[std::size_t(r)].substr(1));
  return std::move(*result);
}

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_RANKS_H
