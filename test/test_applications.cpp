// Applications: offset and erosion against exact answers.
#include "test_support.h"
#include "suite_shapes.h"

#include <CGAL_pmsum/point_offset.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Random.h>
#include <CGAL/intersections.h>

#include <boost/property_map/function_property_map.hpp>

#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

#include <catch2/catch.hpp>

using namespace pmsum_shapes;

namespace {
/// Distance from x to the surface of the box [lo, hi].
double distance_to_box_surface(const IK::Point_3& x, double lo, double hi)
{
  double out = 0, in = HUGE_VAL;
  for (int c = 0; c < 3; ++c) {
    const double e = (std::max)({lo - x[c], 0., x[c] - hi});
    out += e * e;
    in = (std::min)({in, x[c] - lo, hi - x[c]});
  }
  return out > 0 ? std::sqrt(out) : in;
}
} // namespace

TEST_CASE("icosphere: vertices on the sphere, inradius within the error", "[applications][offset]")
{
  for (double e : {0.2, 0.02, 0.005}) {
    Mesh s;
    const double inner = CGAL::make_icosphere(0.5, e, s);
    CHECK(inner >= (1 - e) * 0.5);
    CHECK(inner < 0.5);
    CHECK(CGAL::is_closed(s));
    CHECK(CGAL::Polygon_mesh_processing::is_outward_oriented(s));
    for (auto v : s.vertices()) CHECK(std::abs(std::sqrt((s.point(v) - CGAL::ORIGIN).squared_length()) - 0.5) < 1e-15);
  }
}

TEST_CASE("offset of a box by a ball: distance r, exact, covered", "[applications][offset]")
{
  const double r = 0.25, d = 0.1;
  Mesh ball;
  const double inner = CGAL::make_icosphere(r, 0.02, ball);
  const Mesh cube = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  std::vector<Record> recs;
  CGAL::point_offset(cube, ball, d, std::back_inserter(recs));
  REQUIRE(recs.size() > 1000);
  // every point at distance in [inner, r] from the box (the ball's polygonal error)
  for (const auto& rec : recs) {
    const double dist = distance_to_box_surface(rec.point, 0, 1);
    REQUIRE(dist >= inner - 1e-12);
    REQUIRE(dist <= r + 1e-12);
  }
  // exact: box + convex ball is the hull of the vertex sums
  Soup ball_soup;
  for (auto v : ball.vertices()) ball_soup.points.push_back({ball.point(v).x(), ball.point(v).y(), ball.point(v).z()});
  ball_soup.convex_pieces.push_back(ball_soup.points);
  const Reference ref(box({0, 0, 0}, {1, 1, 1}), ball_soup);
  std::size_t bad = 0;
  for (const auto& rec : recs)
    bad += !ref.on_boundary(CGAL::Pmsum::exact_point<EK>(rec, get(CGAL::vertex_point, cube), get(CGAL::vertex_point, ball)));
  CHECK(bad == 0);
  // covered: the true offset surface (box faces pushed out, quarter cylinders, ball corners)
  // is within r - inner of the polyhedral one, so within d + (r - inner) of the points.
  std::vector<IK::Point_3> pts, truth;
  for (const auto& rec : recs) pts.push_back(rec.point);
  const int n = 40;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      // faces
      truth.emplace_back(u, v, -r); truth.emplace_back(u, v, 1 + r);
      truth.emplace_back(u, -r, v); truth.emplace_back(u, 1 + r, v);
      truth.emplace_back(-r, u, v); truth.emplace_back(1 + r, u, v);
      // the edge along x at y = z = 0: quarter cylinder; the corner at the origin: ball octant
      const double a = v * 1.5707963267948966, b = u * 1.5707963267948966;
      truth.emplace_back(u, -r * std::cos(a), -r * std::sin(a));
      truth.emplace_back(-r * std::cos(a) * std::cos(b), -r * std::sin(a) * std::cos(b), -r * std::sin(b));
    }
  CHECK(coverage_distance(truth, pts) < d + (r - inner));
}

TEST_CASE("offset by a cube is exact", "[applications][offset]")
{
  const Mesh cube = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1})), c = to_mesh<Mesh>(box({-0.2, -0.2, -0.2}, {0.2, 0.2, 0.2}));
  std::vector<IK::Point_3> pts;
  CGAL::point_offset(cube, c, 0.1, std::back_inserter(pts));
  REQUIRE(!pts.empty());
  for (const auto& p : pts) {
    double m = 0;
    for (int k = 0; k < 3; ++k) m = (std::max)(m, std::abs(p[k] - 0.5));
    REQUIRE(m == Approx(0.7).margin(1e-15)); // boundary of [-0.2, 1.2]^3
  }
}

TEST_CASE("erosion of a box by a ball: exact box, covered", "[applications][erosion]")
{
  using EMesh = CGAL::Surface_mesh<EK::Point_3>;
  const double r = 0.2, d = 0.08;
  EMesh ball;
  CGAL::make_icosphere(r, 0.02, ball);
  const EMesh cube = to_mesh<EMesh>(box({0, 0, 0}, {1, 1, 1}));
  std::vector<EK::Point_3> pts;
  CGAL::point_erosion(cube, ball, d, std::back_inserter(pts));
  REQUIRE(pts.size() > 100);
  // {x : B + x inside [0,1]^3} = prod [-min_c B, 1 - max_c B], exactly
  EK::FT lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (auto v : ball.vertices())
    for (int c = 0; c < 3; ++c) {
      lo[c] = (std::min)(lo[c], ball.point(v)[c]);
      hi[c] = (std::max)(hi[c], ball.point(v)[c]);
    }
  std::size_t bad = 0;
  for (const auto& x : pts) {
    bool inside = true, on = false;
    for (int c = 0; c < 3; ++c) {
      inside = inside && -lo[c] <= x[c] && x[c] <= 1 - hi[c];
      on = on || x[c] == -lo[c] || x[c] == 1 - hi[c];
    }
    bad += !(inside && on);
  }
  CHECK(bad == 0);
  // covered: the faces of the eroded box
  std::vector<IK::Point_3> dp, truth;
  for (const auto& x : pts) dp.emplace_back(CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()));
  double l[3], h[3];
  for (int c = 0; c < 3; ++c) { l[c] = CGAL::to_double(-lo[c]); h[c] = CGAL::to_double(1 - hi[c]); }
  const int n = 30;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      for (int c = 0; c < 3; ++c)
        for (double side : {l[c], h[c]}) {
          double p[3];
          p[c] = side;
          p[(c + 1) % 3] = l[(c + 1) % 3] + u * (h[(c + 1) % 3] - l[(c + 1) % 3]);
          p[(c + 2) % 3] = l[(c + 2) % 3] + v * (h[(c + 2) % 3] - l[(c + 2) % 3]);
          truth.emplace_back(p[0], p[1], p[2]);
        }
    }
  CHECK(coverage_distance(truth, dp) < d);
}

TEST_CASE("erosion needs a closed mesh", "[applications][erosion]")
{
  const Mesh open = to_mesh<Mesh>(open_box({0, 0, 0}, {1, 1, 1}));
  Mesh ball;
  CGAL::make_icosphere(0.1, 0.05, ball);
  std::vector<IK::Point_3> pts;
  CHECK_THROWS_AS(CGAL::point_erosion(open, ball, 0.1, std::back_inserter(pts)), CGAL::Pmsum::Invalid_input);
}

#include <CGAL_pmsum/Penetration_depth.h>

#include <CGAL/Random.h>
#include <CGAL/convex_hull_3.h>

#include <thread>

TEST_CASE("penetration depth of convex pairs: within d of the exact depth", "[applications][pd]")
{
  for (unsigned seed : {11u, 12u}) {
    const Soup ps = random_convex(10, seed), qs = transformed(random_convex(12, seed + 50), 0.8);
    const Mesh P = to_mesh<Mesh>(ps), Q = to_mesh<Mesh>(qs);
    const double d = 0.05;
    auto pd = CGAL::Penetration_depth<Mesh, Mesh>::make(P, Q, d);
    REQUIRE(pd.number_of_contact_points() > 1000);
    // exact contact space: hull of q - p; PD(t) = min over its facets of the distance to the plane
    const Reference reference(ps, qs, /*negate_p=*/true);
    const Exact_convex& contact = reference.pieces.front();
    CGAL::Random rng(seed);
    std::size_t inside = 0;
    for (int i = 0; i < 300; ++i) {
      const IK::Point_3 t(rng.get_double(-2, 2), rng.get_double(-2, 2), rng.get_double(-2, 2));
      const std::optional<double> exact = contact.depth(EK::Point_3(t.x(), t.y(), t.z()));
      const auto r = pd.query(t);
      REQUIRE(r.overlapping == bool(exact));
      if (!exact) { REQUIRE(r.depth == 0); continue; }
      ++inside;
      REQUIRE(r.depth >= *exact - 1e-9);
      REQUIRE(r.depth < *exact + d);
      // the translation reaches the contact space: the contact point is exact, its double
      // rounding may be 1e-16 inside; just beyond it (the sum is convex) P and Q are apart
      REQUIRE(!pd.overlaps(r.contact + 1e-9 * r.direction));
    }
    CHECK(inside > 10);
  }
}

namespace {
/// The smallest squared distance from q to the points, by brute force, computed as the tree does.
double brute_force_nearest(const std::vector<double>& xyz, const double* q)
{
  double best = HUGE_VAL;
  for (std::size_t i = 0; i < xyz.size(); i += 3) best = (std::min)(best, CGAL::Pmsum::internal::squared_distance(&xyz[i], q));
  return best;
}
} // namespace

TEST_CASE("nearest-point tree: the same nearest distance as brute force", "[applications][pd]")
{
  // Points on a sphere, on lattices in three tilted planes (many equal distances), and duplicates;
  // queries far outside, deep inside, near the points and on them.
  CGAL::Random rng(7);
  std::vector<double> xyz;
  for (int i = 0; i < 20000; ++i) {
    const double z = rng.get_double(-1, 1), a = rng.get_double(0, 6.283185307179586), r = std::sqrt(1 - z * z);
    xyz.insert(xyz.end(), {r * std::cos(a), r * std::sin(a), z});
  }
  for (int plane = 0; plane < 3; ++plane)
    for (int i = 0; i < 100; ++i)
      for (int j = 0; j < 60; ++j) {
        const double u = i / 64., v = j / 64.;
        const double p[3][3] = {{u, v, 2}, {2 + u, 0.5 * u, v}, {u + v, u - v, -2 + 0.25 * v}};
        xyz.insert(xyz.end(), p[plane], p[plane] + 3);
      }
  for (int i = 0; i < 300; ++i) xyz.insert(xyz.end(), {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
  const std::size_t n = xyz.size() / 3;
  const CGAL::Pmsum::internal::Nearest_point_tree tree(n, [&](std::size_t i, int a) { return xyz[3 * i + a]; });
  REQUIRE(tree.size() == n);
  std::size_t mismatches = 0;
  for (int i = 0; i < 2000; ++i) {
    double q[3];
    const double scale = i % 4 == 0 ? 1000 : i % 4 == 1 ? 0.3 : 3; // far, inside the sphere, around
    for (double& c : q) c = rng.get_double(-scale, scale);
    if (i % 10 == 9) { // on a point, or next to one
      const std::size_t j = std::size_t(rng.get_int(0, int(n)));
      for (int a = 0; a < 3; ++a) q[a] = xyz[3 * j + a] + (i % 20 == 9 ? 0 : rng.get_double(-1e-3, 1e-3));
    }
    const auto r = tree.nearest(q);
    const double expected = brute_force_nearest(xyz, q);
    mismatches += r.second != expected || CGAL::Pmsum::internal::squared_distance(&xyz[3 * r.first], q) != expected;
  }
  CHECK(mismatches == 0);
  // one point; all points equal
  const std::vector<double> one = {1, 2, 3};
  const CGAL::Pmsum::internal::Nearest_point_tree t1(1, [&](std::size_t i, int a) { return one[3 * i + a]; });
  const double q[3] = {1, 2, 5};
  CHECK(t1.nearest(q).first == 0);
  CHECK(t1.nearest(q).second == 4);
  const CGAL::Pmsum::internal::Nearest_point_tree same(500, [&](std::size_t, int a) { return one[a]; });
  CHECK(same.nearest(q).second == 4);
}

/// The greedy net of spacing d/2 of 3,000 random points of a slab 12 x 12 x 2.
static CGAL::Pmsum::internal::Covering_net random_net(double d, CGAL::Random& rng)
{
  std::vector<CGAL::Pmsum::internal::Point3> random;
  for (int i = 0; i < 3000; ++i) random.push_back({rng.get_double(-6, 6), rng.get_double(-6, 6), rng.get_double(-1, 1)});
  CGAL::Pmsum::internal::Covering_net net(d, 8);
  for (std::size_t i : CGAL::Pmsum::internal::greedy_net(random, d)) net.insert(random[i]);
  return net;
}

TEST_CASE("covering net: covers_all finds a point closer than r to all three corners iff brute force does", "[applications][net]")
{
  using CGAL::Pmsum::internal::Point3;
  const double d = 1;
  CGAL::Random rng(11);
  const CGAL::Pmsum::internal::Covering_net net = random_net(d, rng);
  REQUIRE(net.size() > 200);
  // Random triangles (sides up to d): covered only if brute force finds a point closer than r
  // to each corner, and not covered only if it finds none closer than r minus a rounding margin.
  std::size_t found = 0, missed = 0, wrong = 0;
  for (int i = 0; i < 4000; ++i) {
    const double r = i % 2 ? d : d / 2;
    const Point3 a{rng.get_double(-6, 6), rng.get_double(-6, 6), rng.get_double(-1, 1)};
    std::array<Point3, 3> t{a, a, a};
    for (int k = 1; k < 3; ++k)
      for (int c = 0; c < 3; ++c) t[k][c] += rng.get_double(-0.5, 0.5) * d;
    auto within = [&](const Point3& y, double s) {
      return std::all_of(t.begin(), t.end(), [&](const Point3& x) {
        return CGAL::Pmsum::internal::squared_distance(x.data(), y.data()) < s * s;
      });
    };
    if (net.covers_all(t, r)) {
      ++found;
      bool any = false;
      for (std::size_t j = 0; j < net.size(); ++j) any = any || within(net.point(j), r);
      wrong += !any;
    } else {
      for (std::size_t j = 0; j < net.size(); ++j) missed += within(net.point(j), r - 1e-12);
    }
  }
  CHECK(wrong == 0);
  CHECK(missed == 0);
  CHECK(found > 400);
  // At the edge: corners at 0.999 r of a point are covered by it, one at 1.001 r is not.
  CGAL::Pmsum::internal::Covering_net one(d, 8);
  const Point3 y{0.3, -0.2, 0.1};
  one.insert(y);
  auto at = [&](const Point3& unit, double s) { return Point3{y[0] + s * unit[0], y[1] + s * unit[1], y[2] + s * unit[2]}; };
  const Point3 u{0.6, 0.8, 0}, v{0, 0.6, 0.8}, w{-0.8, 0, 0.6};
  for (double s : {0.999, 1.001}) {
    const std::array<Point3, 3> t{at(u, 0.999 * d), at(v, 0.999 * d), at(w, s * d)};
    CHECK(one.covers_all(t, d) == (s < 1));
  }
  CHECK(!CGAL::Pmsum::internal::Covering_net(d, 8).covers_all({y, y, y}, d)); // an empty net covers nothing
}

TEST_CASE("covering net: covers_all_parts covers every point of the triangle, and more triangles than covers_all",
          "[applications][net]")
{
  using CGAL::Pmsum::internal::Point3;
  const double d = 1;
  CGAL::Random rng(12);
  const CGAL::Pmsum::internal::Covering_net net = random_net(d, rng);
  std::vector<Point3> points;
  for (std::size_t j = 0; j < net.size(); ++j) points.push_back(net.point(j));
  // Is every point of a 24 x 24 barycentric grid of t closer than r to a point of the net?
  auto brute_force = [&](const std::array<Point3, 3>& t, double r) {
    const int n = 24;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        Point3 x;
        for (int c = 0; c < 3; ++c) x[c] = (t[0][c] * (n - i - j) + t[1][c] * i + t[2][c] * j) / n;
        if (std::none_of(points.begin(), points.end(), [&](const Point3& y) {
              return CGAL::Pmsum::internal::squared_distance(x.data(), y.data()) < r * r;
            }))
          return false;
      }
    return true;
  };
  std::size_t parts = 0, whole = 0, wrong = 0, depth0 = 0;
  for (int i = 0; i < 1500; ++i) {
    const Point3 a{rng.get_double(-5, 5), rng.get_double(-5, 5), rng.get_double(-1, 1)};
    std::array<Point3, 3> t{a, a, a};
    for (int k = 1; k < 3; ++k)
      for (int c = 0; c < 3; ++c) t[k][c] += rng.get_double(-1, 1) * d;
    const bool by_parts = net.covers_all_parts(t, d, 2), by_one = net.covers_all(t, d);
    depth0 += net.covers_all_parts(t, d, 0) != by_one;
    CHECK((by_one <= by_parts)); // a triangle one point covers is covered in parts too
    parts += by_parts;
    whole += by_one;
    if (by_parts) wrong += !brute_force(t, d);
  }
  CHECK(wrong == 0);
  CHECK(depth0 == 0);
  CHECK(parts > whole + 100);
  // Two points 1.6 d apart: a thin triangle along them is covered by neither alone, by the two
  // in parts cut three times (not twice); one with a corner 1.06 d from both is not.
  CGAL::Pmsum::internal::Covering_net two(d, 8);
  two.insert({0, 0, 0});
  two.insert({1.6 * d, 0, 0});
  const std::array<Point3, 3> thin{Point3{-0.5 * d, 0, 0}, Point3{2.1 * d, 0, 0}, Point3{0.8 * d, 0.1 * d, 0}};
  CHECK(!two.covers_all(thin, d));
  CHECK(!two.covers_all_parts(thin, d, 2));
  CHECK(two.covers_all_parts(thin, d, 3));
  const std::array<Point3, 3> far{Point3{-0.5 * d, 0, 0}, Point3{2.1 * d, 0, 0}, Point3{0.8 * d, 0.7 * d, 0}};
  CHECK(!two.covers_all_parts(far, d, 6));
}

TEST_CASE("penetration depth: nearest_contact is the nearest contact point", "[applications][pd]")
{
  const Soup ps = random_convex(10, 21), qs = transformed(random_convex(12, 71), 0.8);
  auto pd = CGAL::Penetration_depth<Mesh, Mesh>::make(to_mesh<Mesh>(ps), to_mesh<Mesh>(qs), 0.05);
  std::vector<double> xyz;
  for (const auto& p : pd.contact_points()) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  CGAL::Random rng(5);
  std::size_t mismatches = 0, overlapping = 0;
  for (int i = 0; i < 500; ++i) {
    const double scale = i % 3 == 0 ? 100 : i % 3 == 1 ? 0.2 : 3; // far outside, deep inside, around
    const IK::Point_3 t(rng.get_double(-scale, scale), rng.get_double(-scale, scale), rng.get_double(-scale, scale));
    const double q[3] = {t.x(), t.y(), t.z()};
    const auto r = pd.nearest_contact(t);
    const double c[3] = {r.contact.x(), r.contact.y(), r.contact.z()};
    const double expected = brute_force_nearest(xyz, q);
    mismatches += r.depth != std::sqrt(expected) || CGAL::Pmsum::internal::squared_distance(c, q) != expected;
    overlapping += pd.overlaps(t);
  }
  CHECK(mismatches == 0);
  CHECK(overlapping > 50);

  // copies have their own overlap test state: one copy per thread gives the sequential answers
  std::vector<IK::Point_3> ts;
  for (int i = 0; i < 300; ++i) ts.emplace_back(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
  std::vector<double> expected;
  for (const auto& t : ts) expected.push_back(pd.query(t).depth);
  std::vector<double> got[2];
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&, k, copy = pd]() mutable {
      for (const auto& t : ts) got[k].push_back(copy.query(t).depth);
    });
  for (auto& th : threads) th.join();
  CHECK(got[0] == expected);
  CHECK(got[1] == expected);
}

