// Bad input: a clear exception, nothing written to the output.
#include "test_support.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace pmsum_test;
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
  } catch (const CGAL::Pmsum::Too_many_candidates& e) {
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

TEST_CASE("a d that needs too many subdivisions", "[errors]")
{
  CHECK_THAT(error_of(cube, cube, 1e-9), Contains("d is too small for P"));
}

TEST_CASE("candidate limit", "[errors]")
{
  const std::string msg = error_of(cube, cube, 0.01, CGAL::parameters::maximum_number_of_candidates(1000));
  CHECK_THAT(msg, Contains("more than the limit of 1000"));
}
