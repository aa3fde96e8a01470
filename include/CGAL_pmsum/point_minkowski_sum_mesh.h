// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::point_minkowski_sum_mesh(): a closed, 2-manifold, outward-oriented triangle mesh of
// the boundary of P + Q without self-intersections, whose vertices are output points of
// point_minkowski_sum() (each exactly on the boundary). The points (the default (d/2, d)-net)
// are joined by CGAL's advancing-front surface reconstruction, chosen and repaired with the
// points' normals (internal/mesh_reconstruction.h); where that mesh is refused, the same points
// are joined plane by plane (internal/plane_triangulation.h: a triangle never leaves the plane
// of a face, so it never bridges a narrow passage); the result is checked (check_mesh.h), and if
// a check fails, or an output point the reconstruction left out lies as far as the covering
// distance used or farther from the mesh, the sum is recomputed with a smaller one. A mesh that fails every
// check is never returned: Mesh_reconstruction_failed is thrown instead.
//
// Why the points must stay near the mesh: they cover the exact boundary within d (every
// boundary point has an output point closer than d), so every boundary point is closer than
// d + e to the mesh, e the largest distance from an output point to the mesh (0 when every
// point is a vertex). A reconstruction that drops the points of a part of the boundary (the
// walls of a narrow passage, say) may still be a valid mesh, of the wrong shape: e tells.
// Where e is below d, the points left out are put back as vertices where they can be
// (internal/mesh_left_out_points.h), which lowers e, often to 0.
// And the mesh must stay near the points: they lie on the exact boundary, so a mesh whose
// every point is closer than d to one (mesh_distance_bound()) is closer than d to the boundary.
// A valid mesh can fail it: a triangle cutting deep across a sharp corner, or closing a hole
// over a part of the boundary whose points it left out.

#ifndef CGAL_PMSUM_POINT_MINKOWSKI_SUM_MESH_H
#define CGAL_PMSUM_POINT_MINKOWSKI_SUM_MESH_H

#include <CGAL_pmsum/check_mesh.h>
#include <CGAL_pmsum/internal/mesh_second_sheet.h>
#include <CGAL_pmsum/internal/mesh_short_handles.h>
#include <CGAL_pmsum/internal/mesh_left_out_points.h>
#include <CGAL_pmsum/internal/mesh_necks.h>
#include <CGAL_pmsum/internal/mesh_reconstruction.h>
#include <CGAL_pmsum/internal/mesh_voids.h>
#include <CGAL_pmsum/internal/plane_triangulation.h>
#include <CGAL_pmsum/point_minkowski_sum.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumMesh
/// Counters and seconds of point_minkowski_sum_mesh().
struct Mesh_statistics
{
  Statistics sum;              ///< the last point_minkowski_sum() run
  double covering_distance = 0;///< the `d` of that run (`d`, or smaller after refinements)
  int refinements = 0;         ///< how many times `d` was halved because a check failed
  /// the points on the sum's sharp creases were kept (a refinement's second try)
  bool crease_points = false;
  /// the mesh was made plane by plane: the advancing front's mesh of the same points was refused
  bool by_planes = false;
  /// output points the reconstruction left out that were put back as vertices (each splitting
  /// its nearest triangle: internal/mesh_left_out_points.h)
  std::size_t points_put_back = 0;
  /// how many times the mesh returned was made again round folds or second sheets that the
  /// checks found in it (their triangles cut with a ring round them, the holes closed again:
  /// internal/mesh_reconstruction.h, remesh_around()); twice at most for each
  int sheets_remeshed = 0;
  std::size_t vertices = 0;    ///< vertices of the mesh (output points of the sum)
  std::size_t triangles = 0;   ///< triangles of the mesh
  Mesh_checks checks;          ///< the checks of the mesh returned
  /// the largest distance from an output point of the last run to the mesh (0 if every
  /// point is a vertex; infinity if the mesh failed a check)
  double point_distance = 0;
  /// a proved bound: every point of the mesh is closer than this to an output point of the
  /// last run, hence to the exact boundary (below `covering_distance`; infinity if the mesh
  /// failed a check)
  double mesh_to_boundary_bound = 0;
  /// \returns a proved bound: every point of the exact boundary is closer than this to the
  /// mesh (`covering_distance + point_distance`)
  double boundary_to_mesh_bound() const { return covering_distance + point_distance; }
  double seconds_sum = 0;      ///< all runs of the sum
  double seconds_mesh = 0;     ///< all reconstructions and checks
  /// why the meshes made before the one returned were refused, way by way and level by level
  /// (empty if the advancing front's first mesh was taken)
  std::string refused;
};