#include <CGAL_pmsum/point_sweep.h>

TEST_CASE("sweep of a cube along a segment is the exact convex box sweep", "[applications][sweep]")
{
  using EMesh = CGAL::Surface_mesh<EK::Point_3>;
  const Soup cube = box({0, 0, 0}, {1, 1, 1});
  const EMesh P = to_mesh<EMesh>(cube);
  const std::vector<EK::Point_3> path = {EK::Point_3(0, 0, 0), EK::Point_3(2, 1, 0.5)};
  const double d = 0.1;
  std::vector<EK::Point_3> pts;
  CGAL::point_sweep(P, path, d, std::back_inserter(pts));
  REQUIRE(pts.size() > 500);
  Soup seg;
  seg.convex_pieces.push_back({{0, 0, 0}, {2, 1, 0.5}});
  const Reference ref(cube, seg); // hull of the cube at both ends
  std::size_t bad = 0;
  for (const auto& x : pts) bad += !ref.on_boundary(x);
  CHECK(bad == 0);
  std::vector<IK::Point_3> dp;
  for (const auto& x : pts) dp.emplace_back(CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()));
  CHECK(coverage_distance(ref.boundary_samples(d / 8), dp) < d);
}

TEST_CASE("sweep along an L-shaped polyline", "[applications][sweep]")
{
  const Soup cube = box({0, 0, 0}, {0.5, 0.5, 0.5});
  const Mesh P = to_mesh<Mesh>(cube);
  const std::vector<IK::Point_3> path = {IK::Point_3(0, 0, 0), IK::Point_3(2, 0, 0), IK::Point_3(2, 2, 0)};
  const double d = 0.1;
  std::vector<IK::Point_3> pts;
  CGAL::point_sweep(P, path, d, std::back_inserter(pts));
  Soup legs;
  legs.convex_pieces.push_back({{0, 0, 0}, {2, 0, 0}});
  legs.convex_pieces.push_back({{2, 0, 0}, {2, 2, 0}});
  const Reference ref(cube, legs); // union of two box sweeps
  REQUIRE(!pts.empty());
  // the swept volume is the union of [0,2.5]x[0,0.5]x[0,0.5] and [2,2.5]x[0,2.5]x[0,0.5]
  for (const auto& p : pts) {
    const bool in_a = p.x() >= 0 && p.x() <= 2.5 && p.y() >= 0 && p.y() <= 0.5;
    const bool in_b = p.x() >= 2 && p.x() <= 2.5 && p.y() >= 0 && p.y() <= 2.5;
    REQUIRE((in_a || in_b));
    REQUIRE((p.z() >= 0 && p.z() <= 0.5));
  }
  CHECK(coverage_distance(ref.boundary_samples(d / 8), pts) < d);
}

TEST_CASE("sweep rejects a bad path", "[applications][sweep]")
{
  const Mesh P = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  std::vector<IK::Point_3> pts;
  const std::vector<IK::Point_3> one = {IK::Point_3(0, 0, 0)};
  const std::vector<IK::Point_3> repeated = {IK::Point_3(0, 0, 0), IK::Point_3(0, 0, 0), IK::Point_3(1, 0, 0)};
  CHECK_THROWS_AS(CGAL::point_sweep(P, one, 0.1, std::back_inserter(pts)), CGAL::Pmsum::Invalid_input);
  CHECK_THROWS_AS(CGAL::point_sweep(P, repeated, 0.1, std::back_inserter(pts)), CGAL::Pmsum::Invalid_input);
  CHECK(pts.empty());
}

// One API style: every entry point takes named parameters, ours and CGAL's in any order
// once the chain starts with one of ours, and fills the statistics it is given.
TEST_CASE("named parameters: any order, every entry point, statistics and vertex point maps", "[applications][api]")
{
  const Soup cube = box({0, 0, 0}, {1, 1, 1});
  const Mesh P = to_mesh<Mesh>(cube), Q = to_mesh<Mesh>(box({0, 0, 0}, {0.5, 0.25, 0.5}));
  const double d = 0.2;
  int calls = 0;
  const std::function<bool(double)> progress = [&calls](double) { ++calls; return true; };
  CGAL::Pmsum::Statistics s1, s2;
  std::vector<IK::Point_3> a, b;
  CGAL::point_minkowski_sum(P, Q, d, std::back_inserter(a),
                            CGAL::parameters::statistics(s1).callback(progress).use_octree_filter(true));
  CGAL::point_minkowski_sum(P, Q, d, std::back_inserter(b),
                            CGAL::parameters::use_octree_filter(true)
                              .callback(progress)
                              .vertex_point_map(get(CGAL::vertex_point, P))
                              .statistics(s2));
  CHECK(a == b);
  CHECK(s1.output_points == a.size());
  CHECK(s2.output_points == b.size());
  CHECK(calls > 0);

  // A vertex point map that moves P by (1, 2, 3) moves the sum: the box [1, 2.5] x [2, 3.25] x [3, 4.5].
  const IK::Vector_3 shift(1, 2, 3);
  auto moved = [&](Mesh::Vertex_index v) { return P.point(v) + shift; };
  const auto vpm = boost::make_function_property_map<Mesh::Vertex_index, IK::Point_3>(moved);
  std::vector<IK::Point_3> c;
  CGAL::point_offset(P, Q, d, std::back_inserter(c), CGAL::parameters::vertex_point_map(vpm));
  CHECK(c.size() > 0);
  const double lo[3] = {1, 2, 3}, hi[3] = {2.5, 3.25, 4.5};
  std::size_t off = 0;
  for (const auto& x : c) {
    bool inside = true, on_face = false;
    for (int k = 0; k < 3; ++k) {
      inside = inside && x[k] >= lo[k] - 1e-12 && x[k] <= hi[k] + 1e-12;
      on_face = on_face || std::abs(x[k] - lo[k]) < 1e-12 || std::abs(x[k] - hi[k]) < 1e-12;
    }
    off += !(inside && on_face);
  }
  CHECK(off == 0);

  // The sweep, the penetration depth and the planner fill the core's statistics too.
  CGAL::Pmsum::Statistics s3, s4, s5;
  std::vector<IK::Point_3> swept;
  const std::vector<IK::Point_3> path = {IK::Point_3(0, 0, 0), IK::Point_3(1, 0, 0)};
  CGAL::point_sweep(P, path, d, std::back_inserter(swept), CGAL::parameters::statistics(s3));
  CHECK(s3.output_points == swept.size());
  CHECK(swept.size() > 0);
  auto pd = CGAL::Penetration_depth<Mesh, Mesh>::make(P, Q, d, CGAL::parameters::statistics(s4).vertex_point_map(vpm));
  CHECK(s4.output_points == pd.number_of_contact_points());
  // moved by (1, 2, 3), the robot P overlaps Q at t = -(1, 2, 3) + (0.1, 0.1, 0.1), and not at t = 0
  CHECK(pd.overlaps(IK::Point_3(-0.9, -1.9, -2.9)));
  CHECK_FALSE(pd.overlaps(IK::Point_3(0, 0, 0)));
}

#include <CGAL_pmsum/point_set_3.h>

#include <CGAL/Point_set_3/IO.h>

#include <sstream>

TEST_CASE("records into a Point_set_3: points, normals, provenance, PLY", "[applications][api]")
{
  const Mesh P = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1})), Q = to_mesh<Mesh>(box({0, 0, 0}, {0.5, 0.5, 0.5}));
  std::vector<CGAL::Pmsum::Minkowski_sum_boundary_point<Mesh, Mesh, IK>> recs;
  CGAL::point_minkowski_sum(P, Q, 0.2, std::back_inserter(recs));
  REQUIRE(recs.size() > 0);
  CGAL::Point_set_3<IK::Point_3> ps;
  const auto maps = CGAL::Pmsum::insert_into_point_set(recs, ps);
  REQUIRE(ps.size() == recs.size());
  REQUIRE(ps.has_normal_map());
  std::size_t i = 0;
  for (auto it = ps.begin(); it != ps.end(); ++it, ++i) {
    CHECK(ps.point(*it) == recs[i].point);
    CHECK(ps.normal(*it) == recs[i].normal);
    CHECK(get(maps.origin_p, *it).dimension == recs[i].origin_p.dimension);
    CHECK(get(maps.origin_q, *it).face == recs[i].origin_q.face);
    CHECK(get(maps.origin_q_dimension, *it) == recs[i].origin_q.dimension);
    CHECK(get(maps.on_trim_curve, *it) == int(recs[i].on_trim_curve));
  }
  // the dimensions travel through PLY
  std::stringstream ply;
  REQUIRE(CGAL::IO::write_PLY(ply, ps, CGAL::parameters::stream_precision(17)));
  CGAL::Point_set_3<IK::Point_3> back;
  REQUIRE(CGAL::IO::read_PLY(ply, back));
  REQUIRE(back.size() == ps.size());
  auto dim = back.property_map<int>("origin_p_dimension");
  REQUIRE(dim.second);
  i = 0;
  for (auto it = back.begin(); it != back.end(); ++it, ++i) CHECK(get(dim.first, *it) == recs[i].origin_p.dimension);
}

#include <CGAL_pmsum/point_minkowski_sum_mesh.h>
#include <CGAL_pmsum/point_offset_mesh.h>
#include <CGAL_pmsum/point_sweep_mesh.h>

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

TEST_CASE("check_mesh: border, self-intersection, orientation, voids", "[applications][mesh]")
{
  using CGAL::Pmsum::check_mesh;
  const auto c1 = check_mesh(to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1})));
  CHECK(c1.valid());
  CHECK(c1.shells == 1);
  CHECK(c1.void_shells == 0);
  CHECK_FALSE(check_mesh(to_mesh<Mesh>(open_box({0, 0, 0}, {1, 1, 1}))).closed);
  Soup crossing = box({0, 0, 0}, {1, 1, 1});
  crossing.append(box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  const auto c2 = check_mesh(to_mesh<Mesh>(crossing));
  CHECK(c2.closed);
  CHECK_FALSE(c2.self_intersection_free);
  CHECK_FALSE(c2.valid());
  // a box with a cubic void: inward inner shell
  Mesh hollow = to_mesh<Mesh>(box({0, 0, 0}, {3, 3, 3}));
  Mesh inner = to_mesh<Mesh>(box({1, 1, 1}, {2, 2, 2}));
  CGAL::Polygon_mesh_processing::reverse_face_orientations(inner);
  hollow.join(inner);
  const auto c3 = check_mesh(hollow);
  CHECK(c3.valid());
  CHECK(c3.shells == 2);
  CHECK(c3.void_shells == 1);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(hollow); // inside out
  CHECK_FALSE(check_mesh(hollow).bounds_a_volume);
}

TEST_CASE("mesh of a sum: valid, vertices exactly on the boundary, within d of it", "[applications][mesh]")
{
  // [0, 1]^3 + [0, 0.5] x [0, 0.25] x [0, 0.5]: the box [0, 1.5] x [0, 1.25] x [0, 1.5]
  const Mesh P = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1})), Q = to_mesh<Mesh>(box({0, 0, 0}, {0.5, 0.25, 0.5}));
  const double d = 0.1, hi[3] = {1.5, 1.25, 1.5};
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_minkowski_sum_mesh(P, Q, d, m, CGAL::parameters::mesh_statistics(ms));
  const auto c = CGAL::Pmsum::check_mesh(m);
  REQUIRE(c.valid());
  CHECK(c.shells == 1);
  CHECK(ms.checks.valid());
  CHECK(ms.refused.empty() == (!ms.by_planes && ms.refinements == 0 && ms.covering_distance == d)); // (the first mesh taken)
  CHECK(ms.vertices == vertices(m).size());
  CHECK(ms.triangles == faces(m).size());
  CHECK(ms.sum.output_points >= ms.vertices); // the vertices are the sum's points
  // the points the reconstruction left out are near the mesh, and the exact boundary is
  // within the proved bound of it (measured at samples d/8 apart)
  CHECK(ms.point_distance < ms.covering_distance);
  const auto exact_box = CGAL::Pmsum::internal::to_shell(to_mesh<Mesh>(box({0, 0, 0}, {1.5, 1.25, 1.5})));
  CHECK(CGAL::Pmsum::measure_mesh_distance({exact_box}, m, d / 8).surface_to_mesh < ms.boundary_to_mesh_bound());
  // the bound rests on the covering: without trim or island points, refused
  Mesh refused;
  CHECK_THROWS_AS(CGAL::point_minkowski_sum_mesh(P, Q, d, refused, CGAL::parameters::use_trim_points(false)),
                  CGAL::Pmsum::Invalid_input);
  CHECK_THROWS_AS(CGAL::point_minkowski_sum_mesh(P, Q, d, refused, CGAL::parameters::search_islands(false)),
                  CGAL::Pmsum::Invalid_input);
  // every vertex on the box's surface; every point of a triangle within d of it
  auto surface_distance = [&](const IK::Point_3& x) {
    double out = 0, in = HUGE_VAL;
    for (int k = 0; k < 3; ++k) {
      const double e = (std::max)({-x[k], 0., x[k] - hi[k]});
      out += e * e;
      in = (std::min)({in, x[k], hi[k] - x[k]});
    }
    return out > 0 ? std::sqrt(out) : in;
  };
  double worst_vertex = 0, worst = 0;
  for (auto v : m.vertices()) worst_vertex = (std::max)(worst_vertex, surface_distance(m.point(v)));
  for (auto f : m.faces()) {
    std::vector<IK::Point_3> t;
    for (auto v : vertices_around_face(m.halfedge(f), m)) t.push_back(m.point(v));
    for (double a = 0; a <= 1; a += 0.25)
      for (double b = 0; a + b <= 1; b += 0.25) {
        const double g = 1 - a - b;
        worst = (std::max)(worst, surface_distance(IK::Point_3(a * t[0].x() + b * t[1].x() + g * t[2].x(),
                                                               a * t[0].y() + b * t[1].y() + g * t[2].y(),
                                                               a * t[0].z() + b * t[1].z() + g * t[2].z())));
      }
  }
  CHECK(worst_vertex < 1e-12);
  CHECK(worst < d);
  CHECK(ms.mesh_to_boundary_bound < ms.covering_distance); // the bound the mesh was checked with, proved
  CHECK(worst <= ms.mesh_to_boundary_bound);
  // the volume of the mesh is the box's, within the error of cutting its edges by chords
  CHECK(std::abs(CGAL::Polygon_mesh_processing::volume(m) - 1.5 * 1.25 * 1.5) < 0.05);
}

