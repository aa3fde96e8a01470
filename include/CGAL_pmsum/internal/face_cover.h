// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The plane-by-plane mesher's test that a whole triangle, not only points of it, lies on a
// face of the sum (plane_triangulation.h).
//
// Every point of a face of the boundary with normal n lies on a convolution facet of the
// candidate pairs in the face's plane (the boundary is in the convolution, the normal filter
// never drops a boundary point, and the other facets meet the plane in segments only). So a
// triangle of the face lies in the union S of the plane's convolution facets (triangles v + t
// and t + w, parallelograms e + f: convex polygons). The converse fails (S has hidden parts),
// which is why the mesher also tests points with the CD filter; what this test adds is what
// points cannot see: a hole of S inside the triangle smaller than the points' spacing, such as
// the mouth of a tunnel 1/2000 wide in a face sampled at d. A triangle meets no hole of S and
// no outer border of S if no piece of the border of S meets it (and it has a point in S,
// which the CD test at its centroid shows). The border pieces are computed exactly: the
// stretches of the facets' edges not covered on their outer side by another facet of the
// plane (Epeck, in the plane's projection along an axis).
//
// For the advancing front's mesh, a weaker test that it can pass where it cuts a reflex
// corner of a face: a triangle of a plane must not join two parts of S that do not meet (its
// corners on no one connected piece of S), as a face laid over the mouth of a slit narrower
// than the points' spacing does, from the points on one lip to those on the other
// (joins_separate_parts(); in doubles, pieces nearer than a billionth of the model's size
// taken as meeting: it only refuses meshes, and never a slit that wide).

#ifndef CGAL_PMSUM_INTERNAL_FACE_COVER_H
#define CGAL_PMSUM_INTERNAL_FACE_COVER_H

#include <CGAL_pmsum/internal/normal_filter.h>
#include <CGAL_pmsum/internal/plane_parts.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// The convolution facets of the 2-dimensional candidate pairs, found by plane; for one
/// plane at a time (set_plane()), whether a triangle of it lies in their union (covers()).
class Face_cover
{
public:
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;

  Face_cover(const Candidate_pairs& pairs, const Mesh_data& mp, const Mesh_data& mq) : m_p(mp), m_q(mq)
  {
    for (const Feature_pair& pair : pairs.pairs) {
      if (pair.p.dimension + pair.q.dimension != 2) continue;
      const std::vector<std::array<double, 3>> corners = facet_corners(pair);
      const Vec3<double> n = cross(corners[1] - corners[0], corners[2] - corners[0]);
      const double length = std::sqrt(dot(n, n));
      if (!(length > 0)) continue;
      const Vec3<double> u = scaled(n, 1 / length);
      for (double sign : {1., -1.}) // both sides: a facet is looked up by its plane
        m_by_plane.emplace(key(scaled(u, sign), sign * dot(u, corners[0])), m_facets.size());
      m_facets.push_back(Facet{pair, u, dot(u, corners[0])});
      for (const auto& c : corners)
        for (double x : c) m_scale = (std::max)(m_scale, std::abs(x));
    }
  }

