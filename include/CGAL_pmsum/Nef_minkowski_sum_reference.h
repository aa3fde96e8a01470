// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
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

#include <cctype>
#include <chrono>
#include <iterator>
#include <sstream>
#include <iostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Pmsum {

/// \ingroup PkgPointMinkowskiSumReference
/// The exact boundary of `P + Q` (or `-P + Q`) computed with `CGAL::minkowski_sum_3()` on Nef
/// polyhedra, to validate point-based results against: is_on_boundary() locates an exact
/// point, shells() gives the boundary shell by shell (outer boundaries and voids) for
/// measure_boundary_coverage(). It can be saved to and read from CGAL's exact Nef file format
/// (.nef3), so that slow Nef computations are done once.
class Nef_minkowski_sum_reference
{
public:
  using Kernel = CGAL::Exact_predicates_exact_constructions_kernel; ///< the exact kernel of the Nef polyhedron
  using Nef = CGAL::Nef_polyhedron_3<Kernel>;                       ///< the Nef polyhedron type
  using Point_3 = Kernel::Point_3;                                  ///< an exact point

  /// Computes the exact sum (regularized). The solid of a mesh is the set of points inside
  /// an odd number of its closed components, whatever their orientation: a component inside
  /// another bounds a void.
  ///
  /// \tparam MeshP, MeshQ models of `FaceListGraph` with an internal vertex point map
  /// \param P the first mesh
  /// \param Q the second mesh
  /// \param negate_p compute `-P + Q` (the contact space) instead of `P + Q`
  /// \pre `P` and `Q` are closed; their coordinates are exactly representable as `double`;
  ///      their components do not cross each other.
  /// \throws Invalid_input if `P` or `Q` has a border
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

  /// Reads a reference saved with save(). The whole stream is read and checked first (CGAL's
  /// reader would build a broken Nef polyhedron from a truncated file); seconds() is then 0.
  /// \param in the stream to read from (to its end)
  /// \throws Invalid_input if the text is not a whole, consistent Nef complex
  explicit Nef_minkowski_sum_reference(std::istream& in)
  {
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    check_nef3_layout(text);
    std::istringstream parsed(text);
    parsed >> m_nef;
    if (!parsed || !m_nef.is_valid()) throw Invalid_input("the exact Nef boundary is not a valid Nef complex");
  }

  /// Writes the sum in CGAL's exact Nef file format (.nef3), for the constructor that reads it.
  /// \param out the stream to write to
  void save(std::ostream& out) const
  {
    Nef copy = m_nef; // CGAL's operator<< takes a non-const Nef; copies share their data
    out << copy;
  }

  /// Tells how long the computation took.
  /// \returns the seconds taken by `CGAL::minkowski_sum_3()` (with the conversions), 0 if
  ///          read from a stream
  double seconds() const { return m_seconds; }
  /// Gives the exact sum.
  /// \returns the regularized Nef polyhedron of the sum
  const Nef& nef() const { return m_nef; }

  /// Exact: is `x` on the boundary of the sum?
  /// \param x an exact point
  /// \returns `true` if `x` lies on the boundary (a vertex, edge or facet of the Nef
  ///          polyhedron), `false` if it lies in the interior or the exterior of the sum
  bool is_on_boundary(const Point_3& x) const
  {
    typename Nef::Volume_const_handle v;
    return !CGAL::assign(v, m_nef.locate(x));
  }

  /// Computes the boundary surfaces of the solid volumes, each once, triangulated and rounded
  /// to double. In each connected solid the shell with the largest bounding box is its outer
  /// boundary; the others bound voids.
  /// \returns the shells, with Shell::is_void set, for measure_boundary_coverage()
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

  /// Appends the triangles of all shells() to a triangle soup, to write an OFF file for instance.
  /// \param points the soup's points, to which those of the shells are appended
  /// \param triangles the soup's triangles, to which those of the shells are appended (as
  ///        indices into `points`)
  void triangle_soup(std::vector<std::array<double, 3>>& points, std::vector<std::array<std::size_t, 3>>& triangles) const
  {
    for (const Shell& s : shells()) {
      const std::size_t off = points.size();
      points.insert(points.end(), s.points.begin(), s.points.end());
      for (const auto& t : s.triangles) triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    }
  }

private:
  /// The layout CGAL's writer gives (SNC_io_parser::print): header, seven section counts, one
  /// line per item numbered from 0 in each section, end marker. CGAL's reader checks most
  /// indices but stops silently at a short or mislabelled line, leaving items unset; and it
  /// allocates every item from the counts first.
  static void check_nef3_layout(const std::string& text)
  {
    auto fail = [](const std::string& why) { throw Invalid_input("not an exact Nef boundary (.nef3): " + why); };
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
      if (!line.empty()) lines.push_back(line);
    }
    if (lines.size() < 10 || lines[0] != "Selective Nef Complex") fail("no 'Selective Nef Complex' header");
    if (lines[1] != "standard") fail("kernel type '" + lines[1] + "', expected 'standard'");
    std::size_t line = 2, total = 0;
    std::vector<std::size_t> counts;
    for (const char* section : {"vertices", "halfedges", "facets", "volumes", "shalfedges", "shalfloops", "sfaces"}) {
      std::istringstream l(lines[line]);
      std::string name;
      long long n = -1;
      if (!(l >> name >> n) || name != section || n < 0 || !(l >> std::ws).eof())
        fail("line " + std::to_string(line + 1) + ": expected '" + section + " COUNT'");
      if (std::size_t(n) > lines.size()) fail(std::string("more ") + section + " than lines");
      counts.push_back(std::size_t(n));
      total += std::size_t(n);
      ++line;
    }
    if (lines.size() != line + total + 1 || lines.back() != "/* end Selective Nef complex */")
      fail("truncated, or items missing or in excess: " + std::to_string(lines.size()) + " lines for " +
           std::to_string(total) + " items");
    for (std::size_t n : counts)
      for (std::size_t i = 0; i < n; ++i, ++line) {
        std::istringstream l(lines[line]);
        long long index = -1;
        std::string brace;
        if (!(l >> index >> brace) || index != static_cast<long long>(i) || brace != "{" ||
            lines[line].find('}') == std::string::npos)
          fail("line " + std::to_string(line + 1) + " is not item " + std::to_string(i) + " of its section");
      }
  }

  /// The solid bounded by the closed components of `pm`, voids included (components touching
  /// along edges or faces, as in non-manifold inputs split by CGAL's reader, are merged exactly).
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
    // The solid is the set of points inside an odd number of components (a void is a
    // component inside another; the components do not cross): the symmetric difference of
    // their interiors. Regularizing puts back the faces that components share back to back.
    std::vector<EMesh> parts;
    CGAL::Polygon_mesh_processing::split_connected_components(m, parts);
    Nef result;
    for (EMesh& part : parts) {
      if (!CGAL::Polygon_mesh_processing::is_outward_oriented(part))
        CGAL::Polygon_mesh_processing::reverse_face_orientations(part);
      result ^= Nef(part);
    }
    return result.regularization();
  }

  Nef m_nef;
  double m_seconds = 0;
};

} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_NEF_MINKOWSKI_SUM_REFERENCE_H