TEST_CASE("mesh of a sum in an exact kernel: valid, every vertex exactly on a face of the sum", "[applications][mesh]")
{
  // (Its vertices are not the doubles the advancing front triangulated: every triangle is
  // searched for crossings, not only those that fill holes.)
  using EMesh = CGAL::Surface_mesh<EK::Point_3>;
  const EMesh P = to_mesh<EMesh>(box({0, 0, 0}, {1, 1, 1})), Q = to_mesh<EMesh>(box({0, 0, 0}, {0.5, 0.25, 0.5}));
  EMesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_minkowski_sum_mesh(P, Q, 0.1, m, CGAL::parameters::mesh_statistics(ms));
  const auto c = CGAL::Pmsum::check_mesh(m);
  REQUIRE(c.valid());
  CHECK(c.shells == 1);
  CHECK(ms.vertices == vertices(m).size());
  const EK::FT hi[3] = {EK::FT(1.5), EK::FT(1.25), EK::FT(1.5)};
  std::size_t off_faces = 0;
  for (auto v : vertices(m)) {
    const EK::Point_3& x = m.point(v);
    bool inside = true, on_face = false;
    for (int k = 0; k < 3; ++k) {
      inside = inside && x[k] >= 0 && x[k] <= hi[k];
      on_face = on_face || x[k] == 0 || x[k] == hi[k];
    }
    off_faces += !(inside && on_face);
  }
  CHECK(off_faces == 0);
  // inside the box (its corners on its surface), missing at most the corners' slivers
  const EK::FT volume = CGAL::Polygon_mesh_processing::volume(m);
  CHECK(volume <= EK::FT(1.5 * 1.25 * 1.5));
  CHECK(volume > EK::FT(2.7));
}

TEST_CASE("mesh of a sum: the same mesh with one thread or two, run after run", "[applications][mesh]")
{
  // The reconstruction meets many equal priorities (cospherical lattice points on flat faces,
  // its own constants for the triangles it puts off); they must not be broken by the order of
  // heap addresses, which a parallel stage leaves different in every run.
  const Mesh P = to_mesh<Mesh>(l_shape()), Q = to_mesh<Mesh>(tetrahedron(0.3));
  const double d = 0.06;
  auto triangles = [](const Mesh& m) { // each from its least vertex (orientation kept), sorted
    std::vector<std::array<std::array<double, 3>, 3>> all;
    for (auto f : m.faces()) {
      std::array<std::array<double, 3>, 3> t;
      int k = 0;
      for (auto v : vertices_around_face(m.halfedge(f), m))
        t[std::size_t(k++)] = {m.point(v).x(), m.point(v).y(), m.point(v).z()};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      all.push_back(t);
    }
    std::sort(all.begin(), all.end());
    return all;
  };
  Mesh sequential;
  CGAL::point_minkowski_sum_mesh(P, Q, d, sequential);
  REQUIRE(CGAL::Pmsum::check_mesh(sequential).valid());
  const auto expected = triangles(sequential);
  for (int run = 0; run < 3; ++run) {
    Mesh parallel;
    CGAL::point_minkowski_sum_mesh<CGAL::Parallel_tag>(P, Q, d, parallel);
    // a bool, not the vectors: Catch would print thousands of triangles (for minutes)
    const auto got = triangles(parallel);
    INFO("run " << run << ": " << got.size() << " triangles, " << expected.size() << " with one thread");
    const bool same = got == expected;
    CHECK(same);
  }
}

TEST_CASE("fill_holes: the same triangles whatever the heap addresses", "[applications][mesh]")
{
  // A hole of 14 nearly coplanar points (on a flat part of a contact space: flat cross - cross,
  // both rotated), each border point with the third corner of the triangle beyond the border
  // edge that ends there. CGAL 5.5's triangulate_hole restricted to a Delaunay triangulation
  // filled it two ways, depending on what had been allocated before (the order of its cells).
  const std::array<std::array<double, 3>, 2> ring[] = {
      {{{{0x1.fcc0e9d72065bp-3, -0x1.4e5dbe0c2b072p-3, -0x1.374d090e14581p-3}}, {{0x1.f8835cc72d4fep-3, -0x1.5363407e1bf97p-3, -0x1.45f1f56233ff1p-3}}}},
      {{{{0x1.0cf3633694bdp-2, -0x1.46c3aace19a2bp-3, -0x1.25ef749122ec5p-3}}, {{0x1.00d27301b9d27p-2, -0x1.51f951fc0761bp-3, -0x1.437fe7991dff8p-3}}}},
      {{{{0x1.1d414943b4d34p-2, -0x1.41b7237bdc0c8p-3, -0x1.1d33b1e6c98e9p-3}}, {{0x1.13a1b95d69cfdp-2, -0x1.509f10fa66b0dp-3, -0x1.4743c1f3bf41ap-3}}}},
      {{{{0x1.2d8f2f50d4e99p-2, -0x1.3caa9c299e765p-3, -0x1.1477ef3c7030cp-3}}, {{0x1.23ef9f6a89e61p-2, -0x1.4b9289a8291aap-3, -0x1.3e87ff4965e3ep-3}}}},
      {{{{0x1.3ddd155df4ffcp-2, -0x1.379e14d760e02p-3, -0x1.0bbc2c9216d3p-3}}, {{0x1.343d8577a9fc5p-2, -0x1.46860255eb847p-3, -0x1.35cc3c9f0c861p-3}}}},
      {{{{0x1.4e2afb6b15161p-2, -0x1.32918d852349fp-3, -0x1.030069e7bd753p-3}}, {{0x1.448b6b84ca129p-2, -0x1.41797b03adee4p-3, -0x1.2d1079f4b3285p-3}}}},
      {{{{0x1.57ca8b5160199p-2, -0x1.23a9a00698a58p-3, -0x1.b1e0b3b58f845p-4}}, {{0x1.5e78e178352c6p-2, -0x1.2d850632e5b3cp-3, -0x1.f4894e7ac82edp-4}}}},
      {{{{0x1.5bfa8f5250c77p-2, -0x1.1a0a9654b5833p-3, -0x1.732d46e4fae79p-4}}, {{0x1.539fcf1ba2dp-2, -0x1.1d83c898b1b8p-3, -0x1.884d866acac88p-4}}}},
      {{{{0x1.539fcf1ba2dp-2, -0x1.1d83c898b1b8p-3, -0x1.884d866acac88p-4}}, {{0x1.57ca8b5160199p-2, -0x1.23a9a00698a58p-3, -0x1.b1e0b3b58f845p-4}}}},
      {{{{0x1.456a9568f50b2p-2, -0x1.25a81c2bf09a8p-3, -0x1.aeaf9db30519cp-4}}, {{0x1.4f25f525c93b3p-2, -0x1.340340efb2adcp-3, -0x1.aa4c12ec58f4fp-4}}}},
      {{{{0x1.37622a5d16fd9p-2, -0x1.2db2c271be7acp-3, -0x1.d498a89df00e5p-4}}, {{0x1.3e40ea7110e69p-2, -0x1.2f552b9200c99p-3, -0x1.c828846d0399fp-4}}}},
      {{{{0x1.1c4e02e2a2f07p-2, -0x1.43743b77df96ep-3, -0x1.124d6f2a9b7aap-3}}, {{0x1.316c5044895a5p-2, -0x1.494dd62cfdf41p-3, -0x1.ff47507461a71p-4}}}},
      {{{{0x1.13b2ab6349797p-2, -0x1.5e986b6a493a6p-3, -0x1.2a2146fe352cap-3}}, {{0x1.2497b61801ce2p-2, -0x1.634680c7fb1e8p-3, -0x1.1b330e3ddfda2p-3}}}},
      {{{{0x1.02cda0ae9124cp-2, -0x1.59ea560c97563p-3, -0x1.390f7fbe8a7f3p-3}}, {{0x1.06de1136c1ed4p-2, -0x1.789116054664fp-3, -0x1.45b0ad01e4335p-3}}}}};
  std::string first;
  for (int run = 0; run < 100; ++run) {
    std::vector<std::unique_ptr<char[]>> noise; // the heap left differently for every run
    for (int k = 0; k < (run * 37) % 200; ++k) noise.emplace_back(new char[std::size_t(16 + (k * 97) % 4000)]);
    noise.clear();
    Mesh m;
    std::vector<Mesh::Vertex_index> border, beyond;
    for (const auto& r : ring) {
      border.push_back(m.add_vertex(IK::Point_3(r[0][0], r[0][1], r[0][2])));
      beyond.push_back(m.add_vertex(IK::Point_3(r[1][0], r[1][1], r[1][2])));
    }
    const std::size_t n = border.size();
    for (std::size_t i = 0; i < n; ++i) REQUIRE(m.add_face(border[i], border[(i + n - 1) % n], beyond[i]) != Mesh::null_face());
    std::vector<Mesh::Face_index> added;
    CGAL::Pmsum::internal::fill_holes(m, 1.0, std::back_inserter(added));
    REQUIRE(added.size() >= n - 2); // (the ring's outer side, 2n edges, is a hole too)
    std::ostringstream triangles;
    for (Mesh::Face_index f : added) {
      for (Mesh::Vertex_index v : m.vertices_around_face(m.halfedge(f))) triangles << std::size_t(v) << ' ';
      triangles << "| ";
    }
    if (run == 0) first = triangles.str();
    INFO("run " << run << ": " << triangles.str() << "; run 0: " << first);
    CHECK(triangles.str() == first);
  }
}

TEST_CASE("fill_hole_by_short_sides: a slit is zipped, with inner sides no longer than needed", "[applications][mesh]")
{
  // A slit between two rows of m + 1 points, spacing s, the rows L apart (a ladder): every
  // triangulation whose inner sides join points of the two rows at most one step apart has
  // m - 1 rungs (L) and m diagonals (sqrt(s^2 + L^2)), and any other inner side is longer (two
  // steps along a row: 2 s). Around the slit, one triangle beyond each border edge.
  const int m = 12;
  const double s = 1, L = 0.5, diagonal = std::sqrt(s * s + L * L);
  auto ladder = [&](Mesh& mesh) {
    std::vector<Mesh::Vertex_index> cycle; // the slit's border: row a forwards, row b backwards
    for (int i = 0; i <= m; ++i) cycle.push_back(mesh.add_vertex(IK::Point_3(i * s, 0, 0)));
    for (int i = m; i >= 0; --i) cycle.push_back(mesh.add_vertex(IK::Point_3(i * s, L, 0)));
    const std::size_t n = cycle.size();
    for (std::size_t k = 0; k < n; ++k) { // beyond the border edge u -> v, away from the slit's middle
      const IK::Point_3 u = mesh.point(cycle[k]), v = mesh.point(cycle[(k + 1) % n]);
      const IK::Vector_3 out = CGAL::midpoint(u, v) - IK::Point_3(m * s / 2, L / 2, 0);
      const auto x = mesh.add_vertex(CGAL::midpoint(u, v) + out / std::sqrt(out.squared_length()));
      REQUIRE(mesh.add_face(cycle[(k + 1) % n], cycle[k], x) != Mesh::null_face());
    }
    return mesh.halfedge(cycle[0], cycle[1]); // (on the slit's side: no face)
  };
  Mesh mesh;
  const auto h = ladder(mesh);
  REQUIRE(mesh.is_border(h));
  std::vector<Mesh::Face_index> added;
  REQUIRE(CGAL::Pmsum::internal::fill_hole_by_short_sides(mesh, h, 2 * diagonal, std::back_inserter(added)));
  CHECK(added.size() == std::size_t(2 * m));
  CHECK(!mesh.is_border(h));
  CHECK(CGAL::is_valid_polygon_mesh(mesh));
  double longest = 0;
  std::size_t inner = 0;
  for (Mesh::Face_index f : added) {
    int in_a = 0; // corners in row a (y = 0): every triangle has one or two
    for (auto c : mesh.halfedges_around_face(mesh.halfedge(f))) {
      in_a += mesh.point(mesh.target(c)).y() == 0;
      if (!mesh.is_border(mesh.opposite(c)) && std::count(added.begin(), added.end(), mesh.face(mesh.opposite(c)))) {
        longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(c)), mesh.point(mesh.target(c)))));
        ++inner;
      }
    }
    CHECK((in_a == 1 || in_a == 2));
  }
  CHECK(inner == std::size_t(2 * (2 * m - 1))); // (each inner side seen from its two triangles)
  CHECK(std::abs(longest - diagonal) < 1e-12);
  // Shorter than the diagonal allowed: no triangulation, the slit left open.
  Mesh open;
  const auto g = ladder(open);
  const std::size_t faces_before = open.number_of_faces();
  added.clear();
  CHECK(!CGAL::Pmsum::internal::fill_hole_by_short_sides(open, g, 0.99 * diagonal, std::back_inserter(added)));
  CHECK(added.empty());
  CHECK(open.number_of_faces() == faces_before);
  CHECK(open.is_border(g));
}

#include <CGAL_pmsum/measure_mesh_distance.h>

TEST_CASE("fill_holes with the points inside: a hole too wide for its border alone", "[applications][mesh]")
{
  // Points on the unit sphere (a Fibonacci lattice, about s apart) joined by their convex hull;
  // the triangles with a corner in a cap of chord radius 0.35 taken away: a hole about 0.7
  // across, every filling of its border alone with an inner side longer than 3 d (d = s), and
  // some 60 points inside it at no vertex.
  const std::size_t count = 2000;
  std::vector<IK::Point_3> points;
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1 - (2 * double(i) + 1) / double(count), r = std::sqrt(1 - z * z), phi = double(i) * 2.399963229728653;
    points.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  Mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  REQUIRE(hull.number_of_vertices() == count);
  std::map<IK::Point_3, std::size_t> index;
  for (std::size_t i = 0; i < count; ++i) index.emplace(points[i], i);
  const IK::Point_3 pole(0, 0, 1);
  auto in_cap = [&](const IK::Point_3& p) { return CGAL::squared_distance(p, pole) < 0.35 * 0.35; };
  std::vector<std::array<std::size_t, 3>> triangles;
  for (Mesh::Face_index f : hull.faces()) {
    std::array<std::size_t, 3> t;
    int k = 0, capped = 0;
    for (Mesh::Vertex_index v : hull.vertices_around_face(hull.halfedge(f))) {
      t[k++] = index.at(hull.point(v));
      capped += in_cap(hull.point(v));
    }
    if (capped == 0) triangles.push_back(t);
  }
  const std::size_t inside = std::size_t(std::count_if(points.begin(), points.end(), in_cap));
  CHECK(inside > 50);
  const double d = std::sqrt(4 * CGAL_PI / double(count));
  using CGAL::Pmsum::internal::Triangles_from;
  // From its border alone the hole stays open: the cap's points are not in the mesh.
  Mesh open;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, open);
  std::vector<Mesh::Face_index> added;
  CGAL::Pmsum::internal::fill_holes(open, 3 * d, std::back_inserter(added));
  CHECK(added.empty());
  // With the points: closed through every one of them, within d of them.
  Mesh mesh;
  const auto checks = CGAL::Pmsum::internal::mesh_from_triangles<CGAL::Sequential_tag>(
    points, triangles, Triangles_from::one_delaunay_triangulation, d, mesh);
  CHECK(checks.valid());
  CHECK(checks.shells == 1);
  CHECK(mesh.number_of_vertices() == count);
  CHECK(long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces()) == 2);
  CHECK(CGAL::Pmsum::internal::largest_distance_to_mesh(points, mesh) == 0);
  CHECK(CGAL::Pmsum::internal::mesh_distance_bound(mesh, points, d) < d);
  // No inner side of the filling longer than 3 d.
  double longest = 0;
  for (Mesh::Edge_index e : mesh.edges())
    longest = (std::max)(longest, std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1)))));
  CHECK(longest <= 3 * d);
}

TEST_CASE("measure_mesh_distance: closed-form distances both ways", "[applications][mesh]")
{
  using CGAL::Pmsum::internal::to_shell;
  const Mesh unit = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  const auto same = CGAL::Pmsum::measure_mesh_distance({to_shell(unit)}, unit, 0.1);
  CHECK(same.mesh_to_surface < 1e-12);
  CHECK(same.surface_to_mesh < 1e-12);
  // [0, 1]^3 against [0, 1]^2 x [0, 1.2]: 0.2 both ways (the top's centre; the top's corners
  // are lattice samples), and a sample is taken at every vertex and edge
  const auto taller = CGAL::Pmsum::measure_mesh_distance({to_shell(to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1.2})))}, unit, 0.1);
  CHECK(taller.mesh_to_surface == Approx(0.2).margin(1e-12));
  CHECK(taller.surface_to_mesh == Approx(0.2).margin(1e-12));
  CHECK(taller.mesh_samples > 12 * 66);
}

