// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The partitioner of `mpirun -np K pmsum sum` alone, simulated for many K (benchmark/mpi/run_mpi.py):
//   mpi_balance P Q d_relative [scale_q] K1 K2 ...
// For each K, the engine's own waves (internal::wave_end, internal::wave_work) of pieces of
// feature pairs (internal::make_pieces) are taken by K ranks as the engine's ranks take them
// from their shared counter: in the wave's order (internal::wave_order, the largest first),
// each by the rank that is free first (of ranks free at once, the one with the least work
// so far), with each piece's candidates as its time (the
// real times vary more: the trim search). Prints one JSON line per K:
//   largest_share   the largest rank's share of the whole work (the memory and the total work)
//   critical_share  the sum over the waves of the wave's largest rank load, over the whole
//                   work: the ranks wait for each other after every wave, so the time is at
//                   least this share of one process's decision time
// Both are 1/K at best.

#include <CGAL_pmsum/internal/distribution.h>
#include <CGAL_pmsum/internal/mesh_data.h>
#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/parallel.h>
#include <CGAL_pmsum/internal/pipeline.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace in = CGAL::Pmsum::internal;

int main(int argc, char** argv)
{
  if (argc < 5) {
    std::cerr << "usage: mpi_balance P Q d_relative scale_q K1 [K2 ...]\n";
    return 2;
  }
  Mesh P, Q;
  if (!CGAL::IO::read_polygon_mesh(argv[1], P) || !CGAL::IO::read_polygon_mesh(argv[2], Q)) {
    std::cerr << "mpi_balance: cannot read the meshes\n";
    return 1;
  }
  const double scale = std::atof(argv[4]);
  for (auto v : vertices(Q)) Q.point(v) = K::Point_3(Q.point(v).x() * scale, Q.point(v).y() * scale, Q.point(v).z() * scale);
  for (Mesh* m : {&P, &Q})
    if (CGAL::is_closed(*m) && !CGAL::Polygon_mesh_processing::is_outward_oriented(*m))
      CGAL::Polygon_mesh_processing::reverse_face_orientations(*m);
  const auto bp = CGAL::Polygon_mesh_processing::bbox(P), bq = CGAL::Polygon_mesh_processing::bbox(Q);
  double diagonal = 0;
  for (int c = 0; c < 3; ++c) diagonal += std::pow(bp.max(c) - bp.min(c) + bq.max(c) - bq.min(c), 2);
  const double d = std::atof(argv[3]) * std::sqrt(diagonal);

  in::Mesh_descriptors<Mesh> dp, dq;
  const in::Mesh_data mp = in::make_mesh_data(P, get(CGAL::vertex_point, P), false, false, "P", dp);
  const in::Mesh_data mq = in::make_mesh_data(Q, get(CGAL::vertex_point, Q), false, false, "Q", dq);
  const in::Candidate_pairs pairs = in::candidate_feature_pairs(mp, mq, true, true);
  const in::Mesh_sampling sp(mp, d / 2, "P"), sq(mq, d / 2, "Q");
  const std::size_t total = in::number_of_candidates(pairs, sp, sq);
  std::vector<std::size_t> work; // of each piece, as the engine cuts the pairs
  const std::vector<in::Pair_piece> pieces = in::make_pieces(pairs, sp, sq, in::piece_work(total), in::piece_rows, work);
  std::size_t waves = 0;
  for (std::size_t first = 0; first < work.size(); first = in::wave_end(work, first, in::wave_work(total))) ++waves;

  for (int a = 5; a < argc; ++a) {
    const int k = std::atoi(argv[a]);
    std::vector<std::size_t> so_far(std::size_t(k), 0);
    double critical = 0;
    std::vector<std::size_t> order;
    for (std::size_t first = 0; first < work.size();) {
      const std::size_t last = in::wave_end(work, first, in::wave_work(total));
      std::vector<std::size_t> load(std::size_t(k), 0); // in this wave
      in::wave_order(work, first, last, order);
      for (std::size_t i : order) {
        // The rank free first; of ranks free at once (at the wave's start), any may win the
        // counter: modelled as the one with the least work so far.
        std::size_t r = 0;
        for (std::size_t s = 1; s < load.size(); ++s)
          if (load[s] < load[r] || (load[s] == load[r] && so_far[s] < so_far[r])) r = s;
        load[r] += work[i];
        so_far[r] += work[i];
      }
      critical += double(*std::max_element(load.begin(), load.end()));
      first = last;
    }
    const double largest = double(*std::max_element(so_far.begin(), so_far.end()));
    std::cout << "{\"k\": " << k << ", \"d\": " << d << ", \"feature_pairs\": " << pairs.pairs.size()
              << ", \"pieces\": " << pieces.size()
              << ", \"candidates\": " << total << ", \"waves\": " << waves
              << ", \"largest_share\": " << largest / double(total) << ", \"critical_share\": " << critical / double(total)
              << "}" << std::endl;
  }
  return 0;
}
