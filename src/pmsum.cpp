// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// pmsum: command-line tool of CGAL_pmsum.
//
//   pmsum sum P Q -d D -o OUT [options]     points on the boundary of P + Q
//
// Exit codes: 0 success, 1 error (bad input, I/O), 2 command-line mistake, 3 refused
// (the run would need more memory than the machine has; --force overrides).

#include "cli_common.h"

#include <CGAL_pmsum/point_minkowski_sum.h>

#include <cstdlib>
#include <functional>
#include <map>

namespace pmsum_cli {
namespace {

const char* const usage_text =
  "usage: pmsum <command> [arguments]\n"
  "\n"
  "commands:\n"
  "  sum P Q -d D -o OUT   points covering the boundary of the Minkowski sum P + Q\n"
  "\n"
  "pmsum <command> --help shows the options of a command.\n";

const char* const sum_help =
  "usage: pmsum sum P Q -d D -o OUT [options]\n"
  "\n"
  "Writes points on the boundary of the Minkowski sum P + Q, every point exactly on the\n"
  "boundary, together covering it within distance D.\n"
  "\n"
  "  P, Q                   triangle meshes (.off, .obj, .ply, .stl); other polygons are\n"
  "                         triangulated, closed meshes oriented outward (with a note)\n"
  "  -d D                   covering distance (> 0)\n"
  "  --relative             D is a fraction of the diagonal of the bounding box of P + Q\n"
  "  -o OUT                 .ply (binary: x y z nx ny nz as doubles) or .xyz (ASCII lines)\n"
  "  --negate-p             boundary of -P + Q (contact space of robot P among obstacles Q)\n"
  "  --scale-q S            multiply Q's coordinates by S first (e.g. to size a tool)\n"
  "  --no-normal-filter     test every sample pair with the CD filter (slow)\n"
  "  --no-cd-filter         write every candidate kept by the normal filter (not all on\n"
  "                         the boundary)\n"
  "  --json FILE            write a summary: sizes, counts, seconds per stage\n"
  "  --force                run even if the estimated output exceeds the available memory\n"
  "  --quiet                no notes and no progress bar\n";

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

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

int command_sum(int argc, char** argv)
{
  const Arguments args(argc, argv, 2, {"-d", "-o", "--json", "--scale-q"},
                       {"--relative", "--negate-p", "--no-normal-filter", "--no-cd-filter", "--force",
                        "--quiet", "--help", "-h"});
  if (args.flag("--help") || args.flag("-h")) { std::cout << sum_help; return 0; }
  if (args.positional.size() != 2) throw Usage_error("sum needs two meshes P and Q");
  if (!args.has("-d")) throw Usage_error("sum needs -d D");
  if (!args.has("-o")) throw Usage_error("sum needs -o OUT");
  const std::string out_path = args.values.at("-o");
  const std::string out_ext = extension(out_path);
  if (out_ext != "ply" && out_ext != "xyz") throw Usage_error("-o must name a .ply or .xyz file");
  double d = args.number("-d");
  if (!(d > 0) || !std::isfinite(d)) throw Usage_error("-d must be a positive number, got " + args.values.at("-d"));
  const bool quiet = args.flag("--quiet");

  const auto t_start = std::chrono::steady_clock::now();
  Mesh P = read_mesh(args.positional[0], "P", quiet);
  Mesh Q = read_mesh(args.positional[1], "Q", quiet);
  if (args.has("--scale-q")) {
    const double s = args.number("--scale-q");
    if (!(s > 0) || !std::isfinite(s)) throw Usage_error("--scale-q must be a positive number");
    scale_mesh(Q, s);
  }
  const double diagonal = sum_diagonal(P, Q);
  const double d_input = d;
  if (args.flag("--relative")) d *= diagonal;
  const double t_read = seconds_since(t_start);

  // Each output point is held in memory (48 bytes) before the file is written.
  const std::size_t limit = args.flag("--force") ? std::size_t(-1) : memory_budget_bytes() / sizeof(Oriented_point);

  using Record = CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, K>;
  std::vector<Oriented_point> points;
  CGAL::Pmsum::Statistics stats;
  Progress progress(!quiet);
  std::function<bool(double)> callback = [&](double f) { return progress(f); };
  struct Sink {
    std::vector<Oriented_point>* pts;
    Sink& operator*() { return *this; }
    Sink& operator++() { return *this; }
    Sink operator++(int) { return *this; }
    Sink& operator=(const Record& r)
    {
      pts->push_back({{r.point.x(), r.point.y(), r.point.z()}, {r.normal.x(), r.normal.y(), r.normal.z()}});
      return *this;
    }
  };
  try {
    CGAL::point_minkowski_sum(P, Q, d, Sink{&points},
                              CGAL::parameters::use_normal_filter(!args.flag("--no-normal-filter"))
                                .use_cd_filter(!args.flag("--no-cd-filter"))
                                .negate_first_mesh(args.flag("--negate-p"))
                                .statistics(stats)
                                .maximum_number_of_candidates(limit)
                                .callback(callback));
  } catch (const CGAL::Pmsum::Too_many_candidates& e) {
    std::ostringstream msg;
    msg << "refused: d = " << d << " leaves " << e.candidates << " candidate points (up to "
        << std::setprecision(3) << double(e.candidates) * sizeof(Oriented_point) / double(1 << 30)
        << " GiB of output), more than the memory available allows; use a larger -d, or --force";
    throw Refused(msg.str());
  }

  const auto t_write = std::chrono::steady_clock::now();
  write_points(out_path, points);
  const double write_seconds = seconds_since(t_write);

  if (args.has("--json")) {
    Json jp, jq, filters, seconds;
    jp.str("file", args.positional[0]).integer("vertices", P.number_of_vertices())
      .integer("faces", P.number_of_faces()).integer("samples", stats.samples_p);
    jq.str("file", args.positional[1]).integer("vertices", Q.number_of_vertices())
      .integer("faces", Q.number_of_faces()).integer("samples", stats.samples_q);
    filters.boolean("normal", !args.flag("--no-normal-filter")).boolean("cd", !args.flag("--no-cd-filter"));
    seconds.num("read", t_read).num("setup", stats.seconds_setup).num("normal_filter", stats.seconds_normal_filter)
      .num("cd_filter", stats.seconds_cd_filter).num("write", write_seconds).num("total", seconds_since(t_start));
    Json j;
    j.str("command", "sum").object("p", jp).object("q", jq)
      .num("d", d).num("d_argument", d_input).boolean("relative", args.flag("--relative"))
      .num("sum_bbox_diagonal", diagonal).boolean("negate_p", args.flag("--negate-p")).object("filters", filters)
      .integer("feature_pairs", stats.feature_pairs).integer("candidates", stats.candidates)
      .integer("cd_queries", stats.cd_queries).integer("triangle_pairs", stats.triangle_pairs)
      .integer("containment_tests", stats.containment_tests).integer("output_points", stats.output_points)
      .str("output", out_path).object("seconds", seconds);
    write_json(args.values.at("--json"), j);
  }
  if (!quiet)
    std::cerr << "pmsum: " << points.size() << " points written to " << out_path << " ("
              << std::setprecision(3) << seconds_since(t_start) << " s)\n";
  return 0;
}

} // namespace
} // namespace pmsum_cli

int main(int argc, char** argv)
{
  using namespace pmsum_cli;
  try {
    if (argc < 2) { std::cerr << usage_text; return 2; }
    const std::string command = argv[1];
    if (command == "--help" || command == "-h" || command == "help") { std::cout << usage_text; return 0; }
    if (command == "sum") return command_sum(argc, argv);
    throw Usage_error("unknown command '" + command + "'");
  } catch (const Usage_error& e) {
    std::cerr << "pmsum: " << e.what() << " (see pmsum " << (argc > 1 ? std::string(argv[1]) + " " : "")
              << "--help)\n";
    return 2;
  } catch (const Refused& e) {
    std::cerr << "pmsum: " << e.what() << "\n";
    return 3;
  } catch (const CGAL::Pmsum::Invalid_input& e) {
    std::cerr << "pmsum: error: " << e.what() << "\n";
    return 1;
  } catch (const Error& e) {
    std::cerr << "pmsum: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "pmsum: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "pmsum: error: " << e.what() << "\n";
    return 1;
  }
}