TEST_CASE("largest_distance_to_mesh: 0 at vertices, the distance to the nearest triangle else", "[applications][mesh]")
{
  using CGAL::Pmsum::internal::largest_distance_to_mesh;
  const Mesh unit = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  std::vector<IK::Point_3> corners;
  for (auto v : unit.vertices()) corners.push_back(unit.point(v));
  CHECK(largest_distance_to_mesh(corners, unit) == 0);
  corners.push_back(IK::Point_3(0.5, 0.25, 1.375)); // above the top: 0.375
  corners.push_back(IK::Point_3(0.5, 0.5, 0.75));   // inside: 0.25 from the top
  CHECK(largest_distance_to_mesh(corners, unit) == Approx(0.375).margin(1e-12));
  CHECK(largest_distance_to_mesh(corners, unit) >= 0.375); // with its rounding margin
  CHECK(largest_distance_to_mesh(corners, Mesh()) == std::numeric_limits<double>::infinity());
}

TEST_CASE("mesh_distance_bound: the largest distance from a mesh to points, bounded from above, closed form",
          "[applications][mesh]")
{
  using CGAL::Pmsum::internal::corner_covering_radius;
  using CGAL::Pmsum::internal::mesh_distance_bound;
  // the farthest point of a triangle from its corners: the circumcentre, or on the longest side
  CHECK(corner_covering_radius({0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.) / 2, 0}) == Approx(1 / std::sqrt(3.)));
  CHECK(corner_covering_radius({0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == Approx(std::sqrt(2.) / 2));
  // obtuse at (2, 1): the bisector of (0, 0)-(2, 1) meets the x axis at 1.25, 1.25 from both
  CHECK(corner_covering_radius({0, 0, 0}, {4, 0, 0}, {2, 1, 0}) == Approx(1.25));
  CHECK(corner_covering_radius({2, 1, 0}, {0, 0, 0}, {4, 0, 0}) == Approx(1.25));
  CHECK(corner_covering_radius({0, 0, 0}, {3, 0, 0}, {1, 0, 0}) == Approx(1)); // flat: half the longer piece
  // the unit cube's surface and its corners: the faces' centres are sqrt(2)/2 from them
  const Mesh unit = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  std::vector<IK::Point_3> points;
  for (auto v : unit.vertices()) points.push_back(unit.point(v));
  const double half_diagonal = std::sqrt(2.) / 2;
  const double b = mesh_distance_bound(unit, points, 0.75);
  CHECK(b >= half_diagonal);
  CHECK(b < 0.75);
  CHECK(mesh_distance_bound(unit, points, 0.7) >= 0.7); // cannot be shown below the true distance
  // with the faces' centres too: 0.5 (the edges' midpoints), which the triangles'
  // corners alone (sqrt(2)/2 apart) cannot show: the triangles are split
  for (int k = 0; k < 3; ++k)
    for (double side : {0., 1.}) {
      double c[3] = {0.5, 0.5, 0.5};
      c[k] = side;
      points.emplace_back(c[0], c[1], c[2]);
    }
  const double with_centres = mesh_distance_bound(unit, points, 0.55);
  CHECK(with_centres >= 0.5);
  CHECK(with_centres < 0.55);
  CHECK(mesh_distance_bound(Mesh(), points, 0.1) == 0);
}

TEST_CASE("insert_left_out_points: points beside the mesh become vertices, one part at a time", "[applications][mesh]")
{
  using CGAL::Pmsum::internal::insert_left_out_points;
  using CGAL::Pmsum::internal::largest_distance_to_mesh;
  Mesh m = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  std::vector<IK::Point_3> points;
  for (auto v : m.vertices()) points.push_back(m.point(v));
  std::vector<std::size_t> part(points.size(), 0);
  // two points just above the top face, over one of its triangles (both put back: the second
  // in the next pass), one just beside the face x = 1, and one beside the bottom of another part
  points.emplace_back(0.7, 0.2, 1.01);
  points.emplace_back(0.75, 0.1, 1.02);
  points.emplace_back(1.03, 0.5, 0.4);
  points.emplace_back(0.5, 0.5, -0.02);
  part.insert(part.end(), {0, 0, 0, 1});
  CHECK(largest_distance_to_mesh(points, m) == Approx(0.03).epsilon(1e-6));
  CHECK(insert_left_out_points<CGAL::Sequential_tag>(points, part, 0.1, m) == 3);
  REQUIRE(CGAL::Pmsum::check_mesh(m).valid());
  CHECK(vertices(m).size() == 8 + 3);
  CHECK(faces(m).size() == 12 + 3 * 2);
  CHECK(largest_distance_to_mesh(points, m) == Approx(0.02).epsilon(1e-6)); // the other part's point
  CHECK(insert_left_out_points<CGAL::Sequential_tag>(points, part, 0.1, m) == 0);
  CHECK(CGAL::Polygon_mesh_processing::volume(m) > 1);
  // With a box of part 1 under the first, 0.05 below it: the point 0.02 under the first box's
  // bottom is nearer to it (part 0) than to the box of its part (0.03 away), and goes into
  // that one's top, within reach 0.1; not with reach 0.01.
  for (const double reach : {0.01, 0.1}) {
    Mesh two = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
    two.join(to_mesh<Mesh>(box({0, 0, -1.05}, {1, 1, -0.05})));
    std::vector<IK::Point_3> at;
    std::vector<std::size_t> of;
    for (auto v : two.vertices()) {
      at.push_back(two.point(v));
      of.push_back(two.point(v).z() < -0.01 ? 1 : 0);
    }
    at.emplace_back(0.5, 0.3, -0.02);
    of.push_back(1);
    INFO("reach " << reach);
    CHECK(insert_left_out_points<CGAL::Sequential_tag>(at, of, reach, two) == (reach > 0.05 ? 1u : 0u));
    REQUIRE(CGAL::Pmsum::check_mesh(two).valid());
    CHECK(largest_distance_to_mesh(at, two) == Approx(reach > 0.05 ? 0 : 0.02).margin(1e-9));
  }
}

TEST_CASE("remove_bubbles: shells smaller than d go, unless none would remain", "[applications][mesh]")
{
  Mesh m = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  m.join(to_mesh<Mesh>(box({2, 0, 0}, {2.1, 0.1, 0.1}))); // diagonal 0.173
  m.join(to_mesh<Mesh>(box({4, 0, 0}, {4.3, 0.3, 0.3}))); // diagonal 0.520
  CGAL::Pmsum::internal::remove_bubbles(m, 0.2);
  CHECK(faces(m).size() == 2 * 12);
  CGAL::Pmsum::internal::remove_bubbles(m, 0.6);
  REQUIRE(faces(m).size() == 12);
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(1));
  Mesh tiny = to_mesh<Mesh>(box({2, 0, 0}, {2.1, 0.1, 0.1}));
  CGAL::Pmsum::internal::remove_bubbles(tiny, 1);
  CHECK(faces(tiny).size() == 12);
}

TEST_CASE("faces_against_their_corners: faces more than 100 degrees from the face normal of each corner",
          "[applications][mesh]")
{
  auto against = [](const Mesh& m, const auto& normal_at) {
    return CGAL::Pmsum::internal::faces_against_their_corners(m, normal_at).size();
  };
  using CGAL::Pmsum::internal::Position;
  using Vector = CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3;
  Mesh m = to_mesh<Mesh>(box({-1, -1, -1}, {1, 1, 1}));
  // Outward from the centre: every face 54.7 degrees from its corners' normals
  auto radial = [](const Position& x) -> std::optional<Vector> {
    const Vector v(x[0], x[1], x[2]);
    return v / std::sqrt(v.squared_length());
  };
  CHECK(against(m, radial) == 0);
  // One normal everywhere: the faces at x = -1 make 180 degrees with it, the others 90 or 0
  auto along_x = [](const Position&) -> std::optional<Vector> { return Vector(1, 0, 0); };
  CHECK(against(m, along_x) == 2);
  // ... but each of them has a corner at z = 1, where no normal is given now
  auto along_x_but_top_left = [](const Position& x) -> std::optional<Vector> {
    if (x[0] == -1 && x[2] == 1) return std::nullopt;
    return Vector(1, 0, 0);
  };
  CHECK(against(m, along_x_but_top_left) == 0);
  // The mesh turned inside out: every face against the outward normals
  CGAL::Polygon_mesh_processing::reverse_face_orientations(m);
  CHECK(against(m, radial) == 12);
}

TEST_CASE("crossings_near: the crossings of the suspect triangles only; the advancing front's cross none",
          "[applications][mesh]")
{
  using CGAL::Pmsum::internal::crossings_near;
  using face_descriptor = Mesh::Face_index;
  // two boxes that cross, and a third far from both
  Soup soup = box({0, 0, 0}, {1, 1, 1});
  soup.append(box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  soup.append(box({3, 0, 0}, {4, 1, 1}));
  const Mesh m = to_mesh<Mesh>(soup);
  REQUIRE(faces(m).size() == 36);
  auto of_box = [](int k) { return [k](face_descriptor f) { return int(f.idx()) / 12 == k; }; };
  const auto second = crossings_near<CGAL::Sequential_tag>(m, of_box(1));
  CHECK_FALSE(second.empty());
  for (const auto& [f, g] : second) CHECK((of_box(1)(f) || of_box(1)(g)));
  CHECK(crossings_near<CGAL::Parallel_if_available_tag>(m, of_box(1)).size() == second.size());
  CHECK(crossings_near<CGAL::Sequential_tag>(m, of_box(2)).empty()); // the boxes' crossings are not near it
  CHECK(crossings_near<CGAL::Sequential_tag>(m, [](face_descriptor) { return false; }).empty());

  // The advancing front's triangles are facets of one Delaunay triangulation: on points
  // scattered at random in a slab, a surface of many folds, no two triangles without a
  // common corner meet.
  using EP = CGAL::Exact_predicates_inexact_constructions_kernel;
  CGAL::Random random(7);
  std::vector<EP::Point_3> points;
  std::vector<EP::Vector_3> normals;
  for (int i = 0; i < 300; ++i) {
    points.emplace_back(random.get_double(0, 1), random.get_double(0, 1), random.get_double(0, 0.2));
    normals.push_back(CGAL::NULL_VECTOR);
  }
  const auto triangles = CGAL::Pmsum::internal::advancing_front_triangles(
    points, normals, std::vector<CGAL::Pmsum::internal::Normal_use>(points.size(), CGAL::Pmsum::internal::Normal_use::none), 1);
  REQUIRE(triangles.size() > 100);
  std::size_t disjoint = 0, meeting = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (std::size_t j = i + 1; j < triangles.size(); ++j) {
      const auto& a = triangles[i];
      const auto& b = triangles[j];
      if (std::find_first_of(a.begin(), a.end(), b.begin(), b.end()) != a.end()) continue;
      ++disjoint;
      meeting += CGAL::do_intersect(EP::Triangle_3(points[a[0]], points[a[1]], points[a[2]]),
                                    EP::Triangle_3(points[b[0]], points[b[1]], points[b[2]]));
    }
  CHECK(disjoint > 1000);
  CHECK(meeting == 0);
}

TEST_CASE("splits_a_part: the points of one part of the sum on two volumes", "[applications][mesh]")
{
  using EP = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  auto positions = [](const Mesh& m) {
    std::vector<EP> p;
    for (auto v : vertices(m)) p.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
    return p;
  };
  using CGAL::Pmsum::internal::splits_a_part;
  // two disjoint boxes: one part on both splits it; a part each does not
  Mesh two = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  two.join(to_mesh<Mesh>(box({2, 0, 0}, {3, 1, 1})));
  const std::vector<EP> p2 = positions(two);
  REQUIRE(p2.size() == 16);
  CHECK(splits_a_part(two, p2, std::vector<std::size_t>(16, 0)));
  std::vector<std::size_t> each(16, 0);
  std::fill(each.begin() + 8, each.end(), 1);
  CHECK_FALSE(splits_a_part(two, p2, each));
  // a box with a void: one volume, whatever the parts
  Mesh hollow = to_mesh<Mesh>(box({0, 0, 0}, {3, 3, 3}));
  Mesh cavity = to_mesh<Mesh>(box({1, 1, 1}, {2, 2, 2}));
  CGAL::Polygon_mesh_processing::reverse_face_orientations(cavity);
  hollow.join(cavity);
  CHECK_FALSE(splits_a_part(hollow, positions(hollow), std::vector<std::size_t>(16, 0)));
  // a solid inside that void is a volume of its own
  hollow.join(to_mesh<Mesh>(box({1.25, 1.25, 1.25}, {1.75, 1.75, 1.75})));
  CHECK(splits_a_part(hollow, positions(hollow), std::vector<std::size_t>(24, 0)));
}

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

TEST_CASE("orient_manifold_triangles: what CGAL's orient_polygon_soup and is_polygon_soup_a_polygon_mesh tell",
          "[applications][mesh]")
{
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  // CGAL's answer and orientation (on a copy, with points to duplicate into).
  auto cgal = [](const Triangles& t, std::size_t points) {
    std::vector<IK::Point_3> p(points);
    std::vector<std::vector<std::size_t>> polygons;
    for (const auto& f : t) polygons.push_back({f[0], f[1], f[2]});
    const bool ok = CGAL::Polygon_mesh_processing::orient_polygon_soup(p, polygons) &&
                    CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons);
    Triangles oriented;
    for (const auto& f : polygons) oriented.push_back({f[0], f[1], f[2]});
    return std::make_pair(ok, oriented);
  };
  auto agree = [&](Triangles t, std::size_t points) {
    const auto [ok, oriented] = cgal(t, points);
    const bool mine = CGAL::Pmsum::internal::orient_manifold_triangles(t);
    CHECK(mine == ok);
    if (mine && ok) CHECK(t == oriented);
    return mine;
  };
  // An octahedron (points +x -x +y -y +z -z), its faces in mixed orientations and order:
  // oriented, every edge run once each way.
  Triangles octahedron;
  for (std::size_t x : {0, 1})
    for (std::size_t y : {2, 3})
      for (std::size_t z : {4, 5}) octahedron.push_back({x, y, z});
  std::swap(octahedron[0], octahedron[5]);
  REQUIRE(agree(octahedron, 6));
  CGAL::Pmsum::internal::orient_manifold_triangles(octahedron);
  std::set<std::pair<std::size_t, std::size_t>> runs;
  for (const auto& f : octahedron)
    for (int i = 0; i < 3; ++i) runs.insert({f[i], f[(i + 1) % 3]});
  CHECK(runs.size() == 24);
  CHECK(octahedron[0] == std::array<std::size_t, 3>{1, 2, 5}); // the first face keeps its way
  // An open strip of four triangles, two of them reversed.
  CHECK(agree({{0, 1, 2}, {1, 3, 2}, {2, 4, 3}, {4, 5, 3}}, 6));
  // Not manifolds: a Moebius strip (five points), three triangles on one edge, two
  // tetrahedra sharing a point; a triangle with a repeated point.
  Triangles moebius;
  for (std::size_t i = 0; i < 5; ++i) moebius.push_back({i, (i + 1) % 5, (i + 2) % 5});
  CHECK(!agree(moebius, 5));
  CHECK(!agree({{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, 5));
  Triangles pinched = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  for (std::size_t i = 0; i < 4; ++i)
    pinched.push_back({pinched[i][0] == 0 ? 0 : pinched[i][0] + 3, pinched[i][1] + 3, pinched[i][2] + 3});
  CHECK(!agree(pinched, 7));
  Triangles repeated = {{0, 1, 1}}; // (CGAL's orient_polygon_soup does not return on it)
  CHECK(!CGAL::Pmsum::internal::orient_manifold_triangles(repeated));
}

TEST_CASE("keep_one_fan_per_point: at a point with several fans, the largest stays", "[applications][mesh]")
{
  using Triangles = std::vector<std::array<std::size_t, 3>>;
  using CGAL::Pmsum::internal::keep_one_fan_per_point;
  // Two tetrahedra sharing point 0 (the pinched pair of the test above), one of them open (a
  // face missing): point 0 has a fan of three and one of two triangles; the three stay.
  Triangles pinched = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}, {0, 5, 6}, {0, 6, 4}, {5, 4, 6}};
  keep_one_fan_per_point(pinched);
  CHECK(pinched == Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}, {5, 4, 6}});
  CHECK(CGAL::Pmsum::internal::orient_manifold_triangles(pinched)); // (point 0 one fan now)
  // A bowtie of two single triangles at point 0: equal fans, the first stays.
  Triangles bowtie = {{0, 1, 2}, {0, 3, 4}};
  keep_one_fan_per_point(bowtie);
  CHECK(bowtie == Triangles{{0, 1, 2}});
  // Removing a fan can split the fan of another point in two: until every point has one.
  // Point 0: the fan (0, 1, 2), (0, 2, 3), (0, 3, 4) stays, (0, 5, 6), (0, 7, 5) go; point 5's
  // fan (5, 8, 6), (0, 5, 6), (0, 7, 5), (5, 7, 9) is then two: (5, 8, 6) stays.
  Triangles chain = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 5, 6}, {0, 7, 5}, {5, 8, 6}, {5, 7, 9}};
  keep_one_fan_per_point(chain);
  CHECK(chain == Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {5, 8, 6}});
  // A manifold is left as it is.
  Triangles octahedron;
  for (std::size_t x : {0, 1})
    for (std::size_t y : {2, 3})
      for (std::size_t z : {4, 5}) octahedron.push_back({x, y, z});
  const Triangles before = octahedron;
  keep_one_fan_per_point(octahedron);
  CHECK(octahedron == before);
}

