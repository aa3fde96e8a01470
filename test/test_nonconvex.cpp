// Non-convex, non-manifold and open operands with exactly known sums, and the filters.
#include "test_support.h"
#include <CGAL_pmsum/internal/segment_search.h>
#include "suite_shapes.h"

#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <tuple>

using namespace pmsum_shapes;

namespace {

/// Runs P + Q and checks exactness and coverage against the union-of-pieces reference, for
/// the default net and for every boundary candidate; returns the latter.
Result check(const Soup& P, const Soup& Q, double d)
{
  return check_net_and_all(P, Q, d, Reference(P, Q)).second;
}

/// Number of points strictly inside the open box (lo, hi).
std::size_t count_in(const std::vector<IK::Point_3>& pts, const Point& lo, const Point& hi)
{
  std::size_t n = 0;
  for (const auto& p : pts) {
    bool in = true;
    for (int c = 0; c < 3; ++c) in = in && lo[c] < p[c] && p[c] < hi[c];
    n += in;
  }
  return n;
}

/// The CD filter of two operands (cd_operands()), and random translations in the box of
/// their sum.
struct Cd_case
{
  Cd_case(const Soup& ps, const Soup& qs)
    : operands(cd_operands(ps, qs)), geometry(operands.first, operands.second), filter(&geometry),
      bp(CGAL::Pmsum::internal::mesh_box(operands.first)), bq(CGAL::Pmsum::internal::mesh_box(operands.second)) {}
  /// Coordinate c of a random translation.
  double coordinate(CGAL::Random& rng, int c) const { return rng.get_double(bp.first[c] + bq.first[c], bp.second[c] + bq.second[c]); }

  std::pair<CGAL::Pmsum::internal::Mesh_data, CGAL::Pmsum::internal::Mesh_data> operands;
  CGAL::Pmsum::internal::Cd_geometry geometry;
  CGAL::Pmsum::internal::Cd_filter filter;
  std::pair<CGAL::Pmsum::internal::Point3, CGAL::Pmsum::internal::Point3> bp, bq;
};

} // namespace

TEST_CASE("L-shape + cube is a union of two boxes", "[nonconvex]")
{
  const Result r = check(l_shape(), box({0, 0, 0}, {0.5, 0.5, 0.5}), 0.1);
  // The normal filter keeps inner candidates here (the reflex edge): the CD filter removes them.
  CHECK(r.points.size() < r.stats.candidates);
}

TEST_CASE("boxes that touch face to face + a cube: the seams inside the sum decided on the facets' planes, the net exact and covering", "[nonconvex][trim]")
{
  // The paper's blocks (five unit boxes of a checkerboard) + a unit cube: a box, [0, 4]^2 x
  // [0, 1.5], whose inside is crossed by convolution facets on the seams x, y = 1, 2, 3 where
  // the boxes' sums touch face to face. There the CD filter needs the perturbation's exact
  // signs at every point, and one patch pair's crossing set holds the facet's points once the
  // facet's plane decides its seam (decision.h, Facet_patch_test): candidates and lattice
  // points decided so are never CD-tested. The output is checked as always: every point
  // exactly on the exact boundary, covering it, a net of the boundary candidates.
  const Result r = check(blocks(3, 0.5), box({0, 0, 0}, {1, 1, 1}), 0.25);
  INFO(r.stats.candidates << " candidates, " << r.stats.candidates_in_patch_pairs << " in patch pairs, "
                          << r.stats.cd_queries << " CD queries, " << r.stats.corner_tests << " corner tests");
  CHECK(r.stats.candidates_in_patch_pairs > 0);
}

TEST_CASE("L-shape + cube, records report the reflex crease exactly", "[nonconvex]")
{
  // The sum's reflex edge is the segment x = y = 1.5, z in [0, 1.5].
  const Result r = run(l_shape(), box({0, 0, 0}, {0.5, 0.5, 0.5}), 0.1);
  std::size_t on_crease = 0;
  for (const auto& x : r.exact) on_crease += (x.x() == 1.5 && x.y() == 1.5);
  CHECK(on_crease >= 10);
}

TEST_CASE("flat faces cut into many triangles are triangulated again without their inner vertices", "[nonconvex][input]")
{
  using namespace CGAL::Pmsum::internal;
  auto merged = [](const Soup& s) {
    const Mesh m = to_mesh<Mesh>(s);
    Mesh_descriptors<Mesh> desc;
    return make_mesh_data(m, get(CGAL::vertex_point, m), false, false, "P", desc, true, /*merge_flat=*/true);
  };
  auto used = [](const Mesh_data& m) {
    std::size_t n = 0;
    for (Index v = 0; v < m.number_of_vertices(); ++v) n += !m.vertex_is_isolated(v);
    return n;
  };
  // A cube or an L cut k times: the points inside its faces and inside its edges go, and
  // what is left has the uncut shape's counts.
  for (int k : {0, 1, 3})
    for (const Soup& shape : {box({0, 0, 0}, {1, 1, 1}), l_shape(), rotated(l_shape())}) {
      INFO("shape of " << shape.points.size() << " vertices cut " << k << " times");
      const Mesh_data m = merged(subdivided(shape, k));
      CHECK(used(m) == shape.points.size());
      CHECK(m.number_of_triangles() == shape.triangles.size());
      CHECK(m.number_of_edges() == 3 * shape.triangles.size() / 2);
      CHECK(m.components.size() == 1);
      CHECK(!merge_planar_patches(m.points, m.triangles)); // nothing left to merge
    }
}

TEST_CASE("flat faces cut into many triangles: the sums stay exact and covering, at the uncut shapes' cost",
          "[nonconvex][input][long]")
{
  // The sums (merged by default) stay exact and covering, with or without -P, and cost about
  // what the uncut shapes cost.
  const Soup L = subdivided(l_shape(), 2), B = subdivided(box({0, 0, 0}, {0.5, 0.5, 0.5}), 2);
  const Result cut = check_net_and_all(L, B, 0.1, Reference(L, B)).second;
  const Result whole = check(l_shape(), box({0, 0, 0}, {0.5, 0.5, 0.5}), 0.1);
  CHECK(cut.stats.candidates < 2 * whole.stats.candidates);
  const Result negated = check_net_and_all(L, B, 0.1, Reference(L, B, true), CGAL::parameters::negate_first_mesh(true)).second;
  // merge_flat_regions(false): the meshes are taken as they are.
  const Result as_is = run(L, B, 0.1, CGAL::parameters::merge_flat_regions(false));
  CHECK(as_is.stats.candidates > 4 * whole.stats.candidates);
  // Every record names a feature of the user's mesh whose vertices carry its nonzero weights
  // (a point of a region triangulated again: the mesh's own feature that holds it; the
  // weights rebuild the exact point: the exactness checks above), trim points too.
  const Mesh mL = to_mesh<Mesh>(L), mB = to_mesh<Mesh>(B); // the indices of the meshes run() made
  auto misnamed = [](const Mesh& m, const auto& f) {
    std::set<Mesh::Vertex_index> of_feature;
    if (f.dimension == 0) of_feature = {f.vertex};
    else if (f.dimension == 1) of_feature = {source(f.halfedge, m), target(f.halfedge, m)};
    else for (auto v : vertices_around_face(halfedge(f.face, m), m)) of_feature.insert(v);
    int nonzero = 0;
    bool ok = f.dimension != 1 || source(f.halfedge, m) == f.vertices[0];
    for (int i = 0; i < 3; ++i)
      if (f.rational_weights ? CGAL::sign((*f.rational_weights)[i]) != CGAL::ZERO : f.weights[i] != 0) {
        ++nonzero;
        ok = ok && of_feature.count(f.vertices[i]) == 1;
      }
    return !ok || nonzero != f.dimension + 1;
  };
  for (const Result* r : {&cut, &negated}) {
    std::size_t located = 0, bad = 0;
    for (const Record& x : r->records) {
      located += !x.on_trim_curve && (x.origin_p.rational_weights || x.origin_q.rational_weights);
      bad += misnamed(mL, x.origin_p) || misnamed(mB, x.origin_q);
    }
    INFO((r == &cut ? "P + Q: " : "-P + Q: ") << r->records.size() << " records, " << located << " located");
    CHECK(located > 0);
    CHECK(bad == 0);
  }
}

TEST_CASE("paper's blocks (non-manifold) + cube of the square's size", "[nonconvex][blocks][long]")
{
  // 3x3 checkerboard: the sum is the full box [0,4]x[0,4]x[0,1.5]. Where four block sums
  // meet along a vertical line, (-P + x) touches the cube on all four sides and the
  // unperturbed CD test would report a (false) boundary point: there must be none inside.
  const Soup B = blocks(3, 0.5), C = box({0, 0, 0}, {1, 1, 1});
  const Result r = check(B, C, 0.125);
  CHECK(count_in(r.points, {0.01, 0.01, 0.01}, {3.99, 3.99, 1.49}) == 0);
}

