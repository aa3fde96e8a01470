// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// CGAL::Pmsum::Nef_minkowski_sum_reference: the exact boundary of P + Q (or -P + Q) computed
// with CGAL::minkowski_sum_3 on Nef polyhedra, to validate point-based results against:
//   - is_on_boundary(x): exact point location of an exact point;
//   - shells(): the boundary, shell by shell (outer boundaries and voids), for coverage.
// It can be saved to and read from CGAL's exact Nef file format (.nef3), so that slow Nef
// computations are done once.
//
// Including this header compiles CGAL's Nef package: keep it out of most translation units.

#ifndef CGAL_PMSUM_NEF_MINKOWSKI_SUM_REFERENCE_H
#define CGAL_PMSUM_NEF_MINKOWSKI_SUM_REFERENCE_H

#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/measure_boundary_coverage.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/IO/Nef_polyhedron_iostream_3.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/minkowski_sum_3.h>

#include <boost/property_map/function_property_map.hpp>

#include <chrono>
#include <iostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

class Nef_minkowski_sum_reference
{
public:
  using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
  using Nef = CGAL::Nef_polyhedron_3<Kernel>;
  using Point_3 = Kernel::Point_3;

  /// Computes the exact sum. P and Q must be closed triangle meshes (outward oriented).
  template <class MeshP, class MeshQ>
  Nef_minkowski_sum_reference(const MeshP& P, const MeshQ& Q, bool negate_p = false)
  {
    const auto start = std::chrono::steady_clock::now();
    // -P is built from the negated mesh: Nef's transform() with a reflection leaves a
    // polyhedron on which CGAL 5.5's convex decomposition fails an assertion.
    Nef np = to_nef(P, "P", negate_p), nq = to_nef(Q, "Q", false);
    m_nef = CGAL::minkowski_sum_3(np, nq).regularization();
    m_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// Reads a reference saved with save().
  explicit Nef_minkowski_sum_reference(std::istream& in)
  {
    in >> m_nef;
    if (!in && !in.eof()) throw Invalid_input("cannot read the exact Nef boundary");
  }

  void save(std::ostream& out) const
  {
    Nef copy = m_nef; // CGAL's operator<< takes a non-const Nef; copies share their data
    out << copy;
  }

  /// Seconds taken by minkowski_sum_3 (with the conversions), 0 if read from a file.
  double seconds() const { return m_seconds; }
  const Nef& nef() const { return m_nef; }

  /// Exact: is x on the boundary of the sum?
  bool is_on_boundary(const Point_3& x) const
  {
    typename Nef::Volume_const_handle v;
    return !CGAL::assign(v, m_nef.locate(x));
  }

  /// The boundary surfaces of the solid volumes, each once, triangulated and rounded to
  /// double. In each connected solid the shell with the largest bounding box is its outer
  /// boundary; the others bound voids.
  std::vector<Shell> shells() const
  {
    using Shell_iterator = typename Nef::Shell_entry_const_iterator;
    using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Converter = CGAL::Cartesian_converter<Kernel, Epick>;
    std::vector<Shell> out;
    auto v = m_nef.volumes_begin();
    if (Nef::Infi_box::extended_kernel()) ++v;
    ++v; // the unbounded volume
    for (; v != m_nef.volumes_end(); ++v) {
      if (!v->mark()) continue;
      const std::size_t first = out.size();
      double largest = -1;
      std::size_t outer = first;
      for (Shell_iterator s = v->shells_begin(); s != v->shells_end(); ++s) {
        std::vector<Epick::Point_3> points;
        std::vector<std::vector<std::size_t>> polygons;
        CGAL::nef_to_pm::collect_polygon_mesh_info(points, polygons, m_nef, s, Converter(), true);
        Shell shell;
        CGAL::Bbox_3 box;
        for (const auto& p : points) {
          shell.points.push_back({p.x(), p.y(), p.z()});
          box += p.bbox();
        }
        for (const auto& poly : polygons)
          if (poly.size() == 3) shell.triangles.push_back({poly[0], poly[1], poly[2]});
        const double size = (box.xmax() - box.xmin()) + (box.ymax() - box.ymin()) + (box.zmax() - box.zmin());
        if (size > largest) { largest = size; outer = out.size(); }
        out.push_back(shell);
      }
      for (std::size_t i = first; i < out.size(); ++i) out[i].is_void = (i != outer);
    }
    return out;
  }

  /// Triangles of all shells, as one soup (for writing an OFF file).
  void triangle_soup(std::vector<std::array<double, 3>>& points, std::vector<std::array<std::size_t, 3>>& triangles) const
  {
    for (const Shell& s : shells()) {
      const std::size_t off = points.size();
      points.insert(points.end(), s.points.begin(), s.points.end());
      for (const auto& t : s.triangles) triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    }
  }

private:
  /// Union of the Nef polyhedra of the closed components of `pm` (components touching along
  /// edges, as in non-manifold inputs split by CGAL's reader, are merged exactly).
  template <class Mesh>
  static Nef to_nef(const Mesh& pm, const std::string& name, bool negate)
  {
    using EMesh = CGAL::Surface_mesh<Point_3>;
    EMesh m;
    auto vpm = get(CGAL::vertex_point, pm);
    const double s = negate ? -1 : 1;
    auto to_exact = [&](typename boost::graph_traits<Mesh>::vertex_descriptor vd) {
      const auto& p = get(vpm, vd);
      return Point_3(s * CGAL::to_double(p.x()), s * CGAL::to_double(p.y()), s * CGAL::to_double(p.z()));
    };
    CGAL::copy_face_graph(pm, m, CGAL::parameters::vertex_point_map(boost::make_function_property_map<
                                                                        typename boost::graph_traits<Mesh>::vertex_descriptor,
                                                                        Point_3>(to_exact)));
    if (!CGAL::is_closed(m))
      throw Invalid_input(name + " has a border: the Nef reference needs closed meshes");
    if (negate) CGAL::Polygon_mesh_processing::reverse_face_orientations(m);
    std::vector<EMesh> parts;
    CGAL::Polygon_mesh_processing::split_connected_components(m, parts);
    Nef result;
    for (const EMesh& part : parts) result += Nef(part);
    return result;
  }

  Nef m_nef;
  double m_seconds = 0;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_NEF_MINKOWSKI_SUM_REFERENCE_H
