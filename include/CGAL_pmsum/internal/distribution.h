// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stages 2 and 3 across processes (named parameter `communicator`). The normal filter's and
// the octree filter's tests are shared out by chunks, every rank a fixed share of them, and
// their results exchanged (map_chunks, parallel.h). The decisions run in waves of
// pieces of feature pairs (parallel.h, candidates.h), and the waves do not depend on the
// number of processes: the ranks take a wave's pieces one by one from a counter they share
// (Communicator::make_counter), so that a rank whose pieces were quick takes more (the work
// of a piece, its trim search above all, is not known in advance), the ranks exchange their
// decisions, and every rank commits the whole wave in canonical order.
// Every rank thus holds the same net and output as one process, point for point, and the
// counters summed over the ranks are one process's.
//
// A failure or a cancellation on one rank during the decisions (deciding, committing, the
// output, the progress callback) travels with the next exchange, so that every rank ends with
// it instead of waiting: the failing rank rethrows its own exception, the others throw
// Rank_failed (agree() does the same for any step). Every rank must be given the same input
// and parameters; a fingerprint of the candidates is compared before the decisions
// (check_same_work), so that different inputs fail on every rank instead of hanging.
// Messages are plain bytes (Byte_writer, Byte_reader), in the layout of the machine: the
// ranks must run the same build on the same architecture.

#ifndef CGAL_PMSUM_INTERNAL_DISTRIBUTION_H
#define CGAL_PMSUM_INTERNAL_DISTRIBUTION_H

#include <CGAL_pmsum/Communicator.h>
#include <CGAL_pmsum/exceptions.h>

#include <CGAL/Exact_rational.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Appends values to a message.
class Byte_writer
{
public:
  template <class T>
  void pod(const T& v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "Byte_writer::pod: a trivially copyable type");
    m_bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void text(const std::string& s)
  {
    pod(std::uint64_t(s.size()));
    m_bytes += s;
  }
  /// A vector of trivially copyable values, with its size.
  template <class T>
  void pods(const std::vector<T>& v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "Byte_writer::pods: trivially copyable values");
    pod(std::uint64_t(v.size()));
    if (!v.empty()) m_bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void rational(const CGAL::Exact_rational& q)
  {
    std::ostringstream os;
    os << q;
    text(os.str());
  }
  /// transfer() (decision.h) writes with these, and reads with Byte_reader's.
  template <class T>
  void io(const T& v) { pod(v); }
  void io(const CGAL::Exact_rational& q) { rational(q); }
  template <class Vector>
  void size_of(const Vector& v) { pod(std::uint64_t(v.size())); }
  std::string& bytes() { return m_bytes; }

private:
  std::string m_bytes;
};

/// Reads values back from a message, in the order they were written.
class Byte_reader
{
public:
  explicit Byte_reader(const std::string& bytes) : m_bytes(bytes) {}
  template <class T>
  T pod()
  {
    static_assert(std::is_trivially_copyable<T>::value, "Byte_reader::pod: a trivially copyable type");
    T v;
    take(&v, sizeof(T));
    return v;
  }
  std::string text()
  {
    const std::uint64_t n = pod<std::uint64_t>();
    if (n > m_bytes.size() - m_at) throw std::length_error("Byte_reader: truncated message");
    std::string s = m_bytes.substr(m_at, std::size_t(n));
    m_at += std::size_t(n);
    return s;
  }
  /// A vector written by Byte_writer::pods.
  template <class T>
  void pods(std::vector<T>& v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "Byte_reader::pods: trivially copyable values");
    const std::uint64_t n = pod<std::uint64_t>();
    if (n > (m_bytes.size() - m_at) / sizeof(T)) throw std::length_error("Byte_reader: truncated message");
    v.resize(std::size_t(n));
    take(v.data(), std::size_t(n) * sizeof(T));
  }
  CGAL::Exact_rational rational()
  {
    std::istringstream is(text());
    CGAL::Exact_rational q;
    is >> q;
    return q;
  }
  template <class T>
  void io(T& v) { v = pod<T>(); }
  void io(CGAL::Exact_rational& q) { q = rational(); }
  template <class Vector>
  void size_of(Vector& v) { v.resize(std::size_t(pod<std::uint64_t>())); }
  bool done() const { return m_at == m_bytes.size(); }