TEST_CASE("paper's blocks + 0.95 cube: the narrow columns appear", "[nonconvex][blocks][long]")
{
  const Soup B = blocks(3, 0.5), C = box({0, 0, 0}, {0.95, 0.95, 0.95});
  const Result r = check(B, C, 0.125);
  // Column between the sums of blocks (0,0), (1,1), (2,0) and (1,-1) at x in (1.95, 2),
  // y in (0.95, 1): a vertical tunnel of width 0.05 through the whole height.
  CHECK(count_in(r.points, {1.9, 0.9, 0.1}, {2.05, 1.05, 1.35}) > 0);
}

TEST_CASE("open cube + ellipsoid: a surface plus a solid (paper Fig. 7)", "[nonconvex][open][long]")
{
  const Soup S = open_box({0, 0, 0}, {1, 1, 1}), E = ellipsoid(0.2, 0.15, 0.1);
  const Result r = check(S, E, 0.05);
  // The walls thicken by the ellipsoid (0.2 in x, 0.15 in y, 0.1 in z) on both sides; the
  // inside stays hollow and the top stays open.
  CHECK(count_in(r.points, {0.21, 0.16, 0.11}, {0.79, 0.84, 1.2}) == 0);  // hollow inside
  CHECK(count_in(r.points, {0.19, 0.3, 0.3}, {0.21, 0.7, 0.7}) > 0);     // inner offset of x = 0
  CHECK(count_in(r.points, {-0.21, 0.3, 0.3}, {-0.19, 0.7, 0.7}) > 0);   // outer offset of x = 0
  CHECK(count_in(r.points, {0.3, 0.3, 0.09}, {0.7, 0.7, 0.11}) > 0);     // inner offset of the floor
}

TEST_CASE("the normal filter removes only pairs the CD filter would not need", "[filters]")
{
  const Soup P = l_shape(), Q = tetrahedron(0.6);
  const double d = 0.2;
  const Result on = run(P, Q, d, CGAL::parameters::use_covering_net(false));
  const Result off = run(P, Q, d, CGAL::parameters::use_normal_filter(false).use_covering_net(false));
  const Reference ref(P, Q);
  REQUIRE(off.stats.candidates > 3 * on.stats.candidates);
  CHECK(exactness_failures(off, ref) == 0);
  // Every point found with the filter is found without it ...
  CHECK(coverage_distance(on.points, off.points) == 0);
  // ... and what the unfiltered run adds does not reach boundary the filtered run missed.
  CHECK(coverage_distance(off.points, on.points) < d);
  const auto samples = ref.boundary_samples(d / 8);
  CHECK(coverage_distance(samples, on.points) < d);
}

TEST_CASE("without the CD filter the output is every candidate", "[filters]")
{
  const Soup P = l_shape(), Q = tetrahedron(0.6);
  const Result with_cd = run(P, Q, 0.2);
  const Result no_cd = run(P, Q, 0.2, CGAL::parameters::use_cd_filter(false));
  CHECK(no_cd.points.size() == with_cd.stats.candidates);
  CHECK(no_cd.stats.cd_queries == 0);
  CHECK(coverage_distance(lattice_points(with_cd.records), no_cd.points) == 0); // trim points are not candidates
  const Reference ref(P, Q);
  CHECK(exactness_failures(no_cd, ref) > 0); // inner points are there
}

TEST_CASE("contact space: -P + Q of an L and a box", "[nonconvex][negate]")
{
  // -L is the union of the negated boxes: check exactness through the generic pieces test.
  const Soup P = l_shape(), Q = box({0, 0, 0}, {0.5, 0.5, 0.5});
  const Result r = run(P, Q, 0.1, CGAL::parameters::negate_first_mesh(true));
  const Reference ref(P, Q, /*negate=*/true);
  REQUIRE(!r.points.empty());
  CHECK(exactness_failures(r, ref) == 0);
  CHECK(coverage_distance(ref.boundary_samples(0.1 / 8), r.points) < 0.1);
  for (const auto& rec : r.records) REQUIRE(rec.negated_p);
}

TEST_CASE("isolated vertices are ignored", "[nonconvex][robustness]")
{
  // A vertex on no face is not part of the solid: with or without the normal filter, no
  // point may come from it.
  Mesh P = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  P.add_vertex(IK::Point_3(10, 10, 10));
  const Mesh Q = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));
  for (bool normal_filter : {true, false}) {
    std::vector<IK::Point_3> pts;
    CGAL::point_minkowski_sum(P, Q, 0.5, std::back_inserter(pts), CGAL::parameters::use_normal_filter(normal_filter));
    REQUIRE(!pts.empty());
    for (const auto& p : pts) REQUIRE(p.x() <= 2);
  }
}

TEST_CASE("edges parallel to the containment ray", "[nonconvex][robustness]")
{
  // The point-in-solid test casts rays along a fixed direction; a solid with edges along it
  // must still be classified exactly (triangles parallel to the ray are skipped).
  const Point w = {1.0, 0.7548776662466927, 0.5698402909980532}; // the ray of cd_filter.h
  const Soup P = convex_hull({{0, 0, 0}, {8 * w[0], 8 * w[1], 8 * w[2]}, {0, 4, 0}, {0, 0, 4}, {4, 0, 0}});
  const Soup Q = box({-0.25, -0.25, -0.25}, {0.25, 0.25, 0.25});
  const Result r = run(P, Q, 0.2, CGAL::parameters::negate_first_mesh(true));
  const Reference ref(P, Q, true);
  REQUIRE(!r.points.empty());
  CHECK(exactness_failures(r, ref) == 0);
}

namespace {
/// The normal filter's kept pairs by brute force over all feature pairs (the oracle for the
/// direction grid, which must keep exactly the same pairs and directions).
std::set<std::tuple<int, unsigned, int, unsigned, int, int, unsigned, unsigned>>
brute_force_pairs(const CGAL::Pmsum::internal::Mesh_data& P, const CGAL::Pmsum::internal::Mesh_data& Q)
{
  using namespace CGAL::Pmsum::internal;
  std::set<std::tuple<int, unsigned, int, unsigned, int, int, unsigned, unsigned>> out;
  auto keep = [&](Feature fp, Feature fq, const Direction& d) {
    for (Feature a : closure(P, fp))
      for (Feature b : closure(Q, fq))
        out.insert({a.dimension, a.index, b.dimension, b.index, int(d.kind), int(d.sign), d.a, d.b});
  };
  std::vector<Direction> dirs;
  for (Index t = 0; t < P.number_of_triangles(); ++t) {
    dirs.clear();
    facet_directions(P, Direction::FACET_OF_P, t, dirs);
    for (Index v = 0; v < Q.number_of_vertices(); ++v)
      for (const Direction& d : dirs)
        if (!Q.vertex_is_isolated(v) && vertex_is_extreme(Q, v, d, P, Q)) keep({2, t}, {0, v}, d);
  }
  for (Index t = 0; t < Q.number_of_triangles(); ++t) {
    dirs.clear();
    facet_directions(Q, Direction::FACET_OF_Q, t, dirs);
    for (Index v = 0; v < P.number_of_vertices(); ++v)
      for (const Direction& d : dirs)
        if (!P.vertex_is_isolated(v) && vertex_is_extreme(P, v, d, P, Q)) keep({0, v}, {2, t}, d);
  }
  for (Index a = 0; a < P.number_of_edges(); ++a)
    for (Index b = 0; b < Q.number_of_edges(); ++b) {
      const Direction plus{Direction::EDGES, 1, a, b};
      bool parallel = true;
      for (int c = 0; c < 3 && parallel; ++c)
        parallel = filtered_sign([&](auto nt) { return plus.vector<decltype(nt)>(P, Q)[c]; }) == CGAL::ZERO;
      if (parallel) continue;
      for (std::int8_t s : {1, -1}) {
        const Direction d{Direction::EDGES, s, a, b};
        if (edge_is_extreme(P, a, d, P, Q) && edge_is_extreme(Q, b, d, P, Q)) keep({1, a}, {1, b}, d);
      }
    }
  return out;
}
} // namespace

