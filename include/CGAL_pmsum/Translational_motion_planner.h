// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Translational_motion_planner: paths of a robot P translating among fixed
// obstacles Q (paper section 9.2), from points covering the contact space C = boundary of
// (-P) + Q.
//
// Free space. P + t meets Q iff t is in (-P) + Q. A path is free when it never enters the
// interior of (-P) + Q: it stays in the regular free space, the closure of the translations
// where P + t and Q are disjoint. Contact is allowed: the robot may touch and slide along
// the obstacles (the tightly fitted robot of the paper's Fig. 12(b)). Every such path keeps
// the interiors of P + t and Q disjoint. (The converse fails only where the free space has
// no interior: a zero-clearance fit, where the robot can only slide along a line, is not on
// the boundary of (-P) + Q, has no contact point, and is not found.)
//
// Method. The roadmap's nodes are the contact points of the core (every one exactly on C,
// together a d-covering of C; each is moved to the nearest doubles on its free side and
// rechecked exactly), its edges join each node to its k nearest nodes (CGAL Kd_tree). A
// query joins start and goal to their nearest nodes and searches the roadmap lazily (Bohlin
// and Kavraki's Lazy PRM): A* finds the shortest path in the roadmap, its unchecked edges are
// checked, invalid ones removed, until a path of checked edges is found or start and goal are
// disconnected. The result is the same as checking every edge first. The path is then
// shortened by exact shortcuts.
//
// Local paths are straight segments, checked exactly (internal/swept_cd.h): the robot swept
// along the segment and moved off the contact by an infinitesimal translation (the sum of
// the free directions of the two ends) must miss Q. No sampling of the segment, no
// tolerance: every segment of a returned path is free for all its points.
//
// What is guaranteed. Soundness: a returned path is free (above). Completeness: none in
// general, and none relative to d either. The contact points cover C within d, so every
// part of the free space's boundary wider than about d has nodes; a passage whose boundary
// has nodes (the tested peg-in-hole and slot problems, with a gap smaller than d) is found
// when the k-nearest-neighbour edges along it are free. Two parts of the boundary farther
// apart than the k-th neighbour and joined only through open space can make the roadmap miss a
// path: the planner then reports that no path was found, which does not prove that none
// exists. (The paper's star-shaped decomposition has the same limits.)

#ifndef CGAL_PMSUM_TRANSLATIONAL_MOTION_PLANNER_H
#define CGAL_PMSUM_TRANSLATIONAL_MOTION_PLANNER_H

#include <CGAL_pmsum/point_minkowski_sum.h>
#include <CGAL_pmsum/internal/swept_cd.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <queue>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumPlanner
/// Counters and seconds of a planner (make) and of its last query (plan).
struct Planner_statistics
{
  std::size_t contact_points = 0;   ///< points of the contact space (the core's output)
  std::size_t nodes = 0;            ///< distinct contact points in the roadmap
  std::size_t roadmap_edges = 0;    ///< k-nearest-neighbour edges (unchecked until needed)
  std::size_t nodes_checked = 0;    ///< nodes whose free direction was computed (exact point tests)
  std::size_t nodes_rejected = 0;   ///< of those, not free after rounding to doubles
  std::size_t edges_checked = 0;    ///< exact segment tests of roadmap edges
  std::size_t edges_invalid = 0;    ///< of those, colliding
  std::size_t search_iterations = 0;///< A* searches of the last query
  std::size_t shortcut_tests = 0;   ///< exact segment tests of the path shortening
  double seconds_contact_space = 0; ///< the core (point-based sum)
  double seconds_roadmap = 0;       ///< kd-tree and neighbour edges
  double seconds_query = 0;         ///< last plan()
};

} // namespace Pmsum