private:
  void take(void* to, std::size_t n)
  {
    if (n > m_bytes.size() - m_at) throw std::length_error("Byte_reader: truncated message");
    if (n == 0) return; // `to` may be null (an empty vector's data)
    std::memcpy(to, m_bytes.data() + m_at, n);
    m_at += n;
  }
  const std::string& m_bytes;
  std::size_t m_at = 0;
};

/// The message of an exception.
inline std::string message_of(std::exception_ptr e)
{
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "unknown error";
  }
}

/// The head of every rank's message in a collective step: failed (with the message),
/// cancelled, or fine.
inline void write_status(Byte_writer& w, std::exception_ptr failure, bool cancelled)
{
  w.pod(std::uint8_t(failure ? 2 : cancelled ? 1 : 0));
  if (failure) w.text(message_of(failure));
}

/// Reads every rank's status (readers in rank order) and throws, on every rank alike, if one
/// failed or was cancelled: a failing rank its own exception (`failure`), the others
/// Rank_failed with the first failing rank's message; else Operation_cancelled.
inline void check_statuses(std::vector<Byte_reader>& readers, std::exception_ptr failure)
{
  std::optional<Rank_failed> first_failure;
  bool any_cancelled = false;
  for (int r = 0; r < int(readers.size()); ++r) {
    const auto status = readers[std::size_t(r)].pod<std::uint8_t>();
    if (status == 2 && !first_failure) first_failure.emplace(r, readers[std::size_t(r)].text());
    any_cancelled = any_cancelled || status == 1;
  }
  if (failure) std::rethrow_exception(failure);
  if (first_failure) throw *first_failure;
  if (any_cancelled) throw Operation_cancelled();
}

/// Collective: does the step that gave `failure` (null: it succeeded) fail on any rank? If so,
/// every rank throws (check_statuses).
inline void agree(Communicator& comm, std::exception_ptr failure)
{
  Byte_writer w;
  write_status(w, failure, false);
  const std::vector<std::string> all = comm.all_gather(w.bytes());
  std::vector<Byte_reader> readers(all.begin(), all.end());
  check_statuses(readers, failure);
}

/// FNV-1a (64 bits) of bytes: the fingerprints that the ranks compare (check_same_work).
class Fnv1a
{
public:
  /// Adds the bytes of the values of a contiguous container (trivially copyable values).
  template <class Values>
  void add(const Values& values)
  {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (std::size_t i = 0; i < values.size() * sizeof(values[0]); ++i) m_h = (m_h ^ bytes[i]) * 0x100000001b3ull;
  }
  std::uint64_t value() const { return m_h; }

private:
  std::uint64_t m_h = 0xcbf29ce484222325ull;
};

/// What every rank throws when the ranks find that they were given different work.
inline Invalid_input different_inputs()
{
  return Invalid_input("the ranks were given different inputs or parameters: every rank must be given the same "
                       "meshes, d and parameters");
}

/// Collective: throws Invalid_input on every rank unless every rank passes the same
/// `fingerprint` (of its input and parameters: the ranks would otherwise take different steps).
inline void check_same_work(Communicator& comm, const std::string& fingerprint)
{
  for (const std::string& f : comm.all_gather(fingerprint))
    if (f != fingerprint) throw different_inputs();
}

/// One rank's share of the decisions, as gathered into Statistics::ranks.
struct Rank_load
{
  std::size_t pieces = 0, candidates = 0, island_cells = 0;
  double seconds_deciding = 0, seconds_exchanging = 0;
};

