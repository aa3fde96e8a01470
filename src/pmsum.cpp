// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// pmsum: command-line tool of CGAL_pmsum.
//
//   pmsum sum P Q -d D -o OUT [options]     points on the boundary of P + Q
//   pmsum validate P Q -d D [options]       the same, checked against CGAL's Nef sum
//
// Exit codes: 0 success, 1 error (bad input, I/O), 2 command-line mistake, 3 refused
// (the run would need more memory than the machine has; --force overrides), 4 validation
// found a point off the exact boundary or a shell not covered within d (or, with --mesh, a
// mesh that fails a check or is farther than d from the boundary), 5 plan found no path,
// 6 mesh could make no valid mesh.

#include "cli_common.h"
#include "shape_presets.h"

#include <CGAL_pmsum/Penetration_depth.h>
#include <CGAL_pmsum/Translational_motion_planner.h>
#include <CGAL_pmsum/point_offset.h>
#include <CGAL_pmsum/point_sweep.h>

#include <cstdlib>
#include <functional>
#include <map>

namespace pmsum_cli {
int command_validate(int argc, char** argv); // validate.cpp
int command_mesh(int argc, char** argv);     // mesh.cpp
namespace {

const char* const usage_text =
  "usage: pmsum <command> [arguments]\n"
  "\n"
  "commands:\n"
  "  sum P Q -d D -o OUT   points covering the boundary of the Minkowski sum P + Q\n"
  "  validate P Q -d D     the same, checked against CGAL's exact Nef Minkowski sum\n"
  "  mesh P Q -d D -o OUT  a closed triangle mesh of the boundary of P + Q, vertices on it\n"
  "  offset MESH -r R -d D -o OUT   points covering the offset (or --erode: erosion) of MESH\n"
  "  sweep MESH --path F -d D -o OUT   points covering the volume swept along a polyline\n"
  "  pd P Q -d D --at X Y Z  penetration depth of P translated by (X, Y, Z) into Q\n"
  "  plan ROBOT OBSTACLE --start X Y Z --goal X Y Z -d D   a free path of a translating robot\n"
  "  generate NAME -o OUT  write a procedural model of the validation suite (.off)\n"
  "\n"
  "pmsum <command> --help shows the options of a command; pmsum --version the version.\n";

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
  const std::string out_path = points_output_path(args);
  const std::string out_ext = extension(out_path);
  // Every output is checked (and its temporary file made) before the work: the levels'
  // too, one per item of --levels (read_sum_input checks the items).
  auto level_path = [&](std::size_t k) {
    return out_path.substr(0, out_path.size() - out_ext.size() - 1) + ".level" + std::to_string(k) + "." + out_ext;
  };
  std::vector<std::pair<std::string, std::string>> outputs = {{"-o", out_path}};
  if (args.has("--levels")) {
    const std::string& list = args.values.at("--levels");
    for (std::size_t k = 0; k <= std::size_t(std::count(list.begin(), list.end(), ',')); ++k)
      outputs.push_back({"-o level " + std::to_string(k), level_path(k)});
  }
  if (args.has("--json")) outputs.push_back({"--json", args.values.at("--json")});
  Output_files files = agreed([&] { return Output_files(outputs, args.positional); });

  const auto t_start = std::chrono::steady_clock::now();
  const Sum_input in = agreed([&] { return read_sum_input(args); });
  CGAL::Pmsum::Statistics stats;
  // Coarse to fine (--levels): each coarser level is written as it completes.
  std::vector<std::string> levels;
  auto t_level = t_start;
  auto level_summary = [&](double d, const CGAL::Pmsum::Statistics& s, const std::string& path) {
    Json l;
    l.num("d", d).str("output", path).integer("samples_p", s.samples_p).integer("samples_q", s.samples_q)
      .integer("candidates", s.candidates).integer("candidates_reused", s.candidates_reused)
      .integer("candidates_certified", s.candidates_certified).integer("cd_queries", s.cd_queries)
      .integer("output_points", s.output_points).num("seconds", seconds_since(t_level));
    levels.push_back(l.dump(2));
    t_level = std::chrono::steady_clock::now();
  };
  double write_seconds = 0;
  const std::vector<Record> records = compute_sum(in, stats, [&](std::size_t k, const CGAL::Pmsum::Statistics& s,
                                                                 std::vector<Record>&& level) {
    const std::string path = level_path(k);
    const auto t_write = std::chrono::steady_clock::now();
    write_points(files["-o level " + std::to_string(k)], oriented_points(level));
    write_seconds += seconds_since(t_write);
    level_summary(in.coarser_d[k], s, path);
  });
  if (!in.coarser_d.empty()) level_summary(in.d, stats, out_path);

