// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers of the pmsum command-line tool: checked mesh reading, output files that appear
// only when complete, a JSON writer, a progress bar.

#ifndef CGAL_PMSUM_CLI_COMMON_H
#define CGAL_PMSUM_CLI_COMMON_H

#include "cli_errors.h"
#include "cli_input.h"
#include "cli_output.h"

#include <CGAL_pmsum/version.h>
#include <CGAL_pmsum/point_minkowski_sum.h>
#include <CGAL_pmsum/point_minkowski_sum_coarse_to_fine.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>
#include <stdexcept>
#include <string>
#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace CGAL {
namespace Pmsum {
struct Mesh_statistics; // point_minkowski_sum_mesh.h, compiled in mesh.cpp only
}
} // namespace CGAL

namespace pmsum_cli {

/// Diagonal of the box a + b (the bounding box of a Minkowski sum); b empty: a's diagonal.
inline double sum_diagonal(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b = CGAL::Bbox_3(0, 0, 0, 0, 0, 0))
{
  double s = 0;
  for (int c = 0; c < 3; ++c) s += std::pow((a.max(c) - a.min(c)) + (b.max(c) - b.min(c)), 2);
  return std::sqrt(s);
}

/// Multiplies every coordinate by s.
inline void scale_mesh(Mesh& m, double s)
{
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    m.point(v) = K::Point_3(p.x() * s, p.y() * s, p.z() * s);
  }
}

/// A point with a normal, as written to PLY / XYZ.
struct Oriented_point { double p[3], n[3]; };

/// Writes points to `out` (.ply binary little-endian, or .xyz ASCII), which appears only
/// when complete.
inline void write_points(Output_file& out, const std::vector<Oriented_point>& pts)
{
  const std::string ext = extension(out.path());
  out.write([&](std::ostream& os) {
    if (ext == "ply") {
      os << "ply\nformat binary_little_endian 1.0\ncomment CGAL_pmsum boundary points of a Minkowski sum\n"
         << "element vertex " << pts.size() << "\n"
         << "property double x\nproperty double y\nproperty double z\n"
         << "property double nx\nproperty double ny\nproperty double nz\nend_header\n";
      static_assert(sizeof(Oriented_point) == 6 * sizeof(double), "packed doubles");
      const std::uint16_t probe = 1;
      if (*reinterpret_cast<const unsigned char*>(&probe) != 1) throw Error("big-endian hosts are not supported");
      os.write(reinterpret_cast<const char*>(pts.data()), std::streamsize(pts.size() * sizeof(Oriented_point)));
    } else {
      // The text of a stream at precision 17 (printf's %.17g), formatted by std::to_chars
      // four times faster, a block of lines at a time.
      std::string block;
      auto number = [&](double x) {
        char text[32];
        block.append(text, std::to_chars(text, text + sizeof(text), x, std::chars_format::general, 17).ptr);
      };
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const Oriented_point& o = pts[i];
        for (double x : {o.p[0], o.p[1], o.p[2], o.n[0], o.n[1], o.n[2]}) {
          number(x);
          block += ' ';
        }
        block.back() = '\n';
        if (block.size() > (1 << 20) || i + 1 == pts.size()) {
          os.write(block.data(), std::streamsize(block.size()));
          block.clear();
        }
      }
    }
  }, std::ios::binary);
}

