// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3 of the pipeline: the collision-detection filter (paper sections 4 and 8), exact.
//
// A candidate x = p + q is a boundary point of P + Q iff the translate t = x + (infinitesimal
// outward perturbation) is outside P + Q, i.e. iff (-P + t) and Q are disjoint. We decide
// that for t = x + e n_1 + e^2 n_2 + ... + e^(k) n_k with e > 0 infinitesimal, where n_1 is
// the candidate's outward direction, n_2.. its other directions, and the chain ends with the
// three axes. Every predicate is an orientation determinant affine in t (design note
// shared/design/exact-contact.md), so its sign is the sign of the first non-zero term of
// (D(x), g.n_1, g.n_2, ...), computed exactly (interval filter, then CGAL::Mpzf). Since the
// chain spans R^3, no evaluated predicate is zero: the configuration is generic and
//   disjoint  <=>  no edge of one mesh crosses a triangle of the other, and no connected
//                  component of one mesh lies inside a closed component of the other.
// The first condition is tested pair by pair (triangle-triangle, bare edge-triangle), by a
// simultaneous traversal of two bounding-volume hierarchies (bvh.h): one of the mesh with
// more triangles ("static", not translated), one of the other ("moving", reflected; its
// boxes translated by the interval of x and rounded outward). Only pairs whose boxes
// overlap are tested exactly; the last crossing found is tried first. The second is a
// ray-parity point-in-solid test from one vertex of each component, with a CGAL AABB tree.
// Meshes with borders bound no volume: only their surface counts.
//
// Scaling: x has denominator S = den_p den_q. Exact evaluations multiply every position by S
// (signs of homogeneous determinants do not change), so that all values are sums of
// products of doubles and integers, which CGAL::Mpzf represents exactly.

#ifndef CGAL_PMSUM_INTERNAL_CD_FILTER_H
#define CGAL_PMSUM_INTERNAL_CD_FILTER_H

#include <CGAL_pmsum/internal/convex_patches.h>
#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/perturbed_predicates.h>

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <initializer_list>
#include <tuple>
#include <unordered_map>
#include <memory>
#include <optional>
#include <stdexcept>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// A point base + shift * t of a CD predicate: base in double coordinates, t the translation.
struct Moving_point
{
  const std::array<double, 3>* base;
  int shift; // -1, 0 or +1
};

/// A translation X / W, exactly (W > 0).
struct Exact_point
{
  Vec3<Exact_nt> X;
  Exact_nt W;
};

/// The translation p + q of a sample of P and a sample of Q, exactly: X = S (p + q) and
/// W = S, S the product of the samples' denominators.
inline Exact_point exact_sum(const Mesh_data& P, const Sample& p, const Mesh_data& Q, const Sample& q)
{
  auto part = [](const Mesh_data& M, const Sample& s, std::int64_t other_den) {
    Vec3<Exact_nt> r = {Exact_nt(0), Exact_nt(0), Exact_nt(0)};
    for (int i = 0; i < 3; ++i)
      if (s.weights[i] != 0) r = r + scaled(M.point<Exact_nt>(s.vertices[i]), Exact_nt(long(s.weights[i] * other_den)));
    return r;
  };
  return {part(P, p, q.denominator) + part(Q, q, p.denominator),
          Exact_nt(long(std::int64_t(p.denominator) * q.denominator))};
}

/// Samples of P and Q whose affine hulls' sum (of a point of each) holds a translation, as
/// far as known (none: nothing known). See Cd_filter::zero_by_construction().
using Spans = boost::container::static_vector<const std::pair<Sample, Sample>*, 3>;

/// The points of an orientation predicate.
using Predicate_points = std::array<Moving_point, 4>;

/// What is known of a translation x that makes orientation predicates zero at x
/// (Cd_filter::zero_by_construction()).
struct Known_zeros
{
  Spans spans;                                 // of x (none: nothing known)
  const Predicate_points* predicate = nullptr; // one zero at x (e.g. x is its root on a segment)
};

/// Is w the zero vector?
inline bool is_null(const Vec3<Exact_nt>& w) { return CGAL::is_zero(w[0]) && CGAL::is_zero(w[1]) && CGAL::is_zero(w[2]); }

/// Interval enclosure of X / W.
inline Vec3<Interval> enclosure(const Exact_point& x)
{
  CGAL::Protect_FPU_rounding<true> guard;
  const Interval w = CGAL::to_interval(x.W);
  return {Interval(CGAL::to_interval(x.X[0])) / w, Interval(CGAL::to_interval(x.X[1])) / w,
          Interval(CGAL::to_interval(x.X[2])) / w};
}

/// The smallest box holding the boxes a and b.
inline Vec3<Interval> hull(const Vec3<Interval>& a, const Vec3<Interval>& b)
{
  Vec3<Interval> h;
  for (int c = 0; c < 3; ++c) h[c] = Interval((std::min)(a[c].inf(), b[c].inf()), (std::max)(a[c].sup(), b[c].sup()));
  return h;
}

/// The orientation predicate of four moving points is affine in the translation t:
/// det[b - a, c - a, d - a] = D(0) + g.t. Its gradient g = (sb - sa) u2 x u3 +
/// (sc - sa) u3 x u1 + (sd - sa) u1 x u2, with u1 = b - a, u2 = c - a, u3 = d - a at t = 0.
template <class NT>
Vec3<NT> gradient(const Moving_point& a, const Moving_point& b, const Moving_point& c, const Moving_point& d)
{
  return orientation_gradient<NT>({to_nt<NT>(*a.base), to_nt<NT>(*b.base), to_nt<NT>(*c.base), to_nt<NT>(*d.base)},
                                  {a.shift, b.shift, c.shift, d.shift});
}

/// D(0) of the same predicate: the orientation of the four base points.
template <class NT>
NT value_at_origin(const Moving_point& a, const Moving_point& b, const Moving_point& c, const Moving_point& d)
{
  const Vec3<NT> pa = to_nt<NT>(*a.base);
  return dot(to_nt<NT>(*d.base) - pa, cross(to_nt<NT>(*b.base) - pa, to_nt<NT>(*c.base) - pa));
}

/// D(0) and g of the same predicate, exactly: D(X / W) has the sign of W d0 + g.X.
struct Affine_predicate
{
  Exact_nt d0;
  Vec3<Exact_nt> g;
};

/// The key of the item pair (u, v) (u of the moving mesh, v of the static one) in the
/// caches of a pair's facts.
inline std::uint64_t pair_key(Index u, Index v) { return std::uint64_t(u) << 32 | v; }

/// A fact of each key met, computed once: at most max_facts facts are kept; then the cache
/// starts again (a reference it returned is valid until the next get() or clear()).
template <class Key, class T, class Hash = std::hash<Key>>
class Fact_cache
{
public:
  static constexpr std::size_t max_facts = std::size_t(1) << 14;
  /// The fact of `key`: compute(), the first time.
  template <class F>
  const T& get(const Key& key, const F& compute)
  {
    auto it = m_facts.find(key);
    if (it != m_facts.end()) return it->second;
    if (m_facts.size() >= max_facts) m_facts.clear();
    return m_facts.emplace(key, compute()).first->second;
  }
  void clear() { m_facts.clear(); }

private:
  std::unordered_map<Key, T, Hash> m_facts;
};

/// A fact of each item pair (u, v) met, under the key pair_key(u, v).
template <class T>
class Pair_cache : public Fact_cache<std::uint64_t, T>
{
public:
  template <class F>
  const T& get(Index u, Index v, const F& compute) { return Fact_cache<std::uint64_t, T>::get(pair_key(u, v), compute); }
};

/// The key of an orientation predicate of four vertices of the meshes, in its order: each
/// point's vertex, mesh (moving or static) and shift.
using Predicate_key = std::array<std::uint64_t, 2>;
struct Predicate_key_hash
{
  std::size_t operator()(const Predicate_key& k) const
  { return std::hash<std::uint64_t>()(k[0] * 0x9E3779B97F4A7C15ull ^ k[1]); }
};

/// What intervals tell of where an item pair crosses along a segment of translations
/// x(l) = a + l (b - a), l in [0, 1]: never at l < low or l > high; at every l with
/// in_from < l < in_to (any perturbation). Elsewhere: unknown (test it).
struct Crossing_range
{
  double low = -HUGE_VAL, in_from = HUGE_VAL, in_to = -HUGE_VAL, high = HUGE_VAL;
  bool misses_segment() const { return low > 1 || high < 0 || low > high; }
  bool covers_segment() const { return in_from < 0 && in_to > 1; }
};

/// The slabs lo < w.t < hi (enclosures) whose intersection is the set of translations t at
/// which two triangles cross (B - A, open): where(T) tells, from intervals, where a triangle
/// T of translations lies with respect to that set.
struct Crossing_slabs
{
  enum class Where { inside, outside, border };
  struct Slab
  {
    Vec3<Interval> w;
    Interval lo, hi;
    int axis; // its index among the axes of the pair (Cd_filter::axis())

