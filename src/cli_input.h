// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh input of the pmsum command-line tool. A file is read into a polygon soup, every
// count its header declares checked against the file's size before anything is allocated
// (OFF and PLY are parsed here; binary STL must be exactly as long as its triangle count
// says; OBJ and ASCII STL, which declare no counts, are read by CGAL), data past what the
// header declares refused, and every face checked (at least three distinct vertices, each
// index naming a vertex) before the mesh is built.

#ifndef CGAL_PMSUM_CLI_INPUT_H
#define CGAL_PMSUM_CLI_INPUT_H

#include "cli_errors.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace pmsum_cli {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

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

/// A polygon soup as read from a file.
struct Polygon_soup
{
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
};

namespace input_internal {

constexpr std::size_t bad_index = std::size_t(-1); // a negative index in the file

/// The lines of a text without comments ('#' to the end of the line) and blank lines, split
/// into tokens.
class Token_lines
{
public:
  explicit Token_lines(std::string_view text) : m_text(text) {}
  /// The next non-blank line's tokens; false at the end.
  bool next(std::vector<std::string_view>& tokens)
  {
    while (m_pos < m_text.size()) {
      std::size_t end = m_text.find('\n', m_pos);
      if (end == std::string_view::npos) end = m_text.size();
      std::string_view line = m_text.substr(m_pos, end - m_pos);
      m_pos = end + 1;
      ++m_line;
      line = line.substr(0, line.find('#'));
      split(line, tokens);
      if (!tokens.empty()) return true;
    }
    return false;
  }
  std::size_t line_number() const { return m_line; }
  std::size_t remaining_bytes() const { return m_pos < m_text.size() ? m_text.size() - m_pos : 0; }