/// Minimal JSON object writer (keys in insertion order).
class Json
{
public:
  Json& add(const std::string& key, const std::string& raw)
  {
    m_items.push_back("\"" + key + "\": " + raw);
    return *this;
  }
  Json& str(const std::string& key, const std::string& v) { return add(key, quote(v)); }
  Json& num(const std::string& key, double v)
  {
    if (!std::isfinite(v)) return add(key, "null"); // JSON has no infinity
    std::ostringstream s;
    s << std::setprecision(10) << v;
    return add(key, s.str());
  }
  Json& integer(const std::string& key, std::size_t v) { return add(key, std::to_string(v)); }
  Json& boolean(const std::string& key, bool v) { return add(key, v ? "true" : "false"); }
  Json& object(const std::string& key, const Json& o) { return add(key, o.dump(1)); }
  Json& append(const Json& o)
  {
    m_items.insert(m_items.end(), o.m_items.begin(), o.m_items.end());
    return *this;
  }
  std::string dump(int indent = 0) const
  {
    const std::string pad(2 * (indent + 1), ' '), end(2 * indent, ' ');
    std::string s = "{\n";
    for (std::size_t i = 0; i < m_items.size(); ++i) s += pad + m_items[i] + (i + 1 < m_items.size() ? ",\n" : "\n");
    return s + end + "}";
  }
  static std::string quote(const std::string& v)
  {
    std::string s = "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') s += '\\';
      s += c;
    }
    return s + "\"";
  }

private:
  std::vector<std::string> m_items;
};

/// Writes a summary: it starts with the version of the tool that wrote it (once, not in
/// its nested objects).
inline void write_json(Output_file& out, const Json& j)
{
  Json top;
  top.str("pmsum_version", CGAL_PMSUM_VERSION).append(j);
  out.write([&](std::ostream& os) { os << top.dump() << "\n"; });
}

/// Progress bar on stderr, shown only on a terminal and once a run has lasted a second.
class Progress
{
public:
  explicit Progress(bool enabled) : m_enabled(enabled && ::isatty(2)), m_start(std::chrono::steady_clock::now()) {}
  bool operator()(double fraction)
  {
    if (!m_enabled) return true;
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    if (t < 1.0) return true;
    const int width = 40, filled = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%  %.1f s", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), int(fraction * 100 + 0.5), t);
    m_drawn = true;
    return true;
  }
  ~Progress() { if (m_drawn) std::fprintf(stderr, "\n"); }

private:
  bool m_enabled, m_drawn = false;
  std::chrono::steady_clock::time_point m_start;
};

/// Parsed options of a command: positional arguments, flags and valued options.
struct Arguments
{
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;
  std::map<std::string, bool> flags;

  Arguments(int argc, char** argv, int first, const std::vector<std::string>& valued,
            const std::vector<std::string>& flag_names)
  {
    for (int i = first; i < argc; ++i) {
      const std::string a = argv[i];
      if (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1])) && a[1] != '.') {
        if (std::find(valued.begin(), valued.end(), a) != valued.end()) {
          if (i + 1 >= argc) throw Usage_error("option " + a + " needs a value");
          values[a] = argv[++i];
        } else if (std::find(flag_names.begin(), flag_names.end(), a) != flag_names.end()) {
          flags[a] = true;
        } else {
          throw Usage_error("unknown option " + a);
        }
      } else {
        positional.push_back(a);
      }
    }
  }
  bool flag(const std::string& f) const { return flags.count(f) != 0; }
  bool has(const std::string& v) const { return values.count(v) != 0; }
  double number(const std::string& v) const
  {
    const std::string& s = values.at(v);
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') throw Usage_error("option " + v + " needs a number, got '" + s + "'");
    return x;
  }
};

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// Memory the process may use for output points, from /proc/meminfo (half of MemAvailable).
inline std::size_t memory_budget_bytes()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::size_t kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024 / 2;
  return std::size_t(4) << 30;
}

/// Options of every command that reads two meshes (sum, validate, pd).
const std::string input_options_help =
  "  P, Q                   triangle meshes (.off, .obj, .ply, .stl); other polygons are\n"
  "                         triangulated, closed meshes oriented outward (with a note)\n"
  "  -d D                   covering distance (> 0)\n"
  "  --relative             D is a fraction of the diagonal of the bounding box of P + Q\n"
  "  --scale-q S            multiply Q's coordinates by S first (e.g. to size a tool)\n"
  "  --quiet                no notes and no progress bar\n";
const std::vector<std::string> input_valued = {"-d", "--scale-q"};
const std::vector<std::string> input_flags = {"--relative", "--quiet", "--help", "-h"};

