// Example: take a unit cube out of a pocket under a lid (the paper's Fig. 12(b) kind of
// problem), or plan between two translations of any robot among any obstacles.
//   example_motion_planning                                   the built-in pocket problem
//   example_motion_planning ROBOT.off OBSTACLE.off d sx sy sz gx gy gz
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL_pmsum/Translational_motion_planner.h>

#include "planning_scenes.h"

#include <cstdlib>
#include <iostream>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv)
{
  Mesh robot, obstacle;
  double d = 1. / 16;
  K::Point_3 start, goal;
  if (argc > 9) {
    if (!PMP::IO::read_polygon_mesh(argv[1], robot) || !PMP::IO::read_polygon_mesh(argv[2], obstacle)) return 1;
    for (Mesh* m : {&robot, &obstacle}) PMP::orient_to_bound_a_volume(*m);
    d = std::atof(argv[3]);
    start = K::Point_3(std::atof(argv[4]), std::atof(argv[5]), std::atof(argv[6]));
    goal = K::Point_3(std::atof(argv[7]), std::atof(argv[8]), std::atof(argv[9]));
  } else {
    const pmsum_shapes::Planning_scene s = pmsum_shapes::pocket_scene(1. / 16);
    robot = pmsum_shapes::to_mesh<Mesh>(s.robot);
    obstacle = pmsum_shapes::to_mesh<Mesh>(s.obstacle);
    start = K::Point_3(s.start[0], s.start[1], s.start[2]);
    goal = K::Point_3(s.goal[0], s.goal[1], s.goal[2]);
  }

  // Built once: the contact space (points exactly on the boundary of -robot + obstacle,
  // covering it within d) and a roadmap over it.
  auto planner = CGAL::Translational_motion_planner<Mesh, Mesh>::make(robot, obstacle, d);
  // Each query: a polyline of translations whose every segment is free (exact test).
  const auto result = planner.plan(start, goal);
  const auto& st = planner.statistics();
  std::cerr << st.contact_points << " contact points (" << st.seconds_contact_space << " s), " << st.roadmap_edges
            << " roadmap edges (" << st.seconds_roadmap << " s); query " << st.seconds_query << " s: "
            << st.nodes_checked << " nodes and " << st.edges_checked << " edges checked (" << st.edges_invalid
            << " invalid), " << st.search_iterations << " searches, " << st.shortcut_tests << " shortcut tests\n";
  if (!result.found) {
    std::cerr << "no path found\n";
    return 1;
  }
  std::cout.precision(17);
  for (const auto& t : result.path) std::cout << t << "\n";
  return 0;
}