/// \ingroup PkgPointMinkowskiSumPlanner
/// Paths of a robot `P` translating among fixed obstacles `Q`, on a roadmap over points
/// covering the contact space, the boundary of `-P + Q`. Sound: every segment of a returned
/// path is free, checked exactly; not complete (see the file comment). Made by make().
///
/// \tparam PolygonMeshP, PolygonMeshQ models of `FaceListGraph`
template <class PolygonMeshP, class PolygonMeshQ>
class Translational_motion_planner
{
public:
  /// the kernel of the queries and answers
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  /// a translation of the robot
  using Point_3 = Kernel::Point_3;

  /// The answer to plan().
  struct Result
  {
    bool found = false;          ///< false: start and goal are not connected in the roadmap
    std::vector<Point_3> path;   ///< translations of P, start first, goal last; each segment free
    double length = 0;           ///< Euclidean length of the path
  };

  /// Computes the contact space of robot `P` (moving) and obstacles `Q` (fixed) with
  /// covering distance `d` and the roadmap joining each contact point to its nearest ones.
  ///
  /// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (for the contact space)
  /// \param P the robot
  /// \param Q the obstacles
  /// \param d covering distance of the contact points
  /// \param np_p named parameters of `P` and of the algorithm: those of point_minkowski_sum()
  ///        (`statistics` receives the contact space's; `negate_first_mesh` is implied) and
  ///        `roadmap_neighbors` (12: the number of nearest nodes each node is joined to)
  /// \param np_q named parameters of `Q` (`vertex_point_map`)
  /// \returns the planner, ready for queries
  /// \pre `d > 0`, `roadmap_neighbors >= 1`; `P` and `Q` as for point_minkowski_sum().
  ///      Violations throw `CGAL::Pmsum::Invalid_input`.
  template <class ConcurrencyTag = CGAL::Sequential_tag, class NamedParametersP = parameters::Default_named_parameters,
            class NamedParametersQ = parameters::Default_named_parameters>
  static Translational_motion_planner make(const PolygonMeshP& P, const PolygonMeshQ& Q, double d,
                                           const NamedParametersP& np_p = parameters::default_values(),
                                           const NamedParametersQ& np_q = parameters::default_values())
  {
    namespace in = Pmsum::internal;
    static_assert(!in::has_any_parameter<NamedParametersP, Pmsum::internal_np::negate_first_mesh_t,
                                         Pmsum::internal_np::mesh_statistics_t>(),
                  "CGAL_pmsum: Translational_motion_planner implies negate_first_mesh and takes no mesh_statistics");
    const unsigned k = parameters::choose_parameter(parameters::get_parameter(np_p, Pmsum::internal_np::roadmap_neighbors), 12u);
    CGAL_precondition_msg(k >= 1, "roadmap_neighbors must be at least 1");
    if (k < 1) throw Pmsum::Invalid_input("roadmap_neighbors (neighbours per node) must be at least 1");
    Pmsum::Statistics local_stats;
    in::Prepared_sum<PolygonMeshP, PolygonMeshQ, NamedParametersP, NamedParametersQ> sum(
      P, Q, d, np_p, np_q, local_stats, in::Negation::always);
    in::Mesh_descriptors<PolygonMeshP> desc_p;
    Translational_motion_planner pl(d, k, in::read_mesh(P, np_p, false, sum.check_overlaps, "P", desc_p, sum.merge_flat_regions),
                                    std::move(sum.mp), std::move(sum.mq));
    std::vector<std::pair<Point, Point>> contacts; // point, outward direction
    // The default net, plus every vertex + vertex contact: the corners of a passage, where a
    // path turns, are such points, and a net may cover them from a node that sees no corner.
    sum.options.keep_vertex_sums = true;
    using Exact = CGAL::Simple_cartesian<CGAL::Exact_rational>; // rounded once, to the nearest doubles
    const in::Mesh_data &minus_p = *pl.m_minus_p, &q = *pl.m_q;
    in::run_pipeline<ConcurrencyTag>(
      minus_p, q, d, sum.options, sum.stats,
      [&](const in::Sample& sp, const in::Sample& sq, const in::Direction& dir, const in::Trim* trim) {
        const auto x = in::output_point<Exact>(minus_p, q, sp, sq, trim);
        const auto n = in::output_normal<Kernel>(minus_p, q, dir);
        contacts.emplace_back(Point{CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())},
                              Point{n.x(), n.y(), n.z()});
      },
      sum.start);
    pl.m_stats.contact_points = contacts.size();
    pl.m_stats.seconds_contact_space = in::seconds_since(sum.start);
    pl.build_roadmap(std::move(contacts));
    return pl;
  }

  /// \returns the counters and seconds of make() and of the last plan()
  const Pmsum::Planner_statistics& statistics() const { return m_stats; }
  /// \returns the covering distance `d` given to make()
  double covering_distance() const { return m_d; }
  /// \returns the number of roadmap nodes
  std::size_t number_of_nodes() const { return m_nodes.size(); }
  /// The roadmap's nodes (contact configurations, rounded to double on their free side).
  /// \returns a copy of the nodes
  std::vector<Point_3> nodes() const
  {
    std::vector<Point_3> r;
    for (const Node& n : m_nodes) r.emplace_back(n.p[0], n.p[1], n.p[2]);
    return r;
  }

  /// Exact: is the translation t in the regular free space, i.e. is some infinitesimal move
  /// of t strictly free? (Not thread-safe: one planner per thread.)
  /// \param t a translation of the robot
  /// \returns whether `t` is in the regular free space
  bool is_free(const Point_3& t) { Point v; return free_direction(to_point(t), v, nullptr); }

  /// Exact: is every translation of the segment [a, b] in the regular free space? Tested as
  /// the robot swept along it, moved by an infinitesimal translation along the free
  /// directions of a and b. (False if a or b is not free.)
  /// \param a, b the segment's ends
  /// \returns whether the whole segment is in the regular free space
  bool is_free(const Point_3& a, const Point_3& b)
  {
    const Point pa = to_point(a), pb = to_point(b);
    Point va, vb;
    if (!free_direction(pa, va, nullptr) || !free_direction(pb, vb, nullptr)) return false;
    const Index n = Index(m_nodes.size());
    m_nodes.push_back(Node{pa, {0, 0, 0}, va, Node::FREE, free_candidate_mask(pa, nullptr)});
    m_nodes.push_back(Node{pb, {0, 0, 0}, vb, Node::FREE, free_candidate_mask(pb, nullptr)});
    const bool ok = nodes_joined(n, n + 1);
    m_nodes.resize(n);
    return ok;
  }

  /// A free polyline from `start` to `goal` (translations of P), or found == false.
  /// Not thread-safe (edge checks are cached in the planner).
  /// \param start, goal translations of the robot
  /// \returns the path (`found`, `path`, `length`)
  /// \pre start and goal are finite and free; violations throw `CGAL::Pmsum::Invalid_input`
  Result plan(const Point_3& start, const Point_3& goal)
  {
    const auto t0 = Pmsum::internal::Clock::now();
    m_stats.search_iterations = 0;
    m_stats.shortcut_tests = 0;
    Result result;
    const Point s = to_point(start), g = to_point(goal);
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(s[c]) || !std::isfinite(g[c])) throw Pmsum::Invalid_input("start and goal must be finite");
    Point vs, vg;
    if (!free_direction(s, vs, nullptr))
      throw Pmsum::Invalid_input("the start configuration is not free: the robot overlaps the obstacle there");
    if (!free_direction(g, vg, nullptr))
      throw Pmsum::Invalid_input("the goal configuration is not free: the robot overlaps the obstacle there");

    // Start and goal as temporary nodes n and n + 1, with edges to their nearest nodes.
    const Index n = Index(m_nodes.size());
    m_nodes.push_back(Node{s, {0, 0, 0}, vs, Node::FREE, free_candidate_mask(s, nullptr)});
    m_nodes.push_back(Node{g, {0, 0, 0}, vg, Node::FREE, free_candidate_mask(g, nullptr)});
    const std::size_t base_edges = m_edges.size();
    std::vector<std::vector<Index>> extra(m_nodes.size());
    auto add_extra = [&](Index a, Index b) {
      extra[a].push_back(Index(m_edges.size()));
      extra[b].push_back(Index(m_edges.size()));
      m_edges.push_back(Edge{a, b, distance(m_nodes[a].p, m_nodes[b].p), Edge::UNKNOWN});
    };
    add_extra(n, n + 1);
    for (Index e : {n, n + 1})
      if (m_tree)
        for (Index j : nearest(m_nodes[e].p, 2 * m_k)) add_extra(e, j);

    std::vector<Index> path;
    for (;;) {
      ++m_stats.search_iterations;
      path = a_star(n, n + 1, extra);
      if (path.empty()) break;
      bool all_valid = true;
      for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        Edge& e = m_edges[edge_between(path[i], path[i + 1], extra)];
        if (e.state == Edge::UNKNOWN) check_edge(e);
        if (e.state == Edge::INVALID) all_valid = false;
      }
      if (all_valid) break;
    }
    if (!path.empty()) {
      shortcut(path);
      result.found = true;
      for (Index i : path) result.path.emplace_back(m_nodes[i].p[0], m_nodes[i].p[1], m_nodes[i].p[2]);
      for (std::size_t i = 0; i + 1 < path.size(); ++i) result.length += distance(m_nodes[path[i]].p, m_nodes[path[i + 1]].p);
    }
    m_nodes.resize(n);
    m_edges.resize(base_edges);
    m_stats.seconds_query = Pmsum::internal::seconds_since(t0);
    return result;
  }