// The advancing front leaves holes on this box with a box-shaped void; plane by plane meshes
// it (every point joins the planes it lies on, so the void's edges have their rows on both faces).
TEST_CASE("crease_wedge: the normals where an edge and a vertex are both extreme, closed form", "[applications][mesh]")
{
  namespace in = CGAL::Pmsum::internal;
  const Mesh P = to_mesh<Mesh>(octahedron(2)), Q = to_mesh<Mesh>(tetrahedron(1. / 128));
  in::Mesh_descriptors<Mesh> dp, dq;
  const in::Mesh_data a = in::make_mesh_data(P, get(CGAL::vertex_point, P), false, false, "P", dp);
  const in::Mesh_data b = in::make_mesh_data(Q, get(CGAL::vertex_point, Q), false, false, "Q", dq);
  auto vertex = [](const in::Mesh_data& m, std::array<double, 3> x) {
    for (in::Index v = 0; v < m.number_of_vertices(); ++v)
      if (m.points[v] == x) return v;
    FAIL("no vertex");
    return in::no_index;
  };
  auto edge = [&](std::array<double, 3> x, std::array<double, 3> y) {
    const in::Index u = vertex(a, x), w = vertex(a, y);
    for (in::Index e = 0; e < a.number_of_edges(); ++e)
      if ((a.edges[e].v[0] == u && a.edges[e].v[1] == w) || (a.edges[e].v[0] == w && a.edges[e].v[1] == u)) return e;
    FAIL("no edge");
    return in::no_index;
  };
  const double t = 1. / 128;
  // unit direction of a wedge end, sorted ends, to compare with closed forms
  auto unit = [](in::Vec3<double> n) {
    const double l = std::sqrt(in::dot(n, n));
    return std::array<double, 3>{n[0] / l, n[1] / l, n[2] / l};
  };
  auto ends = [&](in::Index e, in::Index v) {
    const auto w = in::crease_wedge(a, e, b, v);
    std::vector<std::array<double, 3>> r;
    if (w) r = {unit((*w)[0]), unit((*w)[1])};
    std::sort(r.begin(), r.end());
    return r;
  };
  auto near = [](const std::vector<std::array<double, 3>>& x, std::vector<std::array<double, 3>> y) {
    std::sort(y.begin(), y.end());
    if (x.size() != y.size()) return false;
    for (std::size_t i = 0; i < x.size(); ++i)
      for (int c = 0; c < 3; ++c)
        if (std::abs(x[i][c] - y[i][c]) > 1e-12) return false;
    return true;
  };
  const double s3 = 1 / std::sqrt(3.), s2 = 1 / std::sqrt(2.);
  // the edge from (0, 0, 2) to (0, -2, 0), normals (+-1, -1, 1)/sqrt 3: the vertex (0, 0, t) is
  // extreme in both (the whole wedge: a crease of 70.5 degrees); (t, 0, 0) in (1, -1, 1) only
  // (a point inside that face of the sum); the origin in neither
  const in::Index e1 = edge({0, 0, 2}, {0, -2, 0});
  CHECK(near(ends(e1, vertex(b, {0, 0, t})), {{s3, -s3, s3}, {-s3, -s3, s3}}));
  CHECK(ends(e1, vertex(b, {t, 0, 0})).empty());
  CHECK(ends(e1, vertex(b, {0, 0, 0})).empty());
  // the edge from (-2, 0, 0) to (0, 0, -2), normals (-1, +-1, -1)/sqrt 3, with the origin: the
  // half wedge down to (-1, 0, -1)/sqrt 2, the strip of that edge plus the tetrahedron's edge
  // along y (35.3 degrees: sharp); with (0, t, 0) the other half
  const in::Index e2 = edge({-2, 0, 0}, {0, 0, -2});
  CHECK(near(ends(e2, vertex(b, {0, 0, 0})), {{-s3, -s3, -s3}, {-s2, 0, -s2}}));
  CHECK(near(ends(e2, vertex(b, {0, t, 0})), {{-s2, 0, -s2}, {-s3, s3, -s3}}));
  const in::Feature fe{1, e2}, fo{0, vertex(b, {0, 0, 0})}, fx{0, vertex(b, {t, 0, 0})};
  CHECK(in::on_sharp_crease(fe, fo, a, b));
  CHECK(in::on_sharp_crease(in::Feature{1, e1}, in::Feature{0, vertex(b, {0, 0, t})}, a, b));
  CHECK_FALSE(in::on_sharp_crease(in::Feature{1, e1}, fx, a, b));
  // a vertex sum at the end of a sharp crease: (0, 0, 2) + (0, 0, t)
  CHECK(in::on_sharp_crease(in::Feature{0, vertex(a, {0, 0, 2})}, in::Feature{0, vertex(b, {0, 0, t})}, a, b));
  CHECK_FALSE(in::on_sharp_crease(in::Feature{2, 0}, fo, a, b)); // a facet: no crease
}

TEST_CASE("mesh of a sharp convex sum at a coarse d: the refinement keeps the creases and corners",
          "[applications][mesh]")
{
  // An octahedron (diagonal 4) plus a tetrahedron of edge 1/128: the sum's corners and the strips along
  // its edges are far narrower than d. At d the advancing front cuts the corners off (a corner
  // closed on its own: a connected part split), and plane by plane leaves the creases open (the
  // net keeps a face's row beside a crease, not the crease's); the refinement keeps the points
  // on sharp creases and gives them the planes of both faces.
  const Mesh P = to_mesh<Mesh>(octahedron(2)), Q = to_mesh<Mesh>(tetrahedron(1. / 128));
  std::vector<IK::Point_3> sums;
  for (auto v : vertices(P))
    for (auto w : vertices(Q)) sums.push_back(P.point(v) + (Q.point(w) - CGAL::ORIGIN));
  Mesh hull;
  CGAL::convex_hull_3(sums.begin(), sums.end(), hull);
  CGAL::Polygon_mesh_processing::triangulate_faces(hull);
  std::vector<IK::Plane_3> planes;
  for (auto f : faces(hull)) {
    const auto h = halfedge(f, hull);
    planes.emplace_back(hull.point(source(h, hull)), hull.point(target(h, hull)), hull.point(target(next(h, hull), hull)));
  }
  for (double d : {0.21, 0.35}) {
    INFO("d = " << d);
    Mesh m;
    CGAL::Pmsum::Mesh_statistics ms;
    REQUIRE_NOTHROW(CGAL::point_minkowski_sum_mesh(P, Q, d, m, CGAL::parameters::mesh_statistics(ms)));
    const auto c = CGAL::Pmsum::check_mesh(m);
    REQUIRE(c.valid());
    CHECK(c.shells == 1);
    // every vertex on the hull's boundary: on no facet's outer side, on one facet's plane
    std::size_t off = 0;
    for (auto v : vertices(m)) {
      double highest = -HUGE_VAL;
      for (const auto& h : planes) {
        const IK::Vector_3 n = h.orthogonal_vector();
        highest = (std::max)(highest, (h.a() * m.point(v).x() + h.b() * m.point(v).y() + h.c() * m.point(v).z() + h.d()) /
                                        std::sqrt(n.squared_length()));
      }
      off += std::abs(highest) > 1e-12;
    }
    CHECK(off == 0);
    const auto dist = CGAL::Pmsum::measure_mesh_distance({CGAL::Pmsum::internal::to_shell(hull)}, m, d / 8);
    CHECK(dist.mesh_to_surface < d);
    CHECK(dist.surface_to_mesh < d);
    CHECK(dist.mesh_to_surface <= ms.mesh_to_boundary_bound); // the proved bounds
    CHECK(dist.surface_to_mesh <= ms.boundary_to_mesh_bound());
  }
}

TEST_CASE("mesh of a sum with a void: two shells, the void inward, within d of the exact boundary",
          "[applications][mesh]")
{
  // ([0, 3]^3 minus (1, 2)^3) + [0, 0.25]^3: the box [0, 3.25]^3 with the void (1.25, 2)^3
  Mesh P = to_mesh<Mesh>(box({0, 0, 0}, {3, 3, 3}));
  Mesh cavity = to_mesh<Mesh>(box({1, 1, 1}, {2, 2, 2}));
  CGAL::Polygon_mesh_processing::reverse_face_orientations(cavity);
  P.join(cavity);
  const Mesh Q = to_mesh<Mesh>(box({0, 0, 0}, {0.25, 0.25, 0.25}));
  const double d = 0.2;
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_minkowski_sum_mesh<CGAL::Parallel_tag>(P, Q, d, m, CGAL::parameters::mesh_statistics(ms));
  const auto c = CGAL::Pmsum::check_mesh(m);
  REQUIRE(c.valid());
  CHECK(c.shells == 2);
  CHECK(c.void_shells == 1);
  Mesh exact_void = to_mesh<Mesh>(box({1.25, 1.25, 1.25}, {2, 2, 2}));
  CGAL::Polygon_mesh_processing::reverse_face_orientations(exact_void);
  using CGAL::Pmsum::internal::to_shell;
  const auto dist = CGAL::Pmsum::measure_mesh_distance(
    {to_shell(to_mesh<Mesh>(box({0, 0, 0}, {3.25, 3.25, 3.25}))), to_shell(exact_void)}, m, d / 8);
  CHECK(dist.mesh_to_surface < d);
  CHECK(dist.surface_to_mesh < d);
  // the volume: the shell's minus the void's, up to the chords cut across the edges
  CHECK(std::abs(CGAL::Polygon_mesh_processing::volume(m) - (std::pow(3.25, 3) - std::pow(0.75, 3))) < 0.3);
}

TEST_CASE("has_false_void: a void of the mesh that opens onto another shell through free space",
          "[applications][mesh]")
{
  // The hollow box [0, 4]^3 (walls 0.5, each pierced by a window of side 1) plus the cube of
  // half-side c: for c > 0.5 the windows close and [0.5 + c, 3.5 - c]^3 is a void of the sum;
  // for c = 0.25 they stay open (0.5 wide) and the cavity [0.75, 3.25]^3 is not a void. With
  // the block [1.9, 2.1]^3 in the cavity and c = 0.6, the void holds the solid [1.3, 2.7]^3
  // (0.2 from its walls). Each mesh: those boxes (the cavity's turned inward), each with a
  // vertex added on its top in the window's column (x, y) = (2.1, 1.95).
  using namespace CGAL::Pmsum::internal;
  auto box_shell = [](double lo, double hi, bool inward) {
    Mesh m = to_mesh<Mesh>(box({lo, lo, lo}, {hi, hi, hi}));
    const IK::Point_2 top(2.1, 1.95);
    for (auto f : faces(m)) {
      const auto h = halfedge(f, m);
      std::vector<IK::Point_3> t;
      for (auto v : vertices_around_face(h, m)) t.push_back(m.point(v));
      if (t[0].z() != hi || t[1].z() != hi || t[2].z() != hi) continue;
      const IK::Triangle_2 tri({t[0].x(), t[0].y()}, {t[1].x(), t[1].y()}, {t[2].x(), t[2].y()});
      if (!tri.has_on_bounded_side(top)) continue;
      const auto spoke = CGAL::Euler::add_center_vertex(h, m);
      m.point(target(spoke, m)) = IK::Point_3(top.x(), top.y(), hi);
      break;
    }
    REQUIRE(m.number_of_vertices() == 9);
    if (inward) CGAL::Polygon_mesh_processing::reverse_face_orientations(m);
    return m;
  };
  struct Case { double c; bool island, false_void; };
  for (const Case k : {Case{0.75, false, false}, Case{0.25, false, true}, Case{0.6, true, false}}) {
    const double c = k.c;
    Soup q = pmsum_shapes::hollow_box_with_windows(4, 0.5, 1);
    if (k.island) q.append(box({1.9, 1.9, 1.9}, {2.1, 2.1, 2.1}));
    const auto operands = cd_operands(box({-c, -c, -c}, {c, c, c}), q);
    const Cd_geometry geometry(operands.first, operands.second);
    Cd_filter filter(&geometry);
    Segment_search search(filter);
    Mesh m = box_shell(-c, 4 + c, false);
    m.join(box_shell(0.5 + c, 3.5 - c, true));
    if (k.island) m.join(box_shell(1.9 - c, 2.1 + c, false));
    const auto checks = CGAL::Pmsum::check_mesh(m);
    REQUIRE(checks.valid());
    REQUIRE(checks.void_shells == 1);
    CHECK(has_false_void(m, search) == k.false_void);
  }
}

TEST_CASE("has_second_sheet: a second sheet over the boundary, inside the sum or outside", "[applications][mesh]")
{
  // The cube of half-side 0.25 plus the slab [0, 2]^2 x [0, 0.4] and the block [0.1, 2.1] x
  // [0.05, 2.05] x [-1.6, -0.6]: the slab S = [-0.25, 2.25]^2 x [-0.25, 0.65] over the block
  // [-0.15, 2.35] x [-0.2, 2.3] x [-1.85, -0.35], a free gap 0.1 high between them (the block
  // shifted off S's grid, so that segments from S cross its triangles inside, not along their
  // sides). The mesh: both boxes' boundaries (each face cut into 128 triangles), and triangles
  // added over the middle of S's top face. Alone, for
  // d = 1.2: the segments from S's top into S meet S's bottom (facing away) and the block's top
  // (facing the same way, beyond the gap), those from the block's top out of it meet S's
  // bottom and S's top (facing the same way, beyond S): no second sheet. A square inside S
  // nearer than d to the top (facing up) or to the bottom (facing down) is one, or above S
  // facing up (in free space over the top); not one farther than d, nor one above S facing
  // down, nor a crevice: a wedge of two triangles sharing a side, the upper one facing down.
  // A small square under S's top met only along its diagonal (by the segment from the top's
  // vertex (1, 1), on the diagonal's line) is one too: a mesh of lattice points can lay a
  // second sheet so (l-shape-contact at 7%, benchmark/mesh/hard/README.md).
  using namespace CGAL::Pmsum::internal;
  Soup q = box({0, 0, 0}, {2, 2, 0.4});
  q.append(box({0.1, 0.05, -1.6}, {2.1, 2.05, -0.6}));
  const double c = 0.25;
  const auto operands = cd_operands(box({-c, -c, -c}, {c, c, c}), q);
  const Cd_geometry geometry(operands.first, operands.second);
  Cd_filter filter(&geometry);
  Segment_search search(filter);
  Soup boundary = subdivided(box({-c, -c, -c}, {2 + c, 2 + c, 0.4 + c}), 3);
  boundary.append(subdivided(box({0.1 - c, 0.05 - c, -1.6 - c}, {2.1 + c, 2.05 + c, -0.6 + c}), 3));
  auto square = [](double z, bool up) {
    Soup s;
    s.points = {{0.5, 0.5, z}, {1.5, 0.5, z}, {1.5, 1.5, z}, {0.5, 1.5, z}};
    s.triangles = {{0, 1, 2}, {0, 2, 3}};
    if (!up)
      for (auto& t : s.triangles) std::swap(t[1], t[2]);
    return s;
  };
  Soup small; // facing up, its diagonal from (0.9, 0.9) to (1.1, 1.1) under S's vertex (1, 1)
  small.points = {{0.9, 0.9, 0.45}, {1.1, 0.9, 0.45}, {1.1, 1.1, 0.45}, {0.9, 1.1, 0.45}};
  small.triangles = {{0, 1, 2}, {0, 2, 3}};
  Soup crevice; // the side x = 1.5, z = 0.45; the upper triangle facing down, the lower one up
  crevice.points = {{1.5, 0.5, 0.45}, {1.5, 1.5, 0.45}, {0.5, 1, 0.5}, {0.5, 1, 0.4}};
  crevice.triangles = {{0, 2, 1}, {0, 1, 3}};
  struct Case { const char* what; Soup added; double d; bool second_sheet; };
  for (const Case& k : {Case{"nothing", Soup(), 1.2, false}, Case{"a square facing up", square(0.45, true), 0.5, true},
                        Case{"a square facing down, 0.7 from the bottom", square(0.45, false), 0.5, false},
                        Case{"a square facing down", square(0.45, false), 1.2, true},
                        Case{"a square facing up, 0.2 from the top", square(0.45, true), 0.15, false},
                        Case{"a square above S facing up", square(0.8, true), 1.2, true},
                        Case{"a square above S facing down", square(0.8, false), 1.2, false},
                        Case{"a crevice", crevice, 1.2, false},
                        Case{"a small square facing up, met along its diagonal", small, 0.5, true}}) {
    INFO(k.what);
    Soup mesh = boundary;
    mesh.append(k.added);
    const Mesh m = to_mesh<Mesh>(mesh);
    CHECK(has_second_sheet(to_shell(m), k.d, search, false) == k.second_sheet);
    CHECK(has_second_sheet(to_shell(m), k.d, search, true) == k.second_sheet); // (chosen on TBB's threads)
    // The triangles of the sheets found, for remesh_around(): the triangle met is one added.
    const auto sheets = second_sheet_triangles(to_shell(m), k.d, search, true, true);
    CHECK(sheets.empty() == !k.second_sheet);
    if (!sheets.empty()) CHECK(sheets.front() >= boundary.triangles.size());
  }
}