  const auto t_write = std::chrono::steady_clock::now();
  write_points(files["-o"], oriented_points(records));
  write_seconds += seconds_since(t_write);

  if (args.has("--json")) {
    Json seconds;
    seconds.num("read", in.read_seconds).num("setup", stats.seconds_setup).num("normal_filter", stats.seconds_normal_filter)
      .num("octree_filter", stats.seconds_octree_filter)
      .num("cd_filter", stats.seconds_cd_filter).num("write", write_seconds).num("total", seconds_since(t_start));
    Json j = sum_summary(in, stats);
    j.str("command", "sum").str("output", out_path).object("seconds", seconds);
    if (!levels.empty()) {
      std::string list = "[";
      for (std::size_t k = 0; k < levels.size(); ++k) list += (k ? ", " : "") + levels[k];
      j.add("levels", list + "]");
    }
    write_json(files["--json"], j);
  }
  if (!in.quiet)
    std::cerr << "pmsum: " << records.size() << " points written to " << out_path << " ("
              << std::setprecision(3) << seconds_since(t_start) << " s)\n";
  return 0;
}

const char* const offset_help =
  "usage: pmsum offset MESH -r R -d D -o OUT [options]\n"
  "\n"
  "Points covering the boundary of MESH + ball(R) (offset), or with --erode of the set of\n"
  "points whose ball(R) lies inside MESH (erosion). The ball is a geodesic polyhedron whose\n"
  "inradius is within --sphere-error (relative, default 0.02) of R: every output point is at\n"
  "a distance between that inradius and R from the surface (both are reported).\n"
  "\n"
  "  -r R                  radius (> 0); with --relative, a fraction of MESH's bbox diagonal\n"
  "  -d D                  covering distance (> 0); with --relative, a fraction too\n"
  "  --cube                offset by the cube [-R, R]^3 instead (maximum norm; exact)\n"
  "  --erode               erosion instead of offset (MESH must be closed)\n"
  "  --sphere-error E      relative error of the polyhedral ball (default 0.02)\n"
  "  -o OUT                .ply or .xyz (erosion: normals are 0)\n"
  "  --mesh                write a closed mesh of the offset's boundary instead, as pmsum mesh\n"
  "                        does (its vertices are the points; -o OUT: .off, .obj, .ply or .stl;\n"
  "                        exit code 6 if no valid mesh is made; not with --erode)\n"
  "  --json FILE           summary\n"
  "  --threads N, --quiet  as for sum\n";

int command_offset(int argc, char** argv)
{
  const Arguments args(argc, argv, 2, {"-r", "-d", "-o", "--sphere-error", "--json", "--threads"},
                       {"--cube", "--erode", "--mesh", "--relative", "--quiet", "--help", "-h"});
  if (args.flag("--help") || args.flag("-h")) { std::cout << offset_help; return 0; }
  if (args.positional.size() != 1) throw Usage_error("offset needs one mesh");
  for (const char* o : {"-r", "-d", "-o"})
    if (!args.has(o)) throw Usage_error(std::string("offset needs ") + o);
  const bool as_mesh = args.flag("--mesh");
  if (as_mesh && args.flag("--erode")) throw Usage_error("--mesh makes a mesh of an offset, not of an erosion");
  const std::string out_path = as_mesh ? mesh_output_path(args) : points_output_path(args);
  double r = args.number("-r"), d = args.number("-d");
  if (!(r > 0) || !std::isfinite(r) || !(d > 0) || !std::isfinite(d)) throw Usage_error("-r and -d must be positive numbers");
  const double error = args.has("--sphere-error") ? args.number("--sphere-error") : 0.02;
  if (!(error > 0 && error < 1)) throw Usage_error("--sphere-error must be in (0, 1)");
  std::vector<std::pair<std::string, std::string>> outputs = {{"-o", out_path}};
  if (args.has("--json")) outputs.push_back({"--json", args.values.at("--json")});
  Output_files files = agreed([&] { return Output_files(outputs, args.positional); });
  const bool quiet = args.flag("--quiet") || !is_main_rank();
  const auto start = std::chrono::steady_clock::now();
  Mesh P = agreed([&] { return read_mesh(args.positional[0], "MESH", quiet); });
  if (args.flag("--relative")) {
    const double diag = sum_diagonal(PMP::bbox(P));
    r *= diag;
    d *= diag;
  }
  Mesh B;
  double inner = r;
  if (args.flag("--cube")) {
    pmsum_shapes::Soup c = pmsum_shapes::box({-r, -r, -r}, {r, r, r});
    B = pmsum_shapes::to_mesh<Mesh>(c);
  } else {
    inner = CGAL::make_icosphere(r, error, B);
  }
  std::vector<Oriented_point> points;
  CGAL::Pmsum::Statistics stats;
  std::optional<Written_mesh> written;
  // The summary (--json), also when no mesh is made (its "mesh": "made" false and the error).
  auto summarize = [&](std::size_t output_points, const Json* mesh) {
    if (!args.has("--json")) return;
    Json j;
    j.str("command", "offset").str("input", args.positional[0]).boolean("erode", args.flag("--erode"))
      .str("structuring_element", args.flag("--cube") ? "cube" : "icosphere").num("r", r)
      .num("ball_inradius", inner).integer("ball_faces", B.number_of_faces()).num("d", d)
      .integer("output_points", output_points);
    if (mesh) j.object("mesh", *mesh);
    j.num("seconds", seconds_since(start));
    write_json(files["--json"], j);
  };
  if (args.flag("--erode")) {
    if (!CGAL::is_closed(P)) throw Error("--erode needs a closed mesh");
    std::vector<K::Point_3> pts;
    CGAL::point_erosion<CGAL::Sequential_tag>(P, B, d, std::back_inserter(pts));
    for (const auto& p : pts) points.push_back({{p.x(), p.y(), p.z()}, {0, 0, 0}});
  } else { // the offset is the sum P + B
    Sum_input in;
    in.P = P;
    in.Q = B;
    in.d = d;
    in.quiet = quiet;
    if (args.has("--threads")) in.threads = int(args.number("--threads"));
    if (as_mesh)
      written = on_mesh_failure([&] { return write_sum_mesh(in, files["-o"]); }, [&](const std::string& error) {
        const Json m = mesh_failure_summary(error);
        summarize(0, &m);
      });
    else points = oriented_points(compute_sum(in, stats));
  }
  if (!as_mesh) write_points(files["-o"], points);
  if (written) summarize(written->sum.output_points, &written->summary);
  else summarize(points.size(), nullptr);
  if (!quiet)
    std::cerr << "pmsum: " << (written ? written->note : std::to_string(points.size()) + " points") << " written to "
              << out_path << "; every " << (written ? "vertex" : "point") << " at distance in ["
              << std::setprecision(6) << inner << ", " << r << "] from the surface\n";
  return 0;
}

const std::string pd_help = std::string(
  "usage: pmsum pd P Q -d D --at X Y Z [--at X Y Z ...] [options]\n"
  "\n"
  "Penetration depth of the moving solid P, translated by t = (X, Y, Z), into the fixed Q:\n"
  "the length and direction of the shortest translation that separates them, from points\n"
  "covering the contact space (boundary of -P + Q) within D; the depth is within D of the\n"
  "exact one. Overlap itself is decided exactly. One line per --at:\n"
  "  X Y Z overlap DEPTH DX DY DZ     or     X Y Z free\n"
  "\n"
  "  --json FILE            summary (contact points, build and query seconds)\n") + input_options_help;

int command_pd(int argc, char** argv)
{
  // --at takes three numbers: pull them out before the generic parser.
  std::vector<std::array<double, 3>> at;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) != "--at") { rest.push_back(argv[i]); continue; }
    if (i + 3 >= argc) throw Usage_error("--at needs three numbers");
    std::array<double, 3> t;
    for (int c = 0; c < 3; ++c) {
      char* end = nullptr;
      t[c] = std::strtod(argv[i + 1 + c], &end);
      if (end == argv[i + 1 + c] || *end != '\0' || !std::isfinite(t[c]))
        throw Usage_error(std::string("--at needs three numbers, got '") + argv[i + 1 + c] + "'");
    }
    at.push_back(t);
    i += 3;
  }
  std::vector<std::string> valued = input_valued;
  valued.push_back("--json");
  const Arguments args(int(rest.size()), rest.data(), 2, valued, input_flags);
  if (args.flag("--help") || args.flag("-h")) { std::cout << pd_help; return 0; }
  if (at.empty()) throw Usage_error("pd needs at least one --at X Y Z");
  std::vector<std::pair<std::string, std::string>> outputs;
  if (args.has("--json")) outputs.push_back({"--json", args.values.at("--json")});
  Output_files files(outputs, args.positional);
  const Sum_input in = read_sum_input(args);
  const auto t_build = std::chrono::steady_clock::now();
  auto pd = CGAL::Penetration_depth<Mesh, Mesh>::make(in.P, in.Q, in.d);
  const double build_seconds = seconds_since(t_build);
  const auto t_query = std::chrono::steady_clock::now();
  std::cout << std::setprecision(10);
  for (const auto& t : at) {
    const auto r = pd.query(K::Point_3(t[0], t[1], t[2]));
    std::cout << t[0] << ' ' << t[1] << ' ' << t[2];
    if (r.overlapping)
      std::cout << " overlap " << r.depth << ' ' << r.direction.x() << ' ' << r.direction.y() << ' ' << r.direction.z() << '\n';
    else
      std::cout << " free\n";
  }
  const double query_seconds = seconds_since(t_query);
  if (args.has("--json")) {
    Json j;
    j.str("command", "pd").str("p", in.p_path).str("q", in.q_path).num("d", in.d)
      .integer("contact_points", pd.number_of_contact_points()).integer("queries", at.size())
      .num("seconds_build", build_seconds).num("seconds_queries", query_seconds);
    write_json(files["--json"], j);
  }
  return 0;
}