namespace internal {

/// The connected parts the sum is made of: the sum of a solid of P and a solid of Q
/// (Solid_checker::solids(): components that touch, voids with their container) is connected,
/// so the points of one such part lie on the boundary of one volume of the sum (an outer
/// shell with its voids). A mesh that puts them on two has split a connected part (a sharp
/// corner cut off, a bubble left, a seam between touching components opened).
class Sum_parts
{
public:
  Sum_parts(const Mesh_data& mp, const Mesh_data& mq)
    : m_p(Solid_checker(mp).solids()), m_q(Solid_checker(mq).solids())
  {}

  /// The part of the output point of samples sp of P and sq of Q.
  std::size_t of(const Mesh_data& mp, const Mesh_data& mq, const Sample& sp, const Sample& sq) const
  { return std::size_t(m_p[component(mp, sp)]) * m_q.size() + m_q[component(mq, sq)]; }

private:
  static Index component(const Mesh_data& m, const Sample& s)
  {
    for (int i = 0; i < 3; ++i)
      if (s.weights[i] != 0) return m.vertex_component[s.vertices[i]];
    return m.vertex_component[s.vertices[0]];
  }

  std::vector<Index> m_p, m_q;
};

/// Does `mesh` (closed, manifold, without self-intersections) put the points of one part of
/// the sum (Sum_parts) on the boundaries of two of its volumes? `part[i]` is the part of the
/// point at `positions[i]`; the mesh's vertices are such points.
template <class TriangleMesh>
bool splits_a_part(const TriangleMesh& mesh, const std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& positions,
                   const std::vector<std::size_t>& part)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const auto index_at = indices_by_position(positions);
  auto volume_id = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  if (PMP::volume_connected_components(mesh, volume_id) < 2) return false;
  std::unordered_map<std::size_t, std::size_t> volume_of; // part -> volume
  for (auto v : vertices(mesh)) {
    const auto it = index_at.find(position(get(CGAL::vertex_point, mesh, v)));
    if (it == index_at.end()) continue;
    const std::size_t volume = get(volume_id, face(halfedge(v, mesh), mesh));
    if (volume_of.emplace(part[it->second], volume).first->second != volume) return true;
  }
  return false;
}

/// Why the mesh of a level was refused, for Mesh_reconstruction_failed.
inline std::string level_failure(const Mesh_statistics& ms, bool split)
{
  if (ms.checks.valid() && ms.checks.shells == 0) return "was empty";
  if (!ms.checks.valid()) return "was " + ms.checks.failures();
  if (split)
    return "split a connected part of the sum (a solid of P plus one of Q) into " +
           std::to_string(ms.checks.shells - ms.checks.void_shells) + " outer shells";
  if (ms.point_distance >= ms.covering_distance)
    return "left output points up to " + std::to_string(ms.point_distance / ms.covering_distance) +
           " times that d from the mesh (a part of the boundary missing)";
  return "had triangles that could not be shown closer than that d to the output points (cutting across the boundary)";
}