TEST_CASE("has_false_short_handle: a tunnel of the mesh a few d round, the sum's or not", "[applications][mesh]")
{
  // The block [0, 4]^3 with the tunnel [1.5, 2.5]^2 along z (tunnel_block()) plus the cube of
  // half-side c: the tunnel [1.5 + c, 2.5 - c]^2 through the box [-c, 4 + c]^3, closed for
  // c >= 0.5. The meshes: that box with that tunnel, or the box alone. Narrow: c = 0.45, the
  // tunnel 0.1 wide, 0.4 round, at d = 1.6 (the balls of radius d/2 see it). Wide: c = 0.05,
  // the tunnel 0.9 wide, 3.6 round, three times d = 1.2 (only the balls of radius 3 d see it).
  using namespace CGAL::Pmsum::internal;
  auto tunnel_mesh = [](double c) {
    const double lo = -c, hi = 4 + c, in_lo = 1.5 + c, in_hi = 2.5 - c;
    Soup frame;
    for (double z : {lo, hi})
      for (const auto& [a, b] : {std::pair{lo, hi}, std::pair{in_lo, in_hi}})
        for (const auto& [x, y] : {std::pair{a, a}, std::pair{b, a}, std::pair{b, b}, std::pair{a, b}}) frame.points.push_back({x, y, z});
    auto outer = [](int k, int z) { return std::size_t(8 * z + k % 4); };
    auto inner = [](int k, int z) { return std::size_t(8 * z + 4 + k % 4); };
    auto quad = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
      frame.triangles.push_back({a, b, c});
      frame.triangles.push_back({a, c, d});
    };
    for (int k = 0; k < 4; ++k) {
      quad(outer(k, 1), outer(k + 1, 1), inner(k + 1, 1), inner(k, 1)); // top, facing up
      quad(outer(k + 1, 0), outer(k, 0), inner(k, 0), inner(k + 1, 0)); // bottom
      quad(outer(k, 0), outer(k + 1, 0), outer(k + 1, 1), outer(k, 1)); // sides, facing out
      quad(inner(k + 1, 0), inner(k, 0), inner(k, 1), inner(k + 1, 1)); // the tunnel's, facing into it
    }
    return to_mesh<Mesh>(subdivided(frame, 3));
  };
  auto box_mesh = [](double c) { return to_mesh<Mesh>(subdivided(box({-c, -c, -c}, {4 + c, 4 + c, 4 + c}), 3)); };
  struct Case { const char* what; Mesh mesh; double c, d; bool false_handle; };
  for (const Case& k : {Case{"narrow: the tunnel, the sum's", tunnel_mesh(0.45), 0.45, 1.6, false},
                        Case{"narrow: the tunnel, closed in the sum", tunnel_mesh(0.45), 0.55, 1.6, true},
                        Case{"narrow: no tunnel", box_mesh(0.45), 0.45, 1.6, false},
                        Case{"wide: the tunnel, the sum's", tunnel_mesh(0.05), 0.05, 1.2, false},
                        Case{"wide: the tunnel, closed in the sum", tunnel_mesh(0.05), 0.55, 1.2, true},
                        Case{"wide: no tunnel", box_mesh(0.05), 0.05, 1.2, false}}) {
    INFO(k.what);
    REQUIRE(CGAL::Pmsum::check_mesh(k.mesh).valid());
    const auto operands = cd_operands(box({-k.c, -k.c, -k.c}, {k.c, k.c, k.c}), pmsum_shapes::tunnel_block());
    const Cd_geometry geometry(operands.first, operands.second);
    Cd_filter filter(&geometry);
    Segment_search search(filter);
    CHECK(has_false_short_handle(to_shell(k.mesh), k.d, search, false) == k.false_handle);
    CHECK(has_false_short_handle(to_shell(k.mesh), k.d, search, true) == k.false_handle); // (the balls on TBB's threads)
  }
  // The wide tunnel is not seen by the narrow balls alone: at d = 0.4 (radius 3 d = 1.2 < 1.8).
  const auto operands = cd_operands(box({-0.55, -0.55, -0.55}, {0.55, 0.55, 0.55}), pmsum_shapes::tunnel_block());
  const Cd_geometry geometry(operands.first, operands.second);
  Cd_filter filter(&geometry);
  Segment_search search(filter);
  CHECK_FALSE(has_false_short_handle(to_shell(tunnel_mesh(0.05)), 0.4, search, false));
}

TEST_CASE("has_neck_or_channel: two blocks joined by a neck across a gap, the sum's or not, or a channel through a block", "[applications][mesh]")
{
  // The blocks A = [0, 4]^2 x [0, 1] and B = [0, 4]^2 x [1.5, 2.5], 0.5 apart, as the sum of the
  // cube of half-side 0.25 and the blocks shrunk by it; with the bar [1.75, 2.25]^2 x [0.75,
  // 1.75] between them (touching both), the sum also has the neck N = [1.5, 2.5]^2 x [1, 1.5].
  // The meshes: the boundary of A, N and B (one shell, the neck's walls 1 wide), or A's and B's
  // (two shells). At d = 0.8 the segments from the neck's walls into the mesh cross the neck
  // (1 < 2 d): through free space where the sum has no neck, and the walls over free space make
  // a ring round it (knot1 + tetrahedron/32 at 3.5% was meshed so, benchmark/mesh/hard/README.md).
  // Where the sum is the whole block [0, 4]^2 x [0, 2.5], the first mesh's outside round the neck
  // is a channel through the solid: the segments out of the mesh from A's top round the neck to
  // B's bottom lie inside the sum, and the triangles under the solid there make a ring (the
  // hollow box + tetrahedron/10 at 5% was meshed so). The two blocks apart where the sum has
  // the neck: the segments out of A's top over the neck, up to B's bottom, lie inside the sum, from
  // one patch of triangles under the solid to another (CGAL's cheese + octahedron/64 at 1.5%: a
  // rod of the sum 0.6-1.2 d thick cut through, its two caps 0.15 d apart).
  using namespace CGAL::Pmsum::internal;
  Soup dumbbell;
  for (const auto& [z, a] : {std::pair{0., 0.}, std::pair{1., 0.}, std::pair{1., 1.5}, std::pair{1.5, 1.5}, std::pair{1.5, 0.},
                             std::pair{2.5, 0.}})
    for (const auto& [x, y] : {std::pair{a, a}, std::pair{4 - a, a}, std::pair{4 - a, 4 - a}, std::pair{a, 4 - a}})
      dumbbell.points.push_back({x, y, z});
  auto quad = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
    dumbbell.triangles.push_back({a, b, c});
    dumbbell.triangles.push_back({a, c, d});
  };
  quad(0, 3, 2, 1);   // A's bottom, facing down
  quad(20, 21, 22, 23); // B's top, facing up
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t n = (k + 1) % 4;
    for (std::size_t ring : {0, 2, 4}) quad(4 * ring + k, 4 * ring + n, 4 * ring + 4 + n, 4 * ring + 4 + k); // sides: A, N, B
    quad(4 + k, 4 + n, 8 + n, 8 + k);     // A's top, round the neck, facing up
    quad(16 + n, 16 + k, 12 + k, 12 + n); // B's bottom, facing down
  }
  const double c = 0.25;
  Soup blocks = box({c, c, c}, {4 - c, 4 - c, 1 - c});
  blocks.append(box({c, c, 1.5 + c}, {4 - c, 4 - c, 2.5 - c}));
  Soup with_bar = blocks;
  with_bar.append(box({1.75, 1.75, 0.75}, {2.25, 2.25, 1.75}));
  const Soup whole = box({c, c, c}, {4 - c, 4 - c, 2.5 - c});
  Soup apart = box({0, 0, 0}, {4, 4, 1});
  apart.append(box({0, 0, 1.5}, {4, 4, 2.5}));
  struct Case { const char* what; const Soup& mesh; const Soup& q; bool neck; }; // (neck: or channel)
  for (const Case& k : {Case{"the neck, across the gap", dumbbell, blocks, true}, Case{"the neck, the sum's", dumbbell, with_bar, false},
                        Case{"the blocks apart", apart, blocks, false}, Case{"a channel round the neck", dumbbell, whole, true},
                        Case{"the sum's neck cut through", apart, with_bar, true}}) {
    INFO(k.what);
    const Mesh m = to_mesh<Mesh>(subdivided(k.mesh, 2));
    REQUIRE(CGAL::Pmsum::check_mesh(m).valid());
    const auto operands = cd_operands(box({-c, -c, -c}, {c, c, c}), k.q);
    const Cd_geometry geometry(operands.first, operands.second);
    Cd_filter filter(&geometry);
    Segment_search search(filter);
    auto free_at = [&](const std::array<double, 3>& x) { return filter.is_free_at(x); };
    CHECK(has_neck_or_channel(to_shell(m), 0.8, search, free_at, false) == k.neck);
    CHECK(has_neck_or_channel(to_shell(m), 0.8, search, free_at, true) == k.neck); // (chosen on TBB's threads)
  }
  // Two membranes over a passage: the block [0, 4]^3 with the tunnel [1.5, 2.5]^2 along z
  // (tunnel_block()) plus the cube of half-side 0.05 meshed whole, at d = 2.2. The segments from
  // the top over the tunnel into the mesh reach the bottom through free space, from one disk of
  // triangles over free space to another, and the rays across their middles meet the tunnel's
  // walls before the mesh: refused. The mesh with the tunnel, or the sum without it, is not.
  const double e = 0.05;
  const Mesh whole_block = to_mesh<Mesh>(subdivided(box({-e, -e, -e}, {4 + e, 4 + e, 4 + e}), 3));
  for (const bool tunnel : {true, false}) {
    INFO((tunnel ? "the sum with the tunnel" : "the sum without it"));
    const auto operands = cd_operands(box({-e, -e, -e}, {e, e, e}), tunnel ? pmsum_shapes::tunnel_block() : box({0, 0, 0}, {4, 4, 4}));
    const Cd_geometry geometry(operands.first, operands.second);
    Cd_filter filter(&geometry);
    Segment_search search(filter);
    auto free_at = [&](const std::array<double, 3>& x) { return filter.is_free_at(x); };
    CHECK(has_neck_or_channel(to_shell(whole_block), 2.2, search, free_at, false) == tunnel);
  }
}

namespace {

/// The boundary of the cells of the grid xs x ys x zs (coordinates, increasing) that `filled`
/// (i, j, k) holds, outward: a square between a filled cell and an empty one (or the grid's
/// outside), in two triangles. The squares in the order of their centres: z descending, then
/// x, then y ascending.
template <class Filled>
Soup cells_boundary(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& zs, Filled&& filled)
{
  const int n[3] = {int(xs.size()) - 1, int(ys.size()) - 1, int(zs.size()) - 1};
  const std::vector<double>* axes[3] = {&xs, &ys, &zs};
  auto in = [&](std::array<int, 3> c) {
    for (int a = 0; a < 3; ++a)
      if (c[a] < 0 || c[a] >= n[a]) return false;
    return bool(filled(c[0], c[1], c[2]));
  };
  Soup s;
  std::map<std::array<int, 3>, std::size_t> index;
  auto corner = [&](std::array<int, 3> g) {
    const auto [it, added] = index.emplace(g, s.points.size());
    if (added) s.points.push_back({xs[g[0]], ys[g[1]], zs[g[2]]});
    return it->second;
  };
  struct Square { std::array<double, 3> centre; std::array<std::size_t, 4> corners; };
  std::vector<Square> squares;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        if (!in({i, j, k})) continue;
        for (int a = 0; a < 3; ++a)
          for (int side : {0, 1}) {
            std::array<int, 3> next = {i, j, k};
            next[a] += side ? 1 : -1;
            if (in(next)) continue;
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            std::array<int, 3> g = {i, j, k};
            g[a] += side;
            std::array<std::array<int, 3>, 4> q = {g, g, g, g}; // counterclockwise seen from outside
            q[1][b] += 1, q[2][b] += 1, q[2][c] += 1, q[3][c] += 1;
            if (!side) std::swap(q[1], q[3]);
            Square sq{{0, 0, 0}, {}};
            for (int v = 0; v < 4; ++v) {
              sq.corners[v] = corner(q[v]);
              for (int e = 0; e < 3; ++e) sq.centre[e] += (*axes[e])[q[v][e]] / 4;
            }
            squares.push_back(sq);
          }
      }
  std::stable_sort(squares.begin(), squares.end(), [](const Square& u, const Square& v) {
    return std::make_tuple(-u.centre[2], u.centre[0], u.centre[1]) < std::make_tuple(-v.centre[2], v.centre[0], v.centre[1]);
  });
  for (const Square& q : squares) {
    s.triangles.push_back({q.corners[0], q.corners[1], q.corners[2]});
    s.triangles.push_back({q.corners[0], q.corners[2], q.corners[3]});
  }
  return s;
}

} // namespace

TEST_CASE("has_neck_or_channel: a plug across a slit of the sum, with a dead-end dent beside it", "[applications][mesh]")
{
  // The sum: the block [0, 5] x [0, 4] x [0, 4] with the slit [2, 3.6] x [1.8, 2.2] right
  // through it along z (the block shrunk by 0.05, its slit widened, plus the cube of half-side
  // 0.05), at d = 1.
  // The meshes: the block with the slit (right); with a plug across the slit, z in [1.5, 2.5]
  // (a handle lost: refused, as the tunnel block above); and with that plug and a dent
  // [3, 3.2] x [1.8, 2.2] x [1.9, 2.5] in it, open to the slit above and a dead end below
  // (refused); and with a channel [3, 3.2] x [1.8, 2.2] right through the plug (the passage
  // kept, narrower: not refused).
  // From the middle of a segment through the plug (the caps' triangles over free space are two
  // disks), the ray across the slit towards the dent meets the mesh through free space, but
  // leaves it for the dent and enters it again 0.2 further on, still in the slit: it does not
  // reach the mesh's outside, and the plug is refused too (elephant + octahedron/128 turned
  // by seed 11 at 1.3% was meshed so: a plug 1.1 d long across a slit 0.42 d thick, a dent
  // 0.14 d wide beside it, Euler characteristic -2 against -4).
  using namespace CGAL::Pmsum::internal;
  const double c = 0.05;
  const Soup q = cells_boundary({c, 2 - c, 3.6 + c, 5 - c}, {c, 1.8 - c, 2.2 + c, 4 - c}, {c, 4 - c},
                                [](int i, int j, int) { return i != 1 || j != 1; });
  const auto operands = cd_operands(box({-c, -c, -c}, {c, c, c}), q);
  const Cd_geometry geometry(operands.first, operands.second);
  Cd_filter filter(&geometry);
  Segment_search search(filter);
  auto free_at = [&](const std::array<double, 3>& x) { return filter.is_free_at(x); };
  // (cells: x in [0, 2], [2, 3], [3, 3.2], [3.2, 3.6], [3.6, 5]; y: the slit is j = 1; z: [0,
  // 1.5], [1.5, 1.9], [1.9, 2.5], [2.5, 4])
  const std::vector<double> xs = {0, 2, 3, 3.2, 3.6, 5}, ys = {0, 1.8, 2.2, 4}, zs = {0, 1.5, 1.9, 2.5, 4};
  auto slit = [](int i, int j) { return i >= 1 && i <= 3 && j == 1; };
  struct Case { const char* what; Soup mesh; bool refused; };
  for (const Case& k : {Case{"the slit", cells_boundary(xs, ys, zs, [&](int i, int j, int) { return !slit(i, j); }), false},
                        Case{"a plug", cells_boundary(xs, ys, zs, [&](int i, int j, int z) { return !slit(i, j) || z == 1 || z == 2; }), true},
                        Case{"a plug with a dead-end dent", cells_boundary(xs, ys, zs, [&](int i, int j, int z) {
                               return !slit(i, j) || z == 1 || (z == 2 && i != 2);
                             }), true},
                        Case{"a plug with a channel through it (the passage kept, narrower)", cells_boundary(xs, ys, zs, [&](int i, int j, int z) {
                               return !slit(i, j) || ((z == 1 || z == 2) && i != 2);
                             }), false}}) {
    INFO(k.what);
    const Mesh m = to_mesh<Mesh>(subdivided(k.mesh, 1));
    REQUIRE(CGAL::Pmsum::check_mesh(m).valid());
    CHECK(has_neck_or_channel(to_shell(m), 1.0, search, free_at, false) == k.refused);
    CHECK(has_neck_or_channel(to_shell(m), 1.0, search, free_at, true) == k.refused); // (chosen on TBB's threads)
  }
}