TEST_CASE("the direction grid keeps exactly the brute-force pairs", "[filters][grid]")
{
  using namespace CGAL::Pmsum::internal;
  const std::vector<std::pair<Soup, Soup>> cases = {
    {l_shape(), tetrahedron(0.6)},
    {random_convex(30, 3), random_convex(25, 4)},
    {blocks(3, 0.5), box({0, 0, 0}, {1, 1, 1})},
    {open_box({0, 0, 0}, {1, 1, 1}), ellipsoid(0.2, 0.15, 0.1)},
    {ellipsoid(1, 0.7, 0.4, 24, 12), transformed(random_convex(40, 9), 0.3)},
  };
  for (bool negate : {false, true})
    for (const auto& [ps, qs] : cases) {
      const Mesh pm = to_mesh<Mesh>(ps), qm = to_mesh<Mesh>(qs);
      Mesh_descriptors<Mesh> dp, dq;
      const Mesh_data P = make_mesh_data(pm, get(CGAL::vertex_point, pm), negate, false, "P", dp);
      const Mesh_data Q = make_mesh_data(qm, get(CGAL::vertex_point, qm), false, false, "Q", dq);
      const Candidate_pairs grid = candidate_feature_pairs(P, Q, true);
      std::set<std::tuple<int, unsigned, int, unsigned, int, int, unsigned, unsigned>> got;
      for (const Feature_pair& fp : grid.pairs)
        for (std::uint32_t k = 0; k < fp.number_of_directions; ++k) {
          const Direction& d = grid.directions[fp.first_direction + k];
          got.insert({fp.p.dimension, fp.p.index, fp.q.dimension, fp.q.index, int(d.kind), int(d.sign), d.a, d.b});
        }
      const auto expected = brute_force_pairs(P, Q);
      REQUIRE(expected.size() > 10);
      CHECK(got == expected);
    }
}

#include <CGAL_pmsum/point_minkowski_sum_coarse_to_fine.h>

TEST_CASE("coarse to fine: every level exact and covering, coarser points reused", "[nonconvex][coarse-to-fine]")
{
  const Soup P = l_shape(), Q = tetrahedron(0.6);
  const Mesh mp = to_mesh<Mesh>(P), mq = to_mesh<Mesh>(Q);
  const Reference ref(P, Q);
  const std::vector<double> ds = {0.4, 0.2, 0.1};
  for (bool net : {true, false}) {
    INFO((net ? "net" : "all candidates"));
    std::vector<std::vector<Record>> levels;
    std::vector<CGAL::Pmsum::Statistics> stats;
    CGAL::point_minkowski_sum_coarse_to_fine(
      mp, mq, ds,
      [&](std::size_t k, const CGAL::Pmsum::Statistics& s, std::vector<Record>&& records) {
        CHECK(k == levels.size());
        levels.push_back(std::move(records));
        stats.push_back(s);
      },
      CGAL::parameters::use_covering_net(net));
    REQUIRE(levels.size() == ds.size());
    std::set<std::tuple<double, double, double>> previous;
    for (std::size_t k = 0; k < ds.size(); ++k) {
      INFO("level " << k << ": " << levels[k].size() << " points, " << stats[k].candidates_reused << " reused");
      Result r;
      for (const Record& rec : levels[k]) {
        r.points.push_back(rec.point);
        r.exact.push_back(CGAL::Pmsum::exact_point<EK>(rec, get(CGAL::vertex_point, mp), get(CGAL::vertex_point, mq)));
      }
      CHECK(exactness_failures(r, ref) == 0);
      CHECK(coverage_distance(ref.boundary_samples(ds[k] / 8), r.points) < ds[k]);
      CHECK(stats[k].output_points == levels[k].size());
      if (net) CHECK(spacing_of_unfacing(levels[k], ds[k]) >= ds[k] / 2 * (1 - 1e-9));
      std::set<std::tuple<double, double, double>> here;
      for (const auto& p : lattice_points(levels[k])) here.insert({p.x(), p.y(), p.z()});
      // Every coarser lattice point is a point of the finer level again (trim points are
      // searched again on the finer lattice).
      for (const auto& p : previous) CHECK(here.count(p) == 1);
      // The coarser decisions are reused: without the net, every coarser candidate's but
      // those certified interior (they are certified again).
      if (k > 0) {
        CHECK(stats[k].candidates_reused > 0);
        if (!net) CHECK(stats[k].candidates_reused + stats[k - 1].candidates_certified >= stats[k - 1].candidates);
      }
      previous = here;
    }
  }
  // The covering distances must decrease.
  CHECK_THROWS_AS(CGAL::point_minkowski_sum_coarse_to_fine(mp, mq, std::vector<double>{0.1, 0.2},
                                                            [](std::size_t, const CGAL::Pmsum::Statistics&, std::vector<Record>&&) {}),
                  CGAL::Pmsum::Invalid_input);
}

#include <CGAL_pmsum/internal/octree_filter.h>

#include <CGAL/Random.h>

namespace {
// Convex pairs for the octree filter's tests: the sum is one exact convex piece, and a box is
// inside it iff its corners are.
const std::pair<Soup, Soup> certificate_pairs[] = {{box({0, 0, 0}, {1, 0.5, 0.25}), tetrahedron(0.6)},
                                                   {octahedron(0.8), ellipsoid(0.3, 0.2, 0.5)}};

/// P and Q of a pair as the filters see them.
struct Pair_data
{
  Mesh mp, mq;
  CGAL::Pmsum::internal::Mesh_descriptors<Mesh> dp, dq;
  CGAL::Pmsum::internal::Mesh_data a, b;
  Pair_data(const Soup& P, const Soup& Q)
    : mp(to_mesh<Mesh>(P)), mq(to_mesh<Mesh>(Q)),
      a(CGAL::Pmsum::internal::make_mesh_data(mp, get(CGAL::vertex_point, mp), false, false, "P", dp)),
      b(CGAL::Pmsum::internal::make_mesh_data(mq, get(CGAL::vertex_point, mq), false, false, "Q", dq))
  {}
};
} // namespace

TEST_CASE("interior certificate: every certified box lies inside the exact sum", "[octree]")
{
  namespace in = CGAL::Pmsum::internal;
  for (const auto& [P, Q] : certificate_pairs) {
    const Pair_data data(P, Q);
    const in::Mesh_data &a = data.a, &b = data.b;
    const in::Interior_certificate certificate(a, b, 24, 1e-9 * 4, false, nullptr);
    const Reference ref(P, Q);
    REQUIRE(ref.pieces.size() == 1);
    const auto box_p = in::mesh_box(a), box_q = in::mesh_box(b);
    CGAL::Random rng(11);
    std::size_t certified = 0, inside = 0;
    for (int i = 0; i < 20000; ++i) {
      in::Point3 c;
      for (int k = 0; k < 3; ++k)
        c[k] = rng.get_double(box_p.first[k] + box_q.first[k], box_p.second[k] + box_q.second[k]);
      const double rho = rng.get_double(0, 0.2);
      const double h = rho / std::sqrt(3.0); // half side of the cube of half-diagonal rho
      bool corners_inside = true;
      for (int corner = 0; corner < 8; ++corner) {
        const EK::Point_3 x(EK::FT(c[0]) + ((corner & 1) ? h : -h), EK::FT(c[1]) + ((corner & 2) ? h : -h),
                            EK::FT(c[2]) + ((corner & 4) ? h : -h));
        corners_inside = corners_inside && ref.pieces[0].locate(x) < 0;
      }
      inside += corners_inside;
      if (!certificate.certifies(c, rho)) continue;
      ++certified;
      REQUIRE(corners_inside); // sound: never a box that reaches the boundary
    }
    INFO(certified << " of " << inside << " inner boxes certified");
    CHECK(certified > inside / 4); // and useful
  }
}

TEST_CASE("octree filter: every point of a certified leaf lies inside the exact sum", "[octree]")
{
  // The leaves are certified top-down, by the nodes of every level that hold them: a wrong
  // node of a leaf (its key, its parent's) would certify leaves outside the node's ball.
  namespace in = CGAL::Pmsum::internal;
  for (const auto& [P, Q] : certificate_pairs) {
    const Pair_data data(P, Q);
    const in::Mesh_data &a = data.a, &b = data.b;
    const in::Octree_settings settings(a, b, 0.01);
    const in::Interior_certificate certificate(a, b, 24, settings.tolerance, false, nullptr);
    const double h = certificate.largest_ball() / 16; // leaves well below the largest node
    in::Octree_filter octree(certificate, settings.lo, settings.hi, h, settings.tolerance);
    REQUIRE(octree.enabled());
    CGAL::Random rng(5);
    auto random_point = [&] {
      in::Point3 x;
      for (int k = 0; k < 3; ++k) x[k] = rng.get_double(settings.lo[k], settings.hi[k]);
      return x;
    };
    std::vector<in::Point3> points;
    std::vector<in::Octree_filter::Key> leaves;
    for (int i = 0; i < 20000; ++i) {
      points.push_back(random_point());
      if (auto k = octree.leaf(points.back())) leaves.push_back(*k);
    }
    std::sort(leaves.begin(), leaves.end());
    leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
    octree.certify(leaves, true, nullptr);
    const Reference ref(P, Q);
    std::size_t certified = 0, inside = 0;
    for (const in::Point3& x : points) {
      const bool in_sum = ref.pieces[0].locate(EK::Point_3(x[0], x[1], x[2])) < 0;
      inside += in_sum;
      if (!octree.certified(x)) continue;
      ++certified;
      REQUIRE(in_sum);
    }
    INFO(certified << " of " << inside << " inner points in certified leaves; " << octree.number_of_certified_leaves()
                   << " of " << octree.number_of_leaves() << " leaves certified");
    CHECK(certified > inside / 2);
  }
}