    /// Where T lies with respect to this slab. Needs rounding towards +infinity.
    Where where(const std::array<Vec3<Interval>, 3>& T) const
    {
      const auto [tl, th] = extent(w, T);
      return where(tl, th);
    }
    /// Where a set of translations t with tl <= w.t <= th lies with respect to this slab.
    Where where(double tl, double th) const
    {
      if (th < lo.inf() || tl > hi.sup()) return Where::outside;
      return tl > lo.sup() && th < hi.inf() ? Where::inside : Where::border;
    }
  };

  /// Bounds of the extent of the triangle T (boxes holding its corners) along w. Needs
  /// rounding towards +infinity.
  static std::pair<double, double> extent(const Vec3<Interval>& w, const std::array<Vec3<Interval>, 3>& T)
  {
    double tl = HUGE_VAL, th = -HUGE_VAL;
    for (const auto& x : T) {
      const Interval wx = dot(w, x);
      tl = (std::min)(tl, wx.inf());
      th = (std::max)(th, wx.sup());
    }
    return {tl, th};
  }

  /// Two convex planar patches' (convex_patches.h): the normals and the edge pairs.
  static constexpr std::size_t max_slabs = 2 + Convex_patches::max_corners * Convex_patches::max_corners;
  boost::container::static_vector<Slab, max_slabs> slabs;
  bool known = false; // false: nothing is known (bare edges)

  /// inside: the pair crosses on all of T (any perturbation); outside: nowhere in T; else
  /// the border of its crossing set may cross T. T: boxes holding the triangle's corners.
  /// Needs rounding towards +infinity.
  Where where(const std::array<Vec3<Interval>, 3>& T) const
  {
    return where_by([&](std::size_t s) { return extent(slabs[s].w, T); });
  }
  /// Does a corner of T certainly lie outside the closure of the crossing set (then no
  /// perturbation of T's points puts all of them in it)? Needs rounding towards +infinity.
  bool leaves(const std::array<Vec3<Interval>, 3>& T) const
  {
    for (const Slab& s : slabs)
      for (const auto& x : T) {
        const Interval wx = dot(s.w, x);
        if (wx.sup() < s.lo.inf() || wx.inf() > s.hi.sup()) return true;
      }
    return false;
  }
  /// where() of a set whose extent along slab s's axis is extent(s) (a pair: low, high).
  template <class Extent>
  Where where_by(const Extent& extent) const
  {
    if (!known) return Where::border;
    bool inside = true;
    for (std::size_t s = 0; s < slabs.size(); ++s) {
      const auto [tl, th] = extent(s);
      const Where w = slabs[s].where(tl, th);
      if (w == Where::outside) return w;
      inside = inside && w == Where::inside;
    }
    return inside ? Where::inside : Where::border;
  }
};

/// Counters of the CD filter, for the summary.
struct Cd_statistics
{
  std::size_t queries = 0;            // is_free calls
  std::size_t triangle_pairs = 0;     // exact triangle-triangle tests
  std::size_t containment_tests = 0;  // ray-parity point-in-solid tests
  void add(const Cd_statistics& o)
  {
    queries += o.queries;
    triangle_pairs += o.triangle_pairs;
    containment_tests += o.containment_tests;
  }
};