/// Options shared by the commands that compute a sum (sum, validate).
const std::string sum_options_help = input_options_help +
  "  --negate-p             boundary of -P + Q (contact space of robot P among obstacles Q)\n"
  "  --no-normal-filter     test every sample pair with the CD filter (slow)\n"
  "  --no-cd-filter         keep every candidate of the normal filter (not all on the boundary)\n"
  "  --no-octree-filter     CD-test candidates in cells certified interior too (same output, slower)\n"
  "  --all-candidates       every boundary candidate (the paper's output), not the default\n"
  "                         (d/2, d)-net: many times more points, and slower\n"
  "  --no-trim-points       no points on the trim curves of the convolution facets: faster,\n"
  "                         but passages narrower than the sample spacing may be uncovered\n"
  "  --no-islands           do not search visible pieces inside one lattice cell (e.g. voids\n"
  "                         smaller than the sample spacing): faster, but those may be uncovered\n"
  "  --no-merge-flat-regions\n"
  "                         sample the meshes as they are; by default flat faces cut into many\n"
  "                         triangles are triangulated again first, without the vertices inside\n"
  "                         them and inside straight creases (exact; the same solids), so that a\n"
  "                         tessellated CAD part costs what its faces cost\n"
  "  --levels D1,D2,...     coarse to fine: first the larger covering distances D1 > D2 > ... > D\n"
  "                         (same unit as -d), each reusing the coarser work; sum writes level\n"
  "                         K to OUT with .levelK before the extension (validate: the last)\n"
  "  --threads N            worker threads (default: all cores; 1 = sequential)\n"
  "  --force                run even if the estimated output exceeds the available memory\n";
const std::vector<std::string> sum_valued = {"-d", "--scale-q", "--threads", "--levels"};
const std::vector<std::string> sum_flags = {"--relative", "--negate-p", "--no-normal-filter", "--no-cd-filter", "--no-octree-filter", "--all-candidates",
                                            "--no-trim-points", "--no-islands", "--no-merge-flat-regions", "--force", "--quiet", "--help", "-h"};

using Record = CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, K>;

/// The -o path of a command that writes points (it must be there): a .ply or .xyz file.
inline std::string points_output_path(const Arguments& args)
{
  const std::string path = args.values.at("-o");
  if (extension(path) != "ply" && extension(path) != "xyz") throw Usage_error("-o must name a .ply or .xyz file");
  return path;
}

/// Throws Usage_error unless `path` ends in .off, .obj, .ply or .stl (mesh.cpp).
void check_mesh_path(const std::string& path);

/// The -o path of a command that writes a mesh (it must be there): .off, .obj, .ply or .stl.
inline std::string mesh_output_path(const Arguments& args)
{
  const std::string path = args.values.at("-o");
  check_mesh_path(path);
  return path;
}

/// The inputs of a sum, read and checked.
struct Sum_input
{
  std::string p_path, q_path;
  Mesh P, Q;
  double d = 0, d_argument = 0, diagonal = 0, read_seconds = 0;
  bool relative = false, negate = false, normal_filter = true, cd_filter = true, octree_filter = true, covering_net = true, trim_points = true, islands = true, merge_flat = true, force = false, quiet = false;
  int threads = 0; // 0: all cores
  // Called with the progress too (the Python module: Ctrl-C and its progress callback);
  // false cancels (CGAL::Pmsum::Operation_cancelled). The tool leaves it empty.
  std::function<bool(double)> callback;
  std::vector<double> coarser_d; // --levels: coarser covering distances, coarse to fine (absolute)
};