  static void split(std::string_view line, std::vector<std::string_view>& tokens)
  {
    tokens.clear();
    std::size_t i = 0;
    auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (i < line.size()) {
      while (i < line.size() && space(line[i])) ++i;
      std::size_t j = i;
      while (j < line.size() && !space(line[j])) ++j;
      if (j > i) tokens.push_back(line.substr(i, j - i));
      i = j;
    }
  }

private:
  std::string_view m_text;
  std::size_t m_pos = 0, m_line = 0;
};

/// A non-negative integer token (false if it is anything else).
inline bool parse_count(std::string_view t, unsigned long long& x)
{
  if (t.empty() || t.size() > 19) return false;
  x = 0;
  for (char c : t) {
    if (c < '0' || c > '9') return false;
    x = x * 10 + unsigned(c - '0');
  }
  return true;
}

/// A vertex index token: non-negative, else bad_index (refused with the face).
inline bool parse_index(std::string_view t, std::size_t& i)
{
  unsigned long long x;
  if (!t.empty() && t[0] == '-') {
    if (!parse_count(t.substr(1), x)) return false;
    i = bad_index;
    return true;
  }
  if (!parse_count(t, x)) return false;
  i = x >= bad_index ? bad_index : std::size_t(x);
  return true;
}

inline bool parse_number(std::string_view t, double& x)
{
  const std::string s(t);
  char* end = nullptr;
  x = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == '\0';
}

/// Every face: at least three distinct vertices, each index naming a vertex.
inline void check_faces(const Polygon_soup& s, const std::string& what)
{
  std::vector<std::size_t> sorted;
  for (std::size_t i = 0; i < s.polygons.size(); ++i) {
    const auto& f = s.polygons[i];
    for (std::size_t v : f)
      if (v >= s.points.size())
        throw Error(what + " face " + std::to_string(i) + " names " +
                    (v == bad_index ? std::string("a vertex with a negative index")
                                    : "vertex " + std::to_string(v) + " (counting from 0)") +
                    ", but there are only " + std::to_string(s.points.size()) + " vertices");
    sorted.assign(f.begin(), f.end());
    std::sort(sorted.begin(), sorted.end());
    if (std::unique(sorted.begin(), sorted.end()) - sorted.begin() < 3)
      throw Error(what + " face " + std::to_string(i) + " has fewer than three distinct vertices");
  }
}

/// ASCII OFF (and its COFF, NOFF, STOFF... variants: extra values per vertex or face are
/// ignored).
inline Polygon_soup read_off(std::string_view text, const std::string& fail)
{
  Token_lines lines(text);
  std::vector<std::string_view> t;
  if (!lines.next(t)) throw Error(fail + "malformed OFF: the file is empty");
  const std::string keyword(t[0]);
  static const char* const variants[] = {"OFF", "COFF", "NOFF", "CNOFF", "NCOFF", "STOFF", "STCOFF", "STNOFF", "STCNOFF"};
  if (std::find(std::begin(variants), std::end(variants), keyword) == std::end(variants)) {
    if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0)
      throw Error(fail + "unsupported OFF variant '" + keyword + "' (3D OFF only)");
    throw Error(fail + "malformed OFF: the file does not start with OFF");
  }
  t.erase(t.begin());
  if (!t.empty() && t[0] == "BINARY") throw Error(fail + "binary OFF is not supported (convert it to ASCII OFF or PLY)");
  if (t.empty() && !lines.next(t)) throw Error(fail + "malformed OFF: no vertex and face counts");
  unsigned long long nv = 0, nf = 0, ne = 0;
  if (t.size() < 2 || !parse_count(t[0], nv) || !parse_count(t[1], nf) || (t.size() > 2 && !parse_count(t[2], ne)))
    throw Error(fail + "malformed OFF: expected the counts 'vertices faces edges'");
  // Each vertex takes at least 6 bytes ("0 0 0\n"), each face at least 8 ("3 0 1 2\n").
  const std::size_t size = text.size();
  if ((long double)(nv) * 6 + (long double)(nf) * 8 > (long double)(size))
    throw Error(fail + "the OFF header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                " faces, more than a file of " + std::to_string(size) + " bytes can hold");
  Polygon_soup s;
  s.points.reserve(nv);
  s.polygons.reserve(nf);
  for (unsigned long long i = 0; i < nv; ++i) {
    if (!lines.next(t))
      throw Error(fail + "malformed OFF: " + std::to_string(nv) + " vertices declared, the file ends after " + std::to_string(i));
    double x[3];
    if (t.size() < 3 || !parse_number(t[0], x[0]) || !parse_number(t[1], x[1]) || !parse_number(t[2], x[2]))
      throw Error(fail + "malformed OFF: line " + std::to_string(lines.line_number()) + ": expected a vertex 'x y z'");
    s.points.emplace_back(x[0], x[1], x[2]);
  }
  for (unsigned long long i = 0; i < nf; ++i) {
    if (!lines.next(t))
      throw Error(fail + "malformed OFF: " + std::to_string(nf) + " faces declared, the file ends after " + std::to_string(i));
    unsigned long long n = 0;
    if (!parse_count(t[0], n))
      throw Error(fail + "malformed OFF: line " + std::to_string(lines.line_number()) + ": expected a face 'n i1 ... in'");
    if (n > t.size() - 1)
      throw Error(fail + "malformed OFF: face " + std::to_string(i) + " declares " + std::to_string(n) +
                  " vertices, its line has " + std::to_string(t.size() - 1) + " values");
    std::vector<std::size_t> f(n);
    for (std::size_t k = 0; k < n; ++k)
      if (!parse_index(t[k + 1], f[k]))
        throw Error(fail + "malformed OFF: face " + std::to_string(i) + ": '" + std::string(t[k + 1]) +
                    "' is not a vertex index");
    s.polygons.push_back(std::move(f));
  }
  if (lines.next(t))
    throw Error(fail + "the file holds more data than its OFF header declares (" + std::to_string(nv) + " vertices, " +
                std::to_string(nf) + " faces): line " + std::to_string(lines.line_number()));
  return s;
}

/// PLY, ASCII or binary: the x, y, z of the 'vertex' elements and the 'vertex_indices' (or
/// 'vertex_index') lists of the 'face' elements; other elements and properties are skipped.
inline Polygon_soup read_ply(std::string_view text, const std::string& fail)
{
  const std::string bad = fail + "malformed PLY: ";
  // Header.
  const std::size_t header_end = text.find("end_header");
  if (text.substr(0, 3) != "ply" || header_end == std::string_view::npos) throw Error(bad + "no 'ply ... end_header' header");
  std::size_t data = text.find('\n', header_end);
  if (data == std::string_view::npos) throw Error(bad + "nothing after the header");
  ++data;
  struct Property { std::string name; int type = 0, count_type = 0; bool list = false; };
  struct Element { std::string name; unsigned long long count = 0; std::vector<Property> properties; };
  std::vector<Element> elements;
  int format = -1; // 0 ascii, 1 binary little-endian, 2 binary big-endian
  auto type_size = [](std::string_view t) -> int {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
  };
  // type codes: size, negative for signed integers, +10 for floating point
  auto type_code = [&](std::string_view t) -> int {
    const int n = type_size(t);
    if (n == 0) return 0;
    if (t == "float" || t == "float32" || t == "double" || t == "float64") return 10 + n;
    return (t[0] == 'u') ? n : -n;
  };
  std::vector<std::string_view> t;
  std::size_t pos = 0;
  while (pos < header_end) {
    std::size_t end = text.find('\n', pos);
    Token_lines::split(text.substr(pos, end - pos), t);
    pos = end + 1;
    if (t.empty() || t[0] == "ply" || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "format" && t.size() >= 2) {
      format = t[1] == "ascii" ? 0 : t[1] == "binary_little_endian" ? 1 : t[1] == "binary_big_endian" ? 2 : -1;
      if (format < 0) throw Error(bad + "unknown format '" + std::string(t[1]) + "'");
    } else if (t[0] == "element" && t.size() == 3) {
      Element e;
      e.name = std::string(t[1]);
      if (!parse_count(t[2], e.count)) throw Error(bad + "bad count '" + std::string(t[2]) + "' of element " + e.name);
      elements.push_back(e);
    } else if (t[0] == "property" && !elements.empty()) {
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        p.list = true;
        p.count_type = type_code(t[2]);
        p.type = type_code(t[3]);
        p.name = std::string(t[4]);
        if (p.count_type == 0 || p.count_type > 10 || p.type == 0) throw Error(bad + "bad list property '" + p.name + "'");
      } else if (t.size() == 3) {
        p.type = type_code(t[1]);
        p.name = std::string(t[2]);
        if (p.type == 0) throw Error(bad + "unknown type '" + std::string(t[1]) + "'");
      } else {
        throw Error(bad + "bad property line");
      }
      elements.back().properties.push_back(p);
    } else {
      throw Error(bad + "unexpected header line '" + std::string(t[0]) + "'");
    }
  }
  if (format < 0) throw Error(bad + "no format line");
  // Every element takes at least: binary, the sizes of its scalars and list counts; ASCII,
  // two bytes per property ("0 ").
  const std::size_t available = text.size() - data;
  long double least = 0;
  for (const Element& e : elements) {
    std::size_t bytes = 0;
    for (const Property& p : e.properties)
      bytes += format == 0 ? 2 : std::size_t(std::abs(p.list ? p.count_type : p.type) % 10);
    least += (long double)(e.count) * (long double)((std::max)(bytes, std::size_t(1)));
  }
  if (least > (long double)(available)) {
    std::string counts;
    for (const Element& e : elements) counts += (counts.empty() ? "" : ", ") + std::to_string(e.count) + " " + e.name;
    throw Error(fail + "the PLY header declares " + counts + ", more than the " + std::to_string(available) +
                " bytes after it can hold");
  }