private:
  using Index = Pmsum::internal::Index;
  using Point = std::array<double, 3>;

  struct Node
  {
    enum State : std::uint8_t { UNKNOWN, FREE, REJECTED };
    Point p;       // translation
    Point n;       // outward direction of the contact (unit), or 0
    Point v;       // free direction, once checked
    State state;
    std::uint64_t free_candidates = 0; // which of candidates(n) are free directions (bit i)
  };
  struct Edge
  {
    enum State : std::uint8_t { UNKNOWN, VALID, INVALID };
    Index a, b;
    double length;
    State state;
  };

  Translational_motion_planner(double d, unsigned k, Pmsum::internal::Mesh_data p, Pmsum::internal::Mesh_data minus_p,
                               Pmsum::internal::Mesh_data q)
    : m_d(d), m_k(k), m_p(std::make_shared<Pmsum::internal::Mesh_data>(std::move(p))),
      m_minus_p(std::make_shared<Pmsum::internal::Mesh_data>(std::move(minus_p))),
      m_q(std::make_shared<Pmsum::internal::Mesh_data>(std::move(q)))
  {
    m_swept = std::make_shared<Pmsum::internal::Swept_cd>(*m_p, *m_q);
  }

  static Point unit(const Point& v)
  {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return l > 0 ? Point{v[0] / l, v[1] / l, v[2] / l} : Point{0, 0, 0};
  }
  static Point to_point(const Point_3& p) { return {p.x(), p.y(), p.z()}; }
  static double distance(const Point& a, const Point& b)
  { return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2])); }

  // ----- roadmap -----------------------------------------------------------------------
  using Traits = CGAL::Search_traits_adapter<Index, CGAL::Pointer_property_map<Point_3>::type,
                                             CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = typename Search::Tree;

  std::vector<Index> nearest(const Point& p, unsigned k) const
  {
    std::vector<Index> r;
    Search search(*m_tree, Point_3(p[0], p[1], p[2]), k, 0, true,
                  typename Search::Distance(CGAL::make_property_map(*m_tree_points)));
    for (const auto& it : search) r.push_back(it.first);
    return r;
  }

  void build_roadmap(std::vector<std::pair<Point, Point>> contacts)
  {
    const auto t0 = Pmsum::internal::Clock::now();
    // Distinct points (pairs of features may give the same sum): keep the first direction.
    std::stable_sort(contacts.begin(), contacts.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t i = 0; i < contacts.size(); ++i)
      if (i == 0 || contacts[i].first != contacts[i - 1].first)
        m_nodes.push_back(Node{contacts[i].first, contacts[i].second, {0, 0, 0}, Node::UNKNOWN, 0});
    m_stats.nodes = m_nodes.size();
    for (const Node& nd : m_nodes) m_tree_points->emplace_back(nd.p[0], nd.p[1], nd.p[2]);
    if (!m_nodes.empty()) {
      std::vector<Index> ids(m_nodes.size());
      for (Index i = 0; i < ids.size(); ++i) ids[i] = i;
      m_tree = std::make_shared<Tree>(ids.begin(), ids.end(), typename Tree::Splitter(),
                                      Traits(CGAL::make_property_map(*m_tree_points)));
      m_tree->build();
    }
    std::vector<std::pair<Index, Index>> pairs;
    // The k nearest, and all (up to 4k) within 2d: the contact points are a d-covering, so
    // nodes whose covered regions meet are at most 2d apart. A passage's few nodes are then
    // joined to the nodes around its mouth.
    for (Index i = 0; i < m_nodes.size(); ++i) {
      const std::vector<Index> near = nearest(m_nodes[i].p, 4 * m_k + 1);
      for (std::size_t r = 0; r < near.size(); ++r) {
        const Index j = near[r];
        if (j == i || (r > m_k && distance(m_nodes[i].p, m_nodes[j].p) > 2 * m_d)) continue;
        pairs.emplace_back((std::min)(i, j), (std::max)(i, j));
      }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    m_adjacency.assign(m_nodes.size(), {});
    for (const auto& [a, b] : pairs) {
      m_adjacency[a].push_back(Index(m_edges.size()));
      m_adjacency[b].push_back(Index(m_edges.size()));
      m_edges.push_back(Edge{a, b, distance(m_nodes[a].p, m_nodes[b].p), Edge::UNKNOWN});
    }
    m_stats.roadmap_edges = m_edges.size();
    m_stats.seconds_roadmap = Pmsum::internal::seconds_since(t0);
  }

  // ----- exact checks ------------------------------------------------------------------
  /// Finds a direction v such that t + e v (e infinitesimal) is strictly free whatever the
  /// next-order terms (tested with the 8 sign patterns of the axes after v): v is then
  /// inside the cone of free directions at t. Candidates: 0 (t strictly free), then
  /// n + m/2 for the contact's direction n and m in 0, the axes and their sums, then the
  /// same without n.
  static std::vector<Point> candidates(const Point* n)
  {
    std::vector<Point> c;
    if (n) {
      c.push_back(*n);
      for (int m = 0; m < 27; ++m)
        if (m != 13)
          c.push_back({(*n)[0] + 0.5 * (m % 3 - 1), (*n)[1] + 0.5 * ((m / 3) % 3 - 1), (*n)[2] + 0.5 * (m / 9 - 1)});
    }
    c.push_back({0, 0, 0}); // t strictly free
    for (int m = 0; m < 27; ++m)
      if (m != 13) c.push_back({double(m % 3) - 1, double((m / 3) % 3) - 1, double(m / 9) - 1});
    return c;
  }

  /// Is w inside the cone of free directions at t? True iff t + e w + e^2 (+-x) + e^3 (+-y)
  /// + e^4 (+-z) is strictly free for the 8 sign patterns (if w were on the cone's boundary,
  /// one of them would go out).
  bool interior(const Point& t, const Point& w)
  {
    for (int s = 0; s < 8; ++s) {
      const std::vector<Point> chain = {w, {s & 1 ? -1. : 1., 0, 0}, {0, s & 2 ? -1. : 1., 0}, {0, 0, s & 4 ? -1. : 1.}};
      if (!m_swept->is_free(t, t, chain)) return false;
    }
    return true;
  }

  /// Bit i: candidates(n)[i] is inside the free cone at t.
  std::uint64_t free_candidate_mask(const Point& t, const Point* n)
  {
    const std::vector<Point> c = candidates(n);
    std::uint64_t mask = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (m_swept->is_free(t, t, {c[i]}) && interior(t, c[i])) mask |= std::uint64_t(1) << i;
    return mask;
  }

  /// Finds a direction v inside the cone of free directions at t: the first of
  /// candidates(n) (the contact's direction n, n + m/2 for m in the axes and their sums,
  /// 0 (strictly free), then the axes and their sums).
  bool free_direction(const Point& t, Point& v, const Point* n)
  {
    const std::vector<Point> c = candidates(n);
    for (const Point& w : c)
      if (m_swept->is_free(t, t, {w}) && interior(t, w)) { v = w; return true; }
    return false;
  }

  /// The free direction at node i that points most toward `toward` (unit candidates).
  Point best_direction(Index i, const Point& toward) const
  {
    const Node& nd = m_nodes[i];
    const bool contact = nd.n != Point{0, 0, 0};
    const std::vector<Point> c = candidates(contact ? &nd.n : nullptr);
    Point best = nd.v;
    double best_dot = -HUGE_VAL;
    for (std::size_t k = 0; k < c.size(); ++k) {
      if (!((nd.free_candidates >> k) & 1)) continue;
      const Point u = unit(c[k]);
      const double dt = u[0] * toward[0] + u[1] * toward[1] + u[2] * toward[2];
      if (dt > best_dot) { best_dot = dt; best = c[k]; }
    }
    return best;
  }

  bool prepare_node(Index i)
  {
    Node& nd = m_nodes[i];
    if (nd.state != Node::UNKNOWN) return nd.state == Node::FREE;
    ++m_stats.nodes_checked;
    // The contact point was rounded to doubles: if that put it inside, step it outward.
    for (int step = 0; step < 4; ++step) {
      if (free_direction(nd.p, nd.v, &nd.n)) {
        nd.state = Node::FREE;
        nd.free_candidates = free_candidate_mask(nd.p, &nd.n);
        return true;
      }
      for (int c = 0; c < 3; ++c)
        if (nd.n[c] != 0) nd.p[c] = std::nextafter(nd.p[c], nd.n[c] > 0 ? HUGE_VAL : -HUGE_VAL);
    }
    nd.state = Node::REJECTED;
    ++m_stats.nodes_rejected;
    return false;
  }

  bool segment_free(const Point& a, const Point& va, const Point& b, const Point& vb)
  {
    const Point sum = {va[0] + vb[0], va[1] + vb[1], va[2] + vb[2]};
    return m_swept->is_free(a, b, {sum, va, vb});
  }

  /// Exact test of the segment between two free nodes: first with each end pushed along
  /// its free direction closest to the segment (so that a segment leaving a corner into a
  /// passage is pushed into the passage), then with their default free directions.
  bool nodes_joined(Index a, Index b)
  {
    const Node &na = m_nodes[a], &nb = m_nodes[b];
    const Point ab = unit({nb.p[0] - na.p[0], nb.p[1] - na.p[1], nb.p[2] - na.p[2]});
    const Point wa = best_direction(a, ab), wb = best_direction(b, {-ab[0], -ab[1], -ab[2]});
    if (segment_free(na.p, wa, nb.p, wb)) return true;
    return (wa != na.v || wb != nb.v) && segment_free(na.p, na.v, nb.p, nb.v);
  }

  void check_edge(Edge& e)
  {
    ++m_stats.edges_checked;
    const bool ok = prepare_node(e.a) && prepare_node(e.b) && nodes_joined(e.a, e.b);
    e.state = ok ? Edge::VALID : Edge::INVALID;
    if (!ok) ++m_stats.edges_invalid;
  }

  // ----- search ------------------------------------------------------------------------
  template <class F>
  void for_each_edge(Index u, const std::vector<std::vector<Index>>& extra, const F& f) const
  {
    if (u < m_adjacency.size())
      for (Index e : m_adjacency[u]) f(e);
    for (Index e : extra[u]) f(e);
  }

  Index edge_between(Index u, Index v, const std::vector<std::vector<Index>>& extra) const
  {
    Index best = Pmsum::internal::no_index;
    for_each_edge(u, extra, [&](Index e) {
      const Edge& ed = m_edges[e];
      if (((ed.a == u && ed.b == v) || (ed.a == v && ed.b == u)) && best == Pmsum::internal::no_index) best = e;
    });
    return best;
  }

  /// Shortest path from s to g over edges not known invalid (A*, Euclidean heuristic).
  std::vector<Index> a_star(Index s, Index g, const std::vector<std::vector<Index>>& extra) const
  {
    const std::size_t N = m_nodes.size();
    std::vector<double> cost(N, std::numeric_limits<double>::infinity());
    std::vector<Index> from(N, Pmsum::internal::no_index);
    std::vector<char> closed(N, 0);
    using Entry = std::pair<double, Index>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    cost[s] = 0;
    open.push({distance(m_nodes[s].p, m_nodes[g].p), s});
    while (!open.empty()) {
      const Index u = open.top().second;
      open.pop();
      if (closed[u]) continue;
      closed[u] = 1;
      if (u == g) break;
      for_each_edge(u, extra, [&](Index e) {
        const Edge& ed = m_edges[e];
        if (ed.state == Edge::INVALID) return;
        const Index w = ed.a == u ? ed.b : ed.a;
        if (closed[w] || m_nodes[w].state == Node::REJECTED) return;
        const double c = cost[u] + ed.length;
        if (c < cost[w]) {
          cost[w] = c;
          from[w] = u;
          open.push({c + distance(m_nodes[w].p, m_nodes[g].p), w});
        }
      });
    }
    std::vector<Index> path;
    if (!closed[g]) return path;
    for (Index u = g; u != Pmsum::internal::no_index; u = from[u]) path.push_back(u);
    std::reverse(path.begin(), path.end());
    return path;
  }

  /// Replaces runs of the path by single segments when they are free (exact test), trying
  /// the farthest vertex first, then halving the jump.
  void shortcut(std::vector<Index>& path)
  {
    std::vector<Index> out = {path.front()};
    std::size_t i = 0;
    while (i + 1 < path.size()) {
      std::size_t next = i + 1;
      for (std::size_t jump = path.size() - 1 - i; jump >= 2; jump /= 2) {
        ++m_stats.shortcut_tests;
        if (nodes_joined(path[i], path[i + jump])) { next = i + jump; break; }
      }
      out.push_back(path[next]);
      i = next;
    }
    path = std::move(out);
  }

  double m_d;
  unsigned m_k;
  std::shared_ptr<Pmsum::internal::Mesh_data> m_p, m_minus_p, m_q;
  std::shared_ptr<Pmsum::internal::Swept_cd> m_swept;
  std::vector<Node> m_nodes;
  std::vector<Edge> m_edges;
  std::vector<std::vector<Index>> m_adjacency;
  std::shared_ptr<std::vector<Point_3>> m_tree_points = std::make_shared<std::vector<Point_3>>();
  std::shared_ptr<Tree> m_tree;
  Pmsum::Planner_statistics m_stats;
};

} // namespace CGAL

#endif // CGAL_PMSUM_TRANSLATIONAL_MOTION_PLANNER_H