/// The start of every mesh function: checks the parameters that a mesh refuses (it meshes the
/// covering net, not every candidate, and its bound rests on the covering: trim and island
/// points), clears `mesh`, and returns the statistics to fill, reset (the named parameter
/// `mesh_statistics`, else `local`).
template <class NamedParameters, class TriangleMesh>
Mesh_statistics& start_mesh(const NamedParameters& np, TriangleMesh& mesh, Mesh_statistics& local, const char* function)
{
  static_assert(!has_any_parameter<NamedParameters, internal_np::use_covering_net_t, internal_np::roadmap_neighbors_t>(),
                "CGAL_pmsum: a mesh of the sum meshes the covering net; use_covering_net and roadmap_neighbors "
                "are not parameters of it");
  if (!parameters::choose_parameter(parameters::get_parameter(np, internal_np::use_trim_points), true) ||
      !parameters::choose_parameter(parameters::get_parameter(np, internal_np::search_islands), true))
    throw Invalid_input(std::string(function) + " needs the covering's trim and island points "
                        "(use_trim_points and search_islands true): its bound rests on the covering");
  Mesh_statistics& ms = *parameters::choose_parameter(parameters::get_parameter(np, internal_np::mesh_statistics), &local);
  ms = Mesh_statistics();
  clear(mesh);
  return ms;
}