const char* const sweep_help =
  "usage: pmsum sweep MESH --path FILE -d D -o OUT [--relative] [--json FILE] [--threads N] [--quiet]\n"
  "\n"
  "Points covering the boundary of the volume swept by MESH translating along a polyline\n"
  "(MESH + path), every point exactly on it. FILE: one point 'x y z' per line, in order\n"
  "(the positions of MESH's origin). With --relative, D is a fraction of the diagonal of\n"
  "the swept volume's bounding box. With --mesh, a closed mesh of that boundary is written\n"
  "instead, as pmsum mesh does (its vertices are the points; -o OUT: .off, .obj, .ply or\n"
  ".stl; exit code 6 if no valid mesh is made).\n";

int command_sweep(int argc, char** argv)
{
  const Arguments args(argc, argv, 2, {"--path", "-d", "-o", "--json", "--threads"},
                       {"--mesh", "--relative", "--quiet", "--help", "-h"});
  if (args.flag("--help") || args.flag("-h")) { std::cout << sweep_help; return 0; }
  if (args.positional.size() != 1) throw Usage_error("sweep needs one mesh");
  for (const char* o : {"--path", "-d", "-o"})
    if (!args.has(o)) throw Usage_error(std::string("sweep needs ") + o);
  const bool as_mesh = args.flag("--mesh");
  const std::string out_path = as_mesh ? mesh_output_path(args) : points_output_path(args);
  double d = args.number("-d");
  if (!(d > 0) || !std::isfinite(d)) throw Usage_error("-d must be a positive number");
  std::vector<std::pair<std::string, std::string>> outputs = {{"-o", out_path}};
  if (args.has("--json")) outputs.push_back({"--json", args.values.at("--json")});
  std::vector<std::string> inputs = args.positional;
  inputs.push_back(args.values.at("--path"));
  Output_files files(outputs, inputs);
  const auto start = std::chrono::steady_clock::now();
  const Mesh P = read_mesh(args.positional[0], "MESH", args.flag("--quiet"));
  std::ifstream in(args.values.at("--path"));
  if (!in) throw Error("cannot read the path '" + args.values.at("--path") + "'");
  std::vector<K::Point_3> path;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    std::istringstream ls(line);
    double x, y, z;
    std::string extra;
    if (!(ls >> x >> y >> z) || (ls >> extra) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw Error("path '" + args.values.at("--path") + "' line " + std::to_string(n) + ": expected three numbers x y z");
    path.emplace_back(x, y, z);
  }
  if (args.flag("--relative")) {
    CGAL::Bbox_3 path_box;
    for (const auto& p : path) path_box += p.bbox();
    d *= sum_diagonal(PMP::bbox(P), path_box);
  }
  std::vector<K::Point_3> pts;
  CGAL::Pmsum::Statistics stats;
  std::optional<Written_mesh> written;
  const int threads = args.has("--threads") ? int(args.number("--threads")) : 0;
  // The summary (--json), also when no mesh is made (its "mesh": "made" false and the error).
  auto summarize = [&](const Json* mesh) {
    if (!args.has("--json")) return;
    Json j;
    j.str("command", "sweep").str("input", args.positional[0]).str("path", args.values.at("--path"))
      .integer("path_points", path.size()).num("d", d).integer("candidates", stats.candidates)
      .integer("cd_queries", stats.cd_queries).integer("output_points", stats.output_points);
    if (mesh) j.object("mesh", *mesh);
    j.num("seconds", seconds_since(start));
    write_json(files["--json"], j);
  };
  if (as_mesh) {
    written = on_mesh_failure([&] { return write_sweep_mesh(P, path, d, threads, files["-o"]); }, [&](const std::string& error) {
      const Json m = mesh_failure_summary(error);
      summarize(&m);
    });
    stats = written->sum;
  } else {
    with_threads(threads, [&](auto tag) {
      CGAL::point_sweep<decltype(tag)>(P, path, d, std::back_inserter(pts), CGAL::parameters::statistics(stats));
    });
    std::vector<Oriented_point> out;
    for (const auto& p : pts) out.push_back({{p.x(), p.y(), p.z()}, {0, 0, 0}});
    write_points(files["-o"], out);
  }
  summarize(written ? &written->summary : nullptr);
  if (!args.flag("--quiet"))
    std::cerr << "pmsum: " << (written ? written->note : std::to_string(pts.size()) + " points") << " written to "
              << out_path << "\n";
  return 0;
}