/// What the collision tests share and never modify: the two meshes in their frames, with
/// their AABB trees. Built once; read concurrently by every thread's Cd_filter.
struct Cd_geometry
{
  /// P and Q are the meshes of the sum (P already negated for a contact space). The mesh
  /// with more triangles stays static; the other is reflected and translated.
  Cd_geometry(const Mesh_data& P, const Mesh_data& Q)
    : p(&P), q(&Q),
      p_moves(P.number_of_triangles() < Q.number_of_triangles()), static_mesh(p_moves ? Q : P, false),
      moving_mesh(p_moves ? P : Q, true), static_patches(*static_mesh.mesh, static_mesh.base),
      moving_patches(*moving_mesh.mesh, moving_mesh.base)
  {
    // Margin for the conservative double slab tests of ray traversal.
    double scale = 1;
    for (const Tree_mesh* tm : {&static_mesh, &moving_mesh})
      for (const auto& x : tm->base) scale = (std::max)({scale, std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
    margin = 1e-6 * 4 * scale;
    exact_doubles = on_small_grid({&static_mesh.base, &moving_mesh.base});
  }

  const Mesh_data* p;
  const Mesh_data* q;
  bool p_moves; // (declared before the meshes, which it chooses)
  Tree_mesh static_mesh, moving_mesh;
  Convex_patches static_patches, moving_patches; // of their triangles (the island search's)
  double margin;
  bool exact_doubles; // D(0) and g of every predicate are exact in double arithmetic
};

/// One thread's collision tester: the state of the current query and counters.
class Cd_filter : Perturbed_predicates<Cd_filter, Moving_point>
{
  friend class Perturbed_predicates<Cd_filter, Moving_point>;

public:
  explicit Cd_filter(const Cd_geometry* g) // shared, not copied: threads construct their own filter
    : m_p(g->p), m_q(g->q), m_p_moves(g->p_moves), m_static(g->static_mesh), m_moving(g->moving_mesh),
      m_static_patches(g->static_patches), m_moving_patches(g->moving_patches), m_margin(g->margin),
      m_exact_doubles(g->exact_doubles) {}

  const Cd_statistics& statistics() const { return m_stats; }

  /// Did the last query of is_free(), answered "not free", decide without looking at the
  /// perturbation?
  /// True iff some pair of items crosses with every predicate of its test non-zero at x
  /// itself, or, if no pair crosses, the containment test that decided was so: then that
  /// test, hence the answer, is the same for any direction. This depends on x only, not on
  /// the order of the tests, so the number of queries does not depend on the threads.
  bool decided_without_perturbation() const { return !m_perturbed; }

  /// Is x = p + q, perturbed along directions[first] (then the other directions of the
  /// candidate, then the axes), outside P + Q?
  bool is_free(const Sample& p, const Sample& q, const Direction* directions, std::uint32_t count,
               std::uint32_t first)
  {
    set_query(p, q, directions, count, first);
    return configuration_is_free();
  }

  /// Are the meshes disjoint for the translation t (a double point; degenerate contacts are
  /// decided for t moved infinitesimally along the axes)? I.e. is t outside P + Q?
  bool is_free_at(const std::array<double, 3>& t)
  {
    m_sp = m_sq = nullptr;
    m_plain = t;
    m_dirs = nullptr; m_dir_count = 0; m_dir_first = 0;
    m_prefix = {};
    m_query_on_plane = false;
    m_support = {};
    m_zero_of.reset();
    m_exact_x.reset();
    m_x = to_nt<Interval>(t);
    return configuration_is_free();
  }

  /// Directions that perturb a query before its own (null ones are skipped).
  using Prefix = std::array<const Vec3<Exact_nt>*, 2>;

  /// Sets the query to the exact translation x, perturbed first along the prefix's
  /// directions (e.g. along a segment of translations: the answer is then the one just past
  /// x on that segment), then along the directions (from directions[0]), then the axes.
  /// The filter keeps pointers to `directions` and to the prefix's vectors.
  /// `zeros`: what is known of x, for zero_by_construction().
  void set_point(const Exact_point& x, const Direction* directions, std::uint32_t count, const Prefix& prefix = {},
                 const Known_zeros& zeros = {})
  {
    m_sp = m_sq = nullptr;
    m_dirs = directions; m_dir_count = count; m_dir_first = 0;
    m_exact_x.emplace(x.X, x.W);
    m_x = enclosure(x);
    m_prefix = prefix;
    m_query_on_plane = false;
    m_support = support(zeros.spans);
    m_zero_of.reset();
    if (zeros.predicate) m_zero_of = *zeros.predicate;
    CGAL::Protect_FPU_rounding<true> guard;
    for (std::size_t k = 0; k < prefix.size(); ++k)
      if (prefix[k])
        for (int c = 0; c < 3; ++c) m_prefix_interval[k][c] = CGAL::to_interval((*prefix[k])[c]);
  }

  /// set_point() for a point x of the plane set by set_plane(), perturbed first along the
  /// prefix's directions (parallel to the plane), then along the plane's directions: the
  /// queries that follow do not test the pairs that cross nowhere on the plane (on_plane()).
  /// `zeros`: what is known of x (its spans: if none, the plane's corners).
  void set_point_on_plane(const Exact_point& x, const Prefix& prefix, const Known_zeros& zeros = {})
  {
    set_point(x, m_plane.directions, m_plane.count, prefix, zeros);
    CGAL_assertion(CGAL::is_zero(dot(m_plane.exact_normal, scaled(x.X, m_plane.exact_point.W) -
                                                           scaled(m_plane.exact_point.X, x.W))));
    m_query_on_plane = true;
    if (zeros.spans.empty()) m_support = m_plane.support;
  }

  /// Is the query set by set_point() free?
  bool is_free_here() { return configuration_is_free(); }

  /// Does item u of the moving mesh cross item v of the static mesh for the query set by
  /// set_point()? `here_perturbed()` then tells whether the test looked at the perturbation.
  bool pair_crosses_here(Index u, Index v) { return items_cross(u, v); }
  /// Points of translations, with what is known of each (set_point()).
  using Points = std::initializer_list<std::pair<const Exact_point*, Known_zeros>>;
  /// Does item pair (u, v) cross at every point x of `points`, each perturbed as by
  /// set_point(x, directions, count, prefix, zeros)? (Where the pair crosses is convex: then
  /// it crosses on their convex hull, perturbed alike.)
  bool pair_crosses_at(Index u, Index v, Points points, const Direction* directions, std::uint32_t count,
                       const Prefix& prefix = {})
  {
    return crosses_at_every(points, directions, count, prefix, [&] { return items_cross(u, v); });
  }
  /// Does moving patch a cross static patch b (convex_patches.h: a triangle of each) at every
  /// point of `points`, perturbed as by pair_crosses_at()? (Where two convex patches cross is
  /// convex too: then they cross on the points' convex hull, perturbed alike.)
  bool patch_pair_crosses_at(Index a, Index b, Points points, const Direction* directions, std::uint32_t count)
  {
    if (a >= m_moving_patches.patches.size() || b >= m_static_patches.patches.size()) return false;
    const std::vector<Index>&A = m_moving_patches.patches[a].triangles, &B = m_static_patches.patches[b].triangles;
    return crosses_at_every(points, directions, count, {}, [&] {
      for (Index u : A)
        for (Index v : B)
          if (items_cross(u, v)) return true;
      return false;
    });
  }
  bool here_perturbed() const { return m_perturbed; }

  /// Is the orientation of these four points zero at the query's translation x by
  /// construction (what set_point() or is_free() was told of x)? It is if they are the
  /// points of the known zero predicate (Known_zeros::predicate, e.g. x is its root on a
  /// segment), in any order; or if the moving points among them (shift +1) include the
  /// vertices of the moving mesh that x's spans weigh and the static ones (shift 0) those of
  /// the static mesh (Support). For with x = m + s, m and s in the affine hulls of those
  /// vertices of the moving and of the static mesh, the first, reflected and translated
  /// (-M_i + x), have -m + x = s in their affine hull, as the second have: two affine hulls of
  /// k and l points that meet span at most k + l - 2 <= 2 dimensions, so the four points
  /// lie in a plane. (Where x is a candidate p + q of a vertex and a triangle, or of two
  /// edges, these are the contacts of the translated meshes: nearly all the orientations
  /// that intervals do not decide.) The CD filter's predicates ask it before an exact
  /// evaluation.
  bool zero_by_construction(std::initializer_list<const Moving_point*> points) const
  {
    if (m_zero_of && same_points(*m_zero_of, points)) return true;
    if (m_support[0].empty()) return false;
    auto among = [&](const boost::container::static_vector<Index, 3>& support, const Tree_mesh& mesh, int shift) {
      for (Index v : support) {
        bool found = false;
        for (const Moving_point* m : points) found = found || (m->shift == shift && m->base == &mesh.base[v]);
        if (!found) return false;
      }
      return true;
    };
    return among(m_support[0], m_moving, 1) && among(m_support[1], m_static, 0);
  }

  /// The last crossing pair found (moving item, static item), if any.
  const std::optional<std::pair<Index, Index>>& last_crossing() const { return m_hit; }
  /// Forgets what earlier queries found: the queries that follow then test the same
  /// triangle pairs whichever queries came before (decide_pair starts each pair so, to make
  /// every count independent of the threads and ranks).
  void forget_last_crossing()
  {
    m_hit.reset();
    m_only_perturbed.reset();
  }

  /// Calls f(u, v) for every pair (item u of the moving mesh, item v of the static mesh, not
  /// two bare edges) whose boxes overlap for some translation in `translations`, until f
  /// returns true.
  /// f may change the query; it returns true to stop.
  template <class F>
  void for_each_overlapping_pair(const Vec3<Interval>& translations, const F& f)
  {
    traverse_pairs(translations, [&](Index u, Index v) { return !(m_moving.is_edge(u) && m_static.is_edge(v)) && f(u, v); });
  }

  /// Calls f(a, b, c, d) for every orientation predicate that the test of the pair (u, v)
  /// can evaluate: its answer depends only on their signs. An edge of A against an edge of
  /// B and that edge of B against that edge of A are one affine function of the
  /// translation (det(b2 - b1, a1 + t - b1, a2 - a1) = det(a2 - a1, b1 - a1 - t, b2 - b1)):
  /// listed once, B's edges against A's only when B is a bare edge.
  template <class F>
  void for_each_predicate(Index u, Index v, const F& f) const
  {
    const bool eu = m_moving.is_edge(u), ev = m_static.is_edge(v);
    std::array<Moving_point, 3> A, B; // triangles (moving, static); or a segment in A[0..1] / B[0..1]
    const Index* m = eu ? m_moving.mesh->edges[m_moving.edge(u)].v.data() : m_moving.mesh->triangles[u].data();
    const Index* s = ev ? m_static.mesh->edges[m_static.edge(v)].v.data() : m_static.mesh->triangles[v].data();
    const int nm = eu ? 2 : 3, ns = ev ? 2 : 3;
    for (int i = 0; i < nm; ++i) A[i] = {&m_moving.base[m[i]], 1};
    for (int i = 0; i < ns; ++i) B[i] = {&m_static.base[s[i]], 0};
    // A point of one against the plane of the other (triangles only).
    if (ns == 3) for (int i = 0; i < nm; ++i) f(B[0], B[1], B[2], A[i]);
    if (nm == 3) for (int i = 0; i < ns; ++i) f(A[0], A[1], A[2], B[i]);
    // An edge of one against the edges of the other's triangle.
    auto edges_against = [&](const std::array<Moving_point, 3>& E, int ne, const std::array<Moving_point, 3>& T) {
      for (int i = 0; i < (ne == 2 ? 1 : 3); ++i)
        for (int k = 0; k < 3; ++k) f(E[i], E[(i + 1) % ne], T[k], T[(k + 1) % 3]);
    };
    if (ns == 3) edges_against(A, nm, B);
    else if (nm == 3) edges_against(B, ns, A);
  }

  /// Enclosures of D(0) and g of the predicate (a, b, c, d): single points where double
  /// arithmetic is exact (Cd_geometry::exact_doubles). Call with rounding protected.
  std::pair<Interval, Vec3<Interval>> affine_enclosure(const Moving_point& a, const Moving_point& b,
                                                       const Moving_point& c, const Moving_point& d) const
  {
    if (m_exact_doubles) return {Interval(value_at_origin<double>(a, b, c, d)), to_nt<Interval>(gradient<double>(a, b, c, d))};
    return {value_at_origin<Interval>(a, b, c, d), gradient<Interval>(a, b, c, d)};
  }

  /// The affine form of the predicate (a, b, c, d), exactly: in double arithmetic where it
  /// is exact (Cd_geometry::exact_doubles), else with Exact_nt.
  Affine_predicate affine_form(const Moving_point& a, const Moving_point& b, const Moving_point& c,
                               const Moving_point& d) const
  {
    if (m_exact_doubles)
      return {Exact_nt(value_at_origin<double>(a, b, c, d)), to_nt<Exact_nt>(gradient<double>(a, b, c, d))};
    return {value_at_origin<Exact_nt>(a, b, c, d), gradient<Exact_nt>(a, b, c, d)};
  }

  /// D(0) and g of the orientation of the four points, exactly; of the meshes' vertices, from
  /// the cache of the predicates met (the orientations that intervals do not decide are
  /// mostly zero: contacts of the features near a candidate's, met again by the candidates
  /// that follow on their pair; anchor + octahedron, one thread: 22% faster, part +
  /// icosahedron 40%, the same output; and the roots of the segment search, which meets the
  /// predicates of one pair on many lines: rotated narrow tunnel 4.05 -> 2.86 s). The
  /// reference is valid until the next call.
  const Affine_predicate& exact_affine_form(const Moving_point& a, const Moving_point& b, const Moving_point& c,
                                            const Moving_point& d)
  {
    auto compute = [&] { return affine_form(a, b, c, d); };
    auto uncached = [&]() -> const Affine_predicate& { return m_affine_form = compute(); };
    if (m_exact_doubles) return uncached(); // (cheaper than a look-up)
    Predicate_key key{};
    int k = 0;
    for (const Moving_point* m : {&a, &b, &c, &d}) {
      // (a vertex of the moving mesh or of the static one: their bases do not change)
      const std::uint64_t code = vertex_code(m_moving, m->base, 0) | vertex_code(m_static, m->base, 1);
      if (code == 0) return uncached();
      key[k / 2] |= (code << 2 | std::uint64_t(m->shift + 1)) << (32 * (k % 2));
      ++k;
    }
    return m_affine_forms.get(key, compute);
  }

  /// What intervals alone tell of where the pair (u, v) crosses along the segment of
  /// translations a + l (b - a) (a and b: boxes holding its ends); see Crossing_range.
  /// Triangle A + t meets triangle B iff t is in the convex polytope B - A, whose facets are
  /// normal to A, to B or to a cross product of an edge of each: the segment is clipped by
  /// the slabs of those eleven axes. Bare edges: nothing is known.
  Crossing_range crossing_range(Index u, Index v, const Vec3<Interval>& a, const Vec3<Interval>& b) const
  {
    Crossing_range r;
    if (m_moving.is_edge(u) || m_static.is_edge(v)) return r;
    CGAL::Protect_FPU_rounding<true> guard;
    bool inside_known = true;
    r.in_from = -HUGE_VAL; r.in_to = HUGE_VAL;
    for_each_slab(u, v, [&](int, const Vec3<Interval>& w, const Interval& lo, const Interval& hi) {
      const Interval wa = dot(w, a), wb = dot(w, b), slope = wb - wa;
      if (slope.inf() > 0 || slope.sup() < 0) { // lo < wa + l slope < hi
        const Interval e1 = (lo - wa) / slope, e2 = (hi - wa) / slope;
        const Interval& enter = slope.inf() > 0 ? e1 : e2;
        const Interval& leave = slope.inf() > 0 ? e2 : e1;
        r.low = (std::max)(r.low, enter.inf());
        r.high = (std::min)(r.high, leave.sup());
        r.in_from = (std::max)(r.in_from, enter.sup());
        r.in_to = (std::min)(r.in_to, leave.inf());
        return !r.misses_segment();
      }
      // Nearly parallel: w.t(l) is between w.a and w.b.
      const double fl = (std::min)(wa.inf(), wb.inf()), fh = (std::max)(wa.sup(), wb.sup());
      if (fh < lo.inf() || fl > hi.sup()) r.low = HUGE_VAL; // misses the slab
      else if (!(fl > lo.sup() && fh < hi.inf())) inside_known = false;
      return !r.misses_segment();
    });
    // Certain crossings need every axis clipped (a miss stops early).
    if (!inside_known || r.misses_segment()) { r.in_from = HUGE_VAL; r.in_to = -HUGE_VAL; }
    return r;
  }

  /// The convex planar patch (convex_patches.h) of item u of the moving mesh, or of item v
  /// of the static one. A bare edge is a patch of its own, numbered after the triangles'.
  Index moving_patch(Index u) const { return patch_of(m_moving, m_moving_patches, u); }
  Index static_patch(Index v) const { return patch_of(m_static, m_static_patches, v); }

  /// The slabs of the crossing set B - A of the patches a (moving) and b (static), and
  /// where the triangle T of translations (boxes holding its corners) lies
  /// (Crossing_slabs::where()); when T is outside, no slab is kept (they stay unknown).
  /// Bare edges: nothing is known. Needs rounding towards +infinity.
  std::pair<Crossing_slabs, Crossing_slabs::Where> patch_crossing_slabs(Index a, Index b, const std::array<Vec3<Interval>, 3>& T) const
  {
    using Where = Crossing_slabs::Where;
    std::pair<Crossing_slabs, Where> r{{}, Where::border};
    if (a >= m_moving_patches.patches.size() || b >= m_static_patches.patches.size()) return r;
    r.first.known = true;
    bool inside = true;
    for (const Crossing_slabs::Slab& s : m_patch_slabs.get(a, b, [&] {
           Patch_slabs slabs;
           polygon_slabs(patch_polygon(m_moving, m_moving_patches, a), patch_polygon(m_static, m_static_patches, b), slabs);
           return slabs;
         })) {
      const Where where = s.where(T);
      if (where == Where::outside) return {{}, where}; // the slabs stay unknown
      inside = inside && where == Where::inside;
      r.first.slabs.push_back(s);
    }
    if (inside) r.second = Where::inside;
    return r;
  }

  /// Are items u (moving) and v (static) two triangles in parallel planes (exactly)? Their
  /// crossing set B - A is then flat (empty interior): they cross at no translation, once
  /// perturbed (every query is). Coplanar faces of CAD models touch so along whole facets of
  /// translations, where their predicates are zero and only the perturbation decides.
  /// The exact test, needed where intervals do not tell (mostly parallel pairs), is cached.
  bool parallel_triangles(Index u, Index v) const
  {
    if (m_moving.is_edge(u) || m_static.is_edge(v)) return false;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Vec3<Interval> c = cross(m_moving.normals[u], m_static.normals[v]);
      for (int i = 0; i < 3; ++i)
        if (c[i].inf() > 0 || c[i].sup() < 0) return false;
    }
    return m_parallel.get(u, v, [&] {
      const Vec3<Exact_nt> a = axis<Exact_nt>(u, v, 0), b = axis<Exact_nt>(u, v, 1);
      return is_null(cross(a, b)) && !is_null(a) && !is_null(b);
    });
  }

  /// A convex polygon of one mesh: a triangle, or a convex planar patch (convex_patches.h):
  /// its corners, one edge per direction, and the triangle whose normal is its normal.
  struct Polygon
  {
    const Tree_mesh* mesh;
    boost::container::static_vector<Index, Convex_patches::max_corners> corners;
    boost::container::static_vector<std::array<Index, 2>, Convex_patches::max_corners> edges;
    Index triangle;
  };
  static Polygon triangle_polygon(const Tree_mesh& m, Index t)
  {
    const auto& tri = m.mesh->triangles[t];
    return {&m, {tri[0], tri[1], tri[2]}, {{tri[0], tri[1]}, {tri[1], tri[2]}, {tri[2], tri[0]}}, t};
  }
  static Polygon patch_polygon(const Tree_mesh& m, const Convex_patches& patches, Index i)
  {
    const Convex_patches::Patch& p = patches.patches[i];
    return {&m, {p.corners.begin(), p.corners.end()}, {p.edges.begin(), p.edges.end()}, p.triangles.front()};
  }

  static Index patch_of(const Tree_mesh& m, const Convex_patches& patches, Index item)
  { return m.is_edge(item) ? Index(patches.patches.size() + (item - m.triangles.size())) : patches.of[item]; }

  /// Number of axes of the facets of B - A (A moving, B static): the normals of A and B,
  /// then the cross products of an edge direction of each.
  static int axis_count(const Polygon& A, const Polygon& B) { return 2 + int(A.edges.size() * B.edges.size()); }

  /// Axis k of those normal to the facets of B - A: the normal of A, of B, then the cross
  /// product of edge i of A and edge j of B (k = 2 + |edges of B| i + j), unnormalised;
  /// Interval: an enclosure.
  template <class NT>
  static Vec3<NT> axis(const Polygon& A, const Polygon& B, int k)
  {
    if constexpr (std::is_same<NT, Interval>::value)
      if (k < 2) return k == 0 ? A.mesh->normals[A.triangle] : B.mesh->normals[B.triangle];
    auto edge = [](const Polygon& p, const std::array<Index, 2>& e) {
      return to_nt<NT>(p.mesh->base[e[1]]) - to_nt<NT>(p.mesh->base[e[0]]);
    };
    if (k < 2) {
      const Polygon& p = k == 0 ? A : B;
      const auto& tri = p.mesh->mesh->triangles[p.triangle];
      return cross(edge(p, {tri[0], tri[1]}), edge(p, {tri[1], tri[2]}));
    }
    const std::size_t n = B.edges.size();
    return cross(edge(A, A.edges[std::size_t(k - 2) / n]), edge(B, B.edges[std::size_t(k - 2) % n]));
  }
  /// Axis k of the triangles u (moving) and v (static).
  template <class NT>
  Vec3<NT> axis(Index u, Index v, int k) const
  { return axis<NT>(triangle_polygon(m_moving, u), triangle_polygon(m_static, v), k); }

  /// Calls f(k, w, lo, hi) for the eleven axes w = axis(u, v, k): lo < w.t < hi for every
  /// t in B - A (enclosures), until f returns false. Skips zero axes. A pair's slabs depend
  /// on it alone, and the segments and cells of a facet meet the same pairs again and again:
  /// they are computed once (slabs()). Needs rounding towards +infinity.
  template <class F>
  void for_each_slab(Index u, Index v, const F& f) const
  {
    for (const Crossing_slabs::Slab& s : slabs(u, v))
      if (!f(s.axis, s.w, s.lo, s.hi)) return;
  }

  /// The slabs of B - A (triangles A = u, B = v) along its non-zero axes. Cached. Needs
  /// rounding towards +infinity.
  using Pair_slabs = boost::container::static_vector<Crossing_slabs::Slab, 11>;
  const Pair_slabs& slabs(Index u, Index v) const
  {
    return m_slabs.get(u, v, [&] {
      Pair_slabs r;
      polygon_slabs(triangle_polygon(m_moving, u), triangle_polygon(m_static, v), r);
      return r;
    });
  }

  /// Appends to r the slabs of B - A (A moving, B static) along its non-zero axes: w, and
  /// the extent [lo, hi] of B - A along w (any w: B - A is the convex hull of the B_k - A_i):
  /// lo = min_k w.B_k - max_i w.A_i, hi = max_k w.B_k - min_i w.A_i. Needs rounding towards
  /// +infinity.
  template <class Slabs>
  static void polygon_slabs(const Polygon& A, const Polygon& B, Slabs& r)
  {
    for (int k = 0; k < axis_count(A, B); ++k) {
      const Vec3<Interval> w = axis<Interval>(A, B, k);
      if (w[0].is_point() && w[1].is_point() && w[2].is_point() && w[0].inf() == 0 && w[1].inf() == 0 && w[2].inf() == 0)
        continue;
      const auto a = extremes(A, w), b = extremes(B, w);
      r.push_back({w, b.first - a.second, b.second - a.first, k});
    }
  }

  /// Starts a plane H of translations, that of the triangle T with corners p_k + q_k
  /// (`corners`: the samples (p_k, q_k); not collinear), whose points are perturbed as by
  /// set_point(x, directions, count, prefix) with prefix directions parallel to H: may_meet_plane() and on_plane() then tell about
  /// pairs, each triangle's extent along H's normal computed once per plane. It replaces the
  /// current query's directions (set_point() sets them again).
  void set_plane(const std::array<std::pair<Sample, Sample>, 3>& corners, const Direction* directions, std::uint32_t count)
  {
    Plane& p = m_plane;
    std::array<Exact_point, 3> T;
    for (int k = 0; k < 3; ++k) T[k] = exact_sum(*m_p, corners[k].first, *m_q, corners[k].second);
    p.support = support({&corners[0], &corners[1], &corners[2]}); // H lies in the sum of their hulls
    auto relative = [&](int k) { // W0 Wk (T[k] - T[0]), a positive multiple
      Vec3<Exact_nt> r;
      for (int c = 0; c < 3; ++c) r[c] = T[k].X[c] * T[0].W - T[0].X[c] * T[k].W;
      return r;
    };
    p.exact_normal = cross(relative(1), relative(2));
    p.exact_point = T[0];
    // The side of H to which the perturbation moves its points: the first v of the chain
    // (directions, then axes) with n.v != 0 (see perturbation_sign()).
    m_dirs = p.directions = directions; m_dir_count = p.count = count; m_dir_first = 0;
    m_prefix = {};
    m_query_on_plane = false;
    p.side = perturbation_sign([&](auto nt) {
      using NT = decltype(nt);
      if constexpr (std::is_same<NT, Interval>::value)
        return Vec3<Interval>{CGAL::to_interval(p.exact_normal[0]), CGAL::to_interval(p.exact_normal[1]),
                              CGAL::to_interval(p.exact_normal[2])};
      else return p.exact_normal;
    });
    CGAL::Protect_FPU_rounding<true> guard;
    std::array<Vec3<Interval>, 3> e;
    for (int k = 0; k < 3; ++k) e[k] = enclosure(T[k]);
    p.normal = cross(e[1] - e[0], e[2] - e[0]);
    std::tie(p.low, p.high) = Crossing_slabs::extent(p.normal, e);
    ++p.stamp;
    p.crossings.clear();
    p.patch_crossings.clear();
    p.moving.resize(m_moving.mesh->number_of_triangles());
    p.fixed.resize(m_static.mesh->number_of_triangles());
  }

  /// Where the pair (u, v) crosses on the plane H set by set_plane(), perturbed: nowhere
  /// (`never`), or where all of its slabs but those of the axes in `ignored` hold the point.
  /// A slab whose axis is not normal to H bounds a region of H by lines; one whose axis is
  /// normal to H either holds all of H (ignored), or none of it (never), or has H as a
  /// bounding plane: then the perturbation moves every point of H into it (ignored) or out
  /// of it (never), the same for all. So the slab that has H as a supporting plane of the
  /// crossing set (coplanar faces), which intervals can never decide on H, is decided once.
  /// Exact; computed once per pair and plane.
  struct Plane_crossing
  {
    bool never = false;
    std::uint64_t ignored = 0; // bit k: axis k
  };
  const Plane_crossing& on_plane(Index u, Index v)
  {
    return m_plane.crossings.get(u, v, [&] {
      if (m_moving.is_edge(u) || m_static.is_edge(v)) return Plane_crossing{};
      return plane_crossing(triangle_polygon(m_moving, u), triangle_polygon(m_static, v));
    });
  }
  /// on_plane() of the patches a (moving) and b (static); bare edges: nothing is known.
  const Plane_crossing& patch_on_plane(Index a, Index b)
  {
    return m_plane.patch_crossings.get(a, b, [&] {
      if (a >= m_moving_patches.patches.size() || b >= m_static_patches.patches.size()) return Plane_crossing{};
      return plane_crossing(patch_polygon(m_moving, m_moving_patches, a), patch_polygon(m_static, m_static_patches, b));
    });
  }

  /// patch_crossing_slabs() of the patches a (moving) and b (static) on the plane H set by
  /// set_plane(), its points perturbed: where intervals leave T on the border of their
  /// crossing set, what patch_on_plane() knows (coplanar faces: the slab that has H as a
  /// bounding plane holds all of H, or none of it).
  std::pair<Crossing_slabs, Crossing_slabs::Where> patch_crossing_slabs_on_plane(Index a, Index b,
                                                                                 const std::array<Vec3<Interval>, 3>& T)
  {
    std::pair<Crossing_slabs, Crossing_slabs::Where> r;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      r = patch_crossing_slabs(a, b, T);
    }
    if (r.second != Crossing_slabs::Where::border || !r.first.known) return r;
    return with_plane(std::move(r.first), patch_on_plane(a, b), T);
  }

