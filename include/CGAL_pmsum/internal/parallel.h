// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Parallel loops (TBB) that fall back to plain loops: map_chunks for the stages that decide
// independent items (normal filter, octree filter; shared among ranks too), run_in_waves for
// the stage whose results are committed in canonical order (decisions, covering net, output;
// shared among ranks with distribution.h), and Per_thread for the state each thread keeps
// (collision filters).

#ifndef CGAL_PMSUM_INTERNAL_PARALLEL_H
#define CGAL_PMSUM_INTERNAL_PARALLEL_H

#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/internal/distribution.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <chrono>
#include <cstddef>
#include <exception>
#include <algorithm>
#include <atomic>
#include <functional>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Runs f(i) for i in [0, n), in parallel if asked and TBB is there.
template <class F>
void for_each_index(std::size_t n, bool parallel, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if (parallel) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
    });
    return;
  }
#else
  (void)parallel;
#endif
  for (std::size_t i = 0; i < n; ++i) f(i);
}

/// The indices [first, last) of chunk k when n indices are cut into `chunks` chunks of about
/// the same size.
inline std::pair<std::size_t, std::size_t> chunk_range(std::size_t k, std::size_t chunks, std::size_t n)
{ return {k * n / chunks, (k + 1) * n / chunks}; }

/// The results of chunks (map_chunks), one chunk after the other.
template <class T>
std::vector<T> concatenate(std::vector<std::vector<T>>&& chunks)
{
  std::size_t n = 0;
  for (const auto& c : chunks) n += c.size();
  std::vector<T> all;
  all.reserve(n);
  for (auto& c : chunks) {
    all.insert(all.end(), c.begin(), c.end());
    c = {};
  }
  return all;
}

/// Runs f(k, results) for each chunk k in [0, n), in parallel if asked, and returns every
/// chunk's results (f appends chunk k's to `results`, empty when called). With a communicator
/// (collective), rank r runs the chunks r, r + K, r + 2K, ... of the K ranks and the ranks
/// exchange their results, so that every rank returns all of them, the same as one process;
/// a failure on one rank ends every rank (check_statuses). T: trivially copyable.
template <class T, class F>
std::vector<std::vector<T>> map_chunks(std::size_t n, bool parallel, Communicator* comm, const F& f)
{
  std::vector<std::vector<T>> results(n);
  const std::size_t K = comm ? std::size_t(comm->size()) : 1, r = comm ? std::size_t(comm->rank()) : 0;
  const std::size_t mine = n > r ? (n - r + K - 1) / K : 0;
  std::exception_ptr failure;
  try {
    for_each_index(mine, parallel, [&](std::size_t j) { f(r + j * K, results[r + j * K]); });
  } catch (...) {
    if (!comm) throw;
    failure = std::current_exception();
  }
  if (!comm || K == 1) {
    if (failure) std::rethrow_exception(failure);
    return results;
  }
  Byte_writer w;
  write_status(w, failure, false);
  w.pod(std::uint64_t(n));
  if (!failure)
    for (std::size_t k = r; k < n; k += K) w.pods(results[k]);
  const std::vector<std::string> all = comm->all_gather(w.bytes());
  std::vector<Byte_reader> readers(all.begin(), all.end());
  check_statuses(readers, failure);
  for (Byte_reader& in : readers)
    if (in.pod<std::uint64_t>() != n) throw different_inputs();
  for (std::size_t s = 0; s < K; ++s)
    if (s != r)
      for (std::size_t k = s; k < n; k += K) readers[s].pods(results[k]);
  return results;
}

/// map_chunks over the indices [0, n) cut into at most 256 ranges of about the same size:
/// f(first, last, results) appends the results of indices [first, last); returns them all,
/// in the order of the indices.
template <class T, class F>
std::vector<T> map_ranges(std::size_t n, bool parallel, Communicator* comm, const F& f)
{
  const std::size_t chunks = (std::min)(n, std::size_t(256));
  return concatenate(map_chunks<T>(chunks, parallel, comm, [&](std::size_t chunk, std::vector<T>& out) {
    const auto [first, last] = chunk_range(chunk, chunks, n);
    f(first, last, out);
  }));
}

/// One T per thread, made from the same constructor arguments; a single T when sequential.
template <class T>
class Per_thread
{
public:
  template <class... Args>
  explicit Per_thread(bool parallel, const Args&... args)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if (parallel) { m_many.emplace(args...); return; }
#else
    (void)parallel;
#endif
    m_one.emplace(args...);
  }
  T& local()
  {
#ifdef CGAL_LINKED_WITH_TBB
    if (m_many) return m_many->local();
#endif
    return *m_one;
  }
  template <class F>
  void for_each(const F& f) const
  {
#ifdef CGAL_LINKED_WITH_TBB
    if (m_many)
      for (const T& t : *m_many) f(t);
#endif
    if (m_one) f(*m_one);
  }

private:
  std::optional<T> m_one;
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::enumerable_thread_specific<T>> m_many;
#endif
};