const char* const plan_help =
  "usage: pmsum plan ROBOT OBSTACLE --start X Y Z --goal X Y Z -d D [options]\n"
  "\n"
  "A path of ROBOT translating among the fixed OBSTACLE from the translation start to goal:\n"
  "a polyline of translations, each segment checked exactly (the robot may touch and slide\n"
  "along the obstacle, never overlap it). The roadmap is built over points covering the\n"
  "contact space (boundary of -ROBOT + OBSTACLE) within D. Prints one 'x y z' line per\n"
  "vertex. Exit code 5 and a one-line message when the roadmap joins no path (which does not\n"
  "prove that none exists); exit code 1 when start or goal overlaps the obstacle.\n"
  "\n"
  "  -d D                  covering distance of the contact points (> 0)\n"
  "  --relative            D is a fraction of the diagonal of the bounding box of -ROBOT + OBSTACLE\n"
  "  -k K                  neighbours per roadmap node (default 12)\n"
  "  -o FILE               also write the path to FILE (same format)\n"
  "  --json FILE           summary: counts, seconds, path length\n"
  "  --threads N           threads of the contact-space computation (default: all cores)\n"
  "  --quiet               no notes\n";

/// Pulls "OPTION x y z" out of argv (the generic parser takes one value per option).
std::vector<std::array<double, 3>> take_triples(int argc, char** argv, const std::string& option, std::vector<char*>& rest)
{
  std::vector<std::array<double, 3>> r;
  rest.clear();
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) != option) { rest.push_back(argv[i]); continue; }
    if (i + 3 >= argc) throw Usage_error(option + " needs three numbers");
    std::array<double, 3> t;
    for (int c = 0; c < 3; ++c) {
      char* end = nullptr;
      t[c] = std::strtod(argv[i + 1 + c], &end);
      if (end == argv[i + 1 + c] || *end != '\0' || !std::isfinite(t[c]))
        throw Usage_error(option + " needs three numbers, got '" + argv[i + 1 + c] + "'");
    }
    r.push_back(t);
    i += 3;
  }
  return r;
}

