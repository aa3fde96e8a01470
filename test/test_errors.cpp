// Bad input: a clear exception, nothing written to the output.
//
// CGAL's assertions are on in this translation unit whatever the build type, so that every
// check here gives the same exception as in a release build (not CGAL::Precondition_exception).
#undef NDEBUG
#undef CGAL_NDEBUG
#include "test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Random.h>
#include <CGAL/intersections.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace pmsum_shapes;
using Catch::Matchers::Contains;

namespace {

const Mesh cube = to_mesh<Mesh>(box({0, 0, 0}, {1, 1, 1}));

/// Output iterator counting what is written, whatever its type.
struct Counter
{
  std::size_t* n;
  Counter& operator*() { return *this; }
  Counter& operator++() { return *this; }
  Counter operator++(int) { return *this; }
  template <class T> Counter& operator=(const T&) { ++*n; return *this; }
};

/// Runs the sum and returns the exception message; fails if nothing is thrown or if
/// anything was written to the output.
template <class MeshP, class MeshQ, class NP = decltype(CGAL::parameters::use_normal_filter(true))>
std::string error_of(const MeshP& P, const MeshQ& Q, double d, const NP& np = CGAL::parameters::use_normal_filter(true))
{
  std::size_t written = 0;
  try {
    CGAL::point_minkowski_sum(P, Q, d, Counter{&written}, np);
  } catch (const CGAL::Pmsum::Invalid_input& e) {
    CHECK(written == 0);
    return e.what();
  } catch (const CGAL::Pmsum::Too_large& e) {
    CHECK(written == 0);
    return e.what();
  }
  FAIL("no exception");
  return "";
}

} // namespace