/// The number of threads for_each_index may use in parallel.
inline std::size_t number_of_threads()
{
#ifdef CGAL_LINKED_WITH_TBB
  return std::size_t(tbb::this_task_arena::max_concurrency());
#else
  return 1;
#endif
}

/// Runs f(k) for k in [0, n), in parallel if asked: the threads take the indices in turn,
/// 0, 1, 2, ..., each the next one as it comes free.
template <class F>
void for_each_in_turn(std::size_t n, bool parallel, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if (parallel) {
    std::atomic<std::size_t> next{0};
    tbb::parallel_for(std::size_t(0), number_of_threads(), [&](std::size_t) {
      for (std::size_t k; (k = next++) < n;) f(k);
    });
    return;
  }
#else
  (void)parallel;
#endif
  for (std::size_t k = 0; k < n; ++k) f(k);
}

/// The end of the wave of run_in_waves that starts at index `first`: the consecutive
/// indices from `first` whose work reaches `wave_work`, at least one.
inline std::size_t wave_end(const std::vector<std::size_t>& work, std::size_t first, std::size_t wave_work)
{
  std::size_t last = first, wave = 0;
  while (last < work.size() && (wave < wave_work || last == first)) wave += work[last++];
  return last;
}

/// The order in which the indices [first, last) of a wave are processed (run_in_waves): the
/// largest work first, in index order among equal work.
inline void wave_order(const std::vector<std::size_t>& work, std::size_t first, std::size_t last,
                       std::vector<std::size_t>& order)
{
  order.resize(last - first);
  std::iota(order.begin(), order.end(), first);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return work[a] > work[b]; });
}

/// Runs process(i, buffer) for every i in [0, work.size()), in waves of consecutive indices
/// holding about `wave_work` of work each (work[i] for index i; at least one index a wave),
/// in parallel within a wave if asked, the largest work first, taken in turn by the threads
/// (and the ranks) as they come free, so that those that take a wave's last indices wait
/// little for each other; each index has a cleared Buffer of its own. After each wave, on the
/// calling thread: commit(i, buffer) for each index of the wave in order,
/// then progress(fraction of the work done), which cancels (throws Operation_cancelled) by
/// returning false. The waves depend neither on the number of threads nor on the ranks.
/// With `ranks` (distribution.h), this rank processes the indices of each wave it takes from
/// the ranks' counter and receives the other ranks' buffers before the commits; a
/// cancellation ends every rank at the next exchange (one more exchange follows the last
/// wave).
template <class Buffer, class Process, class Commit>
void run_in_waves(const std::vector<std::size_t>& work, std::size_t wave_work, bool parallel, const Process& process,
                  const Commit& commit, const std::function<bool(double)>& progress, Wave_ranks* ranks = nullptr)
{
  std::size_t total = 0, done = 0;
  for (std::size_t w : work) total += w;
  std::vector<Buffer> buffers;
  std::vector<std::size_t> mine, order; // mine: the indices this rank processed (with ranks)
  const std::size_t batch = parallel ? number_of_threads() : 1;
  // With ranks, whatever fails (or cancels) on this rank travels with the next exchange.
  std::exception_ptr failure;
  bool cancelled = false;
  for (std::size_t first = 0; first < work.size();) {
    const std::size_t last = wave_end(work, first, wave_work);
    if (buffers.size() < last - first) buffers.resize(last - first);
    for (std::size_t k = 0; k < last - first; ++k) buffers[k].clear();
    const auto start = std::chrono::steady_clock::now();
    wave_order(work, first, last, order);
    mine.clear();
    try {
      if (!ranks) {
        for_each_in_turn(order.size(), parallel, [&](std::size_t k) { process(order[k], buffers[order[k] - first]); });
      } else if (!failure && !cancelled) {
        // Taken from the ranks' counter as many at a time as there are threads.
        for (std::vector<std::size_t> taken; !(taken = ranks->take(work, first, order, batch)).empty();) {
          mine.insert(mine.end(), taken.begin(), taken.end());
          for_each_index(taken.size(), parallel, [&](std::size_t k) { process(taken[k], buffers[taken[k] - first]); });
        }
      }
    } catch (...) {
      if (!ranks) throw;
      failure = std::current_exception();
    }
    if (ranks) {
      ranks->add_deciding_seconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      ranks->exchange(buffers, first, last, mine, failure, cancelled);
    }
    try {
      for (std::size_t i = first; i < last; ++i) {
        commit(i, buffers[i - first]);
        done += work[i];
      }
      if (progress && !progress(total == 0 ? 1. : double(done) / double(total))) {
        if (!ranks) throw Operation_cancelled();
        cancelled = true;
      }
    } catch (...) {
      if (!ranks) throw;
      failure = std::current_exception();
    }
    first = last;
  }
  if (ranks) {
    ranks->close(); // every rank is here: a failure of one was carried, not thrown
    ranks->exchange(buffers, 0, 0, {}, failure, cancelled);
  }
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PARALLEL_H
