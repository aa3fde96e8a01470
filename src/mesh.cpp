// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// pmsum mesh: a closed, manifold, outward-oriented triangle mesh of the boundary of P + Q
// without self-intersections (CGAL::point_minkowski_sum_mesh()). Its own translation unit:
// the only one of the tool that compiles the surface reconstruction and the mesh checks.

#include "cli_common.h"

#include <CGAL_pmsum/point_minkowski_sum_mesh.h>
#include <CGAL_pmsum/point_sweep_mesh.h>

#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/IO/STL.h>

namespace pmsum_cli {

Mesh compute_mesh(const Sum_input& in, CGAL::Pmsum::Mesh_statistics& ms)
{
  Mesh mesh;
  Progress progress(!in.quiet);
  CGAL::Pmsum::Statistics stats;
  const auto np = sum_parameters(in, stats, progress_callback(in, progress)).mesh_statistics(ms);
  run_refusing_too_large(in, [&](auto tag) { CGAL::point_minkowski_sum_mesh<decltype(tag)>(in.P, in.Q, in.d, mesh, np); });
  return mesh;
}

namespace {

std::string mesh_note(const CGAL::Pmsum::Mesh_statistics& ms)
{
  return "a mesh of " + std::to_string(ms.vertices) + " vertices and " + std::to_string(ms.triangles) + " triangles (" +
         std::to_string(ms.checks.shells) + " shells, " + std::to_string(ms.checks.void_shells) + " voids" +
         (ms.refinements ? ", d halved " + std::to_string(ms.refinements) + " times" : std::string()) +
         (ms.crease_points ? ", the crease points kept" : "") +
         (ms.by_planes ? ", plane by plane" : "") + ")";
}

} // namespace

Json mesh_failure_summary(const std::string& error)
{
  Json j;
  j.boolean("made", false).str("error", error);
  return j;
}

Json mesh_summary(const CGAL::Pmsum::Mesh_statistics& ms, const std::string& error)
{
  if (!error.empty()) return mesh_failure_summary(error); // (ms.checks: those of the last mesh refused)
  Json j;
  j.boolean("made", true).str("error", "");
  const CGAL::Pmsum::Mesh_checks& c = ms.checks;
  j.integer("vertices", ms.vertices).integer("triangles", ms.triangles).num("covering_distance", ms.covering_distance)
    .integer("refinements", std::size_t(ms.refinements)).boolean("crease_points", ms.crease_points).boolean("by_planes", ms.by_planes).boolean("closed", c.closed).boolean("manifold", c.manifold)
    .boolean("self_intersection_free", c.self_intersection_free).boolean("bounds_a_volume", c.bounds_a_volume)
    .integer("shells", c.shells).integer("void_shells", c.void_shells).add("euler_characteristic", std::to_string(c.euler_characteristic)).num("point_distance", ms.point_distance)
    .integer("points_put_back", ms.points_put_back).integer("sheets_remeshed", std::size_t(ms.sheets_remeshed))
    .num("mesh_to_boundary_bound", ms.mesh_to_boundary_bound)
    .num("boundary_to_mesh_bound", ms.boundary_to_mesh_bound()).str("refused", ms.refused);
  return j;
}

Written_mesh write_sum_mesh(const Sum_input& in, Output_file& file)
{
  CGAL::Pmsum::Mesh_statistics ms;
  write_mesh(file, compute_mesh(in, ms));
  return {mesh_summary(ms), mesh_note(ms), ms.sum};
}

Written_mesh write_sweep_mesh(const Mesh& P, const std::vector<K::Point_3>& path, double d, int threads,
                              Output_file& file)
{
  CGAL::Pmsum::Mesh_statistics ms;
  Mesh mesh;
  with_threads(threads, [&](auto tag) {
    CGAL::point_sweep_mesh<decltype(tag)>(P, path, d, mesh, CGAL::parameters::mesh_statistics(ms));
  });
  write_mesh(file, mesh);
  return {mesh_summary(ms), mesh_note(ms), ms.sum};
}

void check_mesh_path(const std::string& path)
{
  const std::string e = extension(path);
  if (e != "off" && e != "ply" && e != "obj" && e != "stl") throw Usage_error("'" + path + "': a mesh must be written to a .off, .obj, .ply or .stl file");
}


void write_mesh(Output_file& file, const Mesh& mesh)
{
  const std::string e = extension(file.path());
  const auto np = CGAL::parameters::stream_precision(17);
  const bool binary = e == "ply" || e == "stl";
  auto write = [&](std::ostream& os) {
    if (binary) CGAL::IO::set_mode(os, CGAL::IO::BINARY); // the stream writers read the mode, not use_binary_mode
    bool ok = false;
    if (e == "off") ok = CGAL::IO::write_OFF(os, mesh, np);
    if (e == "obj") ok = CGAL::IO::write_OBJ(os, mesh, np);
    if (e == "ply") ok = CGAL::IO::write_PLY(os, mesh, np);
    if (e == "stl") ok = CGAL::IO::write_STL(os, mesh, np);
    if (!ok) throw Error("cannot write the mesh to '" + file.path() + "'"); // the temporary file is removed
  };
  file.write(write, binary ? std::ios::out | std::ios::binary : std::ios::out);
}

namespace {

const std::string mesh_help = std::string(
  "usage: pmsum mesh P Q -d D -o OUT [options]\n"
  "\n"
  "Writes a triangle mesh of the boundary of the Minkowski sum P + Q: closed, 2-manifold,\n"
  "oriented outward (voids inward), without self-intersections, one shell per shell of the\n"
  "boundary. Its vertices are output points of `pmsum sum` (on the exact boundary, covering it\n"
  "within D). If the mesh made at D fails a check, it is made again at D with the trim\n"
  "curves searched where the covering does not need them, then the sum is recomputed at D/2,\n"
  "then D/4 (each with and without every point on a sharp crease of the sum kept); if no\n"
  "valid mesh is made, no mesh is written (the JSON summary is, with \"made\": false and\n"
  "the error) and the exit code is 6.\n"
  "\n"
  "  -o OUT                 .off, .obj (17 digits), .ply (binary doubles) or .stl (binary:\n"
  "                         coordinates rounded to float)\n"
  "  --json FILE            write a summary: the mesh's checks and sizes, the d used, the\n"
  "                         largest distance from an output point to the mesh and the bound it\n"
  "                         proves on the exact boundary's distance, seconds of the sum and of\n"
  "                         the reconstruction; written also when no mesh is made\n"
  "The options of sum follow, but --all-candidates, --no-cd-filter, --no-trim-points,\n"
  "--no-islands and --levels.\n") + sum_options_help;

} // namespace

int command_mesh(int argc, char** argv)
{
  std::vector<std::string> valued = {"-d", "--scale-q", "--threads", "-o", "--json"};
  std::vector<std::string> flags = sum_flags;
  // The vertices must be boundary points of the net: not every candidate, not untested ones,
  // and a covering (the mesh's bound needs it): trim and island points too.
  for (const char* f : {"--all-candidates", "--no-cd-filter", "--no-trim-points", "--no-islands"}) flags.erase(std::remove(flags.begin(), flags.end(), f), flags.end());
  const Arguments args(argc, argv, 2, valued, flags);
  if (args.flag("--help") || args.flag("-h")) { std::cout << mesh_help; return 0; }
  if (!args.has("-o")) throw Usage_error("mesh needs -o OUT");
  const std::string out_path = mesh_output_path(args);
  std::vector<std::pair<std::string, std::string>> outputs = {{"-o", out_path}};
  if (args.has("--json")) outputs.push_back({"--json", args.values.at("--json")});
  Output_files files = agreed([&] { return Output_files(outputs, args.positional); });

  const auto t_start = std::chrono::steady_clock::now();
  const Sum_input in = agreed([&] { return read_sum_input(args); });
  CGAL::Pmsum::Mesh_statistics ms;
  // The JSON summary is written whether the mesh is made or not (then "made": false, the
  // error, and the counters of the last sum computed); the mesh only if it is made.
  auto summarize = [&](const std::string& error, double write_seconds) {
    if (!args.has("--json")) return;
    Json seconds;
    seconds.num("read", in.read_seconds).num("sum", ms.seconds_sum).num("reconstruction", ms.seconds_mesh)
      .num("write", write_seconds).num("total", seconds_since(t_start));
    Json j = sum_summary(in, ms.sum);
    j.str("command", "mesh").str("output", error.empty() ? out_path : "").object("mesh", mesh_summary(ms, error))
      .object("seconds", seconds);
    write_json(files["--json"], j);
  };
  const Mesh mesh = on_mesh_failure([&] { return compute_mesh(in, ms); }, [&](const std::string& error) { summarize(error, 0); });
  const auto t_write = std::chrono::steady_clock::now();
  write_mesh(files["-o"], mesh);
  summarize("", seconds_since(t_write));
  if (!in.quiet) {
    if (!ms.refused.empty()) std::cerr << "pmsum: note: refused first: " << ms.refused << "\n";
    std::cerr << "pmsum: " << mesh_note(ms) << " written to " << out_path << " (" << std::setprecision(3)
              << seconds_since(t_start) << " s)\n";
  }
  return 0;
}

} // namespace pmsum_cli