  // Data.
  std::size_t cursor = data;
  Token_lines ascii(text.substr(data));
  std::vector<std::string_view> line;
  std::size_t token = 0;
  auto next_value = [&](int code, double& value) {
    if (format == 0) {
      while (token >= line.size()) {
        if (!ascii.next(line)) throw Error(bad + "the file ends before the elements its header declares");
        token = 0;
      }
      if (!parse_number(line[token++], value)) throw Error(bad + "'" + std::string(line[token - 1]) + "' is not a number");
      return;
    }
    const int size = std::abs(code) % 10;
    if (cursor + size > text.size()) throw Error(bad + "the file ends before the elements its header declares");
    unsigned char b[8];
    std::memcpy(b, text.data() + cursor, size);
    cursor += size;
    const std::uint16_t probe = 1;
    const bool little_host = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    if ((format == 1) != little_host) std::reverse(b, b + size);
    switch (code) {
      case 1: { std::uint8_t x; std::memcpy(&x, b, 1); value = x; break; }
      case -1: { std::int8_t x; std::memcpy(&x, b, 1); value = x; break; }
      case 2: { std::uint16_t x; std::memcpy(&x, b, 2); value = x; break; }
      case -2: { std::int16_t x; std::memcpy(&x, b, 2); value = x; break; }
      case 4: { std::uint32_t x; std::memcpy(&x, b, 4); value = x; break; }
      case -4: { std::int32_t x; std::memcpy(&x, b, 4); value = x; break; }
      case 14: { float x; std::memcpy(&x, b, 4); value = x; break; }
      case 18: { double x; std::memcpy(&x, b, 8); value = x; break; }
      default: throw Error(bad + "unsupported property type");
    }
  };
  Polygon_soup s;
  for (const Element& e : elements) {
    const bool vertex = e.name == "vertex", face = e.name == "face";
    int ix = -1, iy = -1, iz = -1, ilist = -1;
    for (int k = 0; k < int(e.properties.size()); ++k) {
      const Property& p = e.properties[k];
      if (vertex && !p.list) {
        if (p.name == "x") ix = k;
        if (p.name == "y") iy = k;
        if (p.name == "z") iz = k;
      }
      if (face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) ilist = k;
    }
    if (vertex && (ix < 0 || iy < 0 || iz < 0)) throw Error(bad + "the vertices have no x, y, z");
    if (face && ilist < 0) throw Error(bad + "the faces have no vertex_indices");
    if (vertex) s.points.reserve(e.count);
    if (face) s.polygons.reserve(e.count);
    for (unsigned long long i = 0; i < e.count; ++i) {
      double xyz[3] = {0, 0, 0};
      for (int k = 0; k < int(e.properties.size()); ++k) {
        const Property& p = e.properties[k];
        double v;
        if (!p.list) {
          next_value(p.type, v);
          if (k == ix) xyz[0] = v;
          if (k == iy) xyz[1] = v;
          if (k == iz) xyz[2] = v;
          continue;
        }
        next_value(p.count_type, v);
        const std::size_t left = format == 0 ? ascii.remaining_bytes() + 2 * (line.size() - token)
                                             : (text.size() - cursor) / std::size_t(std::abs(p.type) % 10);
        if (!(v >= 0) || v != std::floor(v) || v > double(left)) {
          char count[32]; // as written: converting it to an integer type may overflow (1e308)
          std::snprintf(count, sizeof count, "%.15g", v);
          throw Error(bad + e.name + " " + std::to_string(i) + " declares a list of " + count +
                      " values, more than the rest of the file holds");
        }
        std::vector<std::size_t> f(static_cast<std::size_t>(v));
        for (std::size_t& x : f) {
          double idx;
          next_value(p.type, idx);
          x = (idx >= 0 && idx == std::floor(idx) && idx < 1e18) ? std::size_t(idx) : bad_index;
        }
        if (k == ilist) s.polygons.push_back(std::move(f));
      }
      if (vertex) s.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
  const bool trailing = format == 0 ? (token < line.size() || ascii.next(line)) : cursor < text.size();
  if (trailing) throw Error(fail + "the file holds more data than its PLY header declares");
  return s;
}

/// Binary STL: exactly 84 + 50 n bytes; equal points get one index (as CGAL's reader does).
inline Polygon_soup read_binary_stl(std::string_view text)
{
  std::uint32_t n;
  std::memcpy(&n, text.data() + 80, 4);
  Polygon_soup s;
  std::map<std::array<float, 3>, std::size_t> index;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::vector<std::size_t> f;
    for (int v = 0; v < 3; ++v) {
      std::array<float, 3> p;
      std::memcpy(p.data(), text.data() + 84 + 50 * std::size_t(i) + 12 + 12 * v, 12);
      const auto it = index.emplace(p, s.points.size());
      if (it.second) s.points.emplace_back(p[0], p[1], p[2]);
      f.push_back(it.first->second);
    }
    s.polygons.push_back(std::move(f));
  }
  return s;
}

inline Polygon_soup read_stl(std::string_view text, const std::string& fail)
{
  const std::size_t size = text.size();
  std::uint32_t n = 0;
  if (size >= 84) std::memcpy(&n, text.data() + 80, 4); // little-endian hosts (checked when writing)
  const bool exact_binary = size >= 84 && 84 + 50 * std::uint64_t(n) == size;
  if (exact_binary) return read_binary_stl(text);
  std::size_t first = 0;
  while (first < size && std::isspace(static_cast<unsigned char>(text[first]))) ++first;
  if (text.substr(first, 5) == "solid") {
    Polygon_soup s;
    std::istringstream in{std::string(text)};
    std::vector<std::array<std::size_t, 3>> triangles;
    if (CGAL::IO::read_STL(in, s.points, triangles, CGAL::parameters::verbose(false))) {
      for (const auto& tri : triangles) s.polygons.push_back({tri[0], tri[1], tri[2]});
      return s;
    }
  }
  if (size < 84) throw Error(fail + "malformed STL: not ASCII, and too short for binary STL");
  throw Error(fail + "binary STL declares " + std::to_string(n) + " triangles, which take 84 + 50 x " +
              std::to_string(n) + " = " + std::to_string(84 + 50 * std::uint64_t(n)) + " bytes, but the file has " +
              std::to_string(size) + " bytes");
}

inline Polygon_soup read_obj(std::string_view text, const std::string& what, const std::string& fail)
{
  Polygon_soup s;
  std::istringstream in{std::string(text)};
  if (!CGAL::IO::read_OBJ(in, s.points, s.polygons, CGAL::parameters::verbose(false))) {
    check_faces(s, what); // CGAL's reader fails on an index out of range: say which
    throw Error(fail + "malformed OBJ");
  }
  return s;
}

} // namespace input_internal

