// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's ranks. Built with CGAL_PMSUM_WITH_MPI and started by mpirun, every rank runs the
// same command: each reads the inputs and decides its share of the sum (named parameter
// `communicator`); rank 0 alone writes the outputs, shows progress and prints errors. A
// failure on one rank (an input it cannot read, an exception) ends every rank: the steps
// that can fail on one rank alone run in agreed(), the library shares the failures of its
// decisions, and any other error on one rank ends every rank (abort_all_ranks). Otherwise (or started without mpirun)
// the tool is one process and nothing here does anything.

#ifndef CGAL_PMSUM_CLI_RANKS_H
#define CGAL_PMSUM_CLI_RANKS_H

#include <CGAL_pmsum/Communicator.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/distribution.h>

#include "cli_errors.h"

#ifdef CGAL_PMSUM_WITH_MPI
#include <CGAL_pmsum/MPI_communicator.h>
#endif

#include <algorithm>
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
/// Set when agreed() throws: every rank knows of the failure.
inline bool& failure_agreed()
{
  static bool agreed = false;
  return agreed;
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
  std::optional<decltype(step())> result;
  try {
    result.emplace(step());
  } catch (...) {
    failure = std::current_exception();
  }
  try {
    CGAL::Pmsum::internal::agree(*c, failure);
  } catch (...) {
    ranks_internal::failure_agreed() = true;
    throw;
  }
  return std::move(*result);
}

/// Did every rank learn of the error being handled (an error of agreed(), or one that every
/// rank meets alike: bad arguments or input, a refusal, a cancellation, another rank's
/// failure)? If not, the other ranks may wait for this one: abort_all_ranks().
inline bool every_rank_knows(std::exception_ptr e)
{
  if (!world_communicator() || ranks_internal::failure_agreed()) return true;
  try {
    std::rethrow_exception(e);
  } catch (const CGAL::Pmsum::Rank_failed&) {
  } catch (const CGAL::Pmsum::Invalid_input&) {
  } catch (const CGAL::Pmsum::Too_large&) {
  } catch (const CGAL::Pmsum::Operation_cancelled&) {
  } catch (const CGAL::Pmsum::Mesh_reconstruction_failed&) {
  } catch (const Usage_error&) {
  } catch (const Refused&) {
  } catch (...) {
    return false;
  }
  return true;
}

/// Ends every rank at once with exit code `code` (MPI_Abort), or this process alone.
[[noreturn]] inline void abort_all_ranks(int code)
{
#ifdef CGAL_PMSUM_WITH_MPI
  if (world_communicator()) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

/// The smallest of every rank's `v` (the ranks must agree on limits they compute alone).
inline std::size_t smallest_over_ranks(std::size_t v)
{
  CGAL::Pmsum::Communicator* c = world_communicator();
  if (!c) return v;
  std::size_t m = v;
  for (const std::string& s : c->all_gather(std::to_string(v))) m = (std::min)(m, std::size_t(std::stoull(s)));
  return m;
}

/// The ranks that share this machine's memory (1 without MPI).
inline std::size_t ranks_on_this_machine()
{
  if (!world_communicator()) return 1;
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE"); // Open MPI
  if (!local) local = std::getenv("MPI_LOCALNRANKS");             // MPICH
  const long n = local ? std::atol(local) : 0;
  return n > 0 ? std::size_t(n) : std::size_t(world_communicator()->size());
}

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_RANKS_H
