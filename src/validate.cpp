// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// pmsum validate: our point-based sum against CGAL's exact Nef Minkowski sum.
// Its own translation unit: it is the only one of the tool that compiles CGAL's Nef package.

#include "cli_common.h"

#include <CGAL_pmsum/Nef_minkowski_sum_reference.h>
#include <CGAL_pmsum/measure_boundary_coverage.h>
#include <CGAL_pmsum/measure_mesh_distance.h>
#include <CGAL_pmsum/point_minkowski_sum_mesh.h>

#include <fstream>

namespace pmsum_cli {

namespace {
const std::string validate_help = std::string(
  "usage: pmsum validate P Q -d D [options]\n"
  "\n"
  "Computes the boundary of P + Q exactly with CGAL::minkowski_sum_3 (Nef polyhedra) or\n"
  "reads it, runs the point-based sum, and reports:\n"
  "  exactness  output points not exactly on the exact boundary (Nef point location)\n"
  "  coverage   per shell of the exact boundary (outer boundaries and voids), the largest\n"
  "             distance from its points (sampled at spacing <= d/8) to the output, / d\n"
  "  times      ours and Nef's, side by side\n"
  "With --mesh, also the mesh of `pmsum mesh` (made by a second run):\n"
  "  checks     closed, manifold, self-intersection free, bounding a volume; its shells and\n"
  "             voids against the exact boundary's\n"
  "  topology   its Euler characteristic (2 - 2 genus, summed over the shells) against the\n"
  "             exact boundary's, where that is a 2-manifold\n"
  "  distance   the Hausdorff distance both ways between the mesh and the exact boundary, / d\n"
  "             (measured at lattice samples of spacing <= d/8 on both)\n"
  "Exit code 0 if every point is exact and every shell is covered within d (and the mesh is\n"
  "valid, has the exact boundary's shells and Euler characteristic and is within d of it\n"
  "both ways), 4 otherwise.\n"
  "\n"
  "  --exact FILE.nef3      read the exact boundary instead of computing it\n"
  "  --save-exact FILE.nef3 save the exact boundary (CGAL's exact Nef format)\n"
  "  --save-exact-off FILE.off  save it as a triangle soup (rounded to double)\n"
  "  --points OUT           write our points (.ply or .xyz)\n"
  "  --shell-points OUT.xyz write our points as x y z nx ny nz (unit outward normal) and\n"
  "                         the index of the nearest exact shell in a 7th column (to\n"
  "                         colour pictures by shell; readers of .xyz take the first six)\n"
  "  --mesh                 validate the mesh of the boundary too (see above)\n"
  "  --save-mesh OUT        with --mesh: write the mesh (.off, .obj, .ply or .stl)\n"
  "  --json FILE            write the report\n") + sum_options_help;
} // namespace

int command_validate(int argc, char** argv)
{
  std::vector<std::string> valued = sum_valued;
  valued.insert(valued.end(), {"--exact", "--save-exact", "--save-exact-off", "--points", "--shell-points", "--json", "--save-mesh"});
  std::vector<std::string> flags = sum_flags;
  flags.push_back("--mesh");
  const Arguments args(argc, argv, 2, valued, flags);
  if (args.flag("--help") || args.flag("-h")) { std::cout << validate_help; return 0; }
  std::vector<std::pair<std::string, std::string>> outputs;
  if (args.has("--save-mesh") && !args.flag("--mesh")) throw Usage_error("--save-mesh needs --mesh");
  if (args.flag("--mesh") && args.flag("--all-candidates")) throw Usage_error("--mesh meshes the covering net: not with --all-candidates");
  if (args.flag("--mesh") && (args.flag("--no-trim-points") || args.flag("--no-islands")))
    throw Usage_error("--mesh needs the covering's trim and island points: not with --no-trim-points or --no-islands");
  if (args.flag("--mesh") && args.has("--levels")) throw Usage_error("--mesh is not available with --levels");
  if (args.has("--save-mesh")) check_mesh_path(args.values.at("--save-mesh"));
  for (const char* o : {"--points", "--shell-points", "--save-exact", "--save-exact-off", "--json", "--save-mesh"})
    if (args.has(o)) outputs.push_back({o, args.values.at(o)});
  if (args.has("--points")) {
    const std::string e = extension(args.values.at("--points"));
    if (e != "ply" && e != "xyz") throw Usage_error("--points must name a .ply or .xyz file");
  }
  std::vector<std::string> inputs = args.positional;
  if (args.has("--exact")) inputs.push_back(args.values.at("--exact"));
  Output_files files = agreed([&] { return Output_files(outputs, inputs); });
  const auto t_start = std::chrono::steady_clock::now();
  const Sum_input in = agreed([&] { return read_sum_input(args); });

  // Ours.
  CGAL::Pmsum::Statistics stats;
  const auto t_ours = std::chrono::steady_clock::now();
  const std::vector<Record> records = compute_sum(in, stats);
  const double ours_seconds = seconds_since(t_ours);
  if (args.has("--points")) write_points(files["--points"], oriented_points(records));
  // mpirun: the other ranks share the sums (and the mesh's, in the same order as rank 0);
  // the exact sum, the checks and the outputs are rank 0's.
  if (!is_main_rank()) {
    if (args.flag("--mesh")) {
      CGAL::Pmsum::Mesh_statistics ms;
      try {
        compute_mesh(in, ms);
      } catch (const CGAL::Pmsum::Mesh_reconstruction_failed&) { // rank 0 reports it
      }
    }
    return 0;
  }

  // The exact boundary.
  std::unique_ptr<CGAL::Pmsum::Nef_minkowski_sum_reference> ref;
  if (args.has("--exact")) {
    std::ifstream f(args.values.at("--exact"));
    if (!f) throw Error("cannot read '" + args.values.at("--exact") + "'");
    ref = std::make_unique<CGAL::Pmsum::Nef_minkowski_sum_reference>(f);
  } else {
    if (!in.quiet) std::cerr << "pmsum: computing the exact sum with CGAL::minkowski_sum_3 (may take minutes)\n";
    ref = std::make_unique<CGAL::Pmsum::Nef_minkowski_sum_reference>(in.P, in.Q, in.negate);
  }
  if (args.has("--save-exact")) files["--save-exact"].write([&](std::ostream& f) { ref->save(f); });
  if (args.has("--save-exact-off")) {
    std::vector<std::array<double, 3>> pts;
    std::vector<std::array<std::size_t, 3>> tris;
    ref->triangle_soup(pts, tris);
    files["--save-exact-off"].write([&](std::ostream& f) {
      f << std::setprecision(17) << "OFF\n" << pts.size() << ' ' << tris.size() << " 0\n";
      for (const auto& p : pts) f << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      for (const auto& t : tris) f << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    });
  }

  // Exactness: every point, from its exact representation.
  const auto t_check = std::chrono::steady_clock::now();
  std::size_t off_boundary = 0;
  const auto vpm_p = get(CGAL::vertex_point, in.P);
  const auto vpm_q = get(CGAL::vertex_point, in.Q);
  for (const Record& r : records)
    off_boundary += !ref->is_on_boundary(CGAL::Pmsum::exact_point<CGAL::Pmsum::Nef_minkowski_sum_reference::Kernel>(r, vpm_p, vpm_q));

  // Coverage, shell by shell.
  const std::vector<CGAL::Pmsum::Shell> shells = ref->shells();
  std::vector<K::Point_3> points;
  for (const Record& r : records) points.push_back(r.point);
  const auto coverage = CGAL::Pmsum::measure_boundary_coverage(shells, points, in.d, in.d / 8);
  const double spacing = CGAL::Pmsum::measure_point_spacing(points) / in.d;
  const double ideal = CGAL::Pmsum::ideal_covering_size(CGAL::Pmsum::shells_area(shells), in.d);
  const double check_seconds = seconds_since(t_check);

  if (args.has("--shell-points")) {
    // nearest shell of each point: by brute force over the shells' vertices is too coarse;
    // use the shell whose sample set is closest (one kd-tree per shell).
    using Traits = CGAL::Search_traits_3<K>;
    using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
    std::vector<std::unique_ptr<Search::Tree>> trees;
    for (const auto& s : shells) {
      std::vector<K::Point_3> sp;
      for (const auto& t : s.triangles)
        for (int i = 0; i < 3; ++i) {
          const auto& a = s.points[t[i]];
          const auto& b = s.points[t[(i + 1) % 3]];
          const auto& c = s.points[t[(i + 2) % 3]];
          sp.emplace_back(a[0], a[1], a[2]);
          sp.emplace_back((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3);
        }
      trees.push_back(std::make_unique<Search::Tree>(sp.begin(), sp.end()));
    }
    files["--shell-points"].write([&](std::ostream& f) {
      f << std::setprecision(9);
      for (const Record& r : records) {
        const K::Point_3& p = r.point;
        std::size_t best = 0;
        double best_d = HUGE_VAL;
        for (std::size_t i = 0; i < trees.size(); ++i) {
          Search s(*trees[i], p, 1);
          if (s.begin() != s.end() && s.begin()->second < best_d) { best_d = s.begin()->second; best = i; }
        }
        f << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << r.normal.x() << ' ' << r.normal.y() << ' '
          << r.normal.z() << ' ' << best << '\n';
      }
    });
  }

  std::size_t covered = 0, voids = 0;
  double worst = 0;
  for (const auto& c : coverage) {
    covered += c.covered(in.d);
    voids += c.is_void;
    worst = (std::max)(worst, c.worst_distance / in.d);
  }

  // The mesh (--mesh): made by a second run, checked, and measured against the exact boundary.
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::Pmsum::Mesh_distance distance;
  std::optional<long> exact_euler; // (none: not a manifold)
  std::string mesh_error;
  double mesh_seconds = 0, distance_seconds = 0;
  bool mesh_ok = true;
  if (args.flag("--mesh")) {
    exact_euler = CGAL::Pmsum::euler_characteristic(shells);
    const auto t_mesh = std::chrono::steady_clock::now();
    try {
      const Mesh mesh = compute_mesh(in, ms);
      mesh_seconds = seconds_since(t_mesh);
      if (args.has("--save-mesh")) write_mesh(files["--save-mesh"], mesh);
      const auto t_distance = std::chrono::steady_clock::now();
      distance = CGAL::Pmsum::measure_mesh_distance(shells, mesh, in.d / 8);
      distance_seconds = seconds_since(t_distance);
    } catch (const CGAL::Pmsum::Mesh_reconstruction_failed& e) {
      mesh_seconds = seconds_since(t_mesh);
      mesh_error = e.what();
    }
    mesh_ok = mesh_error.empty() && ms.checks.valid() && ms.checks.shells == coverage.size() &&
              ms.checks.void_shells == voids && distance.mesh_to_surface < in.d && distance.surface_to_mesh < in.d &&
              distance.surface_to_mesh < ms.boundary_to_mesh_bound() && // the proved bounds, checked
              distance.mesh_to_surface < ms.mesh_to_boundary_bound &&
              (!exact_euler || ms.checks.euler_characteristic == *exact_euler); // no handle too many or too few
  }
  const bool ok = off_boundary == 0 && covered == coverage.size() && mesh_ok;

  std::cout << std::setprecision(4) << "pmsum validate: " << in.p_path << " + " << in.q_path << (in.negate ? " (negated P)" : "")
            << ", d = " << in.d << "\n"
            << "  points            " << records.size() << "\n"
            << "  exactness         " << off_boundary << " points not on the exact boundary\n"
            << "  shells            " << coverage.size() << " (" << voids << " voids), " << covered << " covered within d\n"
            << "  worst coverage    " << worst << " d\n"
            << "  minimum spacing   " << spacing << " d\n"
            << "  points / ideal    " << double(records.size()) / ideal << " (ideal: area / (2.598 d^2) = " << ideal << ")\n";
  for (std::size_t i = 0; i < coverage.size(); ++i)
    std::cout << "    shell " << i << (coverage[i].is_void ? " (void) " : " (outer) ") << coverage[i].triangles
              << " triangles: worst " << coverage[i].worst_distance / in.d << " d, "
              << coverage[i].touched << "/" << coverage[i].samples << " samples within d\n";
  if (args.flag("--mesh")) {
    const CGAL::Pmsum::Mesh_checks& c = ms.checks;
    if (!mesh_error.empty())
      std::cout << "  mesh              " << mesh_error << "\n";
    else
      std::cout << "  mesh              " << ms.vertices << " vertices, " << ms.triangles << " triangles (d = "
                << ms.covering_distance << ", " << ms.refinements << " refinements"
                << (ms.by_planes ? ", plane by plane" : "") << ")\n"
                << "  mesh checks       " << (c.valid() ? "closed, manifold, self-intersection free, bounding a volume" : c.failures())
                << "; " << c.shells << " shells (" << c.void_shells << " voids), exact: " << coverage.size() << " ("
                << voids << ")\n"
                << "  mesh topology     Euler characteristic " << c.euler_characteristic << ", exact: "
                << (exact_euler ? std::to_string(*exact_euler) : std::string("- (not a 2-manifold: not compared)")) << "\n"
                << "  mesh distance     mesh to exact " << distance.mesh_to_surface / in.d << " d, exact to mesh "
                << distance.surface_to_mesh / in.d << " d (proved below " << ms.boundary_to_mesh_bound() / in.d
                << " d: output points within " << ms.point_distance / in.d << " d of the mesh; mesh within "
                << ms.mesh_to_boundary_bound / in.d << " d of the output points)\n";
    std::cout << "  mesh seconds      " << mesh_seconds << " (sum " << ms.seconds_sum << ", reconstruction "
              << ms.seconds_mesh << "), Nef ratio " << (mesh_seconds > 0 ? ref->seconds() / mesh_seconds : 0) << "\n";
  }
  std::cout << "  seconds           ours " << ours_seconds << ", Nef " << ref->seconds()
            << (args.has("--exact") ? " (read from file)" : "") << ", ratio "
            << (ours_seconds > 0 && ref->seconds() > 0 ? ref->seconds() / ours_seconds : 0) << "\n"
            << "  verdict           " << (ok ? "OK" : "FAILED") << "\n";

  if (args.has("--json")) {
    Json j = sum_summary(in, stats);
    Json shells_json;
    std::string arr = "[";
    for (std::size_t i = 0; i < coverage.size(); ++i) {
      Json s;
      s.boolean("void", coverage[i].is_void).integer("triangles", coverage[i].triangles)
        .integer("samples", coverage[i].samples).num("worst_over_d", coverage[i].worst_distance / in.d)
        .integer("samples_within_d", coverage[i].touched).boolean("covered", coverage[i].covered(in.d));
      arr += (i ? ", " : "") + s.dump(2);
    }
    arr += "]";
    Json seconds;
    seconds.num("ours", ours_seconds).num("nef", ref->seconds()).num("checks", check_seconds);
    if (args.flag("--mesh")) {
      Json m = mesh_summary(ms, mesh_error);
      m.num("mesh_to_exact_over_d", distance.mesh_to_surface / in.d)
        .num("exact_to_mesh_over_d", distance.surface_to_mesh / in.d).integer("mesh_samples", distance.mesh_samples)
        .integer("exact_samples", distance.surface_samples)
        .add("exact_euler_characteristic", exact_euler ? std::to_string(*exact_euler) : "null").boolean("ok", mesh_ok);
      j.object("mesh", m);
      seconds.num("mesh", mesh_seconds).num("mesh_sum", ms.seconds_sum).num("mesh_reconstruction", ms.seconds_mesh)
        .num("mesh_distance", distance_seconds);
    }
    seconds.num("total", seconds_since(t_start));
    j.str("command", "validate").integer("exactness_failures", off_boundary)
      .integer("shells", coverage.size()).integer("void_shells", voids).integer("shells_covered", covered)
      .num("worst_coverage_over_d", worst)
      .num("minimum_spacing_over_d", spacing).num("ideal_points", ideal).num("points_over_ideal", double(records.size()) / ideal).add("shell_coverage", arr).boolean("nef_from_file", args.has("--exact"))
      .object("seconds", seconds).boolean("ok", ok);
    write_json(files["--json"], j);
  }
  return ok ? 0 : 4;
}

} // namespace pmsum_cli