TEST_CASE("d must be positive and finite", "[errors]")
{
  for (double d : {0., -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    CHECK_THAT(error_of(cube, cube, d), Contains("d must be positive and finite"));
}

TEST_CASE("empty mesh", "[errors]")
{
  CHECK_THAT(error_of(Mesh(), cube, 0.1), Contains("P has no faces"));
  CHECK_THAT(error_of(cube, Mesh(), 0.1), Contains("Q has no faces"));
}

TEST_CASE("coordinates that are not finite", "[errors]")
{
  Mesh m = cube;
  m.point(*m.vertices().begin()) = IK::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK_THAT(error_of(cube, m, 0.1), Contains("Q vertex 0 has a coordinate that is not finite"));
  m.point(*m.vertices().begin()) = IK::Point_3(0, std::numeric_limits<double>::infinity(), 0);
  CHECK_THAT(error_of(m, cube, 0.1), Contains("P vertex 0 has a coordinate that is not finite"));
}

TEST_CASE("exact coordinates that are not doubles", "[errors]")
{
  using EMesh = CGAL::Surface_mesh<EK::Point_3>;
  EMesh m = to_mesh<EMesh>(box({0, 0, 0}, {1, 1, 1}));
  const auto v = *m.vertices().begin();
  m.point(v) = EK::Point_3(EK::FT(1) / 3, 0, 0);
  CHECK_THAT(error_of(m, m, 0.1), Contains("not a double"));
}

TEST_CASE("non-triangle faces", "[errors]")
{
  Mesh quad;
  auto a = quad.add_vertex({0, 0, 0}), b = quad.add_vertex({1, 0, 0}), c = quad.add_vertex({1, 1, 0}),
       d = quad.add_vertex({0, 1, 0});
  quad.add_face(a, b, c, d);
  CHECK_THAT(error_of(quad, cube, 0.1), Contains("P face 0 is not a triangle (4 vertices)"));
}

TEST_CASE("degenerate faces", "[errors]")
{
  Mesh m;
  auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({2, 0, 0}),
       d = m.add_vertex({0, 1, 1});
  m.add_face(a, b, d);
  REQUIRE(m.add_face(b, a, c) != Mesh::null_face()); // collinear
  CHECK_THAT(error_of(cube, m, 0.1), Contains("Q face 1 is degenerate"));
}

TEST_CASE("inward oriented solid", "[errors]")
{
  Mesh m = cube;
  CGAL::Polygon_mesh_processing::reverse_face_orientations(m);
  CHECK_THAT(error_of(m, cube, 0.1), Contains("P is oriented inward"));
}

TEST_CASE("a d that needs too many subdivisions is a refusal for size, not bad input", "[errors]")
{
  std::size_t written = 0;
  try {
    CGAL::point_minkowski_sum(cube, cube, 1e-12, Counter{&written});
    FAIL("no exception");
  } catch (const CGAL::Pmsum::Covering_distance_too_small& e) {
    CHECK_THAT(std::string(e.what()), Contains("d is too small for P"));
    CHECK(dynamic_cast<const CGAL::Pmsum::Too_large*>(&e) != nullptr);
  }
  CHECK(written == 0);
}

TEST_CASE("candidate limit", "[errors]")
{
  const std::string msg = error_of(cube, cube, 0.01, CGAL::parameters::maximum_number_of_candidates(1000));
  CHECK_THAT(msg, Contains("more than the limit of 1000"));
}

TEST_CASE("without the normal filter, the feature pairs are counted before they are stored", "[errors]")
{
  // 38 features per cube (8 vertices, 18 edges, 12 triangles): 38 x 38 pairs, each with the facet directions around both features
  std::string msg;
  try {
    std::size_t written = 0;
    CGAL::point_minkowski_sum(cube, cube, 0.5, Counter{&written},
                              CGAL::parameters::use_normal_filter(false).maximum_number_of_candidates(1000));
    FAIL("no exception");
  } catch (const CGAL::Pmsum::Too_many_feature_pairs& e) {
    msg = e.what();
    CHECK(e.limit == 1000);
  }
  CHECK_THAT(msg, Contains("without the normal filter, the 38 x 38 feature pairs"));
  CHECK_THAT(msg, Contains("more than the limit of 1000"));
  // within the limit, the run goes on
  std::vector<IK::Point_3> out;
  CGAL::point_minkowski_sum(cube, cube, 0.5, std::back_inserter(out),
                            CGAL::parameters::use_normal_filter(false).maximum_number_of_candidates(100000));
  CHECK(out.size() > 8);
}

namespace {
/// The soup with every triangle reversed (a void, when nested in a solid).
Soup reversed(Soup s)
{
  for (auto& t : s.triangles) std::swap(t[1], t[2]);
  return s;
}
Mesh mesh_of(const std::vector<Soup>& parts)
{
  Soup s;
  for (const Soup& p : parts) s.append(p);
  return to_mesh<Mesh>(s);
}
/// Runs the sum with Q = cube; true if it succeeds with output.
bool accepted(const Mesh& P)
{
  std::vector<IK::Point_3> out;
  CGAL::point_minkowski_sum(P, cube, 0.5, std::back_inserter(out));
  return !out.empty();
}
} // namespace

TEST_CASE("overlapping closed components", "[errors]")
{
  // three mutually overlapping cubes (the example)
  const Mesh three = mesh_of({box({0, 0, 0}, {2, 2, 2}), box({1, 1, 1}, {3, 3, 3}), box({1, 0.5, 0.5}, {4, 1.5, 1.5})});
  CHECK_THAT(error_of(three, cube, 0.5), Contains("P components 0 and 1 overlap (faces"));
  CHECK_THAT(error_of(cube, three, 0.5), Contains("Q components 0 and 1 overlap"));
  // the same cube twice: coincident faces on the same side
  CHECK_THAT(error_of(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({0, 0, 0}, {1, 1, 1})}), cube, 0.5),
             Contains("P components 0 and 1 overlap"));
  // a cube sharing the bottom face of a larger one and inside it
  CHECK_THAT(error_of(mesh_of({box({0, 0, 0}, {2, 2, 2}), box({0, 0, 0}, {1, 1, 1})}), cube, 0.5),
             Contains("P components 0 and 1 overlap"));
  // an outward cube strictly inside another: nested solids, not a void
  CHECK_THAT(error_of(mesh_of({box({0, 0, 0}, {3, 3, 3}), box({1, 1, 1}, {2, 2, 2})}), cube, 0.5),
             Contains("P components 0 and 1 overlap: 1 lies inside 0 and both are oriented outward"));
  // with check_overlaps(false) the caller vouches for the input: no check, no error
  std::vector<IK::Point_3> out;
  CHECK_NOTHROW(CGAL::point_minkowski_sum(three, cube, 0.5, std::back_inserter(out),
                                          CGAL::parameters::check_overlaps(false)));
}