TEST_CASE("mesh of a grate with its axes permuted: no second sheet, the sum's Euler characteristic", "[applications][mesh]")
{
  // grate-a (8 bars, 9 holes) with (x, y, z) -> (-0.75 z, x, 1.5 y), plus a cube of side 0.3,
  // d = 2% of the sum's diagonal: the advancing front meshed the faces beside a convex edge
  // and, over them, a second sheet of chords, a handle too many (Euler characteristic -18),
  // until has_second_sheet() refused it. The sum is a union of boxes (each bar plus the cube),
  // so its boundary's Euler characteristic is twice the union's, which the boxes' nerve gives:
  // the sum over the sets of boxes that meet of (-1)^(size + 1).
  const Soup bars = grate(4, 4, 1, 0.5, 0.25); // (grate-a)
  auto turn = [](const Point& p) { return Point{-0.75 * p[2], p[0], 1.5 * p[1]}; };
  Soup p;
  for (const Point& x : bars.points) p.points.push_back(turn(x));
  for (auto t : bars.triangles) p.triangles.push_back({t[2], t[1], t[0]}); // (the map turns the orientation)
  const double side = 0.3;
  std::vector<Box> sum;
  for (const Box& b : bars.boxes) {
    const Point lo = turn(b.min), hi = turn(b.max);
    sum.push_back({{hi[0], lo[1], lo[2]}, {lo[0] + side, hi[1] + side, hi[2] + side}});
  }
  long chi = 0;
  for (unsigned set = 1; set < (1u << sum.size()); ++set) {
    Box meet{{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, {HUGE_VAL, HUGE_VAL, HUGE_VAL}};
    int size = 0;
    for (std::size_t i = 0; i < sum.size(); ++i)
      if (set >> i & 1) {
        ++size;
        for (int a = 0; a < 3; ++a) {
          meet.min[a] = (std::max)(meet.min[a], sum[i].min[a]);
          meet.max[a] = (std::min)(meet.max[a], sum[i].max[a]);
        }
      }
    if (meet.min[0] <= meet.max[0] && meet.min[1] <= meet.max[1] && meet.min[2] <= meet.max[2])
      chi += size % 2 == 1 ? 1 : -1;
  }
  REQUIRE(2 * chi == -16); // (9 holes: genus 9)
  const Mesh P = to_mesh<Mesh>(p), Q = to_mesh<Mesh>(box({0, 0, 0}, {side, side, side}));
  double diagonal = 0;
  for (int a = 0; a < 3; ++a) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Box& b : sum) {
      lo = (std::min)(lo, b.min[a]);
      hi = (std::max)(hi, b.max[a]);
    }
    diagonal += (hi - lo) * (hi - lo);
  }
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  REQUIRE_NOTHROW(CGAL::point_minkowski_sum_mesh(P, Q, 0.02 * std::sqrt(diagonal), m, CGAL::parameters::mesh_statistics(ms)));
  const auto checks = CGAL::Pmsum::check_mesh(m);
  REQUIRE(checks.valid());
  CHECK(checks.shells == 1);
  CHECK(checks.euler_characteristic == 2 * chi);
  // The advancing front's mesh at d, made again round its second sheets (it was meshed plane
  // by plane before), within d of its points both ways.
  CHECK(ms.refinements == 0);
  CHECK(!ms.by_planes);
  CHECK(ms.sheets_remeshed >= 1);
  CHECK(ms.point_distance < ms.covering_distance);
  CHECK(ms.mesh_to_boundary_bound < ms.covering_distance);
}

TEST_CASE("mesh of frame + knot at 4%: no handle explained by a cycle along a groove", "[applications][mesh][long]")
{
  // The suite's frame + knot (`pmsum generate frame`, `knot`) at d = 4% of the sum's diagonal.
  // Its exact boundary (CGAL's Nef sum, `pmsum validate`) is one shell of Euler characteristic 2.
  // The mesh made at d/2 had a handle too many (Euler characteristic 0) that the short-handle
  // check let pass: the wide balls round it were explained by a cycle out along one wall of a
  // groove of the sum and back along the other, which passed the tube test without winding
  // round the axis. Now that mesh is refused and the next level is right.
  const Soup frame = pmsum_shapes::frame(3, 1, 0.5, 0.5), knot = pmsum_shapes::torus_knot(2, 3, 2, 1, 0.3, 32, 5);
  double diagonal = 0;
  for (int a = 0; a < 3; ++a) {
    auto extent = [a](const Soup& s) {
      const auto [lo, hi] = std::minmax_element(s.points.begin(), s.points.end(),
                                                [a](const Point& x, const Point& y) { return x[a] < y[a]; });
      return (*hi)[a] - (*lo)[a];
    };
    diagonal += std::pow(extent(frame) + extent(knot), 2);
  }
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  REQUIRE_NOTHROW(CGAL::point_minkowski_sum_mesh(to_mesh<Mesh>(frame), to_mesh<Mesh>(knot), 0.04 * std::sqrt(diagonal), m,
                                                 CGAL::parameters::mesh_statistics(ms)));
  const auto checks = CGAL::Pmsum::check_mesh(m);
  REQUIRE(checks.valid());
  CHECK(checks.shells == 1);
  CHECK(checks.euler_characteristic == 2);
}

TEST_CASE("mesh of CGAL's hand + an octahedron at 2%: no neck across a gap where two parts of the hand nearly meet", "[applications][mesh][long]")
{
  // CGAL's hand (data/hand.off) plus its octahedron scaled by 0.0111958 (5% of the hand's
  // diagonal), d = 2% of the sum's diagonal: `pmsum mesh hand.off octahedron.off -d 0.02
  // --relative --scale-q 0.0111958`. Its exact boundary (CGAL's Nef sum, `pmsum validate`) is
  // one shell of Euler characteristic 2. The mesh made at d had a handle too many (Euler
  // characteristic 0, every other check passed, within 0.58 d of the exact boundary both
  // ways): a neck across a gap 0.2-0.5 d wide that narrows into a wedge, whose walls were over
  // free space only within d/8 of them, so that the test at d/4 saw two disks of them where
  // they make a ring (internal/mesh_necks.h). Now that mesh is refused and the next level is
  // right.
  Mesh P, Q;
  REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_PMSUM_DATA_DIR) + "/hand.off", P));
  REQUIRE(CGAL::IO::read_polygon_mesh(std::string(CGAL_PMSUM_DATA_DIR) + "/octahedron.off", Q));
  for (auto v : Q.vertices()) {
    const auto& p = Q.point(v);
    Q.point(v) = IK::Point_3(p.x() * 0.0111958, p.y() * 0.0111958, p.z() * 0.0111958);
  }
  const CGAL::Bbox_3 bp = CGAL::Polygon_mesh_processing::bbox(P), bq = CGAL::Polygon_mesh_processing::bbox(Q);
  double diagonal = 0;
  for (int c = 0; c < 3; ++c) diagonal += std::pow((bp.max(c) - bp.min(c)) + (bq.max(c) - bq.min(c)), 2);
  Mesh m;
  REQUIRE_NOTHROW(CGAL::point_minkowski_sum_mesh(P, Q, 0.02 * std::sqrt(diagonal), m));
  const auto checks = CGAL::Pmsum::check_mesh(m);
  REQUIRE(checks.valid());
  CHECK(checks.shells == 1);
  CHECK(checks.euler_characteristic == 2);
}

TEST_CASE("mesh of a thin part: the advancing front, or plane by plane", "[applications][mesh]")
{
  const Mesh Q = to_mesh<Mesh>(box({0, 0, 0}, {0.02, 0.02, 0.02}));
  // a plate 0.3 thick (sum 0.32): three point spacings at d = 0.2, meshed without refinement
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_minkowski_sum_mesh(to_mesh<Mesh>(box({0, 0, 0}, {2, 2, 0.3})), Q, 0.2, m,
                                 CGAL::parameters::mesh_statistics(ms));
  CHECK(CGAL::Pmsum::check_mesh(m).valid());
  CHECK(ms.checks.shells == 1);
  // a plate 0.02 thick (sum 0.04) at d = 0.4, thinner than the spacing at d/4 (0.05) too: both
  // sides keep their points (the net lets no point cover one facing it), and it is meshed; its
  // volume is at most the box's (every point of the mesh's solid is in the hull of its vertices,
  // on the box), less the chords cut along the rims
  Mesh thin;
  CGAL::point_minkowski_sum_mesh(to_mesh<Mesh>(box({0, 0, 0}, {2, 2, 0.02})), Q, 0.4, thin,
                                 CGAL::parameters::mesh_statistics(ms));
  REQUIRE(CGAL::Pmsum::check_mesh(thin).valid());
  CHECK(ms.checks.shells == 1);
  CHECK(ms.point_distance < ms.covering_distance);
  const double volume = CGAL::Polygon_mesh_processing::volume(thin), box_volume = 2.02 * 2.02 * 0.04;
  CHECK(volume <= box_volume * (1 + 1e-9));
  CHECK(volume > 0.9 * box_volume);
}

TEST_CASE("mesh that cannot be made: an error, and no mesh", "[applications][mesh]")
{
  // the suite's tunnel block + a cube of half-side 0.499, which leaves its tunnel 0.002 wide
  // (the CLI's offset by that cube), at a very coarse d, 0.19 of the sum's size: at every
  // level (d, d/2, d/4) the advancing front leaves output points far from its mesh, and plane
  // by plane is refused (a known limit: when it is meshed, this test must change): at the last
  // level for a face over empty space (until plane by plane kept one fan of triangles per
  // point, 2026-12-08, its triangles there were not a manifold). (The
  // suite's tunnel + tunnel-cube at d = 1.6 was such a case until the island search
  // skipped the cells inside the sum once perturbed, 2026-12-07: now meshed at d/2.)
  const Mesh P = to_mesh<Mesh>(tunnel_block());
  const Mesh Q = to_mesh<Mesh>(box({-0.499, -0.499, -0.499}, {0.499, 0.499, 0.499}));
  Mesh m = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  CGAL::Pmsum::Mesh_statistics ms;
  std::string why;
  try {
    CGAL::point_minkowski_sum_mesh(P, Q, 1.6, m, CGAL::parameters::mesh_statistics(ms));
  } catch (const CGAL::Pmsum::Mesh_reconstruction_failed& e) {
    why = e.what();
  }
  INFO(why);
  CHECK(why.find("at d = 0.399609 with the crease points plane by plane closed a hole over empty space; so none is returned") !=
        std::string::npos);
  CHECK(num_faces(m) == 0);
  CHECK(ms.refinements == 2);
}

TEST_CASE("mesh of a narrow tunnel, in its axes and turned: plane by plane, the tunnel kept", "[applications][mesh]")
{
  // A block with a tunnel + a cube turned about z that leaves it 1/2000 wide (d/700), then the
  // whole turned by a non-round rotation: the tunnel's walls, narrower than the points'
  // spacing, lie between four corner rows of trim points; the net keeps both rows of each
  // wall (the ends of a free part shorter than d/2 do not cover each other) and the mouths'
  // corners (where a row meets the top or bottom face: the ends of the wall's free part on
  // its facet's border, seen from the facet's side), so the walls are triangulated in their
  // planes up to the faces and the tunnel stays open: one shell of genus 1 (Euler
  // characteristic 0; lids over its mouths would make it 2).
  for (bool turned : {false, true}) {
    INFO((turned ? "turned" : "in its axes"));
    const auto turn = [&](const auto& polyhedron) { return turned ? rotated(polyhedron) : polyhedron; };
    const Mesh P = to_mesh<Mesh>(turn(tunnel_block()));
    const Mesh Q = to_mesh<Mesh>(turn(turned_cube((1 - 1. / 2000) / 1.4, 0.8, 0.6)));
    Mesh m;
    CGAL::Pmsum::Mesh_statistics ms;
    CGAL::point_minkowski_sum_mesh(P, Q, turned ? 0.45 : 0.34, m, CGAL::parameters::mesh_statistics(ms));
    REQUIRE(CGAL::Pmsum::check_mesh(m).valid());
    CHECK(ms.by_planes);
    CHECK(ms.refinements == 0);
    CHECK(ms.refused.find("by the advancing front") != std::string::npos); // (why the first mesh was not taken)
    CHECK(ms.checks.shells == 1u);
    CHECK(ms.point_distance < ms.covering_distance);
    const long euler = long(vertices(m).size()) - long(edges(m).size()) + long(faces(m).size());
    CHECK(euler == 0);
    CHECK(ms.checks.euler_characteristic == euler);
  }
}

TEST_CASE("mesh of the narrow tunnel turned at a coarser d: no void in the tunnel", "[applications][mesh]")
{
  // The turned pair of the test above at d = 0.78 (7% of the sum's diagonal). The advancing
  // front closed the tunnel over both mouths and left a needle of 8 vertices inside it, an
  // inward shell: two shells (one void) where the sum has one, every other check passed.
  // has_false_void() tested one segment per vertex of the needle, to the nearest vertex of the
  // outer shell: on the same wall of the tunnel (its points lie at the same places on both
  // walls), a segment along a face of the sum, not free. The next nearest, across the tunnel,
  // is free: the void is refuted, and the points are meshed plane by plane, the tunnel kept.
  const Mesh P = to_mesh<Mesh>(rotated(tunnel_block()));
  const Mesh Q = to_mesh<Mesh>(rotated(turned_cube((1 - 1. / 2000) / 1.4, 0.8, 0.6)));
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_minkowski_sum_mesh(P, Q, 0.78, m, CGAL::parameters::mesh_statistics(ms));
  REQUIRE(ms.checks.valid());
  CHECK(ms.checks.shells == 1u);
  CHECK(ms.checks.void_shells == 0u);
  CHECK(ms.checks.euler_characteristic == 0);
  CHECK(ms.point_distance < ms.covering_distance);
}