TEST_CASE("crossing ranges agree with the exact pair tests along segments", "[filters][trim]")
{
  // Cd_filter::crossing_range() tells from intervals where along a segment of translations
  // a pair of triangles certainly crosses and where it certainly does not; the segment
  // search trusts it instead of testing. Check it against the exact (perturbed) test.
  using namespace CGAL::Pmsum::internal;
  const std::vector<std::pair<Soup, Soup>> cases = {
    {random_convex(30, 3), random_convex(25, 4)},
    {l_shape(), transformed(tetrahedron(0.6), 0.7)},
    {tunnel_block(), turned_cube(0.5, 0.8, 0.6)},
  };
  CGAL::Random rng(11);
  std::size_t in = 0, out = 0, tested = 0;
  for (const auto& [ps, qs] : cases) {
    Cd_case cd(ps, qs);
    Cd_filter& filter = cd.filter;
    for (int k = 0; k < 40; ++k) {
      std::array<Exact_point, 2> ends;
      for (auto& e : ends) {
        e.W = Exact_nt(1);
        for (int c = 0; c < 3; ++c) e.X[c] = Exact_nt(cd.coordinate(rng, c));
      }
      if (k % 2) { // along an edge of a static triangle: parallel to its plane
        const Tree_mesh& st = cd.geometry.static_mesh;
        const auto& tri = st.mesh->triangles[rng.get_int(0, int(st.mesh->number_of_triangles()))];
        for (int c = 0; c < 3; ++c) ends[1].X[c] = ends[0].X[c] + Exact_nt(st.base[tri[1]][c]) - Exact_nt(st.base[tri[0]][c]);
      }
      const Translation_segment s(ends[0], ends[1]);
      const Vec3<Interval> a = enclosure(s.a), b = enclosure(s.b);
      std::vector<std::pair<Index, Index>> pairs;
      filter.for_each_overlapping_pair(hull(a, b), [&](Index u, Index v) { pairs.emplace_back(u, v); return false; });
      for (const auto& [u, v] : pairs) {
        const Crossing_range r = filter.crossing_range(u, v, a, b);
        CHECK(!(r.misses_segment() && r.in_from < r.in_to)); // a miss claims no crossing
        for (int i = 0; i <= 16; ++i) {
          const double l = i / 16.0;
          const bool certainly_in = r.in_from < l && l < r.in_to, certainly_out = l < r.low || l > r.high;
          if (!certainly_in && !certainly_out) continue;
          filter.set_point(s.at(Segment_parameter{Exact_nt(i), Exact_nt(16)}), nullptr, 0);
          const bool crosses = filter.pair_crosses_here(u, v);
          ++tested;
          INFO("pair " << u << ", " << v << " at l = " << l);
          CHECK(crosses == certainly_in);
          (certainly_in ? in : out) += 1;
        }
      }
    }
  }
  INFO(in << " certainly crossing, " << out << " certainly not");
  CHECK(in > 100);   // the ranges decide both ways, often
  CHECK(out > 1000);
}

TEST_CASE("convex planar patches: a box's faces are one patch each, and their crossing sets are collisions", "[filters][islands]")
{
  // The island search drops a piece of a cell when one pair of convex planar patches
  // (convex_patches.h) certainly crosses on all of it, the trim search a whole cell. Check the patches of boxes, and that
  // the small triangles of translations that a patch pair's slabs put inside its crossing
  // set are collisions (exact tests at 15 points of each), including those that no pair of
  // their triangles' slabs holds whole (across the diagonals).
  using namespace CGAL::Pmsum::internal;
  const std::vector<std::pair<Soup, Soup>> cases = {
    {box({0, 0, 0}, {1, 0.5, 0.25}), box({0, 0, 0}, {0.3, 0.7, 0.4})},
    {tunnel_block(), turned_cube(0.5, 0.8, 0.6)},
    {random_convex(30, 3), box({0, 0, 0}, {0.5, 0.5, 0.5})},
  };
  for (const auto& [ps, qs] : cases) {
    const Cd_case cd(ps, qs);
    for (const Convex_patches* patches : {&cd.geometry.static_patches, &cd.geometry.moving_patches}) {
      std::size_t triangles = 0;
      for (const Convex_patches::Patch& patch : patches->patches) {
        CHECK(patch.corners.size() <= Convex_patches::max_corners);
        CHECK(patch.edges.size() <= patch.corners.size());
        triangles += patch.corners.size() - 2; // convex, no corner inside: a fan
      }
      CHECK(triangles == patches->of.size());
    }
  }
  { // boxes: one patch per face, a rectangle (two edge directions)
    const Cd_case cd(cases[0].first, cases[0].second);
    for (const Convex_patches* patches : {&cd.geometry.static_patches, &cd.geometry.moving_patches}) {
      REQUIRE(patches->patches.size() == 6);
      for (const Convex_patches::Patch& patch : patches->patches) {
        CHECK(patch.corners.size() == 4);
        CHECK(patch.edges.size() == 2);
      }
    }
  }
  CGAL::Random rng(5);
  std::size_t inside = 0, by_patches_only = 0, by_witness = 0;
  for (const auto& [ps, qs] : cases) {
    Cd_case cd(ps, qs);
    Cd_filter& filter = cd.filter;
    Segment_search search(filter);
    for (int k = 0; k < 400; ++k) {
      // a small triangle T of translations, corners t_i
      std::array<std::array<double, 3>, 3> t;
      for (int c = 0; c < 3; ++c) t[0][c] = cd.coordinate(rng, c);
      const double r = rng.get_double(0.01, 0.3);
      for (int i = 1; i < 3; ++i)
        for (int c = 0; c < 3; ++c) t[i][c] = t[0][c] + rng.get_double(-r, r);
      std::array<Vec3<Interval>, 3> T;
      for (int i = 0; i < 3; ++i) T[i] = {Interval(t[i][0]), Interval(t[i][1]), Interval(t[i][2])};
      const Vec3<Interval> e = hull(hull(T[0], T[1]), T[2]);
      std::map<std::pair<Index, Index>, bool> patch_pairs; // does a pair of their triangles hold T?
      filter.for_each_overlapping_pair(e, [&](Index u, Index v) {
        CGAL::Protect_FPU_rounding<true> guard;
        Crossing_slabs slabs;
        slabs.known = true;
        for (const Crossing_slabs::Slab& slab : filter.slabs(u, v)) slabs.slabs.push_back(slab);
        patch_pairs[{filter.moving_patch(u), filter.static_patch(v)}] |= slabs.where(T) == Crossing_slabs::Where::inside;
        return false;
      });
      bool patches_inside = false, only_patches = false;
      for (const auto& [patches, triangles] : patch_pairs) {
        CGAL::Protect_FPU_rounding<true> guard;
        const bool holds = filter.patch_crossing_slabs(patches.first, patches.second, T).second == Crossing_slabs::Where::inside;
        CHECK((!triangles || holds)); // a patch pair holds its triangles' crossing sets
        patches_inside = patches_inside || holds;
        only_patches = only_patches || (holds && !triangles);
      }
      // The trim search's skip (Segment_search::patch_pair_covers()): with the scan, exactly
      // when a patch pair holds T; with a corner's witness alone, only then.
      CHECK(search.patch_pair_covers(T, {}, true) == patches_inside);
      const bool corner_free = filter.is_free_at(t[0]);
      const auto witness = corner_free ? std::nullopt : filter.last_crossing();
      Segment_search fresh(filter); // (no recent pairs: the witness alone)
      if (fresh.patch_pair_covers(T, {witness, std::nullopt, std::nullopt}, false)) {
        CHECK(patches_inside);
        ++by_witness;
      }
      if (!patches_inside) continue;
      for (double a = 0; a <= 1; a += 0.25)
        for (double b = 0; a + b <= 1; b += 0.25) {
          std::array<double, 3> x;
          for (int c = 0; c < 3; ++c) x[c] = (1 - a - b) * t[0][c] + a * t[1][c] + b * t[2][c];
          INFO("translation " << x[0] << " " << x[1] << " " << x[2]);
          CHECK(!filter.is_free_at(x));
        }
      ++inside;
      by_patches_only += only_patches;
    }
  }
  INFO(inside << " triangles of translations inside a patch pair's crossing set, " << by_patches_only
              << " in no pair of their triangles', " << by_witness << " found by a corner's witness alone");
  CHECK(inside > 100);
  CHECK(by_patches_only > 10);
  CHECK(by_witness > 10);
}