/// The mesh of the boundary that `pipeline` (made coarse to fine, on mp and mq) covers: the
/// points of covering distance d are reconstructed into `mesh` and checked (check_mesh(), the
/// no connected part of the sum split (splits_a_part()), no void the sum does not have
/// (has_false_void()), no second sheet (has_second_sheet()), no neck across free space nor
/// channel through the solid (has_neck_or_channel()), no handle narrower than d nor
/// handle or neck a few d round that the sum is not shown to have (has_false_short_handle()),
/// the points' distance to the mesh and the mesh's to the points (mesh_distance_bound())); a
/// mesh with second sheets is first made again round them (remesh_around()) and checked
/// again whole, twice at most; if a check fails, the level is made again
/// with the trim curves searched wherever they are (not only where the covering needs them),
/// then d is halved, twice at most, at d/2 first without the points on sharp creases, then
/// with them, at d/4 alike (see `levels`), reusing the coarser decisions; then
/// Mesh_reconstruction_failed, which says why each level was refused.
/// `stats` receives each level's counters (ms.sum the last one's); `start` is when the input
/// stage began. GT: the kernel in which the points are computed.
template <class GT, class ConcurrencyTag, class TriangleMesh>
void mesh_levels(Pipeline<ConcurrencyTag>& pipeline, const Mesh_data& mp, const Mesh_data& mq, double d,
                 Statistics& stats, Clock::time_point start, TriangleMesh& mesh, Mesh_statistics& ms)
{
  using Point = typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type;
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  // The levels: d with the trim search the covering needs, then d again (a hair smaller:
  // coarse to fine needs a smaller d) with the trim curves searched in every cell with a
  // corner inside (a hole in a face narrower than d, a narrow tunnel's mouth, is closed
  // without them), then d/2, then d/2 again keeping the points on sharp creases (they help
  // a corner or a strip far narrower than d; second, because rows of crease points beside the
  // faces' rows may hurt the advancing front, and they make more vertices: frame + knot at 5%
  // of the diagonal, 5,785 vertices at d/2 without them, 9,559 with), then d/4, then d/4
  // again with them (a grate plus a tiny tetrahedron is meshed plane by plane there). From
  // d/2 on, narrow strips are followed.
  struct Level { int halvings; Creases creases; bool again; Strips strips; };
  const Level levels[] = {{0, Creases::as_covering_needs, false, Strips::as_covering_needs},
                          {0, Creases::as_covering_needs, true, Strips::inside_corners},
                          {1, Creases::as_covering_needs, false, Strips::followed},
                          {1, Creases::sharp_kept, true, Strips::followed},
                          {2, Creases::as_covering_needs, false, Strips::followed},
                          {2, Creases::sharp_kept, true, Strips::followed}};
  const Sum_parts parts(mp, mq);
  std::string failures;
  for (const Level& level : levels) {
    const bool creases = level.creases == Creases::sharp_kept;
    const double dl = d / double(1 << level.halvings) * (level.again ? 1 - 1. / 1024 : 1);
    const auto t_sum = Clock::now();
    std::vector<Point> points;
    std::vector<Epick::Vector_3> face_normals;          // of a face through the point
    std::vector<Normal_use> use;                        // what that normal tells the advancing front
    std::vector<std::size_t> part;                      // Sum_parts::of() the point
    Crease_planes crease_planes;                        // the faces at points on creases
    stats = Statistics();
    pipeline.run_level(dl, stats, [&](const Sample& sp, const Sample& sq, const Direction& direction, const Trim* trim) {
      points.emplace_back(output_point<GT>(mp, mq, sp, sq, trim));
      part.push_back(parts.of(mp, mq, sp, sq));
      face_normals.push_back(output_normal<Epick>(mp, mq, direction));
      bool on_crease = false;
      if (!trim)
        for_each_crease_wedge(sp.origin, sq.origin, mp, mq, [&](const std::array<Vec3<double>, 2>& w, const Mesh_data& E, Index e) {
          on_crease = on_crease || !E.edges[e].flat;
          for (const Vec3<double>& n : w) crease_planes.emplace_back(points.size() - 1, Epick::Vector_3(n[0], n[1], n[2]));
        });
      // On a convolution edge or vertex, or a trim curve, the normal is one of several: none is
      // given. A vertex plus an edge off every crease of the pair (a vertex sample at the end of
      // an edge whose sum with an edge of the other mesh is a face) tells the side it is on:
      // the face's normal, unless the point is on a crease of other features too (as where parts
      // of a mesh touch), so it only refuses triangles to the opposite side (back_to_back()).
      const int dimension = sp.origin.dimension + sq.origin.dimension;
      const bool given = !trim && dimension == 2;
      use.push_back(given ? Normal_use::normal : !trim && dimension == 1 && !on_crease ? Normal_use::side : Normal_use::none);
    }, start, level.strips, level.creases);
    start = Clock::now();
    ms.sum = stats;
    ms.seconds_sum += seconds_since(t_sum);
    const auto t_mesh = Clock::now();
    const auto positions = double_positions(points);
    const auto index_at = indices_by_position(points);
    auto face_normal_at = [&](const Position& x) -> std::optional<Epick::Vector_3> {
      const auto i = index_at.find(x);
      if (i == index_at.end() || use[i->second] != Normal_use::normal) return std::nullopt;
      return face_normals[i->second];
    };
    // The advancing front first; where its mesh is refused, the points plane by plane
    // (internal/plane_triangulation.h), which needs the CD filter's exact test at a point.
    const Cd_geometry* geometry = pipeline.geometry();
    std::optional<Face_cover> cover; // of this level's pairs, made when first asked for
    auto level_cover = [&]() -> Face_cover& {
      if (!cover) cover.emplace(pipeline.pairs(), mp, mq);
      return *cover;
    };
    for (int way = 0; way < (geometry ? 2 : 1); ++way) {
      const auto t_way = Clock::now();
      std::vector<std::array<std::size_t, 3>> triangles;
      std::optional<Cd_filter> cd;
      auto free_at = [&](const std::array<double, 3>& x) { return cd->is_free_at(x); };
      if (way == 0) {
        triangles = advancing_front_triangles(positions, face_normals, use, dl);
      } else {
        cd.emplace(geometry);
        triangles = plane_triangles(positions, face_normals, crease_planes, dl, free_at, level_cover());
      }
      ms.checks = mesh_from_triangles<ConcurrencyTag>(
        points, triangles, way == 0 ? Triangles_from::one_delaunay_triangulation : Triangles_from::anywhere, dl, mesh);
      // A mesh with folds or second sheets is made again round them (remesh_around()), twice
      // at most for each, and checked again whole.
      auto remesh = [&](const std::vector<std::size_t>& cut_out) { // (indices in the order of faces(mesh))
        using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
        const std::vector<face_descriptor> face_of(faces(mesh).begin(), faces(mesh).end());
        std::set<face_descriptor> cut;
        for (std::size_t f : cut_out) cut.insert(face_of[f]);
        ms.checks = remesh_around<ConcurrencyTag>(points, std::move(cut), dl, mesh);
      };
      // Folds first, before points are put back (a tent folded flat onto its neighbours holds
      // its point): made again round, twice at most; where some remain, the mesh as it was
      // goes on (the plates turned by seed 23 + a small cube at 2% keep a fold, and their
      // mesh made again round its second sheet is right).
      int fold_remeshes = 0;
      if (std::vector<std::size_t> folds = ms.checks.valid() ? faces_against_their_corners(mesh, face_normal_at)
                                                             : std::vector<std::size_t>();
          !folds.empty()) {
        const TriangleMesh before_folds = mesh;
        const Mesh_checks before_folds_checks = ms.checks;
        while (!folds.empty() && fold_remeshes < 2) {
          remesh(folds);
          ++fold_remeshes;
          if (ms.checks.valid()) folds = faces_against_their_corners(mesh, face_normal_at);
          else break;
        }
        if (!folds.empty() || !ms.checks.valid()) {
          mesh = before_folds;
          ms.checks = before_folds_checks;
          fold_remeshes = 0;
        }
      }
      bool passed = false, across = false, split = false;
      const char* refuted = nullptr;
      for (int remeshed = 0;; ++remeshed) {
        ms.sheets_remeshed = fold_remeshes + remeshed;
        ms.point_distance = ms.checks.valid() ? largest_distance_to_mesh(points, mesh)
                                              : std::numeric_limits<double>::infinity();
        // Points left out, none as far as dl (farther: a part of the boundary is missing, and
        // the level refused): put back where they can be, the mesh is then closer to them.
        ms.points_put_back = ms.point_distance > 0 && ms.point_distance < dl
                               ? insert_left_out_points<ConcurrencyTag>(points, part, dl, mesh) : 0;
        if (ms.points_put_back > 0) {
          ms.checks = check_mesh_given<ConcurrencyTag>(mesh, true); // (tents that cross were taken down)
          ms.point_distance = ms.checks.valid() ? largest_distance_to_mesh(points, mesh) : std::numeric_limits<double>::infinity();
        }
        ms.mesh_to_boundary_bound = ms.checks.valid() ? mesh_distance_bound(mesh, points, dl)
                                                      : std::numeric_limits<double>::infinity();
        // Plane by plane, the holes left are closed by fill_holes(): never over empty space. By
        // the advancing front, never from one lip of a slit in a plane to the other.
        across = ms.checks.valid() && geometry &&
                 (cd ? !no_face_over_empty_space(mesh, dl, free_at) || !no_face_over_hole(mesh, dl, level_cover())
                     : !no_face_joining_parts(mesh, dl, level_cover(), [&](const std::array<double, 3>& x) {
                         return Cd_filter(geometry).is_free_at(x);
                       }));
        ms.covering_distance = dl;
        ms.refinements = level.halvings;
        ms.crease_points = creases;
        // (one outer shell: one volume, nothing to split)
        split = ms.checks.valid() && ms.checks.shells - ms.checks.void_shells > 1 && splits_a_part(mesh, positions, part);
        passed = ms.checks.valid() && ms.checks.shells > 0 && !split && ms.point_distance < dl &&
                 ms.mesh_to_boundary_bound < dl && !across;
        // Last (they search segments): a void that the sum does not have (mesh_voids.h), two
        // sheets over one part of the boundary (mesh_second_sheet.h), a neck across free space
        // or a channel through the solid (mesh_necks.h), a handle the sum is not shown to have (mesh_short_handles.h).
        refuted = nullptr;
        std::vector<std::size_t> sheets; // (triangles of second sheets, in the order of faces(mesh))
        if (passed && geometry && ms.checks.void_shells > 0) {
          Cd_filter filter(geometry);
          Segment_search search(filter);
          if (has_false_void(mesh, search))
            refuted = "made a void that the sum does not have (a passage narrower than that d closed)";
        }
        if (passed && geometry && !refuted) {
          // The other three read the mesh as one shell: with threads, side by side (a filter
          // each; they are most of a passing level's checks and mostly run on one thread);
          // the first of them, in this order, that refutes it answers.
          const Shell shell = to_shell(mesh);
          std::array<bool, 3> refutes = {false, false, false};
          for_each_index(refutes.size(), pipeline.parallel, [&](std::size_t k) {
            if (!pipeline.parallel && std::count(refutes.begin(), refutes.end(), true) > 0) return;
            Cd_filter filter(geometry);
            Segment_search search(filter);
            if (k == 0) refutes[k] = !(sheets = second_sheet_triangles(shell, dl, search, pipeline.parallel, true)).empty();
            if (k == 1)
              refutes[k] = has_neck_or_channel(shell, dl, search, [&](const std::array<double, 3>& x) { return filter.is_free_at(x); },
                                               pipeline.parallel);
            if (k == 2) refutes[k] = has_false_short_handle(shell, dl, search, pipeline.parallel);
          });
          const char* const refusals[] = {
            "laid two sheets over one part of the boundary (a pocket between them: a handle the sum may not have)",
            "joined two parts of the boundary by a neck across free space, or cut a channel through the solid",
            "made a handle or a neck a few times that d round that the sum is not shown to have"};
          const auto first = std::find(refutes.begin(), refutes.end(), true);
          if (first != refutes.end()) refuted = refusals[first - refutes.begin()];
        }
        if (sheets.empty() || remeshed == 2) break;
        remesh(sheets);
      }
      ms.seconds_mesh += seconds_since(t_way); // (the checks included)
      if (passed && !refuted) {
        ms.vertices = vertices(mesh).size(); // num_vertices() may count removed elements
        ms.triangles = faces(mesh).size();
        ms.by_planes = way == 1;
        ms.refused = failures;
        return;
      }
      failures += std::string(failures.empty() ? "the reconstruction at d = " : "; at d = ") + std::to_string(dl) +
                  (creases                                  ? " with the crease points"
                   : level.strips == Strips::inside_corners ? " with every trim cell searched"
                   : level.again                            ? " without them"
                                                            : "") +
                  (way == 0 ? " by the advancing front " : " plane by plane ") +
                  (across ? (cd ? "closed a hole over empty space" : "laid a face across a slit, from one part of a plane to another")
                          : refuted ? refuted : level_failure(ms, split));
      clear(mesh); // a failed mesh is never left in `mesh`, whatever the next level throws
    }
  }
  throw Mesh_reconstruction_failed("no valid mesh of the sum's boundary could be made: " + failures +
                                   "; so none is returned");
}

} // namespace internal
} // namespace Pmsum