  /// Selects the facets in the plane of unit normal n (up to its sign) and offset c (equal
  /// within 1e-9, relative to 1 for the normal and to the model's size for the offset),
  /// seen along coordinate axis `drop`. Returns: are there any?
  bool set_plane(const std::array<double, 3>& n, double c, int drop)
  {
    // The keys of the planes within the tolerance: in each component, the key of (n, c) and
    // its neighbour where (n, c) is that near the edge between them (mostly one key).
    const std::array<double, 4> value = {n[0] * key_scale[0], n[1] * key_scale[1], n[2] * key_scale[2], c * key_scale[3]};
    std::array<std::vector<std::int64_t>, 4> options;
    for (int a = 0; a < 4; ++a) {
      const std::int64_t r = std::llround(value[a]);
      const double margin = tolerance * key_scale[a] * (a == 3 ? m_scale : 1) + 1e-3, off = value[a] - double(r);
      options[a] = {r};
      if (off > 0.5 - margin) options[a].push_back(r + 1);
      if (off < margin - 0.5) options[a].push_back(r - 1);
    }
    std::vector<std::size_t> chosen;
    for (std::int64_t k0 : options[0])
      for (std::int64_t k1 : options[1])
        for (std::int64_t k2 : options[2])
          for (std::int64_t k3 : options[3]) {
            const auto range = m_by_plane.equal_range(Key{k0, k1, k2, k3});
            for (auto it = range.first; it != range.second; ++it) chosen.push_back(it->second);
          }
    std::sort(chosen.begin(), chosen.end());
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    std::vector<std::size_t> in_plane;
    for (std::size_t f : chosen) {
      const Vec3<double>& u = m_facets[f].normal;
      const double s = dot(u, Vec3<double>{n[0], n[1], n[2]}) >= 0 ? 1 : -1;
      bool same = std::abs(s * m_facets[f].offset - c) <= tolerance * m_scale;
      for (int a = 0; a < 3; ++a) same &= std::abs(s * u[a] - n[a]) <= tolerance;
      if (same) in_plane.push_back(f);
    }
    m_plane = {std::move(in_plane), drop};
    m_border = nullptr;
    m_parts = nullptr;
    return !m_plane.first.empty();
  }

  /// Does the triangle with these corners, each moved `inset` towards its centroid (beyond
  /// the rounding of its corners), projected along the plane's axis, meet no piece of the
  /// border of the union of the plane's facets? (Then, if one of its points is in the union,
  /// all of it is.) @pre set_plane() was called (the plane whose facets are asked).
  bool covers(const std::array<std::array<double, 3>, 3>& corners, double inset)
  {
    if (!m_border) { // (a plane is asked for again by no_face_over_hole() after plane_triangles())
      auto known = m_borders.find(m_plane);
      if (known == m_borders.end()) {
        std::vector<Polygon> polygons;
        for (std::size_t f : m_plane.first) add_polygon(f, polygons);
        known = m_borders.emplace(m_plane, border(polygons)).first;
      }
      m_border = &known->second;
    }
    std::array<EK::Point_2, 3> t;
    for (int k = 0; k < 3; ++k) {
      double u[2], length = 0;
      for (int a = 0; a < 2; ++a) {
        const int c = (m_plane.second + 1 + a) % 3;
        u[a] = (corners[0][c] + corners[1][c] + corners[2][c]) / 3 - corners[k][c];
        length += u[a] * u[a];
      }
      length = std::sqrt(length);
      if (!(length > 0)) return false;
      t[k] = EK::Point_2(corners[k][(m_plane.second + 1) % 3] + inset / length * u[0],
                         corners[k][(m_plane.second + 2) % 3] + inset / length * u[1]);
    }
    const EK::Triangle_2 triangle(t[0], t[1], t[2]);
    const CGAL::Bbox_2 box = triangle.bbox();
    for (const auto& [piece, piece_box] : *m_border)
      if (CGAL::do_overlap(box, piece_box) && CGAL::do_intersect(piece, triangle)) return false;
    return true;
  }

  /// Do the corners of this triangle of the plane lie on no one part of the union of the
  /// plane's facets (its connected pieces, facets nearer than a billionth of the model's
  /// size taken as meeting), each on some part? Such a triangle joins two pieces of a plane
  /// across a gap, such as the two sides of a slit narrower than the points' spacing: a
  /// membrane over its mouth. (A triangle that cuts a reflex corner of a face, partly off
  /// the facets too, has its corners on one part.) @pre set_plane() was called.
  bool joins_separate_parts(const std::array<std::array<double, 3>, 3>& corners)
  {
    Plane_parts::Part_list common;
    for (int k = 0; k < 3; ++k) {
      const Plane_parts::Part_list of_corner =
        parts().holding({corners[k][(m_plane.second + 1) % 3], corners[k][(m_plane.second + 2) % 3]});
      if (of_corner.empty()) return false; // (not on this plane's facets: nothing known)
      if (k == 0) common = of_corner;
      else {
        Plane_parts::Part_list both;
        std::set_intersection(common.begin(), common.end(), of_corner.begin(), of_corner.end(), std::back_inserter(both));
        common = std::move(both);
      }
    }
    return common.empty();
  }