TEST_CASE("Euler characteristic of shells: spheres and a torus; borders and touching solids not compared", "[applications][mesh]")
{
  using CGAL::Pmsum::Shell;
  using CGAL::Pmsum::euler_characteristic;
  auto shell_of = [](const Soup& soup) {
    Shell s;
    for (const auto& p : soup.points) s.points.push_back({p[0], p[1], p[2]});
    s.triangles = soup.triangles;
    return s;
  };
  const Shell cube = shell_of(box({0, 0, 0}, {1, 1, 1}));
  CHECK(euler_characteristic({cube}) == 2);
  CHECK(euler_characteristic({cube, cube}) == 4); // two spheres
  CHECK(euler_characteristic({}) == 0);
  // an n x m grid closed on itself both ways: a torus, V - E + F = nm - 3nm + 2nm = 0
  Shell torus;
  const std::size_t n = 7, m = 5;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const double u = 2 * CGAL_PI * double(i) / n, v = 2 * CGAL_PI * double(j) / m;
      torus.points.push_back({(3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  auto at = [&](std::size_t i, std::size_t j) { return (i % n) * m + j % m; };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      torus.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      torus.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  CHECK(euler_characteristic({torus}) == 0);
  CHECK(euler_characteristic({torus, cube}) == 2);
  // not a closed 2-manifold: nothing to compare
  Shell open = cube;
  open.triangles.pop_back();
  CHECK(!euler_characteristic({open}));
  Shell turned = cube; // one triangle turned the other way
  std::swap(turned.triangles[0][1], turned.triangles[0][2]);
  CHECK(!euler_characteristic({turned}));
  // two cubes in one shell, their common vertices once: sharing an edge (on four triangles) or
  // only a corner (a vertex with two fans)
  auto touching = [&](const Point& lo) {
    Soup two = box({0, 0, 0}, {1, 1, 1});
    two.append(box(lo, {lo[0] + 1, lo[1] + 1, lo[2] + 1}));
    Shell s = shell_of(two);
    for (auto& t : s.triangles)
      for (std::size_t& k : t)
        for (std::size_t e = 0; e < k; ++e)
          if (s.points[e] == s.points[k]) { k = e; break; }
    return s;
  };
  CHECK(!euler_characteristic({touching({1, 1, 0})}));
  CHECK(!euler_characteristic({touching({1, 1, 1})}));
  CHECK(euler_characteristic({touching({2, 0, 0})}) == 4); // apart: two spheres in one list
}

TEST_CASE("mesh of a narrow slot, a slit and slivers: plane by plane, the passage kept", "[applications][mesh]")
{
  // Two unit cubes 1/2 apart, on a floor (a slot) or not (a slit: two solids), + a cube turned
  // about z whose extent along x is 1/2 - 1/2000: the sum keeps a passage 1/2000 wide (d/300),
  // where the advancing front joins the walls; plane by plane, no triangle leaves its plane.
  // The same cube tilted by 0.01 rad about x: faces at 0.01 rad from the slot's (slivers),
  // meshed at the validation suite's d.
  for (int kind : {0, 1, 2}) {
    INFO((kind == 0 ? "slot" : kind == 1 ? "slit" : "slivers"));
    const bool floor = kind != 1;
    const double d = kind == 2 ? 0.1535 : 0.15;
    const Mesh P = to_mesh<Mesh>(slot_blocks(0.5, floor));
    const Mesh Q = to_mesh<Mesh>(kind == 2 ? turned_cube((0.5 - 1. / 2000) / 1.4, 0.8, 0.6, std::cos(0.01), std::sin(0.01))
                                           : turned_cube((0.5 - 1. / 2000) / 1.4, 0.8, 0.6));
    Mesh m;
    CGAL::Pmsum::Mesh_statistics ms;
    CGAL::point_minkowski_sum_mesh(P, Q, d, m, CGAL::parameters::mesh_statistics(ms));
    REQUIRE(CGAL::Pmsum::check_mesh(m).valid());
    CHECK(ms.by_planes);
    CHECK(ms.refinements == 0);
    CHECK(ms.checks.shells == (floor ? 1u : 2u));    // the slit's two solids stay apart
    CHECK(ms.point_distance < ms.covering_distance); // the passage's walls are in the mesh
    // every face of the sum has vertices, those of its bounding box too: the box is exact
    const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(m), bp = CGAL::Polygon_mesh_processing::bbox(P),
                       bq = CGAL::Polygon_mesh_processing::bbox(Q);
    for (int k = 0; k < 3; ++k) {
      CHECK(b.min(k) == Approx(bp.min(k) + bq.min(k)).margin(1e-12));
      CHECK(b.max(k) == Approx(bp.max(k) + bq.max(k)).margin(1e-12));
    }
  }
}

TEST_CASE("no_face_over_hole: a face over a tunnel's mouth narrower than the points' spacing", "[applications][mesh]")
{
  namespace in = CGAL::Pmsum::internal;
  // A 4 x 4 x 4 block, with and without a tunnel, + the cube turned about z that leaves the
  // tunnel 1/2000 wide: the convex hull of the vertex sums is the sum of the block (convex),
  // and the sum of the block with the tunnel but for its mouths, which its top and bottom
  // faces cover.
  const Mesh mq = to_mesh<Mesh>(turned_cube((1 - 1. / 2000) / 1.4, 0.8, 0.6));
  for (bool tunnel : {false, true}) {
    INFO((tunnel ? "tunnel" : "block"));
    const Mesh mp = to_mesh<Mesh>(tunnel ? tunnel_block() : box({0, 0, 0}, {4, 4, 4}));
    in::Mesh_descriptors<Mesh> dp, dq;
    const in::Mesh_data a = in::make_mesh_data(mp, get(CGAL::vertex_point, mp), false, false, "P", dp);
    const in::Mesh_data b = in::make_mesh_data(mq, get(CGAL::vertex_point, mq), false, false, "Q", dq);
    in::Face_cover cover(in::candidate_feature_pairs(a, b, true), a, b);
    std::vector<IK::Point_3> sums;
    for (auto v : vertices(mp))
      for (auto w : vertices(mq)) sums.push_back(get(CGAL::vertex_point, mp, v) + (get(CGAL::vertex_point, mq, w) - CGAL::ORIGIN));
    Mesh hull;
    CGAL::convex_hull_3(sums.begin(), sums.end(), hull);
    CGAL::Polygon_mesh_processing::triangulate_faces(hull);
    CHECK(in::no_face_over_hole(hull, 0.34, cover) == !tunnel);
  }
}

TEST_CASE("no_face_joining_parts: a face across a slit, not one across a reflex corner", "[applications][mesh]")
{
  namespace in = CGAL::Pmsum::internal;
  auto operands = [](const Soup& p, const Soup& q) {
    const Mesh mp = to_mesh<Mesh>(p), mq = to_mesh<Mesh>(q);
    in::Mesh_descriptors<Mesh> dp, dq;
    return std::make_tuple(in::make_mesh_data(mp, get(CGAL::vertex_point, mp), false, false, "P", dp),
                           in::make_mesh_data(mq, get(CGAL::vertex_point, mq), false, false, "Q", dq), mp, mq);
  };
  auto hull_of_sums = [](const Mesh& mp, const Mesh& mq, double x_max) { // of P's vertices with x <= x_max
    std::vector<IK::Point_3> sums;
    for (auto v : vertices(mp))
      for (auto w : vertices(mq))
        if (get(CGAL::vertex_point, mp, v).x() <= x_max)
          sums.push_back(get(CGAL::vertex_point, mp, v) + (get(CGAL::vertex_point, mq, w) - CGAL::ORIGIN));
    Mesh hull;
    CGAL::convex_hull_3(sums.begin(), sums.end(), hull);
    CGAL::Polygon_mesh_processing::triangulate_faces(hull);
    return hull;
  };
  // Two unit cubes 0.05 apart plus a cube of side 0.02: two boxes 0.03 apart, whose faces in
  // the planes y = 0, y = 1.02, z = 0 and z = 1.02 are two parts of each. The hull of all the
  // vertex sums lays faces across the slit, from one part to the other; the left box's
  // hull does not. On a floor up to z = 0.95, the slit is a notch 0.05 deep: for d = 0.34
  // the sum is solid d / 2 under the gap, and the hull's faces across it pass.
  const double s = 0.02, d = 0.34;
  struct Sum_geometry // (the geometry refers to the operands)
  {
    std::pair<in::Mesh_data, in::Mesh_data> operands;
    in::Cd_geometry geometry;
    Sum_geometry(const Soup& p, double s)
      : operands(cd_operands(box({-s / 2, -s / 2, -s / 2}, {s / 2, s / 2, s / 2}), p)), geometry(operands.first, operands.second) {}
  };
  auto free_at = [&](const Soup& p) {
    return [s, sum = std::make_shared<Sum_geometry>(p, s)](const std::array<double, 3>& x) {
      return in::Cd_filter(&sum->geometry).is_free_at({x[0] - s / 2, x[1] - s / 2, x[2] - s / 2}); // (Q is [0, s]^3)
    };
  };
  {
    const Soup slit = slot_blocks(0.05, false);
    const auto [a, b, mp, mq] = operands(slit, box({0, 0, 0}, {s, s, s}));
    in::Face_cover cover(in::candidate_feature_pairs(a, b, true), a, b);
    CHECK(in::no_face_joining_parts(hull_of_sums(mp, mq, 1), d, cover, free_at(slit)));
    CHECK(!in::no_face_joining_parts(hull_of_sums(mp, mq, 3), d, cover, free_at(slit)));
    REQUIRE(cover.set_plane({0, -1, 0}, 0, 1));
    CHECK(cover.joins_separate_parts({{{0.5, 0, 0.5}, {1.6, 0, 0.5}, {0.5, 0, 0.9}}}));
    CHECK(!cover.joins_separate_parts({{{0.5, 0, 0.5}, {1.02, 0, 0.5}, {0.5, 0, 0.9}}}));
    CHECK(!cover.joins_separate_parts({{{0.5, 0, 0.5}, {1.04, 0, 0.5}, {0.5, 0, 0.9}}})); // (a corner off the facets)
    const auto gaps = cover.gaps_between_parts({{{0.5, 0, 0.5}, {1.6, 0, 0.5}, {0.5, 0, 0.9}}});
    REQUIRE(gaps.size() == 2); // on the sides from (1.6, 0, 0.5)
    for (const auto& g : gaps) CHECK(g[0] == Approx(1.035).margin(1e-12));
  }
  {
    Soup notch = box({0, 0, 0}, {2.05, 1, 0.95});
    notch.append(box({0, 0, 0.95}, {1, 1, 1}));
    notch.append(box({1.05, 0, 0.95}, {2.05, 1, 1}));
    const auto [a, b, mp, mq] = operands(notch, box({0, 0, 0}, {s, s, s}));
    in::Face_cover cover(in::candidate_feature_pairs(a, b, true), a, b);
    REQUIRE(cover.set_plane({0, 0, 1}, 1 + s, 2));
    CHECK(cover.joins_separate_parts({{{0.5, 0.5, 1 + s}, {1.6, 0.5, 1 + s}, {0.5, 0.9, 1 + s}}}));
    const auto gaps = cover.gaps_between_parts({{{0.5, 0.5, 1 + s}, {1.6, 0.5, 1 + s}, {0.5, 0.9, 1 + s}}});
    CHECK(gaps.size() == 2);
    const auto notch_free = free_at(notch);
    CHECK(notch_free({1.035, 0.5, 1}));         // in the notch
    CHECK(!notch_free({1.035, 0.5, 1 + s - d / 2})); // under it
    // (the hull's top faces have sides on the sum's edges y = 0 and y = 1 + s: the middle of
    // the gap there, moved under the face, lies on the sum's boundary, free: refused)
    Mesh across;
    const auto v0 = across.add_vertex({0.5, 0.5, 1 + s}), v1 = across.add_vertex({1.6, 0.5, 1 + s}), v2 = across.add_vertex({0.5, 0.9, 1 + s});
    across.add_face(v0, v1, v2);
    CHECK(in::no_face_joining_parts(across, d, cover, notch_free));
    CHECK(!in::no_face_joining_parts(across, 0.06, cover, notch_free)); // (free 0.03 under it)
    CHECK(!in::no_face_joining_parts(hull_of_sums(mp, mq, 3), d, cover, notch_free));
  }
  // The L-shape plus the cube: its bottom face (z = 0) is one part, with a reflex corner at
  // (1.02, 1.02). A triangle across that corner leaves the facets (no_face_over_hole()
  // refuses it) but joins no parts.
  {
    const auto [a, b, mp, mq] = operands(l_shape(), box({0, 0, 0}, {s, s, s}));
    in::Face_cover cover(in::candidate_feature_pairs(a, b, true), a, b);
    REQUIRE(cover.set_plane({0, 0, -1}, 0, 2));
    const std::array<std::array<double, 3>, 3> corner_cut = {{{1 + s, 1 + s + 0.05, 0}, {1 + s + 0.05, 1 + s, 0}, {1 + s - 0.05, 1 + s, 0}}};
    CHECK(!cover.covers(corner_cut, 1e-9));
    CHECK(!cover.joins_separate_parts(corner_cut));
  }
}

TEST_CASE("kept_triangles: in order, or the kept ones up to a side three share; the tests first where that can come", "[applications][mesh]")
{
  using CGAL::Pmsum::internal::kept_triangles;
  using T = std::array<std::size_t, 3>;
  // a fan of three triangles on side 0-1 (a fin: no manifold has it), and two others on
  // sides of their own
  const std::vector<T> candidates = {{2, 3, 4}, {0, 1, 2}, {3, 4, 5}, {1, 0, 5}, {0, 1, 6}, {4, 6, 7}};
  std::vector<std::size_t> asked;
  auto keep_all_but = [&](std::size_t skipped) {
    return [&asked, skipped](std::size_t k) {
      asked.push_back(k);
      return k != skipped;
    };
  };
  // all kept: the fin's third stops it, and only the fin's three were asked (2-3-4 and 3-4-5
  // share side 3-4, but two triangles make no third)
  CHECK(kept_triangles(candidates, 8, keep_all_but(99)) == std::vector<T>{{0, 1, 2}, {1, 0, 5}, {0, 1, 6}});
  CHECK(asked == std::vector<std::size_t>{1, 3, 4});
  // one of the fin refused: every candidate asked once, the kept ones in their order
  asked.clear();
  CHECK(kept_triangles(candidates, 8, keep_all_but(3)) == std::vector<T>{{2, 3, 4}, {0, 1, 2}, {3, 4, 5}, {0, 1, 6}, {4, 6, 7}});
  std::sort(asked.begin(), asked.end());
  CHECK(asked == std::vector<std::size_t>{0, 1, 2, 3, 4, 5});
}

TEST_CASE("no_face_over_empty_space: chords pass, a lid over a tunnel does not", "[applications][mesh]")
{
  using CGAL::Pmsum::internal::no_face_over_empty_space;
  auto outside_ball = [](const std::array<double, 3>& x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2] > 1; };
  // an octahedron inscribed in the unit ball (faces inside it), and one twice as large (faces
  // 2/sqrt(3) - 1 = 0.155 outside it): the ball within d/2 inside for d = 1, not for d = 0.25
  const Mesh inscribed = to_mesh<Mesh>(octahedron(1)), outer = to_mesh<Mesh>(octahedron(2));
  CHECK(no_face_over_empty_space(inscribed, 0.01, outside_ball));
  CHECK(no_face_over_empty_space(outer, 1.0, outside_ball));
  CHECK_FALSE(no_face_over_empty_space(outer, 0.25, outside_ball));
  // the unit cube, and the same with a tunnel (0.2, 0.8)^2 along z: the top and bottom faces
  // close the tunnel's mouths
  const Mesh cube = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  auto outside_cube = [](const std::array<double, 3>& x) {
    return !(x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1 && x[2] > 0 && x[2] < 1);
  };
  auto outside_tunnel_block = [&](const std::array<double, 3>& x) {
    return outside_cube(x) || (x[0] > 0.2 && x[0] < 0.8 && x[1] > 0.2 && x[1] < 0.8);
  };
  CHECK(no_face_over_empty_space(cube, 0.1, outside_cube));
  CHECK_FALSE(no_face_over_empty_space(cube, 0.1, outside_tunnel_block));
}

TEST_CASE("mesh of an offset: valid, every vertex between the ball's inradius and r from the box",
          "[applications][mesh][offset]")
{
  const double r = 0.25, d = 0.1;
  Mesh ball;
  const double inner = CGAL::make_icosphere(r, 0.02, ball);
  const Mesh cube = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_offset_mesh(cube, ball, d, m, CGAL::parameters::mesh_statistics(ms));
  const auto c = CGAL::Pmsum::check_mesh(m);
  REQUIRE(c.valid());
  CHECK(c.shells == 1);
  CHECK(ms.vertices == vertices(m).size());
  CHECK(ms.point_distance < ms.covering_distance);
  double nearest = HUGE_VAL, farthest = 0;
  for (auto v : m.vertices()) {
    nearest = (std::min)(nearest, distance_to_box_surface(m.point(v), 0, 1));
    farthest = (std::max)(farthest, distance_to_box_surface(m.point(v), 0, 1));
  }
  CHECK(nearest >= inner - 1e-12);
  CHECK(farthest <= r + 1e-12);
  // The offset is convex and the vertices lie on its boundary: the mesh's volume is below the
  // round offset's (Steiner: 1 + 6 r + 3 pi r^2 + 4/3 pi r^3), and above the one of radius
  // `inner` less the caps its triangles cut off (a sagitta of (d/2)^2 / (2 inner) at most).
  auto steiner = [](double s) { return 1 + 6 * s + 3 * CGAL_PI * s * s + 4. / 3 * CGAL_PI * s * s * s; };
  const double volume = CGAL::Polygon_mesh_processing::volume(m);
  CHECK(volume < steiner(r));
  CHECK(volume > steiner(inner - d * d / (8 * inner)));
}

TEST_CASE("mesh of a sweep: valid, every vertex on the exact swept polytope, its volume", "[applications][mesh][sweep]")
{
  // an icosphere swept along (2, 1, 0.5): the hull of the icosphere at both ends
  Mesh P;
  CGAL::make_icosphere(0.5, 0.02, P);
  const std::vector<IK::Point_3> path = {IK::Point_3(0, 0, 0), IK::Point_3(2, 1, 0.5)};
  const double d = 0.1;
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_sweep_mesh(P, path, d, m, CGAL::parameters::mesh_statistics(ms));
  const auto c = CGAL::Pmsum::check_mesh(m);
  REQUIRE(c.valid());
  CHECK(c.shells == 1);
  CHECK(ms.point_distance < ms.covering_distance);
  std::vector<IK::Point_3> corners;
  for (auto v : P.vertices())
    for (const IK::Point_3& t : path) corners.push_back(P.point(v) + (t - CGAL::ORIGIN));
  Mesh hull;
  CGAL::convex_hull_3(corners.begin(), corners.end(), hull);
  // every vertex on the hull's boundary (rounding aside): on one facet plane, inside all
  std::vector<IK::Plane_3> planes;
  for (auto f : hull.faces()) {
    std::vector<IK::Point_3> t;
    for (auto v : vertices_around_face(hull.halfedge(f), hull)) t.push_back(hull.point(v));
    planes.emplace_back(t[0], t[1], t[2]);
  }
  double worst = 0;
  for (auto v : m.vertices()) {
    double outside = -HUGE_VAL; // largest signed distance to a facet plane: 0 on the boundary
    for (const auto& h : planes) {
      const IK::Vector_3 n = h.orthogonal_vector();
      outside = (std::max)(outside, (h.a() * m.point(v).x() + h.b() * m.point(v).y() + h.c() * m.point(v).z() + h.d()) /
                                      std::sqrt(n.squared_length()));
    }
    worst = (std::max)(worst, std::abs(outside));
  }
  CHECK(worst < 1e-12);
  // inscribed in the convex hull: a smaller volume, by the corners its triangles cut
  const double volume = CGAL::Polygon_mesh_processing::volume(m), exact = CGAL::Polygon_mesh_processing::volume(hull);
  CHECK(volume <= exact);
  CHECK(volume > 0.99 * exact);
}

TEST_CASE("mesh of a swept cube: plane by plane, its volume exact", "[applications][mesh][sweep]")
{
  // the unit cube swept along v = (2, 1, 0.5): the advancing front cuts its corners (three flat
  // faces meeting) into shells of their own; plane by plane every face is exact. Volume: the
  // cube's plus |v| times its shadow along v, (|vx| + |vy| + |vz|) / |v|: 1 + 3.5
  const Mesh P = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  const std::vector<IK::Point_3> path = {IK::Point_3(0, 0, 0), IK::Point_3(2, 1, 0.5)};
  Mesh m;
  CGAL::Pmsum::Mesh_statistics ms;
  CGAL::point_sweep_mesh(P, path, 0.1, m, CGAL::parameters::mesh_statistics(ms));
  REQUIRE(CGAL::Pmsum::check_mesh(m).valid());
  CHECK(ms.by_planes);
  CHECK(ms.checks.shells == 1);
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(4.5).epsilon(1e-12));
}