inline Sum_input read_sum_input(const Arguments& args)
{
  if (args.positional.size() != 2) throw Usage_error("two meshes P and Q are needed");
  if (!args.has("-d")) throw Usage_error("-d D is needed");
  Sum_input in;
  in.d_argument = args.number("-d");
  if (!(in.d_argument > 0) || !std::isfinite(in.d_argument))
    throw Usage_error("-d must be a positive number, got " + args.values.at("-d"));
  in.quiet = args.flag("--quiet") || !is_main_rank(); // rank 0 alone shows progress and messages
  in.relative = args.flag("--relative");
  in.negate = args.flag("--negate-p");
  in.normal_filter = !args.flag("--no-normal-filter");
  in.cd_filter = !args.flag("--no-cd-filter");
  in.octree_filter = !args.flag("--no-octree-filter");
  in.covering_net = !args.flag("--all-candidates");
  in.trim_points = !args.flag("--no-trim-points");
  in.islands = !args.flag("--no-islands");
  in.merge_flat = !args.flag("--no-merge-flat-regions");
  in.force = args.flag("--force");
  if (args.has("--threads")) {
    const double t = args.number("--threads");
    if (!(t >= 1) || t != std::floor(t) || t > 1024) throw Usage_error("--threads must be a positive integer");
    in.threads = int(t);
  }
  in.p_path = args.positional[0];
  in.q_path = args.positional[1];
  const auto start = std::chrono::steady_clock::now();
  in.P = read_mesh(in.p_path, "P", in.quiet);
  in.Q = read_mesh(in.q_path, "Q", in.quiet);
  if (args.has("--scale-q")) {
    const double s = args.number("--scale-q");
    if (!(s > 0) || !std::isfinite(s)) throw Usage_error("--scale-q must be a positive number");
    scale_mesh(in.Q, s);
  }
  in.diagonal = sum_diagonal(PMP::bbox(in.P), PMP::bbox(in.Q));
  in.d = in.relative ? in.d_argument * in.diagonal : in.d_argument;
  if (args.has("--levels")) {
    std::stringstream list(args.values.at("--levels"));
    std::string item;
    double previous = std::numeric_limits<double>::infinity();
    while (std::getline(list, item, ',')) {
      char* end = nullptr;
      const double x = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0' || !(x > in.d_argument) || !(x < previous) || !std::isfinite(x))
        throw Usage_error("--levels needs decreasing distances larger than -d, separated by commas, got '" +
                          args.values.at("--levels") + "'");
      previous = x;
      in.coarser_d.push_back(in.relative ? x * in.diagonal : x);
    }
    if (in.coarser_d.empty()) throw Usage_error("--levels needs at least one distance larger than -d");
  }
  in.read_seconds = seconds_since(start);
  return in;
}

/// Calls f(CGAL::Parallel_tag()) on `threads` threads (0: all cores), or
/// f(CGAL::Sequential_tag()) for one thread or without TBB.
template <class F>
void with_threads(int threads, F&& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if (threads != 1) {
    std::optional<tbb::global_control> limit;
    if (threads > 1) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    f(CGAL::Parallel_tag());
    return;
  }
#endif
  f(CGAL::Sequential_tag());
}

/// The named parameters of a run from the command line: the filters, the negation, the
/// statistics, the candidate limit (the memory budget, unless --force) and `callback`.
/// (--all-candidates is the caller's: the mesh takes no use_covering_net.)
inline auto sum_parameters(const Sum_input& in, CGAL::Pmsum::Statistics& stats,
                           const std::function<bool(double)>& callback)
{
  // Each output point is held in memory before the file is written, by every rank of this
  // machine under mpirun; the ranks agree on the smallest limit.
  const std::size_t limit =
    in.force ? std::size_t(-1) : smallest_over_ranks(memory_budget_bytes() / sizeof(Record) / ranks_on_this_machine());
  return CGAL::parameters::use_normal_filter(in.normal_filter)
    .use_cd_filter(in.cd_filter)
    .use_octree_filter(in.octree_filter)
    .use_trim_points(in.trim_points)
    .search_islands(in.islands)
    .merge_flat_regions(in.merge_flat)
    .negate_first_mesh(in.negate)
    .statistics(stats)
    .maximum_number_of_candidates(limit)
    .callback(callback)
    .communicator(world_communicator());
}