  /// The middle of each gap between the plane's facets along the sides of this triangle of
  /// the plane whose ends lie on no one part (see joins_separate_parts()): where the side
  /// crosses from one part to another. Along a side, the stretches its facets cover are
  /// found in doubles (Plane_parts::covered_along()); stretches shorter than the parts'
  /// tolerance are not gaps.
  /// @pre set_plane() was called.
  std::vector<std::array<double, 3>> gaps_between_parts(const std::array<std::array<double, 3>, 3>& corners)
  {
    const int x = (m_plane.second + 1) % 3, y = (m_plane.second + 2) % 3;
    std::vector<std::array<double, 3>> out;
    for (int k = 0; k < 3; ++k) {
      const std::array<double, 3>& a = corners[k];
      const std::array<double, 3>& b = corners[(k + 1) % 3];
      const Plane_parts::Part_list pa = parts().holding({a[x], a[y]}), pb = parts().holding({b[x], b[y]});
      Plane_parts::Part_list both;
      std::set_intersection(pa.begin(), pa.end(), pb.begin(), pb.end(), std::back_inserter(both));
      if (pa.empty() || pb.empty() || !both.empty()) continue;
      std::vector<std::pair<double, double>> covered = parts().covered_along({a[x], a[y]}, {b[x], b[y]});
      covered.emplace_back(1, 1); // (the ends lie on parts, within the tolerance)
      std::sort(covered.begin(), covered.end());
      const double length = std::sqrt((b[x] - a[x]) * (b[x] - a[x]) + (b[y] - a[y]) * (b[y] - a[y]));
      const double shortest = length > 0 ? tolerance * m_scale / length : 1;
      double reached = 0;
      for (const auto& [from, to] : covered) {
        if (from - reached > shortest) {
          const double t = (reached + from) / 2;
          out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
        }
        reached = (std::max)(reached, to);
      }
    }
    return out;
  }

private:
  using Key = std::array<std::int64_t, 4>;
  using Plane = std::pair<std::vector<std::size_t>, int>; // (facets, axis dropped)

  /// The parts of the selected plane's facets, made when first asked for.
  const Plane_parts& parts()
  {
    if (!m_parts) m_parts = &m_parts_by_plane.try_emplace(m_plane, parts_of_plane()).first->second;
    return *m_parts;
  }

  /// The selected plane's facets projected on its axes (rounded), and their parts.
  Plane_parts parts_of_plane() const
  {
    const int x = (m_plane.second + 1) % 3, y = (m_plane.second + 2) % 3;
    std::vector<std::vector<std::array<double, 2>>> polygons;
    for (std::size_t f : m_plane.first) {
      polygons.emplace_back();
      for (const auto& c : facet_corners(m_facets[f].pair)) polygons.back().push_back({c[x], c[y]});
    }
    return Plane_parts(polygons, tolerance * m_scale);
  }
  /// A corner of a projected facet: the point, and its coordinates (exact sums p + q) each
  /// as the pair (rounded sum, rounding error), which is equal for equal points only.
  struct Corner
  {
    EK::Point_2 point;
    std::array<double, 4> sum;
    bool operator==(const Corner& other) const { return sum == other.sum; }
  };
  using Polygon = std::vector<Corner>; // convex, counterclockwise
  using Border = std::vector<std::pair<EK::Segment_2, CGAL::Bbox_2>>; // pieces with their boxes
  struct Facet
  {
    Feature_pair pair;
    Vec3<double> normal; // unit (rounded)
    double offset;       // normal . (a corner)
  };

  /// Relative to 1 for normals, to the model's size for offsets and positions: equal planes,
  /// and pieces of one that meet, within it.
  static constexpr double tolerance = 1e-9;
  static constexpr std::array<double, 4> key_scale = {1e6, 1e6, 1e6, 1e3};
  static Key key(const Vec3<double>& u, double c)
  {
    return Key{std::llround(u[0] * key_scale[0]), std::llround(u[1] * key_scale[1]), std::llround(u[2] * key_scale[2]),
               std::llround(c * key_scale[3])};
  }

