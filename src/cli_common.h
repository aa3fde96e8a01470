// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Helpers of the pmsum command-line tool: checked mesh reading, output files that appear
// only when complete, a JSON writer, a progress bar.

#ifndef CGAL_PMSUM_CLI_COMMON_H
#define CGAL_PMSUM_CLI_COMMON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <array>
#include <vector>

namespace pmsum_cli {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// An error the user can fix: printed as one line, exit code 1.
struct Error : std::runtime_error { using std::runtime_error::runtime_error; };
/// A command-line mistake: printed with a usage hint, exit code 2.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };
/// A run refused because it would exhaust the machine (--force overrides): exit code 3.
struct Refused : std::runtime_error { using std::runtime_error::runtime_error; };

inline std::string extension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string e = path.substr(dot + 1);
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

/// Notes for the user (stderr), e.g. "triangulated 6 faces".
inline void note(const std::string& msg, bool quiet)
{
  if (!quiet) std::cerr << "pmsum: note: " << msg << "\n";
}

/// Reads a mesh (OFF, OBJ, PLY, STL), repairing the polygon soup on the way (CGAL's PMP
/// reader: duplicated points, non-manifold edges and vertices, inconsistent orientation).
/// Non-triangle faces are triangulated and closed meshes oriented outward, with a note.
inline Mesh read_mesh(const std::string& path, const std::string& name, bool quiet)
{
  const std::string what = name + " ('" + path + "')";
  const std::string ext = extension(path);
  if (ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    throw Error("cannot read " + what + ": unknown format '." + ext + "' (use .off, .obj, .ply or .stl)");
  if (!std::ifstream(path).good()) throw Error("cannot read " + what + ": no such file or not readable");
  Mesh m;
  bool ok = false;
  try {
    ok = PMP::IO::read_polygon_mesh(path, m, CGAL::parameters::verbose(false));
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) throw Error("cannot read " + what + ": malformed or not a polygon mesh");
  if (m.number_of_faces() == 0) throw Error(what + " has no faces");
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Error(what + " has a vertex with a coordinate that is not finite (NaN or infinity)");
  }
  std::size_t polygons = 0;
  for (auto f : m.faces()) polygons += (m.degree(f) != 3);
  if (polygons > 0) {
    if (!PMP::triangulate_faces(m))
      throw Error(what + " has faces that cannot be triangulated");
    note(what + ": triangulated " + std::to_string(polygons) + " non-triangle faces", quiet);
  }
  if (CGAL::is_closed(m)) {
    // CGAL's does_bound_a_volume() accepts either global orientation: orient, then count
    // the faces whose vertex cycle changed.
    std::vector<std::array<Mesh::Vertex_index, 3>> before;
    for (auto f : m.faces()) {
      auto h = m.halfedge(f);
      before.push_back({m.source(h), m.target(h), m.target(m.next(h))});
    }
    PMP::orient_to_bound_a_volume(m);
    std::size_t flipped = 0, i = 0;
    for (auto f : m.faces()) {
      const auto h = m.halfedge(f);
      const auto& b = before[i++];
      const Mesh::Vertex_index s = m.source(h), t = m.target(h);
      flipped += !((s == b[0] && t == b[1]) || (s == b[1] && t == b[2]) || (s == b[2] && t == b[0]));
    }
    if (flipped > 0)
      note(what + " was not oriented outward: reversed " + std::to_string(flipped) + " of " +
             std::to_string(m.number_of_faces()) + " faces to bound its volume", quiet);
  }
  return m;
}

/// Diagonal of the bounding box of P + Q (the sum of the two boxes).
inline double sum_diagonal(const Mesh& P, const Mesh& Q)
{
  const CGAL::Bbox_3 a = PMP::bbox(P), b = PMP::bbox(Q);
  double s = 0;
  for (int c = 0; c < 3; ++c) s += std::pow((a.max(c) - a.min(c)) + (b.max(c) - b.min(c)), 2);
  return std::sqrt(s);
}

/// Multiplies every coordinate by s.
inline void scale_mesh(Mesh& m, double s)
{
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    m.point(v) = K::Point_3(p.x() * s, p.y() * s, p.z() * s);
  }
}