TEST_CASE("touching and nested closed components are valid", "[errors]")
{
  // along a face, along an edge, at a vertex
  CHECK(accepted(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})})));
  CHECK(accepted(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({1, 1, 0}, {2, 2, 1})})));
  CHECK(accepted(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({1, 1, 1}, {2, 2, 2})})));
  // along part of a face, offset (faces overlap partly, opposite sides)
  CHECK(accepted(mesh_of({box({0, 0, 0}, {2, 2, 1}), box({1, 1, 1}, {3, 3, 2})})));
  // a void (inward cube) inside a solid, and a solid inside that void
  CHECK(accepted(mesh_of({box({0, 0, 0}, {5, 5, 5}), reversed(box({1, 1, 1}, {4, 4, 4}))})));
  CHECK(accepted(mesh_of({box({0, 0, 0}, {5, 5, 5}), reversed(box({1, 1, 1}, {4, 4, 4})), box({2, 2, 2}, {3, 3, 3})})));
  // a void touching its shell's inner side along a face
  CHECK(accepted(mesh_of({box({0, 0, 0}, {5, 5, 5}), reversed(box({0, 1, 1}, {4, 4, 4}))})));
  // an inward cube inside a void is not valid
  CHECK_THAT(error_of(mesh_of({box({0, 0, 0}, {5, 5, 5}), reversed(box({1, 1, 1}, {4, 4, 4})),
                               reversed(box({2, 2, 2}, {3, 3, 3}))}), cube, 0.5),
             Contains("P component 2 is oriented inward inside the void of component 1"));
}

TEST_CASE("solids: components that touch, and a void with its container, are one", "[errors]")
{
  using CGAL::Pmsum::internal::Index;
  auto solids = [](const Mesh& P) {
    CGAL::Pmsum::internal::Mesh_descriptors<Mesh> desc;
    const auto m = CGAL::Pmsum::internal::make_mesh_data(P, get(CGAL::vertex_point, P), false, false, "P", desc);
    return CGAL::Pmsum::internal::Solid_checker(m, "P").solids();
  };
  // touching along a face, at a vertex; a hair apart
  CHECK(solids(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1})})) == std::vector<Index>{0, 0});
  CHECK(solids(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({1, 1, 1}, {2, 2, 2})})) == std::vector<Index>{0, 0});
  CHECK(solids(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({1 + 1e-9, 0, 0}, {2, 1, 1})})) == std::vector<Index>{0, 1});
  // a chain (0 touches 2, 2 touches 1) and one apart
  CHECK(solids(mesh_of({box({0, 0, 0}, {1, 1, 1}), box({2, 0, 0}, {3, 1, 1}), box({1, 0, 0}, {2, 1, 1}),
                        box({5, 0, 0}, {6, 1, 1})})) == std::vector<Index>{0, 0, 0, 1});
  // a void is its shell's; a solid inside the void is apart
  CHECK(solids(mesh_of({box({0, 0, 0}, {5, 5, 5}), reversed(box({1, 1, 1}, {4, 4, 4})), box({2, 2, 2}, {3, 3, 3})})) ==
        std::vector<Index>{0, 0, 1});
}