  /// The corners of the convolution facet of `pair` in cyclic order (rounded sums p + q).
  std::vector<std::array<double, 3>> facet_corners(const Feature_pair& pair) const
  {
    std::vector<std::array<double, 3>> out;
    for (const auto& [i, j] : corner_indices(pair)) out.push_back(m_p.points[i] + m_q.points[j]);
    return out;
  }

  /// The (vertex of P, vertex of Q) of each corner of the facet of `pair`, in cyclic order.
  std::vector<std::pair<Index, Index>> corner_indices(const Feature_pair& pair) const
  {
    std::vector<std::pair<Index, Index>> out;
    if (pair.p.dimension == 0)
      for (Index w : m_q.triangles[pair.q.index]) out.emplace_back(pair.p.index, w);
    else if (pair.q.dimension == 0)
      for (Index v : m_p.triangles[pair.p.index]) out.emplace_back(v, pair.q.index);
    else {
      const auto& a = m_p.edges[pair.p.index].v;
      const auto& b = m_q.edges[pair.q.index].v;
      out = {{a[0], b[0]}, {a[1], b[0]}, {a[1], b[1]}, {a[0], b[1]}};
    }
    return out;
  }

  /// a + b exactly: the rounded sum and its rounding error (Knuth's TwoSum, which needs
  /// rounding to nearest).
  static std::array<double, 2> two_sum(double a, double b)
  {
    CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
  }

  /// Appends facet f's projection, exactly (each coordinate the exact sum p + q),
  /// counterclockwise; none if it projects to a segment.
  void add_polygon(std::size_t f, std::vector<Polygon>& polygons) const
  {
    Polygon polygon;
    for (const std::pair<Index, Index>& corner : corner_indices(m_facets[f].pair)) {
      const auto &p = m_p.points[corner.first], &q = m_q.points[corner.second];
      const int x = (m_plane.second + 1) % 3, y = (m_plane.second + 2) % 3;
      const std::array<double, 2> sx = two_sum(p[x], q[x]), sy = two_sum(p[y], q[y]);
      polygon.push_back(Corner{EK::Point_2(EK::FT(p[x]) + EK::FT(q[x]), EK::FT(p[y]) + EK::FT(q[y])),
                               {sx[0], sx[1], sy[0], sy[1]}});
    }
    const CGAL::Orientation o = CGAL::orientation(polygon[0].point, polygon[1].point, polygon[2].point);
    if (o == CGAL::COLLINEAR) return;
    if (o == CGAL::CLOCKWISE) std::reverse(polygon.begin(), polygon.end());
    polygons.push_back(std::move(polygon));
  }