namespace {

/// -P (the filter's translations are -P + Q): two unit boxes 0.5 apart along x; Q: a box 0.5
/// wide. Their sums with Q, [0, 1.5] and [1.5, 3] along x, touch on the plane x = 1.5.
struct Wall_case
{
  static Soup minus_p()
  {
    Soup ps = box({-1, -1, -1}, {0, 0, 0});
    ps.append(box({-2.5, -1, -1}, {-1.5, 0, 0}));
    return ps;
  }
  Wall_case() : cd(minus_p(), box({0, 0, 0}, {0.5, 0.5, 0.5})) {}

  /// Is translation x free, perturbed along the axes?
  bool free_at(const CGAL::Pmsum::internal::Exact_point& x)
  {
    cd.filter.set_point(x, nullptr, 0);
    return cd.filter.is_free_here();
  }

  /// A small random triangle of translations on the plane x = wall, within y, z in (0, 1.5):
  /// its exact corners and boxes holding them.
  struct Cell
  {
    std::array<CGAL::Pmsum::internal::Exact_point, 3> x;
    std::array<CGAL::Pmsum::internal::Vec3<CGAL::Pmsum::internal::Interval>, 3> T;
    double y, z; // near which
  };
  static Cell cell(CGAL::Random& rng, double wall)
  {
    using namespace CGAL::Pmsum::internal;
    Cell r;
    r.y = rng.get_double(0.05, 1.45);
    r.z = rng.get_double(0.05, 1.45);
    for (int i = 0; i < 3; ++i) {
      const std::array<double, 3> t = {wall, r.y + rng.get_double(-0.04, 0.04), r.z + rng.get_double(-0.04, 0.04)};
      r.x[i] = {{Exact_nt(t[0]), Exact_nt(t[1]), Exact_nt(t[2])}, Exact_nt(1)};
      r.T[i] = {Interval(t[0]), Interval(t[1]), Interval(t[2])};
    }
    return r;
  }

  /// Free points among 15 of the triangle (exact tests).
  std::size_t free_points(const Cell& cell)
  {
    std::size_t n = 0;
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) {
        CGAL::Pmsum::internal::Exact_point m;
        for (int c = 0; c < 3; ++c) m.X[c] = (4 - a - b) * cell.x[0].X[c] + a * cell.x[1].X[c] + b * cell.x[2].X[c];
        m.W = CGAL::Pmsum::internal::Exact_nt(4);
        n += free_at(m);
      }
    return n;
  }

  Cd_case cd;
};

} // namespace

TEST_CASE("cells on a wall where two parts of the sum touch face to face: in one patch pair's crossing set once perturbed", "[filters][islands]")
{
  // Wall_case: the plane x = 1.5 of translations, where the two boxes' sums touch, is inside
  // the sum, but on the border of every patch pair's crossing set, so intervals never hold a
  // cell there. Perturbed (here along the axes), the wall's points lie in one box's sum: of
  // the pairs on whose border the cell lies (no corner certainly outside: Crossing_slabs::
  // leaves()), one crosses at each exact corner (Cd_filter::patch_pair_crosses_at(), the
  // island search's test), and then no point of the cell may be free. On the sum's faces
  // x = 0 and x = 3, perturbed outward on one of them, a pair holds exactly where the corners
  // are not free.
  using namespace CGAL::Pmsum::internal;
  Wall_case wc;
  Cd_filter& filter = wc.cd.filter;
  CGAL::Random rng(7);
  std::size_t covered_on_wall = 0, covered_outside = 0, free_outside = 0;
  for (const double wall : {0., 1.5, 3.}) {
    for (int k = 0; k < 60; ++k) {
      const Wall_case::Cell cell = Wall_case::cell(rng, wall);
      const auto& [x, T, y, z] = cell;
      INFO("plane x = " << wall << ", cell near y = " << y << ", z = " << z);
      // the patch pairs met (as Island_search::island_point()'s traversal): none holds T by
      // intervals; those that T may lie on the border of, is one in it once perturbed?
      std::set<std::pair<Index, Index>> met;
      filter.for_each_overlapping_pair(hull(hull(T[0], T[1]), T[2]), [&](Index u, Index v) {
        met.insert({filter.moving_patch(u), filter.static_patch(v)});
        return false;
      });
      bool covered = false;
      for (const auto& [a, b] : met) {
        bool touching = false;
        {
          CGAL::Protect_FPU_rounding<true> guard;
          const auto [slabs, where] = filter.patch_crossing_slabs(a, b, T);
          CHECK(where != Crossing_slabs::Where::inside);
          touching = where == Crossing_slabs::Where::border && slabs.known && !slabs.leaves(T);
        }
        covered = covered || (touching && filter.patch_pair_crosses_at(a, b, {{&x[0], {}}, {&x[1], {}}, {&x[2], {}}}, nullptr, 0));
      }
      if (wall == 1.5) {
        CHECK(covered);
        covered_on_wall += covered;
      } else {
        const bool corner_free = wc.free_at(x[0]);
        CHECK(covered == !corner_free);
        covered_outside += covered;
        free_outside += corner_free;
      }
      if (covered) CHECK(wc.free_points(cell) == 0);
    }
  }
  CHECK(covered_on_wall == 60);
  CHECK(covered_outside == 60); // one outer face is perturbed inward, the other outward
  CHECK(free_outside == 60);
}

TEST_CASE("the trim search's skip on a facet's plane: cells on a wall where two parts touch face to face", "[filters][trim]")
{
  // The case above, seen by the trim search: a facet on the plane x = wall of translations,
  // its points perturbed along the axes (x first). Segment_search::patch_pair_covers() with
  // the plane started (start_plane()) also uses what the plane tells of each patch pair (the
  // slab normal to it holds the whole plane once perturbed, or none of it): on the wall
  // x = 1.5 and on the face x = 0 (perturbed into the sum) it holds small cells whole, where
  // intervals alone hold none; on the face x = 3 (perturbed out of the sum) none, and no
  // corner there is inside. Every cell it holds has no free point (exact tests, perturbed
  // as the plane's points are).
  using namespace CGAL::Pmsum::internal;
  Wall_case wc;
  Cd_filter& filter = wc.cd.filter;
  const Mesh_data &P = wc.cd.operands.first, &Q = wc.cd.operands.second; // P: -P's vertices
  auto vertex_sample = [](const Mesh_data& M, const std::array<double, 3>& x) {
    for (Index v = 0; v < M.points.size(); ++v)
      if (M.points[v] == x) return Sample{Feature{0, v}, {v, v, v}, {1, 0, 0}, 1};
    FAIL("no vertex at " << x[0] << " " << x[1] << " " << x[2]);
    return Sample{};
  };
  CGAL::Random rng(11);
  for (const double wall : {0., 1.5, 3.}) {
    // a facet on x = wall: a face of -P's box there (x = 0: of the first, 1.5: of the second,
    // 3 = 2.5 + 0.5: of the second) plus a vertex of Q
    const double px = wall == 0 ? 0. : 1.5, qx = wall == 3 ? 0.5 : 0.;
    const Sample q = vertex_sample(Q, {qx, 0, 0});
    const double x0 = wall == 3 ? 2.5 : px;
    const std::array<std::pair<Sample, Sample>, 3> corners = {{{vertex_sample(P, {x0, 0, 0}), q},
                                                                {vertex_sample(P, {x0, 1, 0}), q},
                                                                {vertex_sample(P, {x0, 0, 1}), q}}};
    std::size_t on_plane = 0, by_intervals = 0;
    for (int k = 0; k < 60; ++k) {
      const Wall_case::Cell cell = Wall_case::cell(rng, wall);
      const auto& [x, T, y, z] = cell;
      INFO("plane x = " << wall << ", cell near y = " << y << ", z = " << z);
      Segment_search plain(filter);
      by_intervals += plain.patch_pair_covers(T, {}, true);
      Segment_search search(filter);
      search.start_plane(corners, nullptr, 0);
      const bool covered = search.patch_pair_covers(T, {}, true);
      on_plane += covered;
      if (wall == 3) CHECK(wc.free_at(x[0]));
      if (covered) CHECK(wc.free_points(cell) == 0);
    }
    INFO("plane x = " << wall << ": " << on_plane << " of 60 cells held on the plane, " << by_intervals << " by intervals");
    CHECK(by_intervals == 0);
    CHECK(on_plane == (wall == 3 ? 0 : 60));
  }
}