  /// The slabs of a crossing set whose border may cross the triangle T (boxes) of H, and
  /// where T lies, once what is known of the set on H (c: on_plane(), patch_on_plane()) is used.
  static std::pair<Crossing_slabs, Crossing_slabs::Where> with_plane(Crossing_slabs set, const Plane_crossing& c,
                                                                     const std::array<Vec3<Interval>, 3>& T)
  {
    using Where = Crossing_slabs::Where;
    std::pair<Crossing_slabs, Where> r{std::move(set), Where::border};
    if (c.never) return {{}, Where::outside};
    if (c.ignored == 0) return r;
    auto& slabs = r.first.slabs;
    slabs.erase(std::remove_if(slabs.begin(), slabs.end(), [&](const Crossing_slabs::Slab& s) { return c.ignored >> s.axis & 1; }),
                slabs.end());
    CGAL::Protect_FPU_rounding<true> guard;
    r.second = r.first.where(T);
    return r;
  }

  /// Does the slab of the polygons A (moving) and B (static) normal to the plane H set by
  /// set_plane() hold every point of H, perturbed: H strictly inside it, or on its border
  /// with the perturbation moving H's points into it? Exact.
  bool slab_normal_to_plane_holds(const Polygon& A, const Polygon& B) const
  {
    const Plane& p = m_plane;
    auto range = [&](const Polygon& m) { // of W n.x over the polygon's corners
      std::pair<Exact_nt, Exact_nt> e;
      for (std::size_t i = 0; i < m.corners.size(); ++i) {
        const Exact_nt y = dot(p.exact_normal, to_nt<Exact_nt>(m.mesh->base[m.corners[i]])) * p.exact_point.W;
        if (i == 0 || y < e.first) e.first = y;
        if (i == 0 || y > e.second) e.second = y;
      }
      return e;
    };
    const auto a = range(A), b = range(B);
    const Exact_nt h = dot(p.exact_normal, p.exact_point.X), lo = b.first - a.second, hi = b.second - a.first;
    if (lo < h && h < hi) return true;
    return lo < hi && ((h == lo && p.side == CGAL::POSITIVE) || (h == hi && p.side == CGAL::NEGATIVE));
  }

