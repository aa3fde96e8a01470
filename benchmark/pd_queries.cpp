// Penetration-depth queries per second on a contact space of about a million points
// (issue 5: paper 0.1 ms per query; goal <= 2 us). Google Benchmark. Queries: a random contact
// point moved by up to 5% of the diagonal along each axis (up to about 18 d from the contact
// space), and "shallow" ones moved by up to d/2 along each axis.
//   pd_queries [--benchmark_format=json]      (run from the build tree; data from the sources)
#include <CGAL_pmsum/Penetration_depth.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <memory>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using PD = CGAL::Penetration_depth<Mesh, Mesh>;

namespace {
struct Setup
{
  Mesh P, Q;
  std::unique_ptr<PD> pd;
  std::vector<K::Point_3> queries, shallow_queries;
  double build_seconds = 0;

  Setup()
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    PMP::IO::read_polygon_mesh(CGAL_PMSUM_DATA_DIR "/knot1.off", P);
    PMP::IO::read_polygon_mesh(CGAL_PMSUM_DATA_DIR "/octahedron.off", Q);
    PMP::orient_to_bound_a_volume(Q);
    for (auto v : Q.vertices()) Q.point(v) = K::Point_3(Q.point(v).x() / 16, Q.point(v).y() / 16, Q.point(v).z() / 16);
    const CGAL::Bbox_3 b = PMP::bbox(P);
    const double diag = std::sqrt(std::pow(b.xmax() - b.xmin(), 2) + std::pow(b.ymax() - b.ymin(), 2) +
                                  std::pow(b.zmax() - b.zmin(), 2));
    const auto start = std::chrono::steady_clock::now();
    const double d = 0.0027 * diag;
#ifdef CGAL_LINKED_WITH_TBB
    pd = std::make_unique<PD>(PD::make<CGAL::Parallel_tag>(P, Q, d));
#else
    pd = std::make_unique<PD>(PD::make(P, Q, d));
#endif
    build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CGAL::Random rng(1);
    for (int i = 0; i < 4096; ++i) {
      // translations near the contact space: a contact point moved by up to 5% of the diagonal
      const auto& c = pd->contact_points()[rng.get_int(0, int(pd->number_of_contact_points()))];
      queries.emplace_back(c.x() + rng.get_double(-0.05, 0.05) * diag, c.y() + rng.get_double(-0.05, 0.05) * diag,
                           c.z() + rng.get_double(-0.05, 0.05) * diag);
    }
    for (int i = 0; i < 4096; ++i) {
      // shallow: a contact point moved by up to d/2 along each axis
      const auto& c = pd->contact_points()[rng.get_int(0, int(pd->number_of_contact_points()))];
      shallow_queries.emplace_back(c.x() + rng.get_double(-0.5, 0.5) * d, c.y() + rng.get_double(-0.5, 0.5) * d,
                                   c.z() + rng.get_double(-0.5, 0.5) * d);
    }
  }
};
Setup& setup()
{
  static Setup s;
  return s;
}
} // namespace

static void BM_nearest_contact(benchmark::State& state)
{
  Setup& s = setup();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(s.pd->nearest_contact(s.queries[i++ & 4095]));
  state.counters["contact_points"] = double(s.pd->number_of_contact_points());
  state.counters["build_seconds"] = s.build_seconds;
}
BENCHMARK(BM_nearest_contact);

static void BM_nearest_contact_shallow(benchmark::State& state)
{
  Setup& s = setup();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(s.pd->nearest_contact(s.shallow_queries[i++ & 4095]));
  state.counters["contact_points"] = double(s.pd->number_of_contact_points());
}
BENCHMARK(BM_nearest_contact_shallow);

static void BM_query_with_exact_overlap_test(benchmark::State& state)
{
  Setup& s = setup();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(s.pd->query(s.queries[i++ & 4095]));
  state.counters["contact_points"] = double(s.pd->number_of_contact_points());
}
BENCHMARK(BM_query_with_exact_overlap_test);

BENCHMARK_MAIN();
