// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// pmsum: command-line tool of CGAL_pmsum.
//
//   pmsum sum P Q -d D -o OUT [options]     points on the boundary of P + Q
//   pmsum validate P Q -d D [options]       the same, checked against CGAL's Nef sum
//
// Exit codes: 0 success, 1 error (bad input, I/O), 2 command-line mistake, 3 refused
// (the run would need more memory than the machine has; --force overrides), 4 validation
// found a point off the exact boundary or a shell not covered within d.

#include "cli_common.h"
#include "shape_presets.h"

#include <cstdlib>
#include <functional>
#include <map>

namespace pmsum_cli {
int command_validate(int argc, char** argv); // validate.cpp
namespace {

const char* const usage_text =
  "usage: pmsum <command> [arguments]\n"
  "\n"
  "commands:\n"
  "  sum P Q -d D -o OUT   points covering the boundary of the Minkowski sum P + Q\n"
  "  validate P Q -d D     the same, checked against CGAL's exact Nef Minkowski sum\n"
  "  generate NAME -o OUT  write a procedural model of the validation suite (.off)\n"
  "\n"
  "pmsum <command> --help shows the options of a command.\n";

const std::string sum_help = std::string(
  "usage: pmsum sum P Q -d D -o OUT [options]\n"
  "\n"
  "Writes points on the boundary of the Minkowski sum P + Q, every point exactly on the\n"
  "boundary, together covering it within distance D.\n"
  "\n"
  "  -o OUT                 .ply (binary: x y z nx ny nz as doubles) or .xyz (ASCII lines)\n"
  "  --json FILE            write a summary: sizes, counts, seconds per stage\n") + sum_options_help;

int command_sum(int argc, char** argv)
{
  std::vector<std::string> valued = sum_valued;
  valued.insert(valued.end(), {"-o", "--json"});
  const Arguments args(argc, argv, 2, valued, sum_flags);
  if (args.flag("--help") || args.flag("-h")) { std::cout << sum_help; return 0; }
  if (!args.has("-o")) throw Usage_error("sum needs -o OUT");
  const std::string out_path = args.values.at("-o");
  const std::string out_ext = extension(out_path);
  if (out_ext != "ply" && out_ext != "xyz") throw Usage_error("-o must name a .ply or .xyz file");

  const auto t_start = std::chrono::steady_clock::now();
  const Sum_input in = read_sum_input(args);
  CGAL::Pmsum::Statistics stats;
  const std::vector<Record> records = compute_sum(in, stats);

  const auto t_write = std::chrono::steady_clock::now();
  write_points(out_path, oriented_points(records));
  const double write_seconds = seconds_since(t_write);

  if (args.has("--json")) {
    Json seconds;
    seconds.num("read", in.read_seconds).num("setup", stats.seconds_setup).num("normal_filter", stats.seconds_normal_filter)
      .num("cd_filter", stats.seconds_cd_filter).num("write", write_seconds).num("total", seconds_since(t_start));
    Json j = sum_summary(in, stats);
    j.str("command", "sum").str("output", out_path).object("seconds", seconds);
    write_json(args.values.at("--json"), j);
  }
  if (!in.quiet)
    std::cerr << "pmsum: " << records.size() << " points written to " << out_path << " ("
              << std::setprecision(3) << seconds_since(t_start) << " s)\n";
  return 0;
}

int command_generate(int argc, char** argv)
{
  const Arguments args(argc, argv, 2, {"-o"}, {"--help", "-h", "--list"});
  if (args.flag("--help") || args.flag("-h") || args.flag("--list")) {
    std::cout << "usage: pmsum generate NAME -o OUT.off\n\nshapes:";
    for (const auto& kv : pmsum_test::shape_presets()) std::cout << ' ' << kv.first;
    std::cout << "\n";
    return 0;
  }
  if (args.positional.size() != 1) throw Usage_error("generate needs one shape name");
  if (!args.has("-o")) throw Usage_error("generate needs -o OUT.off");
  pmsum_test::Soup s;
  try {
    s = pmsum_test::shape_preset(args.positional[0]);
  } catch (const std::invalid_argument& e) {
    throw Usage_error(e.what());
  }
  if (!pmsum_test::write_off(s, args.values.at("-o"))) throw Error("cannot write '" + args.values.at("-o") + "'");
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
    if (command == "validate") return command_validate(argc, argv);
    if (command == "generate") return command_generate(argc, argv);
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