int command_plan(int argc, char** argv)
{
  std::vector<char*> rest1, rest2;
  const auto starts = take_triples(argc, argv, "--start", rest1);
  const auto goals = take_triples(int(rest1.size()), rest1.data(), "--goal", rest2);
  const Arguments args(int(rest2.size()), rest2.data(), 2, {"-d", "-k", "-o", "--json", "--threads"},
                       {"--relative", "--quiet", "--help", "-h"});
  if (args.flag("--help") || args.flag("-h")) { std::cout << plan_help; return 0; }
  if (args.positional.size() != 2) throw Usage_error("plan needs two meshes ROBOT and OBSTACLE");
  if (starts.size() != 1 || goals.size() != 1) throw Usage_error("plan needs one --start X Y Z and one --goal X Y Z");
  if (!args.has("-d")) throw Usage_error("plan needs -d D");
  double d = args.number("-d");
  if (!(d > 0) || !std::isfinite(d)) throw Usage_error("-d must be a positive number");
  unsigned k = 12;
  if (args.has("-k")) {
    const double kk = args.number("-k");
    if (!(kk >= 1) || kk != std::floor(kk) || kk > 1000) throw Usage_error("-k must be a positive integer");
    k = unsigned(kk);
  }
  int threads = 0;
  if (args.has("--threads")) {
    const double t = args.number("--threads");
    if (!(t >= 1) || t != std::floor(t) || t > 1024) throw Usage_error("--threads must be a positive integer");
    threads = int(t);
  }
  const bool quiet = args.flag("--quiet");
  std::vector<std::pair<std::string, std::string>> outputs;
  if (args.has("-o")) outputs.push_back({"-o", args.values.at("-o")});
  if (args.has("--json")) outputs.push_back({"--json", args.values.at("--json")});
  Output_files files(outputs, args.positional);
  const auto start = std::chrono::steady_clock::now();
  const Mesh R = read_mesh(args.positional[0], "ROBOT", quiet);
  const Mesh O = read_mesh(args.positional[1], "OBSTACLE", quiet);
  if (args.flag("--relative")) d *= sum_diagonal(PMP::bbox(R), PMP::bbox(O));
  using Planner = CGAL::Translational_motion_planner<Mesh, Mesh>;
  std::optional<Planner> planner;
  with_threads(threads, [&](auto tag) { planner.emplace(Planner::make<decltype(tag)>(R, O, d, CGAL::parameters::roadmap_neighbors(k))); });
  const auto& s = starts.front();
  const auto& g = goals.front();
  const Planner::Result r = planner->plan(K::Point_3(s[0], s[1], s[2]), K::Point_3(g[0], g[1], g[2]));
  const auto& st = planner->statistics();
  if (args.has("--json")) {
    Json j;
    j.str("command", "plan").str("robot", args.positional[0]).str("obstacle", args.positional[1]).num("d", d)
      .integer("k", k).boolean("found", r.found).integer("path_vertices", r.path.size()).num("path_length", r.length)
      .integer("contact_points", st.contact_points).integer("nodes", st.nodes).integer("roadmap_edges", st.roadmap_edges)
      .integer("nodes_checked", st.nodes_checked).integer("edges_checked", st.edges_checked)
      .integer("edges_invalid", st.edges_invalid).integer("searches", st.search_iterations)
      .num("seconds_contact_space", st.seconds_contact_space).num("seconds_roadmap", st.seconds_roadmap)
      .num("seconds_query", st.seconds_query).num("seconds", seconds_since(start));
    write_json(files["--json"], j);
  }
  if (!r.found) {
    std::cerr << "pmsum: no path found: start and goal are not connected in the roadmap of " << st.nodes
              << " contact points (try a smaller -d or a larger -k)\n";
    return 5;
  }
  std::ostringstream text;
  text << std::setprecision(17);
  for (const auto& t : r.path) text << t.x() << ' ' << t.y() << ' ' << t.z() << '\n';
  std::cout << text.str();
  if (args.has("-o")) files["-o"].write([&](std::ostream& os) { os << text.str(); });
  if (!quiet)
    std::cerr << "pmsum: path of " << r.path.size() << " vertices, length " << std::setprecision(6) << r.length << " ("
              << st.contact_points << " contact points, " << std::setprecision(3) << seconds_since(start) << " s)\n";
  return 0;
}