/// The progress callback of a run: the bar (unless --quiet) and Sum_input::callback.
inline std::function<bool(double)> progress_callback(const Sum_input& in, Progress& progress)
{
  return [&in, &progress](double f) { return (!in.callback || in.callback(f)) && progress(f); };
}

/// Calls run(tag) with the threads of --threads; a run refused for its size (too many
/// candidates for the memory) becomes Refused (exit code 3).
template <class Run>
void run_refusing_too_large(const Sum_input& in, Run&& run)
{
  try {
    with_threads(in.threads, run);
  } catch (const CGAL::Pmsum::Too_many_feature_pairs& e) {
    throw Refused(std::string("refused: ") + e.what() + ": more than the memory available allows; use the normal "
                  "filter, or --force");
  } catch (const CGAL::Pmsum::Too_many_candidates& e) {
    std::ostringstream msg;
    msg << "refused: d = " << in.d << " leaves " << e.candidates << " candidate points (up to "
        << std::setprecision(3) << double(e.candidates) * sizeof(Record) / double(1 << 30)
        << " GiB of output), more than the memory available allows; use a larger -d, or --force";
    throw Refused(msg.str());
  }
}

/// Runs point_minkowski_sum with a progress bar; refuses (exit code 3) a run whose output
/// would not fit in memory, unless --force.
/// With --levels, `coarser_level(k, stats, records)` receives each coarser level first.
inline std::vector<Record> compute_sum(
  const Sum_input& in, CGAL::Pmsum::Statistics& stats,
  const std::function<void(std::size_t, const CGAL::Pmsum::Statistics&, std::vector<Record>&&)>& coarser_level = {})
{
  std::vector<Record> records;
  Progress progress(!in.quiet);
  const auto np = sum_parameters(in, stats, progress_callback(in, progress)).use_covering_net(in.covering_net);
  run_refusing_too_large(in, [&](auto tag) {
    if (in.coarser_d.empty()) {
      CGAL::point_minkowski_sum<decltype(tag)>(in.P, in.Q, in.d, std::back_inserter(records), np);
      return;
    }
    std::vector<double> ds = in.coarser_d;
    ds.push_back(in.d);
    CGAL::point_minkowski_sum_coarse_to_fine<decltype(tag)>(
      in.P, in.Q, ds,
      [&](std::size_t k, const CGAL::Pmsum::Statistics& s, std::vector<Record>&& level) {
        if (k + 1 < ds.size()) {
          if (coarser_level) coarser_level(k, s, std::move(level));
        } else {
          records = std::move(level);
        }
      },
      np);
  });
  return records;
}

/// A closed mesh of the boundary (CGAL::point_minkowski_sum_mesh(), mesh.cpp), with a
/// progress bar; refused as compute_sum() is. Throws Mesh_reconstruction_failed.
Mesh compute_mesh(const Sum_input& in, CGAL::Pmsum::Mesh_statistics& ms);
/// A mesh written by a command that can write points or a mesh (offset, sweep: mesh.cpp):
/// the JSON object of its checks and sizes, the note for stderr ("a mesh of V vertices and T
/// triangles (S shells, ...)"), and the counters of the sum it was made from.
struct Written_mesh
{
  Json summary;
  std::string note;
  CGAL::Pmsum::Statistics sum;
};
/// Writes to `file` a closed mesh of the boundary of in.P + in.Q (compute_mesh()).
Written_mesh write_sum_mesh(const Sum_input& in, Output_file& file);
/// Writes to `file` a closed mesh of the volume swept by P along `path` (CGAL::point_sweep_mesh()).
Written_mesh write_sweep_mesh(const Mesh& P, const std::vector<K::Point_3>& path, double d, int threads,
                              Output_file& file);