TEST_CASE("on a small grid, double arithmetic decides the predicates as exact arithmetic does", "[filters][exact]")
{
  // Where all coordinates are on a small power-of-two grid (Cd_geometry::exact_doubles), the
  // CD filter evaluates D(0) and g of its predicates in double arithmetic and their sign at x
  // as S D(0) + g.X. Same answers as the exact determinant, at contacts (translations that
  // are sums of vertices: every predicate of a touching pair is zero there) and along
  // segments between them (the segment search's roots).
  using namespace CGAL::Pmsum::internal;
  using Points = std::vector<std::array<double, 3>>;
  const Points quarters = {{0, 0.25, 3.5}, {-2, 0.75, 1}}, tenth = {{0.1, 0, 0}};
  const Points wide = {{1, 0, 0}, {0x1p-20, 0, 0}}, widest_small = {{32767, 0, 0}, {1, 0, 0}},
               too_wide = {{32768, 0, 0}, {1, 0, 0}}, huge = {{0x1p400, 0, 0}};
  CHECK(on_small_grid({&quarters}));
  CHECK(on_small_grid({&widest_small}));
  CHECK(!on_small_grid({&quarters, &widest_small})); // 32767 is 2^17 quarters
  CHECK(!on_small_grid({&quarters, &tenth}));
  CHECK(!on_small_grid({&wide}));
  CHECK(!on_small_grid({&too_wide}));
  CHECK(!on_small_grid({&huge}));

  const auto [hook_a, hook_b] = pmsum_shapes::hooks_pair();
  const std::vector<std::pair<Soup, Soup>> cases = {
    {l_shape(), tetrahedron(0.75)}, {hook_a, hook_b}, {tunnel_block(), box({0, 0, 0}, {1, 1, 1})},
    {box({0, 0, 0}, {3, 2, 2}), box({0, 0, 0}, {0.25, 0.125, 0.25})}};
  CGAL::Random rng(5);
  std::size_t free_contacts = 0, inside = 0, segments = 0, ends_found = 0, contained_starts = 0;
  for (const auto& [ps, qs] : cases) {
    const auto operands = cd_operands(ps, qs);
    const Mesh_data &P = operands.first, &Q = operands.second;
    const Cd_geometry doubles(P, Q);
    Cd_geometry exact(P, Q);
    REQUIRE(doubles.exact_doubles);
    exact.exact_doubles = false;
    Cd_filter fd(&doubles), fe(&exact);
    auto contact = [&] { // a sum of vertices (P is negated: a difference of the input's)
      const auto& a = P.points[std::size_t(rng.get_int(0, int(P.points.size())))];
      const auto& b = Q.points[std::size_t(rng.get_int(0, int(Q.points.size())))];
      return std::array<double, 3>{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    };
    for (int k = 0; k < 300; ++k) {
      const auto t = contact();
      const bool is_free = fd.is_free_at(t);
      CHECK(is_free == fe.is_free_at(t));
      (is_free ? free_contacts : inside) += 1;
    }
    Segment_search sd(fd), se(fe);
    // A translation in the box of the sum (on a grid of 1/64): often inside by containment,
    // where no pair crosses (the segment search then knows its first element without a test).
    std::array<double, 3> lo = {0, 0, 0}, hi = {0, 0, 0}; // the sum of P's and Q's boxes (their components')
    for (const Mesh_data* M : {&P, &Q})
      for (int c = 0; c < 3; ++c) {
        double l = M->components.front().min[c], h = M->components.front().max[c];
        for (const auto& component : M->components) l = std::min(l, component.min[c]), h = std::max(h, component.max[c]);
        lo[c] += l;
        hi[c] += h;
      }
    auto anywhere = [&] {
      std::array<double, 3> t;
      for (int c = 0; c < 3; ++c) t[c] = std::round(rng.get_double(lo[c], hi[c]) * 64) / 64;
      return t;
    };
    for (int k = 0; k < 90; ++k) {
      const auto a = k % 3 ? anywhere() : contact(), b = contact();
      if (a == b) continue;
      if (!fd.is_free_at(a) && !(fd.last_crossing() && fd.pair_crosses_here(fd.last_crossing()->first, fd.last_crossing()->second)))
        ++contained_starts;
      const Translation_segment s({to_nt<Exact_nt>(a), Exact_nt(1)}, {to_nt<Exact_nt>(b), Exact_nt(1)});
      std::vector<Segment_parameter> ed, ee, en;
      sd.free_ends(s, nullptr, 0, ed);
      se.free_ends(s, nullptr, 0, ee);
      REQUIRE(ed.size() == ee.size());
      for (std::size_t i = 0; i < ed.size(); ++i) CHECK(compare(ed[i], ee[i]) == CGAL::ZERO);
      // Without the quick exits (as where an end is known free): the same ends.
      sd.free_ends(s, nullptr, 0, en, Known_ends{{}, true});
      REQUIRE(en.size() == ed.size());
      for (std::size_t i = 0; i < ed.size(); ++i) CHECK(compare(ed[i], en[i]) == CGAL::ZERO);
      ++segments;
      ends_found += ed.size();
    }
  }
  INFO(free_contacts << " free contacts, " << inside << " inside, " << segments << " segments, " << ends_found << " ends, "
                     << contained_starts << " segments from a point inside by containment");
  CHECK(free_contacts > 100);
  CHECK(contained_starts > 20);
  CHECK(inside > 100);
  CHECK(ends_found > 50);
}

TEST_CASE("orientations zero by construction: the CD filter answers as if told nothing", "[filters][exact]")
{
  // Where a query's translation x is p + q with p and q in the affine hulls of known vertices
  // of P and Q (a candidate, a lattice point of a convolution facet), or a predicate's root
  // on a segment, the CD filter takes the orientations that this makes zero for zero without
  // evaluating them (Cd_filter::zero_by_construction()). Check that each is zero, exactly,
  // and every answer against a filter told nothing, at the contacts of vertex-triangle and
  // edge-edge pairs, at roots, and along segments of a convolution facet's plane.
  using namespace CGAL::Pmsum::internal;
  const std::vector<std::pair<Soup, Soup>> cases = {
    {random_convex(30, 3), random_convex(25, 4)},        // arbitrary doubles: Mpzf evaluations
    {l_shape(), transformed(tetrahedron(0.6), 0.7)},     // and a small grid: double evaluations
    {tunnel_block(), turned_cube(0.5, 0.8, 0.6)}};
  CGAL::Random rng(17);
  std::size_t contacts = 0, zeros_told = 0, perturbed = 0, roots = 0, segments = 0, ends_found = 0;
  std::size_t untold_zeros = 0, nonzero_told = 0, different = 0; // must stay 0
  for (const auto& [ps, qs] : cases) {
    const auto operands = cd_operands(ps, qs);
    const Mesh_data &P = operands.first, &Q = operands.second;
    const Cd_geometry geometry(P, Q);
    Cd_filter told(&geometry), untold(&geometry);
    auto vertex = [&](const Mesh_data& M) {
      const Index v = Index(rng.get_int(0, int(M.points.size())));
      return Sample{{0, v}, {v, v, v}, {1, 0, 0}, 1};
    };
    auto on_edge = [&](const Mesh_data& M) {
      const Index e = Index(rng.get_int(0, int(M.edges.size())));
      const std::int32_t a = rng.get_int(1, 5);
      return Sample{{1, e}, {M.edges[e].v[0], M.edges[e].v[1], M.edges[e].v[1]}, {a, 5 - a, 0}, 5};
    };
    auto in_triangle = [&](const Mesh_data& M, Index t) {
      const std::int32_t a = rng.get_int(1, 5), b = rng.get_int(1, 7 - a);
      return Sample{{2, t}, M.triangles[t], {a, b, 7 - a - b}, 7};
    };
    auto triangle = [&](const Mesh_data& M) { return Index(rng.get_int(0, int(M.number_of_triangles()))); };
    // Every overlapping pair at x, told `zeros` or nothing: the same answers. (Without
    // directions to perturb along, some roots on these segments meet a predicate that is
    // zero for every translation, parallel edges: both filters must then refuse alike.)
    auto answer = [](const auto& test) {
      try {
        return int(test());
      } catch (const std::logic_error&) {
        return -1; // "a perturbed predicate is identically zero"
      }
    };
    auto same_answers = [&](const Exact_point& x, const Known_zeros& zeros) {
      std::vector<std::pair<Index, Index>> pairs;
      untold.for_each_overlapping_pair(enclosure(x), [&](Index u, Index v) { pairs.emplace_back(u, v); return false; });
      told.set_point(x, nullptr, 0, {}, zeros);
      untold.set_point(x, nullptr, 0);
      for (const auto& uv : pairs) {
        const Index u = uv.first, v = uv.second; // (lambdas below capture them: no structured binding)
        untold.for_each_predicate(u, v, [&](const Moving_point& a, const Moving_point& b, const Moving_point& c,
                                            const Moving_point& d) {
          untold_zeros += untold.zero_by_construction({&a, &b, &c, &d});
          if (!told.zero_by_construction({&a, &b, &c, &d})) return;
          const Affine_predicate f = untold.affine_form(a, b, c, d);
          nonzero_told += !CGAL::is_zero(x.W * f.d0 + dot(f.g, x.X));
          ++zeros_told;
        });
        const int crosses = answer([&] { return told.pair_crosses_here(u, v); });
        perturbed += crosses >= 0 && told.here_perturbed();
        different += crosses != answer([&] { return untold.pair_crosses_here(u, v); });
      }
      different += answer([&] { return told.is_free_here(); }) != answer([&] { return untold.is_free_here(); });
    };
    for (int k = 0; k < 60; ++k) {
      // A contact: a vertex of one and a point of a triangle of the other, or two edges.
      std::pair<Sample, Sample> pq;
      if (k % 3 == 0) pq = {in_triangle(P, triangle(P)), vertex(Q)};
      else if (k % 3 == 1) pq = {vertex(P), in_triangle(Q, triangle(Q))};
      else pq = {on_edge(P), on_edge(Q)};
      const Exact_point x = exact_sum(P, pq.first, Q, pq.second);
      same_answers(x, {{&pq}});
      ++contacts;
      // The roots of the predicates of the pairs along a segment from x to another contact.
      const std::pair<Sample, Sample> other = {vertex(P), vertex(Q)};
      const Translation_segment s(x, exact_sum(P, other.first, Q, other.second));
      std::vector<std::pair<Index, Index>> pairs;
      untold.for_each_overlapping_pair(hull(enclosure(s.a), enclosure(s.b)), [&](Index u, Index v) {
        pairs.emplace_back(u, v);
        return false;
      });
      for (std::size_t i = 0; i < pairs.size() && i < 8; ++i)
        untold.for_each_predicate(pairs[i].first, pairs[i].second, [&](const Moving_point& a, const Moving_point& b,
                                                                        const Moving_point& c, const Moving_point& d) {
          const Affine_predicate f = untold.affine_form(a, b, c, d);
          const Exact_nt da = s.a.W * f.d0 + dot(f.g, s.a.X), db = s.b.W * f.d0 + dot(f.g, s.b.X);
          if (CGAL::sign(da) == CGAL::sign(db) || CGAL::is_zero(da) || CGAL::is_zero(db)) return;
          const Predicate_points zero = {a, b, c, d};
          same_answers(s.at(Segment_parameter{da, da - db}), {{}, &zero});
          ++roots;
        });
    }
    // Segments between lattice points of a vertex-triangle pair's facet, on its plane (told
    // the plane and the ends' samples) and off it (told nothing): the same free parts.
    for (int k = 0; k < 30; ++k) {
      const Index t = triangle(P);
      const Sample q = vertex(Q);
      std::array<std::pair<Sample, Sample>, 3> corners;
      for (int i = 0; i < 3; ++i) corners[i] = {Sample{{0, P.triangles[t][i]}, {P.triangles[t][i], 0, 0}, {1, 0, 0}, 1}, q};
      const std::array<std::pair<Sample, Sample>, 2> ends = {{{in_triangle(P, t), q}, {in_triangle(P, t), q}}};
      const Exact_point a = exact_sum(P, ends[0].first, Q, q), b = exact_sum(P, ends[1].first, Q, q);
      if (CGAL::is_zero(a.X[0] * b.W - b.X[0] * a.W) && CGAL::is_zero(a.X[1] * b.W - b.X[1] * a.W) &&
          CGAL::is_zero(a.X[2] * b.W - b.X[2] * a.W))
        continue;
      Segment_search on_plane(told), off_plane(untold);
      on_plane.start_plane(corners, nullptr, 0);
      std::vector<Segment_parameter> e_on, e_off;
      on_plane.free_ends(Translation_segment(a, b, ends), nullptr, 0, e_on);
      off_plane.free_ends(Translation_segment(a, b), nullptr, 0, e_off);
      REQUIRE(e_on.size() == e_off.size());
      for (std::size_t i = 0; i < e_on.size(); ++i) different += compare(e_on[i], e_off[i]) != CGAL::ZERO;
      ++segments;
      ends_found += e_on.size();
    }
  }
  INFO(contacts << " contacts, " << zeros_told << " zeros by construction, " << perturbed
                << " pair tests that met a zero, " << roots << " roots, " << segments << " segments, " << ends_found
                << " free ends");
  CHECK(untold_zeros == 0);
  CHECK(nonzero_told == 0); // every zero told is one
  CHECK(different == 0);
  CHECK(zeros_told > 1000);
  CHECK(perturbed > 100); // zeros were met (and decided by the perturbation)
  CHECK(roots > 100);
  CHECK(ends_found > 10);
}

// --- Ranks (named parameter `communicator`): threads stand for the processes. ------------
#include <CGAL_pmsum/Communicator.h>
#include <CGAL_pmsum/point_minkowski_sum_coarse_to_fine.h>
#include "shape_presets.h"

#include <array>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace {

/// K threads of one process as K ranks: all_gather waits for the K messages; the counter is
/// an atomic.
class Thread_ranks
{
public:
  explicit Thread_ranks(int k) : m_slots(std::size_t(k)) {}
  struct Rank : CGAL::Pmsum::Communicator
  {
    Thread_ranks* all;
    int r;
    Rank(Thread_ranks* a, int rank) : all(a), r(rank) {}
    int rank() const override { return r; }
    int size() const override { return int(all->m_slots.size()); }
    std::vector<std::string> all_gather(const std::string& bytes) override
    {
      std::unique_lock<std::mutex> lock(all->m_mutex);
      const std::size_t round = all->m_round;
      all->m_slots[std::size_t(r)] = bytes;
      if (++all->m_arrived == all->m_slots.size()) {
        all->m_result = all->m_slots;
        all->m_arrived = 0;
        ++all->m_round;
        all->m_changed.notify_all();
      } else {
        all->m_changed.wait(lock, [&] { return all->m_round != round; });
      }
      return all->m_result;
    }
    std::unique_ptr<Counter> make_counter() override
    {
      all_gather({});
      if (r == 0) all->m_counter = 0;
      all_gather({});
      return std::make_unique<Shared>(&all->m_counter);
    }
    struct Shared : Counter
    {
      std::atomic<std::uint64_t>* value;
      explicit Shared(std::atomic<std::uint64_t>* v) : value(v) {}
      std::uint64_t fetch_add(std::uint64_t n) override { return value->fetch_add(n); }
    };
  };

private:
  std::atomic<std::uint64_t> m_counter{0};
  std::vector<std::string> m_slots, m_result;
  std::size_t m_arrived = 0, m_round = 0;
  std::mutex m_mutex;
  std::condition_variable m_changed;
};

/// f(communicator, rank) on k thread-ranks: each rank's result, or each rank's error message
/// (all empty if none failed).
template <class T>
std::pair<std::vector<T>, std::vector<std::string>> on_ranks(int k, const std::function<T(CGAL::Pmsum::Communicator&, int)>& f)
{
  Thread_ranks ranks(k);
  const std::size_t n = std::size_t(k);
  std::vector<T> results(n);
  std::vector<std::string> errors(n);
  std::vector<std::thread> threads;
  for (int r = 0; r < k; ++r)
    threads.emplace_back([&, r] {
      Thread_ranks::Rank me(&ranks, r);
      try {
        results[std::size_t(r)] = f(me, r);
      } catch (const CGAL::Pmsum::Operation_cancelled&) {
        errors[std::size_t(r)] = "cancelled";
      } catch (const std::exception& e) {
        errors[std::size_t(r)] = e.what();
      }
    });
  for (std::thread& t : threads) t.join();
  return {results, errors};
}

/// P + Q computed by k ranks: each rank's records and statistics (throws the first error).
std::vector<Result> run_on_ranks(const Soup& P, const Soup& Q, double d, int k,
                                 const std::function<bool(int, double)>& callback = {})
{
  const auto [results, errors] = on_ranks<Result>(k, [&](CGAL::Pmsum::Communicator& me, int r) {
    auto np = CGAL::parameters::communicator(&me);
    if (!callback) return run(P, Q, d, np);
    return run(P, Q, d, np.callback(std::function<bool(double)>([&, r](double f) { return callback(r, f); })));
  });
  for (const std::string& e : errors)
    if (!e.empty()) throw std::runtime_error(e);
  return results;
}

/// The points of each level of P + Q, coarse to fine (d_levels), on `ranks` (nullptr: one process).
std::vector<std::vector<IK::Point_3>> levels(const Soup& P, const Soup& Q, const std::vector<double>& d_levels,
                                             CGAL::Pmsum::Communicator* ranks)
{
  const Mesh mp = to_mesh<Mesh>(P), mq = to_mesh<Mesh>(Q);
  std::vector<std::vector<IK::Point_3>> out;
  CGAL::point_minkowski_sum_coarse_to_fine(
    mp, mq, d_levels,
    [&](std::size_t, const CGAL::Pmsum::Statistics&, std::vector<Record>&& level) { out.push_back(all_points(level)); },
    CGAL::parameters::communicator(ranks));
  return out;
}

} // namespace

