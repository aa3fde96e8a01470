// Convex + convex: the exact answer is the convex hull of the vertex sums.
#include "test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>

#include <catch2/catch.hpp>

#include <set>

using namespace pmsum_shapes;

namespace {

/// Both outputs, the default net and every boundary candidate: exact and covering.
void check_convex(const Soup& P, const Soup& Q, double d, bool negate = false)
{
  const auto [net, all] = check_net_and_all(P, Q, d, Reference(P, Q, negate), CGAL::parameters::negate_first_mesh(negate));
  // The rounded output points are the exact ones, rounded.
  for (const Result* r : {&net, &all})
    for (std::size_t i = 0; i < r->points.size(); ++i)
      REQUIRE(CGAL::squared_distance(r->points[i], IK::Point_3(CGAL::to_double(r->exact[i].x()),
                                                                CGAL::to_double(r->exact[i].y()),
                                                                CGAL::to_double(r->exact[i].z()))) < 1e-24);
  // Convex operands: every candidate kept by the normal filter is on the boundary.
  CHECK(all.points.size() == all.stats.candidates);
  // The net saves collision tests: what it covers is never tested.
  CHECK(net.stats.candidates_covered > 0);
  CHECK(net.stats.cd_queries < all.stats.cd_queries);
}

} // namespace

TEST_CASE("cube + cube is the doubled cube", "[convex]")
{
  check_convex(box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 1, 1}), 0.3);
  check_convex(box({0, 0, 0}, {1, 1, 1}), box({-0.5, 0.25, 0}, {0.5, 0.5, 2}), 0.2);
}

TEST_CASE("tetrahedron + octahedron", "[convex]")
{
  check_convex(tetrahedron(1), octahedron(0.5), 0.1);
  check_convex(tetrahedron(1), octahedron(0.5), 0.1, /*negate=*/true);
}

TEST_CASE("random convex polytopes", "[convex]")
{
  for (unsigned seed : {1u, 2u, 3u}) {
    INFO("seed " << seed);
    const Soup P = random_convex(14, seed), Q = transformed(random_convex(10, seed + 100), 0.5);
    check_convex(P, Q, 0.15);
    check_convex(P, Q, 0.15, /*negate=*/true);
  }
}

TEST_CASE("records name their origins and rebuild the exact point", "[convex][records]")
{
  const Soup P = tetrahedron(1), Q = box({0, 0, 0}, {0.5, 0.5, 0.5});
  const Result r = run(P, Q, 0.2);
  REQUIRE(!r.records.empty());
  std::set<std::pair<int, int>> kinds;
  for (std::size_t i = 0; i < r.records.size(); ++i) {
    const Record& rec = r.records[i];
    for (const auto* f : {&rec.origin_p, &rec.origin_q}) {
      const int nonzero = int(f->weights[0] != 0) + int(f->weights[1] != 0) + int(f->weights[2] != 0);
      REQUIRE(nonzero == f->dimension + 1);
      REQUIRE(f->denominator == f->weights[0] + f->weights[1] + f->weights[2]);
    }
    kinds.insert({rec.origin_p.dimension, rec.origin_q.dimension});
    // unit normal
    REQUIRE(std::abs(rec.normal.squared_length() - 1) < 1e-12);
    REQUIRE(!rec.negated_p);
  }
  // facet-vertex, vertex-facet and edge-edge pairs, and their closures, all occur
  for (std::pair<int, int> k : {std::pair{2, 0}, {0, 2}, {1, 1}, {1, 0}, {0, 1}, {0, 0}})
    CHECK(kinds.count(k) == 1);
  // never case 5
  for (std::pair<int, int> k : {std::pair{2, 2}, {2, 1}, {1, 2}}) CHECK(kinds.count(k) == 0);
}

namespace {
template <class Mesh>
std::vector<IK::Point_3> point_set(const Soup& P, const Soup& Q, double d)
{
  const Mesh mp = to_mesh<Mesh>(P), mq = to_mesh<Mesh>(Q);
  using Point = typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<Point> pts;
  CGAL::point_minkowski_sum(mp, mq, d, std::back_inserter(pts));
  std::vector<IK::Point_3> out;
  for (const auto& p : pts) out.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  return out;
}

/// Same size, and every point of each set within 1e-12 of a point of the other (Epeck
/// rounds the exact point, Epick computes it in double arithmetic).
bool same_points(const std::vector<IK::Point_3>& a, const std::vector<IK::Point_3>& b)
{
  return a.size() == b.size() && coverage_distance(a, b) < 1e-12 && coverage_distance(b, a) < 1e-12;
}
} // namespace

TEST_CASE("Surface_mesh and Polyhedron_3 with Epick and Epeck give the same points", "[convex][kernels]")
{
  const Soup P = tetrahedron(1), Q = octahedron(0.5);
  const auto a = point_set<CGAL::Surface_mesh<IK::Point_3>>(P, Q, 0.15);
  const auto b = point_set<CGAL::Surface_mesh<EK::Point_3>>(P, Q, 0.15);
  const auto c = point_set<CGAL::Polyhedron_3<IK>>(P, Q, 0.15);
  const auto e = point_set<CGAL::Polyhedron_3<EK>>(P, Q, 0.15);
  REQUIRE(a.size() > 100);
  CHECK(same_points(a, b));
  CHECK(same_points(a, c));
  CHECK(same_points(a, e));
}