/// A point with a normal, as written to PLY / XYZ.
struct Oriented_point { double p[3], n[3]; };

/// Writes points to `path` (.ply binary little-endian, or .xyz ASCII) through a temporary
/// file renamed at the end, so that an interrupted run leaves no partial output.
inline void write_points(const std::string& path, const std::vector<Oriented_point>& pts)
{
  const std::string ext = extension(path);
  const std::string tmp = path + ".part" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw Error("cannot write '" + path + "'");
    if (ext == "ply") {
      out << "ply\nformat binary_little_endian 1.0\ncomment CGAL_pmsum boundary points of a Minkowski sum\n"
          << "element vertex " << pts.size() << "\n"
          << "property double x\nproperty double y\nproperty double z\n"
          << "property double nx\nproperty double ny\nproperty double nz\nend_header\n";
      static_assert(sizeof(Oriented_point) == 6 * sizeof(double), "packed doubles");
      const std::uint16_t probe = 1;
      if (*reinterpret_cast<const unsigned char*>(&probe) != 1) throw Error("big-endian hosts are not supported");
      out.write(reinterpret_cast<const char*>(pts.data()), std::streamsize(pts.size() * sizeof(Oriented_point)));
    } else {
      out << std::setprecision(17);
      for (const auto& o : pts)
        out << o.p[0] << ' ' << o.p[1] << ' ' << o.p[2] << ' ' << o.n[0] << ' ' << o.n[1] << ' ' << o.n[2] << '\n';
    }
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw Error("cannot write '" + path + "' (disk full?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error("cannot write '" + path + "'");
  }
}

/// Minimal JSON object writer (keys in insertion order).
class Json
{
public:
  Json& add(const std::string& key, const std::string& raw)
  {
    m_items.push_back("\"" + key + "\": " + raw);
    return *this;
  }
  Json& str(const std::string& key, const std::string& v) { return add(key, quote(v)); }
  Json& num(const std::string& key, double v)
  {
    std::ostringstream s;
    s << std::setprecision(10) << v;
    return add(key, s.str());
  }
  Json& integer(const std::string& key, std::size_t v) { return add(key, std::to_string(v)); }
  Json& boolean(const std::string& key, bool v) { return add(key, v ? "true" : "false"); }
  Json& object(const std::string& key, const Json& o) { return add(key, o.dump(1)); }
  std::string dump(int indent = 0) const
  {
    const std::string pad(2 * (indent + 1), ' '), end(2 * indent, ' ');
    std::string s = "{\n";
    for (std::size_t i = 0; i < m_items.size(); ++i) s += pad + m_items[i] + (i + 1 < m_items.size() ? ",\n" : "\n");
    return s + end + "}";
  }
  static std::string quote(const std::string& v)
  {
    std::string s = "\"";
    for (char c : v) {
      if (c == '"' || c == '\\') s += '\\';
      s += c;
    }
    return s + "\"";
  }

private:
  std::vector<std::string> m_items;
};

inline void write_json(const std::string& path, const Json& j)
{
  std::ofstream out(path);
  out << j.dump() << "\n";
  if (!out) throw Error("cannot write '" + path + "'");
}

/// Progress bar on stderr, shown only on a terminal and once a run has lasted a second.
class Progress
{
public:
  explicit Progress(bool enabled) : m_enabled(enabled && ::isatty(2)), m_start(std::chrono::steady_clock::now()) {}
  bool operator()(double fraction)
  {
    if (!m_enabled) return true;
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    if (t < 1.0) return true;
    const int width = 40, filled = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%  %.1f s", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), int(fraction * 100 + 0.5), t);
    m_drawn = true;
    return true;
  }
  ~Progress() { if (m_drawn) std::fprintf(stderr, "\n"); }

private:
  bool m_enabled, m_drawn = false;
  std::chrono::steady_clock::time_point m_start;
};

/// Memory the process may use for output points, from /proc/meminfo (half of MemAvailable).
inline std::size_t memory_budget_bytes()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::size_t kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024 / 2;
  return std::size_t(4) << 30;
}

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_COMMON_H