TEST_CASE("ranks: k ranks give one process's output and counts", "[ranks][long]")
{
  // 1.5% and 7% of the sums' diagonals; both have trim points (the tunnel's passage).
  const std::vector<std::tuple<const char*, const char*, double>> pairs = {{"knot", "tetrahedron", 0.15},
                                                                          {"tunnel", "tunnel-cube-rotated", 0.6}};
  for (const auto& [p, q, d] : pairs) {
    const Soup P = pmsum_shapes::shape_preset(p), Q = pmsum_shapes::shape_preset(q);
    const Result one = run(P, Q, d);
    REQUIRE(one.stats.ranks.empty());
    for (int k : {1, 2, 3}) {
      INFO(p << " + " << q << " on " << k << " ranks");
      const std::vector<Result> many = run_on_ranks(P, Q, d, k);
      for (const Result& r : many) {
        REQUIRE(r.records.size() == one.records.size());
        std::size_t different = 0;
        for (std::size_t i = 0; i < r.records.size(); ++i) {
          const Record &a = r.records[i], &b = one.records[i];
          different += !(a.point == b.point && a.normal == b.normal && a.origin_p.weights == b.origin_p.weights &&
                         a.origin_q.weights == b.origin_q.weights &&
                         a.origin_p.rational_weights == b.origin_p.rational_weights &&
                         a.origin_q.rational_weights == b.origin_q.rational_weights);
        }
        CHECK(different == 0);
        CHECK(r.stats.trim_points == one.stats.trim_points);
        CHECK(one.stats.trim_points > 0);
        CHECK(r.stats.candidates_covered == one.stats.candidates_covered);
        CHECK(r.stats.cd_queries == one.stats.cd_queries);
        CHECK(r.stats.candidates_in_patch_pairs == one.stats.candidates_in_patch_pairs);
        CHECK(r.stats.triangle_pairs == one.stats.triangle_pairs);
        CHECK(r.stats.trim_segments == one.stats.trim_segments);
        CHECK(r.stats.island_cells == one.stats.island_cells);
        // Each rank's share: every candidate decided once (every pair in one or more pieces),
        // the work shared out.
        REQUIRE(r.stats.ranks.size() == std::size_t(k));
        std::size_t pieces = 0, candidates = 0, largest = 0;
        for (const auto& s : r.stats.ranks) {
          pieces += s.pieces;
          candidates += s.candidates;
          largest = (std::max)(largest, s.candidates);
        }
        CHECK(pieces >= one.stats.feature_pairs);
        CHECK(candidates == one.stats.candidates);
        if (k > 1) CHECK(largest < one.stats.candidates);
      }
    }
  }
}

