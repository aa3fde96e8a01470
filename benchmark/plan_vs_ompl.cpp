// Translational motion planning: CGAL_pmsum's planner against OMPL's RRTConnect and PRM in
// R^3 with the same exact collision checks (benchmark/run_benchmarks.py --only plan runs it).
//
//   plan_vs_ompl PROBLEM PLANNER SEED [TIME_LIMIT]
//     PROBLEM  pocket | slot | slot-narrow   (src/shapes/planning_scenes.h, clearance 1/16 for a unit
//              cube; slot-narrow: clearance 1/200, d/100 of our planner's d = 0.5)
//     PLANNER  pmsum | rrtconnect | prm
// Prints one JSON line: solved, seconds (wall clock, single thread; for pmsum the contact
// space and the roadmap included), path vertices and length, and whether every segment of
// the path passed the exact segment test afterwards.
//
// OMPL gets the exact tests of the planner as its state validity checker (the robot at t,
// moved infinitesimally along the axes, misses the obstacle: CGAL_pmsum's exact point test)
// and as its motion validator (the exact swept-segment test of internal/swept_cd.h, the
// same that checks our edges), so both planners return paths that are free for every point,
// and neither uses a discretisation resolution.

#include "planning_scenes.h"

#include <CGAL_pmsum/Translational_motion_planner.h>

#include <CGAL/Surface_mesh.h>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace in = CGAL::Pmsum::internal;

namespace {

/// The exact tests, shared by OMPL's callbacks (PRM may call them from two threads).
struct Exact_checker
{
  in::Mesh_data p, q;
  std::unique_ptr<in::Swept_cd> cd;
  std::mutex mutex;

  Exact_checker(const Mesh& P, const Mesh& Q)
  {
    in::Mesh_descriptors<Mesh> dp, dq;
    p = in::make_mesh_data(P, get(CGAL::vertex_point, P), false, false, "P", dp);
    q = in::make_mesh_data(Q, get(CGAL::vertex_point, Q), false, false, "Q", dq);
    cd = std::make_unique<in::Swept_cd>(p, q);
  }
  static std::array<double, 3> point(const ob::State* s)
  {
    const auto* r = s->as<ob::RealVectorStateSpace::StateType>();
    return {r->values[0], r->values[1], r->values[2]};
  }
  bool free(const ob::State* s)
  {
    std::lock_guard<std::mutex> lock(mutex);
    const auto t = point(s);
    return cd->is_free(t, t, {});
  }
  bool free(const ob::State* a, const ob::State* b)
  {
    std::lock_guard<std::mutex> lock(mutex);
    return cd->is_free(point(a), point(b), {});
  }
};

class Exact_motion_validator : public ob::MotionValidator
{
public:
  Exact_motion_validator(const ob::SpaceInformationPtr& si, Exact_checker* c) : ob::MotionValidator(si), m_c(c) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override
  {
    const bool ok = m_c->free(s2) && m_c->free(s1, s2);
    if (ok) ++valid_; else ++invalid_;
    return ok;
  }
  bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last_valid) const override
  {
    if (checkMotion(s1, s2)) return true;
    // No last valid state along the motion is computed: report the start.
    if (last_valid.first) si_->copyState(last_valid.first, s1);
    last_valid.second = 0;
    return false;
  }

private:
  Exact_checker* m_c;
};

} // namespace

int main(int argc, char** argv)
{
  if (argc < 4) {
    std::cerr << "usage: plan_vs_ompl pocket|slot|slot-narrow pmsum|rrtconnect|prm SEED [TIME_LIMIT]\n";
    return 2;
  }
  const std::string problem = argv[1], planner = argv[2];
  const unsigned long seed = std::stoul(argv[3]);
  const double time_limit = argc > 4 ? std::atof(argv[4]) : 10.0;
  const double d = 0.5;
  const pmsum_shapes::Planning_scene scene = problem == "pocket"        ? pmsum_shapes::pocket_scene(1. / 16)
                                           : problem == "slot-narrow" ? pmsum_shapes::slot_scene(d / 100)
                                                                      : pmsum_shapes::slot_scene(1. / 16);
  const Mesh R = pmsum_shapes::to_mesh<Mesh>(scene.robot), O = pmsum_shapes::to_mesh<Mesh>(scene.obstacle);
  const K::Point_3 start(scene.start[0], scene.start[1], scene.start[2]), goal(scene.goal[0], scene.goal[1], scene.goal[2]);
  Exact_checker checker(R, O);

  bool solved = false;
  std::vector<std::array<double, 3>> path;
  double seconds = 0;
  if (planner == "pmsum") {
    const auto t0 = std::chrono::steady_clock::now();
    auto pl = CGAL::Translational_motion_planner<Mesh, Mesh>::make<CGAL::Sequential_tag>(R, O, d);
    const auto r = pl.plan(start, goal);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    solved = r.found;
    for (const auto& t : r.path) path.push_back({t.x(), t.y(), t.z()});
  } else {
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(seed);
    auto space = std::make_shared<ob::RealVectorStateSpace>(3);
    ob::RealVectorBounds bounds(3);
    if (problem == "pocket") {
      bounds.setLow(-1.5);
      bounds.setHigh(3.5);
    } else { // the room's inside, for the robot's corner
      bounds.setLow(0, -1.25); bounds.setHigh(0, 0.75);
      bounds.setLow(1, -1); bounds.setHigh(1, 0);
      bounds.setLow(2, -1); bounds.setHigh(2, 0);
    }
    space->setBounds(bounds);
    og::SimpleSetup ss(space);
    ss.setStateValidityChecker([&](const ob::State* s) { return checker.free(s); });
    ss.getSpaceInformation()->setMotionValidator(std::make_shared<Exact_motion_validator>(ss.getSpaceInformation(), &checker));
    ob::ScopedState<> s(space), g(space);
    for (int c = 0; c < 3; ++c) { s[c] = scene.start[c]; g[c] = scene.goal[c]; }
    ss.setStartAndGoalStates(s, g);
    if (planner == "prm") ss.setPlanner(std::make_shared<og::PRM>(ss.getSpaceInformation()));
    else ss.setPlanner(std::make_shared<og::RRTConnect>(ss.getSpaceInformation()));
    const auto t0 = std::chrono::steady_clock::now();
    const ob::PlannerStatus st = ss.solve(time_limit);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    solved = st == ob::PlannerStatus::EXACT_SOLUTION;
    if (solved)
      for (const ob::State* x : ss.getSolutionPath().getStates()) path.push_back(Exact_checker::point(x));
  }
  // Independent re-check of the returned path with the exact segment test (axes chain).
  bool verified = solved;
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    length += std::sqrt(std::pow(path[i + 1][0] - path[i][0], 2) + std::pow(path[i + 1][1] - path[i][1], 2) +
                        std::pow(path[i + 1][2] - path[i][2], 2));
    if (planner != "pmsum") verified = verified && checker.cd->is_free(path[i], path[i + 1], {});
  }
  std::cout << "{\"problem\": \"" << problem << "\", \"planner\": \"" << planner << "\", \"seed\": " << seed
            << ", \"time_limit\": " << time_limit << ", \"solved\": " << (solved ? "true" : "false")
            << ", \"seconds\": " << seconds << ", \"path_vertices\": " << path.size() << ", \"length\": " << length
            << ", \"verified\": " << (verified ? "true" : "false") << "}\n";
  return 0;
}