TEST_CASE("Epeck output points are exact", "[convex][kernels]")
{
  using EMesh = CGAL::Surface_mesh<EK::Point_3>;
  const Soup P = tetrahedron(1), Q = octahedron(0.5);
  const EMesh mp = to_mesh<EMesh>(P), mq = to_mesh<EMesh>(Q);
  std::vector<EK::Point_3> pts;
  CGAL::point_minkowski_sum(mp, mq, 0.15, std::back_inserter(pts));
  const Reference ref(P, Q);
  REQUIRE(!pts.empty());
  std::size_t bad = 0;
  for (const auto& p : pts) bad += !ref.on_boundary(p);
  CHECK(bad == 0);
}

TEST_CASE("progress callback reaches 1 and can cancel", "[convex][callback]")
{
  const Mesh mp = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1})), mq = to_mesh<Mesh>(octahedron(0.5));
  std::vector<double> seen;
  std::vector<IK::Point_3> pts;
  std::function<bool(double)> record = [&](double f) { seen.push_back(f); return true; };
  CGAL::point_minkowski_sum(mp, mq, 0.1, std::back_inserter(pts), CGAL::parameters::callback(record));
  REQUIRE(seen.size() > 2);
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() == 1.0);
  std::function<bool(double)> stop = [](double f) { return f < 0.3; };
  pts.clear();
  CHECK_THROWS_AS(CGAL::point_minkowski_sum(mp, mq, 0.1, std::back_inserter(pts), CGAL::parameters::callback(stop)),
                  CGAL::Pmsum::Operation_cancelled);
}

TEST_CASE("statistics add up", "[convex][statistics]")
{
  const Result r = run(random_convex(12, 7), octahedron(0.3), 0.1);
  CHECK(r.stats.output_points == r.points.size());
  CHECK(r.stats.samples_p > 12);
  CHECK(r.stats.samples_q > 6);
  // Convex: no candidate is inner, so each is either covered by the net or tested.
  CHECK(r.stats.cd_queries + r.stats.candidates_covered >= r.stats.candidates);
  CHECK(r.stats.candidates_covered > 0);
  CHECK(r.stats.feature_pairs > 0);
}

TEST_CASE("sample counts are the samples listed, coarse to fine too", "[convex][statistics]")
{
  // number_of_samples() counts an edge's samples in closed form (shared fractions of its own
  // and its two triangles' lattices counted once): it must match the samples listed.
  using namespace CGAL::Pmsum::internal;
  const auto ops = cd_operands(random_convex(40, 3), ellipsoid(1, 0.3, 0.7));
  for (const Mesh_data* m : {&ops.first, &ops.second}) {
    const Mesh_sampling coarse(*m, 0.13, "M");
    for (const Mesh_sampling& s : {coarse, Mesh_sampling(*m, 0.07, "M"), Mesh_sampling(*m, 0.021, "M", &coarse)})
      for (int dim = 1; dim <= 2; ++dim)
        for (Index i = 0; i < (dim == 1 ? m->number_of_edges() : m->number_of_triangles()); ++i) {
          std::vector<Sample> listed;
          s.samples(Feature{dim, i}, listed);
          REQUIRE(s.number_of_samples(Feature{dim, i}) == listed.size());
        }
  }
}

TEST_CASE("Parallel_tag gives the same points in the same order", "[parallel][long]")
{
#ifdef CGAL_LINKED_WITH_TBB
  const Mesh mp = to_mesh<Mesh>(l_shape()), mq = to_mesh<Mesh>(random_convex(12, 5));
  for (bool negate : {false, true}) {
    for (bool net : {true, false}) {
      INFO((net ? "net" : "all candidates") << (negate ? ", negated" : ""));
      std::vector<Record> seq, par;
      CGAL::Pmsum::Statistics s1, s2;
      CGAL::point_minkowski_sum<CGAL::Sequential_tag>(
        mp, mq, 0.05, std::back_inserter(seq), CGAL::parameters::negate_first_mesh(negate).use_covering_net(net).statistics(s1));
      CGAL::point_minkowski_sum<CGAL::Parallel_tag>(
        mp, mq, 0.05, std::back_inserter(par), CGAL::parameters::negate_first_mesh(negate).use_covering_net(net).statistics(s2));
      REQUIRE(seq.size() > 1000);
      REQUIRE(seq.size() == par.size());
      for (std::size_t i = 0; i < seq.size(); ++i) {
        REQUIRE(seq[i].point == par[i].point);
        REQUIRE(seq[i].normal == par[i].normal);
      }
      // Waves do not depend on the threads, nor does what is tested in them.
      CHECK(s1.cd_queries == s2.cd_queries);
    }
  }
#else
  WARN("built without TBB: CGAL::Parallel_tag is unavailable");
#endif
}