/// \ingroup PkgPointMinkowskiSumMesh
/// Computes a triangle mesh of the boundary of the Minkowski sum `P + Q` (or `-P + Q`): its
/// vertices are output points of point_minkowski_sum() (exactly on the boundary, rounded
/// only if the mesh's kernel is inexact), joined by CGAL's advancing-front surface
/// reconstruction. The mesh returned is closed, 2-manifold, free of self-intersections and
/// bounds a volume (outer shells outward, voids inward), it never splits a connected part of
/// the sum (the sum of a solid of `P` and a solid of `Q`, components that touch and a void with
/// its container counting as one solid: the output points of such a part all lie on one
/// outer shell and its voids), none of its voids opens onto another shell through free space
/// (an exact segment test from the void's vertices nearest to another shell: a passage
/// narrower than `d` that the reconstruction closed), no triangle faces against the faces of
/// the sum all three of its corners lie on (more than 100 degrees from each: a fold) where making
/// the mesh again round them (as below) removes it, no triangle lies inside the sum under a
/// vertex, or outside it over the vertex, facing its way, as a second sheet over that part of
/// the boundary (exact segment tests along the vertex's normal: a pocket between two sheets,
/// a handle the sum may not have; such a mesh is made again round them, twice at most, and
/// checked again), it joins no two parts of the boundary by a neck across free
/// space nor cuts a channel through the solid (exact segment tests from its triangles into it
/// and out of it: where one is wholly outside the sum, the triangles over free space there must
/// not make a ring; inside it, those under the solid), every handle of it narrower than about `d` is one the sum
/// has (where the mesh within `d/2` of a vertex along its edges is not a disk, a cycle of its
/// border must go round a tube of the sum: exact segment tests towards the tube's axis and
/// away from it), every output point
/// of the sum lies closer than `d'` to it and every point of it closer than `d'` to an output
/// point (`d'` the covering distance used): if the
/// reconstruction at `d` fails a check, the same points are triangulated plane by plane (the
/// planes of the sum's faces; `Mesh_statistics::by_planes`); if that fails too, the sum is
/// recomputed at `d/2`, then at `d/2` keeping every point on a sharp crease of the sum
/// (`Mesh_statistics::crease_points`), then `d/4`, then `d/4` with them again (after `d`, with more trim points: the edges of every face strip narrower
/// than d/2 followed to the strip's ends); if every one fails,
/// `CGAL::Pmsum::Mesh_reconstruction_failed` is thrown and `mesh` is left empty.
///
/// Proved: every point of the exact boundary is closer than `d' + e` to the mesh, `e` the
/// largest distance from an output point to the mesh (`Mesh_statistics::point_distance`,
/// below `d'`; 0 when every point is a vertex), since the points cover the boundary
/// within `d'`; and every point of the mesh is closer than `Mesh_statistics::mesh_to_boundary_bound`
/// (below `d'`) to an output point, hence to the exact boundary (a mesh for which that bound
/// cannot be shown below `d'` is refused like one failing a check). Measured, not proved: the
/// actual distances both ways (usually well below the bounds), and the mesh's shells against the
/// exact boundary's (`pmsum validate --mesh`, `benchmark/mesh/results/results.md`).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
/// \tparam PolygonMeshP, PolygonMeshQ models of `FaceListGraph`
/// \tparam TriangleMesh a model of `MutableFaceGraph` whose point type is constructible from
///         the points of P's geometric traits (e.g. `Surface_mesh<GeomTraits::Point_3>`)
/// \tparam NamedParametersP, NamedParametersQ named parameter packs
/// \param P the first mesh
/// \param Q the second mesh
/// \param d covering distance of the vertices
/// \param mesh the output (cleared first)
/// \param np_p as for point_minkowski_sum(), and `mesh_statistics` (a
///        `CGAL::Pmsum::Mesh_statistics&` to fill); `use_covering_net` is not allowed, and
///        `use_trim_points` and `search_islands` must be true (the mesh needs the covering)
/// \param np_q as for point_minkowski_sum()
/// \pre the preconditions of point_minkowski_sum(), and `use_trim_points` and `search_islands`
///      not false; violations throw `CGAL::Pmsum::Invalid_input`
/// \throws CGAL::Pmsum::Mesh_reconstruction_failed if no valid mesh was made
template <class ConcurrencyTag = CGAL::Sequential_tag, class PolygonMeshP, class PolygonMeshQ, class TriangleMesh,
          class NamedParametersP = parameters::Default_named_parameters,
          class NamedParametersQ = parameters::Default_named_parameters>
