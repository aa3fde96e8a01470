// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output files of the pmsum command-line tool. Every output path of a command is checked
// before any work (not an input file, in an existing writable directory) by creating its
// temporary file there (.pmsum-XXXXXX, a short name whatever the length of the output's);
// the file is written there and renamed at the end, so that an output appears only when
// complete. A temporary file is removed if the command fails, and on SIGINT, SIGTERM or
// SIGHUP (the process then exits with 128 + the signal number).

#ifndef CGAL_PMSUM_CLI_OUTPUT_H
#define CGAL_PMSUM_CLI_OUTPUT_H

#include "cli_errors.h"
#include "cli_ranks.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace pmsum_cli {
namespace output_internal {

/// Temporary files to remove on a signal, in static storage (the handler may only call
/// async-signal-safe functions: unlink and _exit).
struct Slot
{
  char path[PATH_MAX];
  volatile std::sig_atomic_t used;
};
constexpr int number_of_slots = 64;
inline Slot slots[number_of_slots];

inline void remove_temporaries_and_exit(int sig)
{
  for (Slot& s : slots)
    if (s.used) ::unlink(s.path);
  ::_exit(128 + sig);
}

} // namespace output_internal

/// Installs the handler that removes the registered temporary files on SIGINT, SIGTERM and
/// SIGHUP (call once, first thing in main). A signal the process was started ignoring (nohup,
/// a background job's SIGINT) stays ignored.
inline void install_signal_cleanup()
{
  struct sigaction sa, old;
  std::memset(&sa, 0, sizeof(sa));
  sa.sa_handler = output_internal::remove_temporaries_and_exit;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler != SIG_IGN) sigaction(sig, &sa, nullptr);
}

/// One output file of a command (see the file comment). Create every output of a command
/// before its work starts; write() writes it and renames it into place. Destroyed without
/// write(), it removes its temporary file: nothing is left behind.
class Output_file
{
public:
  /// `what` names the option ("-o", "--json"); `inputs` are the command's input files.
  /// On a rank other than 0 (cli_ranks.h) it does nothing: rank 0 writes the outputs.
  Output_file(const std::string& path, const std::string& what, const std::vector<std::string>& inputs)
    : m_path(path), m_what(what)
  {
    if (!is_main_rank()) return;
    namespace fs = std::filesystem;
    std::error_code ec;
    if (path.empty()) throw Usage_error(what + " needs a file name");
    const fs::path p(path);
    for (const std::string& in : inputs)
      if (!in.empty() && fs::exists(p, ec) && fs::equivalent(p, fs::path(in), ec))
        throw Usage_error(what + " '" + path + "' is the input file '" + in + "'; refusing to overwrite it");
    if (fs::is_directory(p, ec)) throw Error("cannot write " + what + " '" + path + "': it is a directory");
    // The file is renamed into place: never over a device, a pipe or a socket (/dev/null...).
    if (fs::exists(p, ec) && !fs::is_regular_file(p, ec))
      throw Error("cannot write " + what + " '" + path + "': not a regular file");
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec))
      throw Error("cannot write " + what + " '" + path + "': no such directory '" + dir.string() + "'");
    std::string tmp = (dir / ".pmsum-XXXXXX").string();
    if (tmp.size() >= PATH_MAX) throw Error("cannot write " + what + " '" + path + "': path too long");
    // mkstemp fills in the name in a registered slot: a signal cannot leave the file behind.
    for (int i = 0; i < output_internal::number_of_slots && m_slot < 0; ++i)
      if (!output_internal::slots[i].used) m_slot = i;
    if (m_slot < 0) throw Error("cannot write " + what + " '" + path + "': too many output files");
    char* name = output_internal::slots[m_slot].path;
    std::memcpy(name, tmp.c_str(), tmp.size() + 1);
    output_internal::slots[m_slot].used = 1;
    const int fd = ::mkstemp(name);
    if (fd < 0) {
      const int e = errno;
      release();
      throw Error("cannot write " + what + " '" + path + "': " + std::strerror(e));
    }
    m_temporary = name;
    // mkstemp creates the file with mode 0600: give it the mode a new file would have.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
  }
  Output_file(const Output_file&) = delete;
  Output_file& operator=(const Output_file&) = delete;
  ~Output_file() { discard(); }

  const std::string& path() const { return m_path; }
  const std::string& what() const { return m_what; }

  /// Calls write(stream) on the temporary file, then renames it to the output path.
  template <class Write>
  void write(Write&& write, std::ios::openmode mode = std::ios::out)
  {
    if (!is_main_rank()) return;
    if (m_temporary.empty()) throw Error("cannot write '" + m_path + "' twice");
    {
      std::ofstream out(m_temporary, mode | std::ios::trunc);
      if (!out) throw Error("cannot write '" + m_path + "'");
      write(out);
      out.flush();
      if (!out) throw Error("cannot write '" + m_path + "' (disk full?)");
    }
    if (std::rename(m_temporary.c_str(), m_path.c_str()) != 0)
      throw Error("cannot write '" + m_path + "': " + std::strerror(errno));
    release();
  }

  /// Removes the temporary file (the output is not written).
  void discard()
  {
    if (m_temporary.empty()) return;
    ::unlink(m_temporary.c_str());
    release();
  }

private:
  void release()
  {
    if (m_slot >= 0) output_internal::slots[m_slot].used = 0;
    m_slot = -1;
    m_temporary.clear();
  }

  std::string m_path, m_what, m_temporary;
  int m_slot = -1;
};

/// The output files of a command, created (hence checked) before its work.
class Output_files
{
public:
  /// `outputs`: (option, path) pairs, e.g. {"-o", "out.ply"}; no two may be the same file.
  Output_files(const std::vector<std::pair<std::string, std::string>>& outputs, const std::vector<std::string>& inputs)
  {
    namespace fs = std::filesystem;
    for (const auto& [what, path] : outputs) {
      std::error_code e1, e2;
      for (const auto& f : m_files)
        if (fs::weakly_canonical(f->path(), e1) == fs::weakly_canonical(path, e2) && !e1 && !e2)
          throw Usage_error(what + " and " + f->what() + " name the same file '" + path + "'");
      m_files.push_back(std::make_unique<Output_file>(path, what, inputs));
    }
  }
  /// The output of option `what` (which must be one of them).
  Output_file& operator[](const std::string& what)
  {
    for (auto& f : m_files)
      if (f->what() == what) return *f;
    throw std::logic_error("no output " + what);
  }

private:
  std::vector<std::unique_ptr<Output_file>> m_files;
};

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_OUTPUT_H