TEST_CASE("each closed component is oriented on its own", "[errors]")
{
  // an outward box and a disjoint inward box: the total volume is positive
  const Mesh m = mesh_of({box({0, 0, 0}, {2, 2, 2}), reversed(box({3, 0, 0}, {4, 1, 1}))});
  CHECK_THAT(error_of(m, cube, 0.5), Contains("P is oriented inward (component 1 has a negative volume)"));
}

TEST_CASE("a closed mesh that intersects itself", "[errors]")
{
  // a cube whose vertex (1,1,1) is pulled through the bottom face to (0.5,0.5,-1)
  Soup s = box({0, 0, 0}, {1, 1, 1});
  s.points[7] = {0.25, 0.5, -1};
  CHECK_THAT(error_of(to_mesh<Mesh>(s), cube, 0.5), Contains("P component 0 intersects itself (faces"));
}

TEST_CASE("the triangle crossing test against exact intersections", "[errors]")
{
  // Reference: the relative interiors meet (non-coplanar: the intersection is a segment whose
  // midpoint is strictly inside both), or coplanar triangles on the same side overlap with
  // positive area. Small integer coordinates make many degenerate (touching) pairs.
  using CGAL::Pmsum::internal::Mesh_data;
  CGAL::Random rng(11);
  auto strictly_inside = [](const EK::Triangle_3& t, const EK::Point_3& p) {
    const auto &a = t[0], &b = t[1], &c = t[2];
    return CGAL::coplanar(a, b, c, p) && CGAL::coplanar_orientation(a, b, c, p) == CGAL::POSITIVE &&
           CGAL::coplanar_orientation(b, c, a, p) == CGAL::POSITIVE && CGAL::coplanar_orientation(c, a, b, p) == CGAL::POSITIVE;
  };
  std::size_t crossing = 0, touching = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Mesh_data m;
    const int range = trial % 2 ? 2 : 4;
    for (int i = 0; i < 6; ++i)
      m.points.push_back({double(rng.get_int(0, range)), double(rng.get_int(0, range)), double(rng.get_int(0, range))});
    if (trial % 3 == 0) // coplanar pairs, in z = 0 or x + y + z = range
      for (auto& p : m.points) p[2] = (trial % 2) ? 0 : range - p[0] - p[1];
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    EK::Point_3 P[6];
    for (int i = 0; i < 6; ++i) P[i] = EK::Point_3(m.points[i][0], m.points[i][1], m.points[i][2]);
    const EK::Triangle_3 T1(P[0], P[1], P[2]), T2(P[3], P[4], P[5]);
    if (T1.is_degenerate() || T2.is_degenerate()) continue;
    m.components.resize(1);
    m.triangle_component = {0, 0};
    m.vertex_component.assign(6, 0);
    const bool got = CGAL::Pmsum::internal::Solid_checker(m, "P").triangles_cross(0, 1);

    bool expected = false;
    if (const auto x = CGAL::intersection(T1, T2)) {
      if (const EK::Segment_3* s = boost::get<EK::Segment_3>(&*x)) {
        const EK::Point_3 mid = CGAL::midpoint(s->source(), s->target());
        const bool coplanar = CGAL::coplanar(P[0], P[1], P[2], P[3]) && CGAL::coplanar(P[0], P[1], P[2], P[4]) &&
                              CGAL::coplanar(P[0], P[1], P[2], P[5]);
        expected = !coplanar && strictly_inside(T1, mid) && strictly_inside(T2, mid);
      } else if (!boost::get<EK::Point_3>(&*x)) { // a triangle or polygon: coplanar, positive area
        expected = CGAL::scalar_product(T1.supporting_plane().orthogonal_vector(),
                                        T2.supporting_plane().orthogonal_vector()) > 0;
      }
      touching += !expected;
    }
    crossing += expected;
    INFO("trial " << trial << ": " << T1 << " / " << T2);
    REQUIRE(got == expected);
  }
  CHECK(crossing > 1000);
  CHECK(touching > 500);
}