/// The checked polygon soup (see the file comment) of a file's contents `text` in the format
/// `ext` names: "off", "ply", "stl" or "obj" (any other is read as OBJ).
inline Polygon_soup parse_soup(std::string_view text, const std::string& ext, const std::string& what)
{
  namespace in = input_internal;
  const std::string fail = "cannot read " + what + ": ";
  Polygon_soup s = ext == "off" ? in::read_off(text, fail)
         : ext == "ply" ? in::read_ply(text, fail)
         : ext == "stl" ? in::read_stl(text, fail)
                        : in::read_obj(text, what, fail);
  in::check_faces(s, what);
  return s;
}

/// Splits the edges of a polygon soup shared by more than two polygons (solids that touch
/// along an edge and share its vertices, or one solid pinched along an edge) the way the
/// solids ask: around such an edge, each polygon that runs b -> a is joined to the next
/// polygon counterclockwise about a -> b, which must run a -> b (the solid lies between
/// them); then each end of such an edge gets one copy per fan of polygons joined around it. Without
/// this, CGAL's soup repair joins the polygons at random and opens the solids into surfaces
/// with borders, whose sum is that of surfaces. Returns the number of edges split; 0 (soup
/// unchanged) when there is none, or when directions do not alternate around an edge (e.g.
/// a component written twice): the checks of the input stage then say what is wrong.
template <class Point>
std::size_t split_non_manifold_edges(std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons)
{
  using Corner = std::pair<std::size_t, std::size_t>; // (polygon, position): the edge from it to the next
  auto at = [&](const Corner& c, std::size_t shift) {
    const auto& poly = polygons[c.first];
    return poly[(c.second + shift) % poly.size()];
  };
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, Corner>> edge_corners; // sorted by edge
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::size_t k = 0; k < polygons[i].size() && polygons[i].size() >= 3; ++k)
      if (at({i, k}, 0) != at({i, k}, 1)) edge_corners.push_back({std::minmax(at({i, k}, 0), at({i, k}, 1)), {i, k}});
  std::sort(edge_corners.begin(), edge_corners.end());
  bool any = false;
  for (std::size_t i = 2; i < edge_corners.size() && !any; ++i) any = edge_corners[i].first == edge_corners[i - 2].first;
  if (!any) return 0;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<Corner>> on_edge;
  for (const auto& [edge, corner] : edge_corners) on_edge[edge].push_back(corner);
  std::map<Corner, Corner> twin;
  std::set<std::size_t> pinched; // the ends of the split edges: only they get copies
  std::size_t split = 0;
  for (auto& [edge, corners] : on_edge) {
    if (corners.size() <= 2) {
      if (corners.size() == 2 && at(corners[0], 0) == at(corners[1], 1)) {
        twin[corners[0]] = corners[1];
        twin[corners[1]] = corners[0];
      }
      continue;
    }
    // angle of each polygon about the axis a -> b, from its vertex after the edge
    const auto& a = points[edge.first];
    const auto& b = points[edge.second];
    const std::array<double, 3> t = {b.x() - a.x(), b.y() - a.y(), b.z() - a.z()};
    const int m = std::abs(t[0]) < std::abs(t[1]) ? (std::abs(t[0]) < std::abs(t[2]) ? 0 : 2)
                                                  : (std::abs(t[1]) < std::abs(t[2]) ? 1 : 2);
    std::array<double, 3> u{0, 0, 0};
    u[m] = 1; // any vector off the axis; only the projection matters
    auto cross = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
      return std::array<double, 3>{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const auto v = cross(t, u), w = cross(v, t); // (w, v, t): right-handed, w and v across the axis
    std::vector<std::pair<double, Corner>> around;
    for (const Corner& c : corners) {
      const auto& p = points[at(c, 2)];
      const std::array<double, 3> d = {p.x() - a.x(), p.y() - a.y(), p.z() - a.z()};
      around.push_back({std::atan2(d[0] * v[0] + d[1] * v[1] + d[2] * v[2], d[0] * w[0] + d[1] * w[1] + d[2] * w[2]), c});
    }
    std::sort(around.begin(), around.end());
    const std::size_t n = around.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Corner& c = around[i].second;
      const Corner& next = around[(i + 1) % n].second;
      const bool backward = at(c, 0) == edge.second; // runs b -> a: the solid is counterclockwise of it
      if (backward == (at(next, 0) == edge.second)) return 0; // directions do not alternate
      if (backward) {
        twin[c] = next;
        twin[next] = c;
      }
    }
    ++split;
    pinched.insert(edge.first);
    pinched.insert(edge.second);
  }
  if (split == 0) return 0;
  // fans: the corner at vertex x of polygon i follows, around x, the corner of x in the polygon
  // across the edge that leaves x in polygon i
  std::map<Corner, Corner> parent;
  std::function<Corner(Corner)> find = [&](Corner c) {
    auto it = parent.find(c);
    if (it == parent.end() || it->second == c) return c;
    return it->second = find(it->second);
  };
  for (const auto& [c, across] : twin) {
    const Corner here = find(c), there = find({across.first, (across.second + 1) % polygons[across.first].size()});
    if (here != there) parent[here] = there;
  }
  std::map<Corner, std::size_t> copy_of_fan;
  std::vector<bool> used(points.size(), false);
  auto new_polygons = polygons;
  for (std::size_t i = 0; i < polygons.size(); ++i)
    for (std::size_t k = 0; k < polygons[i].size(); ++k) {
      const std::size_t x = polygons[i][k];
      if (!pinched.count(x)) continue;
      const auto [it, first] = copy_of_fan.emplace(find({i, k}), x);
      if (first && used[x]) { // another fan already holds x: a copy
        it->second = points.size();
        points.push_back(points[x]);
      }
      used[x] = true;
      new_polygons[i][k] = it->second;
    }
  polygons.swap(new_polygons);
  return split;
}