TEST_CASE("ranks: coarse to fine, every level is one process's (the decisions reused travel too)", "[ranks]")
{
  const Soup P = pmsum_shapes::shape_preset("knot"), Q = pmsum_shapes::shape_preset("tetrahedron");
  const std::vector<double> ds = {0.4, 0.2};
  const auto one = levels(P, Q, ds, nullptr);
  REQUIRE(one.size() == 2);
  const auto [many, errors] = on_ranks<std::vector<std::vector<IK::Point_3>>>(
    2, [&](CGAL::Pmsum::Communicator& me, int) { return levels(P, Q, ds, &me); });
  for (std::size_t r = 0; r < 2; ++r) {
    CHECK(errors[r].empty());
    CHECK(many[r] == one);
  }
}

TEST_CASE("ranks: a failure on one rank ends every rank, with its message", "[ranks]")
{
  const Soup P = pmsum_shapes::shape_preset("knot"), Q = pmsum_shapes::shape_preset("tetrahedron");
  const auto [results, errors] = on_ranks<Result>(2, [&](CGAL::Pmsum::Communicator& me, int r) {
    return run(P, Q, 0.15, CGAL::parameters::communicator(&me).callback(std::function<bool(double)>([r](double f) {
      if (r == 1 && f > 0.5) throw std::runtime_error("injected failure");
      return true;
    })));
  });
  CHECK(errors[1] == "injected failure");
  CHECK(errors[0] == "rank 1: injected failure");
}

TEST_CASE("ranks: ranks given different meshes all throw Invalid_input, before sharing any test", "[ranks]")
{
  // The same sizes, P moved a little on rank 1: the meshes' fingerprint tells them apart.
  const Soup P = pmsum_shapes::shape_preset("knot"), Q = pmsum_shapes::shape_preset("tetrahedron");
  Soup moved = P;
  for (auto& p : moved.points)
    for (double& c : p) c *= 1.001;
  const auto [results, errors] = on_ranks<Result>(2, [&](CGAL::Pmsum::Communicator& me, int r) {
    return run(r == 0 ? P : moved, Q, 0.15, CGAL::parameters::communicator(&me));
  });
  for (const std::string& e : errors) CHECK(e.find("different inputs") != std::string::npos);
}

TEST_CASE("ranks: a cancellation on one rank ends every rank", "[ranks]")
{
  const Soup P = pmsum_shapes::shape_preset("knot"), Q = pmsum_shapes::shape_preset("tetrahedron");
  CHECK_THROWS_WITH(run_on_ranks(P, Q, 0.15, 2, [](int rank, double) { return rank != 1; }), "cancelled");
}

TEST_CASE("ranks: chunks mapped over the ranks are one process's, and a failure in one ends every rank", "[ranks]")
{
  using CGAL::Pmsum::internal::map_chunks;
  // Chunk k holds k values k * 100 + i: uneven sizes, empty chunk 0, more chunks than ranks and fewer.
  auto chunk = [](std::size_t k, std::vector<std::uint32_t>& out) {
    for (std::size_t i = 0; i < k; ++i) out.push_back(std::uint32_t(k * 100 + i));
  };
  for (std::size_t n : {std::size_t(0), std::size_t(2), std::size_t(7)}) {
    const auto one = map_chunks<std::uint32_t>(n, false, nullptr, chunk);
    REQUIRE(one.size() == n);
    for (std::size_t k = 0; k < n; ++k) CHECK(one[k].size() == k);
    for (int ranks : {1, 2, 3}) {
      INFO(n << " chunks on " << ranks << " ranks");
      std::array<std::atomic<int>, 3> calls{}; // chunks computed by each rank
      const auto [many, errors] = on_ranks<std::vector<std::vector<std::uint32_t>>>(
        ranks, [&](CGAL::Pmsum::Communicator& me, int r) {
          return map_chunks<std::uint32_t>(n, true, &me, [&](std::size_t k, std::vector<std::uint32_t>& out) {
            ++calls[std::size_t(r)];
            chunk(k, out);
          });
        });
      int total = 0;
      for (int r = 0; r < ranks; ++r) {
        CHECK(errors[std::size_t(r)].empty());
        CHECK(many[std::size_t(r)] == one);
        CHECK(calls[std::size_t(r)] <= int((n + std::size_t(ranks) - 1) / std::size_t(ranks)));
        total += calls[std::size_t(r)];
      }
      CHECK(total == int(n)); // each chunk computed by one rank
    }
  }
  // A chunk that throws on rank 1: rank 1 rethrows it, rank 0 learns it.
  const auto [results, errors] = on_ranks<int>(2, [&](CGAL::Pmsum::Communicator& me, int) {
    map_chunks<std::uint32_t>(4, false, &me, [&](std::size_t k, std::vector<std::uint32_t>& out) {
      if (k == 3) throw std::runtime_error("injected failure");
      chunk(k, out);
    });
    return 0;
  });
  CHECK(errors[1] == "injected failure");
  CHECK(errors[0] == "rank 1: injected failure");
  // Ranks that disagree on the number of chunks: every rank throws Invalid_input.
  const auto [r2, e2] = on_ranks<int>(2, [&](CGAL::Pmsum::Communicator& me, int r) {
    map_chunks<std::uint32_t>(r == 0 ? 4 : 5, false, &me, chunk);
    return 0;
  });
  for (const std::string& e : e2) CHECK(e.find("different inputs") != std::string::npos);
}