  /// Can the crossing set B - A of the pair (u, v) meet the plane set by set_plane()?
  /// (Intervals: its extent along the plane's normal.) Needs rounding towards +infinity.
  bool may_meet_plane(Index u, Index v)
  {
    CGAL_precondition(m_plane.stamp != 0);
    if (m_moving.is_edge(u) || m_static.is_edge(v)) return true;
    auto extent = [&](const Tree_mesh& m, Index t, std::vector<Plane::Extent>& memo) -> const Plane::Extent& {
      Plane::Extent& e = memo[t];
      if (e.stamp != m_plane.stamp) {
        e.stamp = m_plane.stamp;
        e.range = extremes(triangle_polygon(m, t), m_plane.normal);
      }
      return e;
    };
    const auto &a = extent(m_moving, u, m_plane.moving).range, &b = extent(m_static, v, m_plane.fixed).range;
    return !(m_plane.high < (b.first - a.second).inf() || m_plane.low > (b.second - a.first).sup());
  }

private:
  /// on_plane() of the polygons A (moving) and B (static), computed.
  Plane_crossing plane_crossing(const Polygon& A, const Polygon& B) const
  {
    Plane_crossing r;
    const Plane& p = m_plane;
    std::optional<bool> holds; // does the slab normal to H hold every point of H, perturbed?
    for (int k = 0; k < axis_count(A, B) && !r.never; ++k) {
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const Vec3<Interval> w = cross(axis<Interval>(A, B, k), p.normal);
        if (!(w[0].do_overlap(0) && w[1].do_overlap(0) && w[2].do_overlap(0))) continue; // not normal to H
      }
      const Vec3<Exact_nt> x = axis<Exact_nt>(A, B, k);
      if (is_null(x)) { r.ignored |= std::uint64_t(1) << k; continue; } // no slab (its enclosure may not show it)
      if (!is_null(cross(x, p.exact_normal))) continue;                   // not normal to H
      // Every axis normal to H gives the same slab: the extent of B - A along H's normal n,
      // compared with H's position n.X / W once.
      if (!holds) holds = slab_normal_to_plane_holds(A, B);
      if (*holds) r.ignored |= std::uint64_t(1) << k;
      else r.never = true;
    }
    return r;
  }

  /// Enclosures of the minimum and the maximum of w.x over the corners x of polygon A.
  /// Needs rounding towards +infinity.
  static std::pair<Interval, Interval> extremes(const Polygon& A, const Vec3<Interval>& w)
  {
    Interval lo = dot(w, to_nt<Interval>(A.mesh->base[A.corners[0]])), hi = lo;
    for (std::size_t k = 1; k < A.corners.size(); ++k) {
      const Interval x = dot(w, to_nt<Interval>(A.mesh->base[A.corners[k]]));
      lo = Interval((std::min)(lo.inf(), x.inf()), (std::min)(lo.sup(), x.sup()));
      hi = Interval((std::max)(hi.inf(), x.inf()), (std::max)(hi.sup(), x.sup()));
    }
    return {lo, hi};
  }

  bool configuration_is_free()
  {
    ++m_stats.queries;
    // 1. Does a triangle or bare edge of one mesh cross a triangle of the other?
    if (surfaces_cross()) return false;
    // 2. Is a component of one mesh inside a closed component of the other?
    for (const auto& c : m_moving.mesh->components) {
      const auto& r = m_moving.base[c.representative_vertex];
      if (inside(m_static, Moving_point{&r, +1})) return false;
    }
    for (const auto& c : m_static.mesh->components) {
      const auto& l = m_static.base[c.representative_vertex];
      if (inside(m_moving, Moving_point{&l, -1})) return false;
    }
    return true;
  }

  // ----- query state -------------------------------------------------------------------
  void set_query(const Sample& p, const Sample& q, const Direction* directions, std::uint32_t count,
                 std::uint32_t first)
  {
    m_sp = &p; m_sq = &q;
    m_dirs = directions; m_dir_count = count; m_dir_first = first;
    m_prefix = {};
    m_query_on_plane = false;
    const std::pair<Sample, Sample> pq(p, q);
    m_support = support({&pq});
    m_zero_of.reset();
    m_exact_x.reset();
    CGAL::Protect_FPU_rounding<true> guard;
    m_x = sample_interval(*m_p, p) + sample_interval(*m_q, q);
  }

  static Vec3<Interval> sample_interval(const Mesh_data& M, const Sample& s)
  {
    Vec3<Interval> r = {Interval(0), Interval(0), Interval(0)};
    for (int i = 0; i < 3; ++i) {
      if (s.weights[i] == 0) continue;
      r = r + scaled(M.point<Interval>(s.vertices[i]), Interval(s.weights[i]) / Interval(s.denominator));
    }
    return r;
  }

  /// S * x exactly, and S.
  const std::pair<Vec3<Exact_nt>, Exact_nt>& exact_x()
  {
    if (!m_exact_x && !m_sp) m_exact_x.emplace(to_nt<Exact_nt>(m_plain), Exact_nt(1));
    if (!m_exact_x) {
      const Exact_point x = exact_sum(*m_p, *m_sp, *m_q, *m_sq);
      m_exact_x.emplace(x.X, x.W);
    }
    return *m_exact_x;
  }

  /// Box b translated by the interval of x, rounded outward. Each bound is computed to
  /// nearest, s = fl(b + x), then moved out by |s| 2^-52, at least one unit in the last place
  /// of s: the exact sum is within half a unit of s and rounding is monotone, so the moved
  /// bound is still beyond it (a sum that rounds to zero or a subnormal is exact).
  CGAL::Bbox_3 translated_box(const CGAL::Bbox_3& b) const { return translated_box(b, m_x); }
  static CGAL::Bbox_3 translated_box(const CGAL::Bbox_3& b, const Vec3<Interval>& m_x)
  {
    auto down = [](double s) { return s - std::abs(s) * 0x1p-52; };
    auto up = [](double s) { return s + std::abs(s) * 0x1p-52; };
    return CGAL::Bbox_3(down(b.xmin() + m_x[0].inf()), down(b.ymin() + m_x[1].inf()), down(b.zmin() + m_x[2].inf()),
                        up(b.xmax() + m_x[0].sup()), up(b.ymax() + m_x[1].sup()), up(b.zmax() + m_x[2].sup()));
  }

  // ----- orientations zero by construction ----------------------------------------------
  /// Vertices of the moving mesh ([0]) and of the static mesh ([1]) such that the query's
  /// translation x is m + s, with m in the affine hull of the first (of P or Q, unreflected)
  /// and s in that of the second; both empty when not known.
  using Support = std::array<boost::container::static_vector<Index, 3>, 2>;

  /// The support of the translations that `spans` hold: the vertices their samples weigh.
  /// Empty if a side would have more than three (no orientation of four points could then
  /// hold both sides).
  Support support(const Spans& spans) const
  {
    std::array<boost::container::static_vector<Index, 3>, 2> pq; // of P, of Q
    for (const std::pair<Sample, Sample>* span : spans)
      for (int side = 0; side < 2; ++side) {
        const Sample& s = side == 0 ? span->first : span->second;
        std::int64_t total = 0;
        for (int i = 0; i < 3; ++i) {
          total += s.weights[i];
          if (s.weights[i] == 0 || std::count(pq[side].begin(), pq[side].end(), s.vertices[i])) continue;
          if (pq[side].size() == 3) return {};
          pq[side].push_back(s.vertices[i]);
        }
        if (total != s.denominator) return {}; // not an affine combination
      }
    return m_p_moves ? Support{pq[0], pq[1]} : Support{pq[1], pq[0]};
  }

  /// Are these the four points of `known`, in any order (hence the same orientation, up to
  /// its sign)?
  static bool same_points(const Predicate_points& known, std::initializer_list<const Moving_point*> points)
  {
    std::array<bool, 4> used{};
    for (const Moving_point* m : points) {
      int k = 0;
      while (k < 4 && (used[k] || known[k].base != m->base || known[k].shift != m->shift)) ++k;
      if (k == 4) return false;
      used[k] = true;
    }
    return true;
  }

  // ----- the points of the perturbed predicates (perturbed_predicates.h) ----------------
  /// The position of m at the translation x (times S for Exact_nt: see exact_x()).
  template <class NT>
  Vec3<NT> position(const Moving_point& m)
  {
    if constexpr (std::is_same<NT, Interval>::value) {
      const Vec3<NT> b = to_nt<NT>(*m.base);
      return m.shift == 0 ? b : m.shift > 0 ? b + m_x : b - m_x;
    } else {
      const auto& [X, S] = exact_x();
      const Vec3<NT> b = scaled(to_nt<NT>(*m.base), S);
      return m.shift == 0 ? b : m.shift > 0 ? b + X : b - X;
    }
  }

  /// Exact sign of the orientation of the four points at x. Where D(0) and g are exact
  /// doubles (Cd_geometry::exact_doubles), the sign of D(0) + g.x: its interval is tighter
  /// and cheaper than that of `value`, the determinant of the translated points, and its
  /// exact evaluation S D(0) + g.X (x = X / S) takes four products by doubles. Elsewhere,
  /// `value`'s interval, then S D(0) + g.X with D(0) and g exact (exact_affine_form()).
  template <class F>
  CGAL::Sign unperturbed_orientation(const Moving_point& a, const Moving_point& b, const Moving_point& c,
                                     const Moving_point& d, const F& value)
  {
    if (!m_exact_doubles)
      return filtered_sign(value, [&] {
        if (zero_by_construction({&a, &b, &c, &d})) return CGAL::ZERO;
        const Affine_predicate& f = exact_affine_form(a, b, c, d);
        const auto& [X, S] = exact_x();
        return CGAL::sign(S * f.d0 + dot(f.g, X));
      });
    const double d0 = value_at_origin<double>(a, b, c, d);
    const Vec3<double> g = gradient<double>(a, b, c, d);
    return filtered_sign([&](auto) { return Interval(d0) + dot(to_nt<Interval>(g), m_x); },
                         [&] {
                           if (zero_by_construction({&a, &b, &c, &d})) return CGAL::ZERO;
                           const auto& [X, S] = exact_x();
                           return CGAL::sign(S * Exact_nt(d0) + dot(to_nt<Exact_nt>(g), X));
                         });
  }

  /// The position at t = 0 (gradients do not depend on t).
  template <class NT>
  static Vec3<NT> frame_position(const Moving_point& m) { return to_nt<NT>(*m.base); }

  /// The gradient g of the orientation of the four points (Perturbed_predicates): exactly,
  /// from exact doubles or from exact_affine_form().
  template <class NT>
  Vec3<NT> orientation_gradient_of(const Moving_point& a, const Moving_point& b, const Moving_point& c,
                                   const Moving_point& d)
  {
    if constexpr (std::is_same<NT, Exact_nt>::value) {
      if (m_exact_doubles) return to_nt<Exact_nt>(gradient<double>(a, b, c, d)); // (no D(0) needed)
      return exact_affine_form(a, b, c, d).g;
    } else {
      return gradient<NT>(a, b, c, d);
    }
  }

  /// 1 + 2 v + mesh (v < 2^28) if `base` is vertex v of `mesh`, else 0: a point's code in a Predicate_key.
  static std::uint64_t vertex_code(const Tree_mesh& mesh, const std::array<double, 3>* base, std::uint64_t which)
  {
    if (base < mesh.base.data() || base >= mesh.base.data() + mesh.base.size()) return 0;
    const std::uint64_t v = std::uint64_t(base - mesh.base.data());
    return v < (std::uint64_t(1) << 28) ? 1 + 2 * v + which : 0;
  }

  static Moving_point fixed_point(const std::array<double, 3>& x) { return {&x, 0}; }

  /// Sign of the perturbation terms g.n_1, g.n_2, ..., g.e_x, g.e_y, g.e_z where g is given
  /// by a generic callable g(nt).
  template <class G>
  CGAL::Sign perturbation_sign(const G& g)
  {
    m_perturbed = true;
    for (std::size_t k = 0; k < m_prefix.size(); ++k) {
      if (!m_prefix[k]) continue;
      const CGAL::Sign s = filtered_sign([&](auto nt) {
        using NT = decltype(nt);
        if constexpr (std::is_same<NT, Interval>::value) return dot(g(nt), m_prefix_interval[k]);
        else return dot(g(nt), *m_prefix[k]);
      });
      if (s != CGAL::ZERO) return s;
    }
    for (std::uint32_t k = 0; k < m_dir_count; ++k) {
      const Direction& d = m_dirs[(m_dir_first + k) % m_dir_count];
      const CGAL::Sign s = filtered_sign([&](auto nt) {
        using NT = decltype(nt);
        return dot(g(nt), d.vector<NT>(*m_p, *m_q));
      });
      if (s != CGAL::ZERO) return s;
    }
    for (int c = 0; c < 3; ++c) {
      const CGAL::Sign s = filtered_sign([&](auto nt) { return g(nt)[c]; });
      if (s != CGAL::ZERO) return s;
    }
    throw std::logic_error("CGAL_pmsum: a perturbed predicate is identically zero");
  }

  // ----- surface crossing --------------------------------------------------------------
  /// Does an item (triangle or bare edge) of the moving mesh, translated, cross an item of
  /// the static mesh? Simultaneous traversal of both hierarchies: a pair of nodes is split
  /// only if the moving node's box, translated by the interval of x and rounded outward
  /// (translated_box), overlaps the static node's box; at the leaves, each pair of items
  /// whose boxes overlap in the same way is tested exactly. Node boxes contain their items'
  /// boxes and translated_box is monotone, so no pair whose items could cross is skipped:
  /// the answer is the same as testing every pair (it is an existence test; the order only
  /// changes which crossing is found and how many pairs are tested). The last crossing
  /// found by this filter is tried first: consecutive candidates are close, and many inner
  /// ones cross there too (forget_last_crossing() starts afresh).
  /// A crossing whose test looked at the perturbation does not stop the search of a
  /// candidate's query (is_free()), unless x is already known to have no other kind: see
  /// decided_without_perturbation(). Other queries (set_point(), is_free_at()) stop at the
  /// first crossing: nothing asks them how they were decided.
  bool surfaces_cross()
  {
    // Stop at the first crossing: x is not a candidate's, or it has no crossing decided at x
    // itself (found by the previous query, on the same samples).
    const bool only_perturbed = !m_sp || (m_only_perturbed && same(m_only_perturbed->first, *m_sp) &&
                                          same(m_only_perturbed->second, *m_sq));
    bool found = false; // a crossing that looked at the perturbation
    auto stop = [&](Index u, Index v) {
      if (!items_cross(u, v)) return false;
      m_hit.emplace(u, v);
      if (!m_perturbed || only_perturbed) return true;
      found = true;
      return false;
    };
    std::optional<std::pair<Index, Index>> tried;
    if (m_hit && CGAL::do_overlap(translated_box(moving_box(m_hit->first)), static_box(m_hit->second))) {
      tried = m_hit;
      if (stop(tried->first, tried->second)) return true;
    }
    if (traverse_pairs(m_x, [&](Index u, Index v) { return !(tried && tried->first == u && tried->second == v) && stop(u, v); }))
      return true;
    if (found) {
      m_perturbed = true;
      if (m_sp) m_only_perturbed.emplace(*m_sp, *m_sq);
    }
    return found;
  }

  /// Simultaneous traversal of both hierarchies (see surfaces_cross()): calls stop(u, v) for
  /// every pair of items whose boxes overlap, the moving one translated by the translations
  /// x and rounded outward, until it returns true; returns whether it did.
  template <class Stop>
  bool traverse_pairs(const Vec3<Interval>& x, const Stop& stop)
  {
    const Bvh& mt = m_moving.items;
    const Bvh& st = m_static.items;
    if (mt.empty() || st.empty()) return false;
    m_stack.clear();
    if (CGAL::do_overlap(translated_box(mt.root().box, x), st.root().box)) m_stack.emplace_back(0, 0);
    while (!m_stack.empty()) {
      const auto [a, b] = m_stack.back();
      m_stack.pop_back();
      const Bvh::Node& na = mt.node(a);
      const Bvh::Node& nb = st.node(b);
      if (na.is_leaf() && nb.is_leaf()) {
        for (std::uint32_t i = na.first; i < na.first + na.count; ++i) {
          const Index u = mt.item(i);
          const CGAL::Bbox_3 box = translated_box(mt.item_box(i), x);
          for (std::uint32_t j = nb.first; j < nb.first + nb.count; ++j)
            if (CGAL::do_overlap(box, st.item_box(j)) && stop(u, st.item(j))) return true;
        }
        continue;
      }
      // Split the static node if the moving one is a leaf or smaller, else the moving one.
      auto size = [](const CGAL::Bbox_3& x) { return x.x_span() + x.y_span() + x.z_span(); };
      if (na.is_leaf() || (!nb.is_leaf() && size(nb.box) >= size(na.box))) {
        const CGAL::Bbox_3 box = translated_box(na.box, x);
        for (std::uint32_t c : {b + 1, nb.right})
          if (CGAL::do_overlap(box, st.node(c).box)) m_stack.emplace_back(a, c);
      } else {
        for (std::uint32_t c : {a + 1, na.right})
          if (CGAL::do_overlap(translated_box(mt.node(c).box, x), nb.box)) m_stack.emplace_back(c, b);
      }
    }
    return false;
  }

  static bool same(const Sample& a, const Sample& b)
  { return a.vertices == b.vertices && a.weights == b.weights && a.denominator == b.denominator; }

  /// Boxes of items, untranslated.
  CGAL::Bbox_3 moving_box(Index u) const
  { return m_moving.is_edge(u) ? m_moving.edge_box(m_moving.edge(u)) : m_moving.triangles[u].second.bbox(); }
  CGAL::Bbox_3 static_box(Index v) const
  { return m_static.is_edge(v) ? m_static.edge_box(m_static.edge(v)) : m_static.triangles[v].second.bbox(); }

  /// Does `crosses_here()` hold at every point of `points`, each set by set_point()?
  template <class Crosses>
  bool crosses_at_every(Points points, const Direction* directions, std::uint32_t count, const Prefix& prefix,
                        const Crosses& crosses_here)
  {
    for (const auto& [x, zeros] : points) {
      set_point(*x, directions, count, prefix, zeros);
      if (!crosses_here()) return false;
    }
    return true;
  }

  /// Does item u of the moving mesh (translated) cross item v of the static mesh? Two bare
  /// edges never do (in the generic configuration). Counts the exact test, and leaves
  /// m_perturbed telling whether this test looked at the perturbation.
  bool items_cross(Index u, Index v)
  {
    const bool eu = m_moving.is_edge(u), ev = m_static.is_edge(v);
    if (eu && ev) return false;
    ++m_stats.triangle_pairs;
    m_perturbed = false;
    if (!eu && !ev) return triangles_cross(u, v);
    if (eu) {
      const auto& e = m_moving.mesh->edges[m_moving.edge(u)].v;
      return segment_crosses({Moving_point{&m_moving.base[e[0]], 1}, Moving_point{&m_moving.base[e[1]], 1}},
                             static_triangle(v));
    }
    const auto& e = m_static.mesh->edges[m_static.edge(v)].v;
    const auto& tm = m_moving.mesh->triangles[u];
    return segment_crosses({Moving_point{&m_static.base[e[0]], 0}, Moving_point{&m_static.base[e[1]], 0}},
                           {Moving_point{&m_moving.base[tm[0]], 1}, Moving_point{&m_moving.base[tm[1]], 1},
                            Moving_point{&m_moving.base[tm[2]], 1}});
  }

  using Perturbed_predicates::triangles_cross;
  /// Does triangle t of the moving mesh (translated) cross triangle s of the static mesh?
  bool triangles_cross(Index t, Index s)
  {
    const auto& tm = m_moving.mesh->triangles[t];
    const auto& ts = m_static.mesh->triangles[s];
    std::array<Moving_point, 3> A, B;
    for (int i = 0; i < 3; ++i) {
      A[i] = {&m_moving.base[tm[i]], 1};
      B[i] = {&m_static.base[ts[i]], 0};
    }
    const Plane_sides sides = plane_sides(t, s, m_x);
    if (separated(sides[0]) || separated(sides[1]) || parallel_triangles(t, s) || (m_query_on_plane && on_plane(t, s).never))
      return false;
    return triangles_cross(A, B, sides);
  }

  /// The signs of the vertices of a moving and a static triangle against the other's plane
  /// (Perturbed_predicates::triangles_cross()), ZERO where not known.
  using Plane_sides = std::array<std::array<CGAL::Sign, 3>, 2>;

  /// Are all three sides known and alike: the triangle strictly on one side of the plane?
  static bool separated(const std::array<CGAL::Sign, 3>& side)
  { return side[0] != CGAL::ZERO && side[0] == side[1] && side[1] == side[2]; }

  /// The sides of the vertices of moving triangle t and static triangle s against the
  /// other's plane that intervals tell for every translation in the box x, from the normals
  /// computed once: when certain they are the signs orientation() would return (it looks at
  /// the perturbation only when the sign at x itself is zero); ZERO elsewhere. Where the
  /// first plane tried separates the triangles, the other's sides are not computed. Tried
  /// first: the plane that separated the last pair the first did not. Which one separates
  /// follows from the sizes (a small triangle of one mesh near a large one's plane), and
  /// most queries meet pairs alike: on a large model ⊕ a small convex solid the large
  /// triangle's plane separates nine pairs in ten. (The sides found are the same either way.)
  Plane_sides plane_sides(Index t, Index s, const Vec3<Interval>& x) const
  {
    const auto& tm = m_moving.mesh->triangles[t];
    const auto& ts = m_static.mesh->triangles[s];
    CGAL::Protect_FPU_rounding<true> guard;
    std::array<Vec3<Interval>, 3> a, b; // moving vertices (translated by x), static vertices
    for (int i = 0; i < 3; ++i) {
      a[i] = to_nt<Interval>(m_moving.base[tm[i]]) + x;
      b[i] = to_nt<Interval>(m_static.base[ts[i]]);
    }
    auto sides = [](const std::array<Vec3<Interval>, 3>& p, const Vec3<Interval>& o, const Vec3<Interval>& n) {
      std::array<CGAL::Sign, 3> side;
      for (int i = 0; i < 3; ++i) {
        const Interval v = dot(p[i] - o, n);
        side[i] = v.inf() > 0 ? CGAL::POSITIVE : v.sup() < 0 ? CGAL::NEGATIVE : CGAL::ZERO;
      }
      return side;
    };
    auto plane = [&](int k) { return k == 0 ? sides(a, b[0], m_static.normals[s]) : sides(b, a[0], m_moving.normals[t]); };
    const int first = m_moving_plane_first ? 1 : 0;
    Plane_sides r{};
    r[first] = plane(first);
    if (separated(r[first])) return r;
    r[1 - first] = plane(1 - first);
    if (separated(r[1 - first])) m_moving_plane_first = !m_moving_plane_first;
    return r;
  }

  std::array<Moving_point, 3> static_triangle(Index s) const
  {
    const auto& ts = m_static.mesh->triangles[s];
    return {Moving_point{&m_static.base[ts[0]], 0}, Moving_point{&m_static.base[ts[1]], 0},
            Moving_point{&m_static.base[ts[2]], 0}};
  }

  // ----- containment -------------------------------------------------------------------
  /// Is the point z inside the closed components of `solid` (in the solid's frame)?
  bool inside(const Tree_mesh& solid, const Moving_point& z)
  {
    m_perturbed = false; // see decided_without_perturbation()
    if (!may_be_inside(solid, z)) return false;
    ++m_stats.containment_tests;
    return ray_parity(solid, z, m_margin);
  }

  const Mesh_data* m_p;
  const Mesh_data* m_q;
  bool m_p_moves; // Cd_geometry::p_moves
  const Tree_mesh& m_static;
  const Tree_mesh& m_moving;
  const Convex_patches& m_static_patches;
  const Convex_patches& m_moving_patches;
  double m_margin;
  bool m_exact_doubles;
  Cd_statistics m_stats;
  bool m_perturbed = false; // the test that decided the current query looked at the perturbation
  std::optional<std::pair<Index, Index>> m_hit;            // last crossing (moving item, static item)
  std::optional<std::pair<Sample, Sample>> m_only_perturbed; // an x whose crossings all look at the perturbation
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_stack; // traversal (moving node, static node)

  // query
  const Sample* m_sp = nullptr; // the candidate x = p + q, or
  const Sample* m_sq = nullptr;
  std::array<double, 3> m_plain{}; // a plain translation (m_sp == nullptr)
  const Direction* m_dirs = nullptr;
  std::uint32_t m_dir_count = 0, m_dir_first = 0;
  Prefix m_prefix{}; // set_point(): the first perturbation directions
  Support m_support; // of the query's translation: zero_by_construction()
  std::optional<Predicate_points> m_zero_of; // Known_zeros::predicate
  bool m_query_on_plane = false; // set_point_on_plane()
  struct Plane // set_plane()
  {
    struct Extent
    {
      std::uint64_t stamp = 0;
      std::pair<Interval, Interval> range; // of a triangle along the normal
    };
    Vec3<Interval> normal;
    double low = 0, high = 0; // of the plane along its normal
    Vec3<Exact_nt> exact_normal;
    Exact_point exact_point; // a point of the plane
    Support support;         // of its points (set_point_on_plane())
    const Direction* directions = nullptr; // its points' perturbation
    std::uint32_t count = 0;
    CGAL::Sign side = CGAL::ZERO; // of the perturbation, along exact_normal
    std::uint64_t stamp = 0;
    std::vector<Extent> moving, fixed;
    Pair_cache<Plane_crossing> crossings; // on_plane(), of the pairs met
    Pair_cache<Plane_crossing> patch_crossings; // patch_on_plane(), of the patch pairs met
  } m_plane;
  mutable Pair_cache<Pair_slabs> m_slabs; // slabs()
  using Patch_slabs = std::vector<Crossing_slabs::Slab>; // (as many as they have: up to max_slabs)
  mutable Pair_cache<Patch_slabs> m_patch_slabs; // patch_crossing_slabs()
  mutable Pair_cache<bool> m_parallel;    // parallel_triangles(), where intervals do not tell
  mutable bool m_moving_plane_first = false; // plane_sides()
  Fact_cache<Predicate_key, Affine_predicate, Predicate_key_hash> m_affine_forms; // exact_affine_form()
  Affine_predicate m_affine_form; // exact_affine_form(), of points not cached
  std::array<Vec3<Interval>, 2> m_prefix_interval;
  Vec3<Interval> m_x;
  std::optional<std::pair<Vec3<Exact_nt>, Exact_nt>> m_exact_x;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_CD_FILTER_H
