// Penetration depth: CGAL_pmsum against FCL (GJK/EPA on convex meshes), side by side, on convex
// pairs whose exact depth is known (distance to the nearest facet plane of the hull of q - p).
//   pd_vs_fcl [OUT.md]       prints (and writes) a markdown table
#include "../test/reference.h" // exact convex references (and the procedural shapes)

#include <CGAL_pmsum/Penetration_depth.h>

#include <CGAL/Random.h>

#include <fcl/fcl.h>

#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace pmsum_shapes;
using Mesh = CGAL::Surface_mesh<IK::Point_3>;

namespace {

std::shared_ptr<fcl::Convexd> to_fcl(const Soup& s)
{
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>();
  for (const auto& p : s.points) vertices->emplace_back(p[0], p[1], p[2]);
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& t : s.triangles) faces->insert(faces->end(), {3, int(t[0]), int(t[1]), int(t[2])});
  return std::make_shared<fcl::Convexd>(vertices, int(s.triangles.size()), faces);
}

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv)
{
  std::ostringstream md;
  md << "# Penetration depth: CGAL_pmsum against FCL\n\n"
     << "Convex pairs (random polytopes on a 1/1024 grid), 2000 random translations t each, of which those "
        "where P + t overlaps Q are measured. Exact depth: distance from t to the nearest facet plane of the "
        "exact hull of q - p. Ours: contact space at d = 0.5% of its diagonal, kd-tree query (and with the "
        "exact overlap test). FCL 0.7: `collide` with one contact, with its libccd solver (MPR) and its own "
        "GJK/EPA solver (indep). Error: the largest |depth - exact depth| over the overlapping t.\n\n"
     << "| pair | vertices P+Q | overlapping t | ours: max error / d | ours: max error | ours µs (kd-tree) | "
        "ours µs (exact overlap + kd-tree) | FCL libccd: max error | misses | µs | FCL indep: max error | misses | µs |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (unsigned seed : {21u, 22u, 23u}) {
    const Soup ps = random_convex(20 + 10 * int(seed % 3), seed), qs = transformed(random_convex(30, seed + 7), 0.7);
    const Mesh P = to_mesh<Mesh>(ps), Q = to_mesh<Mesh>(qs);
    // exact contact space (convex): hull of q - p
    const Reference reference(ps, qs, /*negate_p=*/true);
    const Exact_convex& contact = reference.pieces.front();
    CGAL::Bbox_3 box;
    for (const auto& v : contact.vertices) box += v.bbox();
    const double diag = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                                  std::pow(box.zmax() - box.zmin(), 2));
    const double d = 0.005 * diag;
    auto pd = CGAL::Penetration_depth<Mesh, Mesh>::make(P, Q, d);

    CGAL::Random rng(seed);
    std::vector<IK::Point_3> ts;
    std::vector<double> exact;
    for (int i = 0; i < 2000; ++i) {
      const IK::Point_3 t(rng.get_double(box.xmin(), box.xmax()), rng.get_double(box.ymin(), box.ymax()),
                          rng.get_double(box.zmin(), box.zmax()));
      if (const auto depth = contact.depth(EK::Point_3(t.x(), t.y(), t.z()))) {
        ts.push_back(t);
        exact.push_back(*depth);
      }
    }

    double ours_err = 0;
    auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < ts.size(); ++i) ours_err = (std::max)(ours_err, std::abs(pd.nearest_contact(ts[i]).depth - exact[i]));
    const double ours_us = seconds_since(start) / double(ts.size()) * 1e6;
    start = std::chrono::steady_clock::now();
    for (const auto& t : ts) (void)pd.query(t);
    const double ours_exact_us = seconds_since(start) / double(ts.size()) * 1e6;

    // FCL: P translated by t against Q, with both of its solvers
    const auto fp = to_fcl(ps), fq = to_fcl(qs);
    struct Fcl_run { double err = 0, us = 0; std::size_t misses = 0; };
    auto run_fcl = [&](fcl::GJKSolverType solver) {
      fcl::CollisionRequestd request(1, true);
      request.gjk_solver_type = solver;
      Fcl_run r;
      std::vector<double> depth(ts.size(), -1);
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < ts.size(); ++i) {
        fcl::Transform3d tp = fcl::Transform3d::Identity();
        tp.translation() = fcl::Vector3d(ts[i].x(), ts[i].y(), ts[i].z());
        fcl::CollisionObjectd op(fp, tp), oq(fq, fcl::Transform3d::Identity());
        fcl::CollisionResultd result;
        fcl::collide(&op, &oq, request, result);
        if (result.isCollision() && result.numContacts() > 0) depth[i] = result.getContact(0).penetration_depth;
      }
      r.us = seconds_since(t0) / double(ts.size()) * 1e6;
      for (std::size_t i = 0; i < ts.size(); ++i) {
        if (depth[i] < 0) { ++r.misses; continue; }
        r.err = (std::max)(r.err, std::abs(depth[i] - exact[i]));
      }
      return r;
    };
    const Fcl_run ccd = run_fcl(fcl::GJKSolverType::GST_LIBCCD), indep = run_fcl(fcl::GJKSolverType::GST_INDEP);
    md << std::setprecision(3) << "| random " << seed << " | " << ps.points.size() << "+" << qs.points.size() << " | "
       << ts.size() << " | " << ours_err / d << " | " << ours_err << " | " << ours_us << " | " << ours_exact_us << " | "
       << ccd.err << " | " << ccd.misses << " | " << ccd.us << " | " << indep.err << " | " << indep.misses << " | "
       << indep.us << " |\n";
  }
  std::cout << md.str();
  if (argc > 1) std::ofstream(argv[1]) << md.str();
  return 0;
}