  /// The border of the union of `polygons`: the stretches of each polygon's edges (the
  /// polygon on their left) whose right side no other polygon covers.
  static Border border(const std::vector<Polygon>& polygons)
  {
    Border out;
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;
    std::vector<Box> edges, polygon_boxes;
    std::vector<std::pair<std::size_t, std::size_t>> edge_ids; // (polygon, corner)
    for (std::size_t g = 0; g < polygons.size(); ++g) {
      CGAL::Bbox_2 box;
      for (std::size_t k = 0; k < polygons[g].size(); ++k) {
        const CGAL::Bbox_2 e = polygons[g][k].point.bbox() + polygons[g][(k + 1) % polygons[g].size()].point.bbox();
        edges.emplace_back(e, edge_ids.size());
        edge_ids.emplace_back(g, k);
        box += e;
      }
      polygon_boxes.emplace_back(box, g);
    }
    std::vector<std::vector<std::size_t>> near(edge_ids.size()); // edge -> polygons near it
    CGAL::box_intersection_d(edges.begin(), edges.end(), polygon_boxes.begin(), polygon_boxes.end(),
                             [&](const Box& e, const Box& g) {
                               if (g.info() != edge_ids[e.info()].first) near[e.info()].push_back(g.info());
                             });
    for (std::size_t e = 0; e < edge_ids.size(); ++e) {
      const Polygon& own = polygons[edge_ids[e].first];
      const Corner &a = own[edge_ids[e].second], &b = own[(edge_ids[e].second + 1) % own.size()];
      std::vector<std::pair<EK::FT, EK::FT>> covered; // parameters along a -> b
      bool whole = false;
      for (std::size_t i = 0; i < near[e].size() && !whole; ++i) whole = right_cover(a, b, polygons[near[e][i]], covered);
      if (whole) continue; // (most edges inside a face: a neighbour shares them)
      std::sort(covered.begin(), covered.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      EK::FT reached = 0; // [0, reached] covered, or a piece of border ends there
      for (const auto& [from, to] : covered) {
        if (!(reached < 1)) break;
        if (reached < from) add_piece(a.point, b.point, reached, (CGAL::min)(from, EK::FT(1)), out);
        if (reached < to) reached = to;
      }
      if (reached < 1) add_piece(a.point, b.point, reached, 1, out);
    }
    return out;
  }

  /// Appends the parameters along a -> b of the stretch of that line whose right side
  /// polygon g covers (through g's interior, or along an edge of g with g on the right), if
  /// any; true if that stretch holds all of a -> b (then perhaps nothing is appended).
  static bool right_cover(const Corner& a, const Corner& b, const Polygon& g,
                          std::vector<std::pair<EK::FT, EK::FT>>& covered)
  {
    // The sides first, by the filtered predicate; constructions only for a polygon that the
    // line meets, and none at a corner that is a or b.
    std::vector<CGAL::Sign> side;
    bool right = false, left = false, has_a = false, has_b = false;
    int on = 0;
    for (const Corner& x : g) {
      side.push_back(CGAL::orientation(a.point, b.point, x.point));
      right |= side.back() == CGAL::NEGATIVE;
      left |= side.back() == CGAL::POSITIVE;
      on += side.back() == CGAL::ZERO;
      has_a |= x == a;
      has_b |= x == b;
    }
    if (!right || (!left && on < 2)) return false;
    if (has_a && has_b) return true; // (g convex, with a corner right of a -> b)
    const EK::Vector_2 ab = b.point - a.point;
    auto area = [&](const EK::Point_2& x) { return ab.x() * (x.y() - a.point.y()) - ab.y() * (x.x() - a.point.x()); };
    auto along = [&](const EK::Point_2& x) { return ((x - a.point) * ab) / ab.squared_length(); };
    std::vector<EK::FT> at; // where the line meets g's border
    for (std::size_t k = 0; k < g.size(); ++k) {
      const std::size_t l = (k + 1) % g.size();
      if (side[k] == CGAL::ZERO) at.push_back(g[k] == a ? EK::FT(0) : g[k] == b ? EK::FT(1) : along(g[k].point));
      else if (side[k] * side[l] == CGAL::NEGATIVE) {
        const EK::FT sk = area(g[k].point), sl = area(g[l].point);
        at.push_back(along(g[k].point + (sk / (sk - sl)) * (g[l].point - g[k].point)));
      }
    }
    const auto [lo, hi] = std::minmax_element(at.begin(), at.end());
    if (!(*lo < *hi)) return false;
    covered.emplace_back(*lo, *hi);
    return !(*lo > 0) && !(*hi < 1);
  }

  static void add_piece(const EK::Point_2& a, const EK::Point_2& b, const EK::FT& from, const EK::FT& to, Border& out)
  {
    if (!(from < to) || !(to > 0)) return;
    const EK::FT f = (CGAL::max)(from, EK::FT(0));
    const EK::Segment_2 piece(a + f * (b - a), a + to * (b - a));
    out.emplace_back(piece, piece.bbox());
  }

  const Mesh_data& m_p;
  const Mesh_data& m_q;
  std::vector<Facet> m_facets;
  std::multimap<Key, std::size_t> m_by_plane;
  double m_scale = 0;
  Plane m_plane;                    // the selected one
  const Border* m_border = nullptr; // its border, in m_borders (once asked)
  const Plane_parts* m_parts = nullptr; // its parts, in m_parts_by_plane (once asked)
  std::map<Plane, Border> m_borders;
  std::map<Plane, Plane_parts> m_parts_by_plane;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_FACE_COVER_H