void point_minkowski_sum_mesh(const PolygonMeshP& P, const PolygonMeshQ& Q, double d, TriangleMesh& mesh,
                              const NamedParametersP& np_p = parameters::default_values(),
                              const NamedParametersQ& np_q = parameters::default_values())
{
  namespace in = Pmsum::internal;
  Pmsum::Mesh_statistics local;
  Pmsum::Mesh_statistics& ms = in::start_mesh(np_p, mesh, local, "point_minkowski_sum_mesh()");
  // One input stage and one pipeline for every level: a refinement reuses the coarser
  // level's decisions (coarse to fine, as point_minkowski_sum_coarse_to_fine()).
  const auto t_input = in::Clock::now();
  Pmsum::Statistics local_stats;
  const in::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(P, Q, d, np_p, np_q,
                                                                                            local_stats);
  in::Pipeline<ConcurrencyTag> pipeline(sum.mp, sum.mq, sum.options, /*coarse_to_fine=*/true);
  ms.seconds_sum += in::seconds_since(t_input);
  in::mesh_levels<typename decltype(sum)::GT>(pipeline, sum.mp, sum.mq, d, sum.stats, sum.start, mesh, ms);
}

} // namespace CGAL

#endif // CGAL_PMSUM_POINT_MINKOWSKI_SUM_MESH_H