/// This rank's part in run_in_waves (parallel.h): which indices of a wave it processes, and
/// the exchange after them. Buffer needs write_bytes(Byte_writer&, const Buffer&) and
/// read_bytes(Byte_reader&, Buffer&).
class Wave_ranks
{
public:
  /// Collective (the shared counter's making).
  explicit Wave_ranks(Communicator& comm) : m_comm(comm), m_counter(comm.make_counter()) {}
  /// Collective: no index is taken any more (Communicator::Counter::close).
  void close() { m_counter->close(); }
  /// Collective, after close(): a new counter, for the islands' waves (pipeline.h): the
  /// work of the indices taken then counts as island cells, not as pieces and candidates.
  void start_islands()
  {
    m_counter = m_comm.make_counter();
    m_next.reset();
    m_islands = true;
  }
  const Rank_load& load() const { return m_load; }
  void add_deciding_seconds(double s) { m_load.seconds_deciding += s; }

  /// Up to n more indices for this rank of the wave that starts at `first`, from the shared
  /// counter, in the wave's `order` (its indices, in the order they are handed out); none
  /// when the wave has no more. The counter hands out 0, 1, 2, ... in turn (k: the wave's
  /// order[k - first]), and a rank stops at the first number beyond the wave, which it keeps
  /// for the next wave: every index is taken by one rank, in its wave.
  std::vector<std::size_t> take(const std::vector<std::size_t>& work, std::size_t first,
                                const std::vector<std::size_t>& order, std::size_t n)
  {
    std::vector<std::size_t> taken;
    while (taken.size() < n) {
      if (!m_next) m_next = std::size_t(m_counter->fetch_add(1));
      if (*m_next >= first + order.size()) break;
      const std::size_t i = order[*m_next - first];
      taken.push_back(i);
      if (m_islands) {
        m_load.island_cells += work[i];
      } else {
        ++m_load.pieces;
        m_load.candidates += work[i];
      }
      m_next.reset();
    }
    return taken;
  }

  /// Collective: sends the buffers of `mine` (indices of the wave [first, last)), receives
  /// the others' into `buffers` (index i in buffers[i - first]). Every rank then throws if a
  /// rank failed (`failure`) or was cancelled: see agree().
  template <class Buffer>
  void exchange(std::vector<Buffer>& buffers, std::size_t first, std::size_t last, const std::vector<std::size_t>& mine,
                std::exception_ptr failure, bool cancelled)
  {
    const auto start = std::chrono::steady_clock::now();
    Byte_writer w;
    write_status(w, failure, cancelled);
    if (!failure && !cancelled)
      for (std::size_t i : mine) {
        w.pod(std::uint64_t(i));
        write_bytes(w, buffers[i - first]);
      }
    const std::vector<std::string> all = m_comm.all_gather(w.bytes());
    m_load.seconds_exchanging += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<Byte_reader> readers(all.begin(), all.end());
    check_statuses(readers, failure);
    std::size_t received = mine.size();
    for (int r = 0; r < int(readers.size()); ++r) {
      if (r == m_comm.rank()) continue;
      Byte_reader& in = readers[std::size_t(r)];
      while (!in.done()) {
        const std::size_t i = std::size_t(in.pod<std::uint64_t>());
        if (i < first || i >= last) throw std::length_error("Wave_ranks: an index outside the wave");
        read_bytes(in, buffers[i - first]);
        ++received;
      }
    }
    if (received != last - first) throw std::length_error("Wave_ranks: a wave's decisions are missing");
  }

  /// Collective: every rank's `bytes`, in rank order.
  std::vector<std::string> gather(const std::string& bytes) { return m_comm.all_gather(bytes); }

private:
  Communicator& m_comm;
  std::unique_ptr<Communicator::Counter> m_counter;
  std::optional<std::size_t> m_next; // taken, beyond the last wave's end
  bool m_islands = false;            // start_islands() called
  Rank_load m_load;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_DISTRIBUTION_H