int command_generate(int argc, char** argv)
{
  const Arguments args(argc, argv, 2, {"-o"}, {"--help", "-h", "--list"});
  if (args.flag("--help") || args.flag("-h") || args.flag("--list")) {
    std::cout << "usage: pmsum generate NAME -o OUT.off\n\nshapes:";
    for (const auto& kv : pmsum_shapes::shape_presets()) std::cout << ' ' << kv.first;
    std::cout << "\n";
    return 0;
  }
  if (args.positional.size() != 1) throw Usage_error("generate needs one shape name");
  if (!args.has("-o")) throw Usage_error("generate needs -o OUT.off");
  Output_files files({{"-o", args.values.at("-o")}}, {});
  pmsum_shapes::Soup s;
  try {
    s = pmsum_shapes::shape_preset(args.positional[0]);
  } catch (const std::invalid_argument& e) {
    throw Usage_error(e.what());
  }
  files["-o"].write([&](std::ostream& os) { pmsum_shapes::write_off(s, os); });
  return 0;
}

} // namespace
} // namespace pmsum_cli

int main(int argc, char** argv)
{
  using namespace pmsum_cli;
  install_signal_cleanup();
  const Ranks_session ranks(argc, argv); // mpirun: every rank runs the command (cli_ranks.h)
  std::ostream& err = error_stream();    // rank 0 alone prints errors
  // An error that this rank alone met ends every rank: the others may be waiting for it.
  auto failed = [&](int code, const std::string& line) {
    if (every_rank_knows(std::current_exception())) {
      err << line << "\n";
      return code;
    }
    std::cerr << line << " (rank " << process_rank() << ")\n";
    abort_all_ranks(code);
  };
  try {
    if (argc < 2) { err << usage_text; return 2; }
    const std::string command = argv[1];
    if (command == "--help" || command == "-h" || command == "help") { std::cout << usage_text; return 0; }
    if (command == "--version") { std::cout << "pmsum " << CGAL_PMSUM_VERSION << " (CGAL_pmsum, CGAL " << CGAL_VERSION_STR << ")\n"; return 0; }
    if (world_communicator() && command != "sum" && command != "offset" && command != "validate" && command != "mesh")
      throw Usage_error("under mpirun, only sum, offset, validate and mesh share their work; run " + command +
                        " as one process");
    if (command == "sum") return command_sum(argc, argv);
    if (command == "validate") return command_validate(argc, argv);
    if (command == "mesh") return command_mesh(argc, argv);
    if (command == "generate") return command_generate(argc, argv);
    if (command == "offset") return command_offset(argc, argv);
    if (command == "pd") return command_pd(argc, argv);
    if (command == "sweep") return command_sweep(argc, argv);
    if (command == "plan") return command_plan(argc, argv);
    throw Unknown_command("unknown command '" + command + "'");
  } catch (const Unknown_command& e) {
    err << "pmsum: " << e.what() << " (see pmsum --help)\n";
    return 2;
  } catch (const Usage_error& e) {
    err << "pmsum: " << e.what() << " (see pmsum " << (argc > 1 ? std::string(argv[1]) + " " : "")
              << "--help)\n";
    return 2;
  } catch (const Refused& e) {
    err << "pmsum: " << e.what() << "\n";
    return 3;
  } catch (const CGAL::Pmsum::Too_large& e) {
    err << "pmsum: refused: " << e.what() << " (use a larger -d)\n";
    return 3;
  } catch (const CGAL::Pmsum::Mesh_reconstruction_failed& e) {
    err << "pmsum: error: " << e.what() << "\n";
    return 6;
  } catch (const CGAL::Pmsum::Invalid_input& e) {
    err << "pmsum: error: " << e.what() << "\n";
    return 1;
  } catch (const Error& e) {
    return failed(1, std::string("pmsum: error: ") + e.what());
  } catch (const std::bad_alloc&) {
    return failed(1, "pmsum: error: out of memory");
  } catch (const std::exception& e) {
    return failed(1, std::string("pmsum: error: ") + e.what());
  }
}