/// The JSON fields of a mesh's sizes and checks (mesh.cpp): "made" and "error" first; if
/// `error` is not empty (no mesh was made), only those (mesh_failure_summary()).
Json mesh_summary(const CGAL::Pmsum::Mesh_statistics& ms, const std::string& error = "");
/// The JSON fields of a mesh that could not be made: "made" false and the error (mesh.cpp).
Json mesh_failure_summary(const std::string& error);
/// Writes `mesh` in the format of its extension (mesh.cpp).
void write_mesh(Output_file& file, const Mesh& mesh);
/// `make()` (a mesh maker: compute_mesh(), write_sum_mesh(), write_sweep_mesh()); if it makes
/// no valid mesh, `failed(error)` first (so that a summary can still be written), then the error
/// goes on (exit code 6).
template <class Make, class Failed>
decltype(auto) on_mesh_failure(Make&& make, Failed&& failed)
{
  try {
    return make();
  } catch (const CGAL::Pmsum::Mesh_reconstruction_failed& e) {
    failed(std::string(e.what()));
    throw;
  }
}

inline std::vector<Oriented_point> oriented_points(const std::vector<Record>& records)
{
  std::vector<Oriented_point> out;
  out.reserve(records.size());
  for (const Record& r : records)
    out.push_back({{r.point.x(), r.point.y(), r.point.z()}, {r.normal.x(), r.normal.y(), r.normal.z()}});
  return out;
}

/// The JSON fields describing a sum's input and statistics.
inline Json sum_summary(const Sum_input& in, const CGAL::Pmsum::Statistics& stats)
{
  Json jp, jq, filters;
  jp.str("file", in.p_path).integer("vertices", in.P.number_of_vertices())
    .integer("faces", in.P.number_of_faces()).integer("samples", stats.samples_p);
  jq.str("file", in.q_path).integer("vertices", in.Q.number_of_vertices())
    .integer("faces", in.Q.number_of_faces()).integer("samples", stats.samples_q);
  filters.boolean("normal", in.normal_filter).boolean("cd", in.cd_filter).boolean("octree", in.octree_filter)
    .boolean("covering_net", in.covering_net).boolean("trim_points", in.trim_points).boolean("islands", in.islands)
    .boolean("merge_flat_regions", in.merge_flat);
  Json j;
  const unsigned cores = std::thread::hardware_concurrency();
  j.object("p", jp).object("q", jq).integer("threads", in.threads ? std::size_t(in.threads) : std::size_t(cores ? cores : 1))
    .num("d", in.d).num("d_argument", in.d_argument).boolean("relative", in.relative)
    .num("sum_bbox_diagonal", in.diagonal).boolean("negate_p", in.negate).object("filters", filters)
    .integer("feature_pairs", stats.feature_pairs).integer("candidates", stats.candidates)
    .integer("octree_leaves", stats.octree_leaves).integer("octree_certified_leaves", stats.octree_certified_leaves)
    .integer("candidates_certified", stats.candidates_certified).integer("candidates_reused", stats.candidates_reused)
    .integer("candidates_covered", stats.candidates_covered)
    .integer("candidates_in_patch_pairs", stats.candidates_in_patch_pairs)
    .integer("cd_queries", stats.cd_queries).integer("triangle_pairs", stats.triangle_pairs)
    .integer("containment_tests", stats.containment_tests).integer("corner_tests", stats.corner_tests)
    .integer("trim_queries", stats.trim_queries)
    .integer("trim_segments", stats.trim_segments).integer("island_cells", stats.island_cells).integer("trim_points", stats.trim_points)
    .integer("output_points", stats.output_points);
  if (!stats.ranks.empty()) {
    // mpirun: each rank's share of the decisions
    std::string list = "[";
    for (std::size_t r = 0; r < stats.ranks.size(); ++r) {
      const CGAL::Pmsum::Rank_statistics& s = stats.ranks[r];
      Json jr;
      jr.integer("rank", r).integer("pieces", s.pieces).integer("candidates", s.candidates).integer("island_cells", s.island_cells)
        .integer("cd_queries", s.cd_queries).num("seconds_deciding", s.seconds_deciding)
        .num("seconds_exchanging", s.seconds_exchanging);
      list += (r ? ", " : "") + jr.dump(2);
    }
    j.integer("processes", stats.ranks.size()).add("ranks", list + "]");
  }
  return j;
}

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_COMMON_H