/// Whether two corners of a face fall on one point when projected along `normal`, as the 2D
/// triangulation of CGAL's triangulate_faces sees them (its own projected predicates; is_simple_2
/// compares the 3D points): it would then insert a constraint from a vertex to itself (a
/// precondition; undefined behaviour in Release). Found by the readers' fuzzer.
inline bool corners_meet_in_projection(std::vector<K::Point_3> corners, const K::Vector_3& normal)
{
  const CGAL::Projection_traits_3<K> traits(normal);
  const auto less = traits.less_xy_2_object();
  std::sort(corners.begin(), corners.end(), less);
  for (std::size_t i = 1; i < corners.size(); ++i)
    if (!less(corners[i - 1], corners[i])) return true;
  return false;
}

/// Reads a polygon soup from an .off, .ply, .obj or .stl file, checked (see the file comment).
inline Polygon_soup read_soup(const std::string& path, const std::string& what)
{
  namespace fs = std::filesystem;
  const std::string ext = extension(path);
  if (ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    throw Error("cannot read " + what + ": unknown format '." + ext + "' (use .off, .obj, .ply or .stl)");
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Error("cannot read " + what + ": no such file or not readable");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error("cannot read " + what + ": no such file or not readable");
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  return parse_soup(text, ext, what);
}

/// The mesh of a checked polygon soup (parse_soup). A valid mesh is built as it is; only a
/// soup that is not one is repaired (CGAL's PMP: duplicated points merged, non-manifold
/// edges and vertices split, orientation made consistent). (Repairing valid input would merge
/// the coincident vertices of solids that touch along faces and then drop the coincident
/// faces, opening the mesh.) Non-triangle faces are triangulated and closed meshes oriented
/// to bound a volume, with a note.
inline Mesh mesh_from_soup(Polygon_soup s, const std::string& what, bool quiet)
{
  if (s.polygons.empty()) throw Error(what + " has no faces");
  for (const auto& p : s.points)
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Error(what + " has a vertex with a coordinate that is not finite (NaN or infinity)");
  // Vertices of no face are ignored by every stage; CGAL 5.5's orient_to_bound_a_volume
  // crashes on them (segmentation fault in volume_connected_components).
  PMP::remove_isolated_points_in_polygon_soup(s.points, s.polygons);
  if (const std::size_t split = split_non_manifold_edges(s.points, s.polygons); split > 0)
    note(what + ": " + std::to_string(split) + " edges with more than two faces, split between the solids that meet there",
         quiet);
  Mesh m;
  if (!PMP::is_polygon_soup_a_polygon_mesh(s.polygons)) {
    PMP::repair_polygon_soup(s.points, s.polygons);
    PMP::orient_polygon_soup(s.points, s.polygons);
    if (!PMP::is_polygon_soup_a_polygon_mesh(s.polygons))
      throw Error("cannot read " + what + ": malformed or not a polygon mesh");
  }
  PMP::polygon_soup_to_polygon_mesh(s.points, s.polygons, m);
  if (m.number_of_faces() == 0) throw Error(what + " has no faces");
  std::size_t polygons = 0;
  for (auto f : m.faces()) polygons += (m.degree(f) != 3);
  if (polygons > 0) {
    // CGAL 5.5's triangulate_faces (its 2D constrained triangulation in the plane of the face's
    // normal) corrupts the mesh on a face that is not a simple polygon in that plane: a face
    // cycle with no end, which hangs every later stage. Such a face is refused first.
    for (auto f : m.faces()) {
      if (m.degree(f) == 3) continue;
      std::vector<K::Point_3> corners;
      for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) corners.push_back(m.point(v));
      const K::Vector_3 normal = PMP::compute_face_normal(f, m);
      // (coordinates near 1e308 overflow it: the exact predicates would then convert an
      // infinity or a NaN, and GMP raise SIGFPE)
      if (!std::isfinite(normal.x()) || !std::isfinite(normal.y()) || !std::isfinite(normal.z()))
        throw Error(what + " has a face of " + std::to_string(corners.size()) +
                    " vertices whose plane overflows double (coordinates too large): it cannot be triangulated");
      if (normal == CGAL::NULL_VECTOR ||
          !CGAL::is_simple_2(corners.begin(), corners.end(), CGAL::Projection_traits_3<K>(normal)) ||
          corners_meet_in_projection(corners, normal))
        throw Error(what + " has a face of " + std::to_string(corners.size()) +
                    " vertices that is not a simple polygon (no area, or edges that cross, in its plane):"
                    " it cannot be triangulated");
    }
    if (!PMP::triangulate_faces(m))
      throw Error(what + " has faces that cannot be triangulated");
    note(what + ": triangulated " + std::to_string(polygons) + " non-triangle faces", quiet);
  }
  // CGAL's orient_to_bound_a_volume needs a mesh that does not intersect itself: on one that
  // does, its ray casts can loop for ever (found by the readers' fuzzer). Such a mesh, or one
  // whose components touch, is left as it is for the library's solid checks, which refuse
  // crossings and wrongly oriented components.
  if (CGAL::is_closed(m) && !PMP::does_self_intersect(m)) {
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

/// Reads a mesh (OFF, OBJ, PLY, STL) through a checked polygon soup: read_soup, then
/// mesh_from_soup.
inline Mesh read_mesh(const std::string& path, const std::string& name, bool quiet)
{
  const std::string what = name + " ('" + path + "')";
  return mesh_from_soup(read_soup(path, what), what, quiet);
}

} // namespace pmsum_cli

#endif // CGAL_PMSUM_CLI_INPUT_H
