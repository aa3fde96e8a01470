// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Python bindings of CGAL_pmsum (pybind11): the module `pmsum`.
//
// The module goes through the command-line tool's code, so that the same options give the
// same points in the same order as `pmsum sum` / `pmsum offset`: the tool's mesh type and
// kernel (Surface_mesh over Epick, src/cli_input.h), its readers (read_soup, mesh_from_soup:
// a file is read exactly as the tool reads it, and a (vertices, faces) pair goes through the
// same checks and repairs), and its compute_sum (src/cli_common.h), which calls
// CGAL::point_minkowski_sum with the tool's named parameters. One translation unit: each one
// that instantiates the exact kernels takes minutes to compile.
//
// Every computation runs with the GIL released; the progress callback of the library takes it
// back about 2000 times per run to check for Ctrl-C (KeyboardInterrupt) and to call the
// optional Python `progress` function.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "cli_common.h" // the tool's reader, Sum_input, compute_sum (src/)
#include "shapes.h"     // pmsum_shapes::box, the --cube structuring element (src/shapes/)

#include <CGAL_pmsum/Penetration_depth.h>
#include <CGAL_pmsum/Translational_motion_planner.h>
#include <CGAL_pmsum/exceptions.h>
#include <CGAL_pmsum/point_offset.h>
#include <CGAL_pmsum/version.h>

#include <CGAL/version.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace {

using pmsum_cli::K;
using pmsum_cli::Mesh;
using pmsum_cli::Polygon_soup;
using pmsum_cli::Record;
using pmsum_cli::Usage_error;
using Feature = CGAL::Pmsum::Mesh_feature<Mesh>;

// ---------------------------------------------------------------------------------------
// Exceptions

py::handle invalid_input_type, too_large_type, cancelled_type, input_warning_type;

// ---------------------------------------------------------------------------------------
// numpy helpers

/// A numpy array that owns `v` (no copy), of shape `shape`.
template <class T>
py::array_t<T> to_array(std::vector<T>&& v, std::vector<py::ssize_t> shape)
{
  auto* heap = new std::vector<T>(std::move(v));
  py::capsule owner(heap, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, heap->data(), owner);
}

/// Points (n, 3) as a numpy array.
template <class Points>
py::array_t<double> points_array(const Points& pts)
{
  std::vector<double> v;
  v.reserve(3 * pts.size());
  for (const auto& p : pts) {
    v.push_back(p.x());
    v.push_back(p.y());
    v.push_back(p.z());
  }
  const py::ssize_t n = py::ssize_t(pts.size());
  return to_array(std::move(v), {n, 3});
}

/// One translation (3,) or several (k, 3), finite: the translations and whether it was one.
std::pair<std::vector<std::array<double, 3>>, bool> translations(const py::handle& obj, const std::string& what)
{
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || !((a.ndim() == 1 && a.shape(0) == 3) || (a.ndim() == 2 && a.shape(1) == 3)))
    throw Usage_error(what + " must be a translation (x, y, z) or an array of them, shape (3,) or (k, 3)");
  const bool single = a.ndim() == 1;
  const py::ssize_t k = single ? 1 : a.shape(0);
  std::vector<std::array<double, 3>> r(static_cast<std::size_t>(k));
  const double* data = a.data();
  for (py::ssize_t i = 0; i < k; ++i)
    for (int c = 0; c < 3; ++c) {
      r[std::size_t(i)][c] = data[3 * i + c];
      if (!std::isfinite(r[std::size_t(i)][c])) throw Usage_error(what + " must be finite");
    }
  return {r, single};
}

// ---------------------------------------------------------------------------------------
// Cancellation and progress

/// The library's progress callback, called on the computing thread with the GIL released:
/// takes the GIL, runs Python's signal handlers (Ctrl-C) and the user's `progress(fraction)`;
/// returns false (the library then throws Operation_cancelled) on an exception or when
/// `progress` returns a false value other than None.
class Interruptible
{
public:
  explicit Interruptible(py::object progress) : m_progress(std::move(progress)) {}

  bool operator()(double fraction)
  {
    py::gil_scoped_acquire gil;
    if (m_error) return false;
    if (PyErr_CheckSignals() != 0) {
      m_error = std::make_exception_ptr(py::error_already_set());
      return false;
    }
    if (m_progress.is_none()) return true;
    try {
      const py::object r = m_progress(fraction);
      if (r.is_none()) return true;
      const int truth = PyObject_IsTrue(r.ptr());
      if (truth < 0) throw py::error_already_set();
      return truth != 0;
    } catch (...) {
      m_error = std::current_exception();
      return false;
    }
  }
  std::function<bool(double)> function() { return [this](double f) { return (*this)(f); }; }
  const std::exception_ptr& error() const { return m_error; }

private:
  py::object m_progress;
  std::exception_ptr m_error;
};

/// Runs f() with the GIL released; a cancellation caused by Python (KeyboardInterrupt, an
/// exception of `progress`) is raised as that Python exception.
template <class F>
auto released(const Interruptible& cb, F&& f) -> decltype(f())
{
  try {
    py::gil_scoped_release nogil;
    return f();
  } catch (const CGAL::Pmsum::Operation_cancelled&) {
    if (cb.error()) std::rethrow_exception(cb.error());
    throw;
  }
}

// ---------------------------------------------------------------------------------------
// Input meshes

/// A mesh argument as given: a file path, or a polygon soup from numpy arrays.
struct Mesh_argument
{
  bool file = false;
  std::string path;
  Polygon_soup soup;
};

/// Reads P or Q from Python (with the GIL): a path (str, bytes, os.PathLike), a
/// (vertices, faces) pair, or an object with `vertices` and `faces` attributes.
Mesh_argument mesh_argument(const py::handle& obj, const std::string& name)
{
  Mesh_argument a;
  if (py::isinstance<py::str>(obj) || py::isinstance<py::bytes>(obj) || py::hasattr(obj, "__fspath__")) {
    a.file = true;
    a.path = py::module_::import("os").attr("fsdecode")(obj).cast<std::string>();
    return a;
  }
  py::object V, F;
  if (py::isinstance<py::tuple>(obj) || py::isinstance<py::list>(obj)) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(obj);
    if (py::len(s) != 2)
      throw py::type_error(name + " must be a file path or a (vertices, faces) pair, got a sequence of length " +
                           std::to_string(py::len(s)));
    V = s[0];
    F = s[1];
  } else if (py::hasattr(obj, "vertices") && py::hasattr(obj, "faces")) {
    V = obj.attr("vertices");
    F = obj.attr("faces");
  } else {
    throw py::type_error(name + " must be a file path or a (vertices, faces) pair of arrays, got " +
                         std::string(py::str(py::type::handle_of(obj).attr("__name__"))));
  }
  auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(V);
  if (!v || v.ndim() != 2 || v.shape(1) != 3)
    throw Usage_error(name + ": vertices must be an array of shape (n, 3) of numbers");
  const double* pv = v.data();
  for (py::ssize_t i = 0; i < v.shape(0); ++i) a.soup.points.emplace_back(pv[3 * i], pv[3 * i + 1], pv[3 * i + 2]);
  py::array f = py::array::ensure(F);
  if (!f || f.ndim() != 2 || (f.size() > 0 && f.shape(1) < 3))
    throw Usage_error(name + ": faces must be an array of shape (m, 3) of vertex indices (or (m, k), k >= 3: polygons)");
  if (f.size() == 0) return a;
  const char kind = f.dtype().kind();
  const py::ssize_t m = f.shape(0), k = f.shape(1);
  a.soup.polygons.assign(std::size_t(m), std::vector<std::size_t>(std::size_t(k)));
  constexpr std::size_t bad = pmsum_cli::input_internal::bad_index; // refused by check_faces
  if (kind == 'i') {
    auto fi = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(f);
    const long long* p = fi.data();
    for (py::ssize_t i = 0; i < m; ++i)
      for (py::ssize_t j = 0; j < k; ++j) {
        const long long x = p[i * k + j];
        a.soup.polygons[std::size_t(i)][std::size_t(j)] = x < 0 ? bad : std::size_t(x);
      }
  } else if (kind == 'u') {
    auto fu = py::array_t<unsigned long long, py::array::c_style | py::array::forcecast>::ensure(f);
    const unsigned long long* p = fu.data();
    for (py::ssize_t i = 0; i < m; ++i)
      for (py::ssize_t j = 0; j < k; ++j) {
        const unsigned long long x = p[i * k + j];
        // (bad_index = 2^64 - 1 itself would read as a negative index: any index >= the
        // vertex count is refused, by check_faces)
        a.soup.polygons[std::size_t(i)][std::size_t(j)] = x >= bad ? bad - 1 : std::size_t(x);
      }
  } else {
    throw Usage_error(name + ": faces must be integers (vertex indices), got an array of dtype " +
                      std::string(py::str(f.dtype())));
  }
  return a;
}

/// Which input row each element of the mesh came from (the provenance of the output).
struct Provenance
{
  std::vector<std::int64_t> vertex_row; // mesh vertex index -> row of the vertices (file or array); -1: none
  std::vector<std::int64_t> face_row;   // mesh face index -> row of the faces (the polygon it is part of)
  std::vector<std::int64_t> edges;      // mesh edge index e -> rows (edges[2e], edges[2e+1]), smaller first
};

/// Maps the mesh built by mesh_from_soup back to the soup it was built from. A valid soup is
/// built as it is (vertex i = row i, face i = row i). Else (vertices of no face removed, edges
/// split, a soup repaired, polygons triangulated), by exact coordinates: each mesh vertex gets a
/// row with its coordinates (a distinct one while there are), each face the polygon that holds
/// its three vertices.
Provenance provenance(const Mesh& m, const Polygon_soup& s)
{
  using Key = std::array<double, 3>;
  auto key = [](const K::Point_3& p) { return Key{p.x(), p.y(), p.z()}; };
  Provenance r;
  const std::size_t np = s.points.size(), nf = s.polygons.size();
  r.vertex_row.assign(m.num_vertices(), -1);
  std::vector<bool> row_taken(np, false);
  bool all = true;
  for (auto v : m.vertices()) {
    const std::size_t i = v.idx();
    if (i < np && !row_taken[i] && key(s.points[i]) == key(m.point(v))) {
      r.vertex_row[i] = std::int64_t(i);
      row_taken[i] = true;
    } else {
      all = false;
    }
  }
  std::map<Key, std::vector<std::size_t>> rows_at; // coordinates -> rows (increasing)
  std::vector<std::size_t> coordinate_id;          // row -> first row with its coordinates
  if (!all) {
    for (std::size_t i = 0; i < np; ++i) rows_at[key(s.points[i])].push_back(i);
    for (auto v : m.vertices()) {
      if (r.vertex_row[v.idx()] >= 0) continue;
      const auto it = rows_at.find(key(m.point(v)));
      if (it == rows_at.end()) continue;
      std::size_t row = it->second.front();
      for (std::size_t j : it->second)
        if (!row_taken[j]) { row = j; break; }
      row_taken[row] = true;
      r.vertex_row[v.idx()] = std::int64_t(row);
    }
    coordinate_id.resize(np);
    for (const auto& [k, rows] : rows_at)
      for (std::size_t j : rows) coordinate_id[j] = rows.front();
  }
  auto face_rows = [&](Mesh::Face_index f) {
    std::vector<std::int64_t> rows;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) rows.push_back(r.vertex_row[v.idx()]);
    return rows;
  };
  // does polygon `p` hold every row of `rows` (exactly, or by coordinates)?
  auto holds = [&](std::size_t p, const std::vector<std::int64_t>& rows, bool by_coordinates) {
    for (std::int64_t x : rows) {
      if (x < 0) return false;
      bool found = false;
      for (std::size_t y : s.polygons[p])
        if (y < np && (by_coordinates ? coordinate_id[y] == coordinate_id[std::size_t(x)] : y == std::size_t(x))) {
          found = true;
          break;
        }
      if (!found) return false;
    }
    return true;
  };
  r.face_row.assign(m.num_faces(), -1);
  std::vector<bool> polygon_taken(nf, false);
  std::vector<Mesh::Face_index> left;
  for (auto f : m.faces()) {
    const std::size_t i = f.idx();
    if (i < nf && !polygon_taken[i] && holds(i, face_rows(f), false)) {
      r.face_row[i] = std::int64_t(i);
      polygon_taken[i] = true;
    } else {
      left.push_back(f);
    }
  }
  if (!left.empty()) {
    if (coordinate_id.empty()) { // (every vertex was found at its row)
      coordinate_id.resize(np);
      for (std::size_t i = 0; i < np; ++i) rows_at[key(s.points[i])].push_back(i);
      for (const auto& [k, rows] : rows_at)
        for (std::size_t j : rows) coordinate_id[j] = rows.front();
    }
    std::vector<std::vector<std::size_t>> polygons_at(np); // coordinate id -> polygons
    for (std::size_t p = 0; p < nf; ++p)
      for (std::size_t y : s.polygons[p])
        if (y < np) polygons_at[coordinate_id[y]].push_back(p);
    for (auto f : left) {
      const auto rows = face_rows(f);
      if (rows.empty() || rows[0] < 0) continue;
      std::int64_t best = -1;
      for (bool by_coordinates : {false, true}) {
        for (std::size_t p : polygons_at[coordinate_id[std::size_t(rows[0])]])
          if (holds(p, rows, by_coordinates) && (best < 0 || (polygon_taken[std::size_t(best)] && !polygon_taken[p])))
            best = std::int64_t(p);
        if (best >= 0) break;
      }
      if (best >= 0) {
        r.face_row[f.idx()] = best;
        polygon_taken[std::size_t(best)] = true;
      }
    }
  }
  r.edges.assign(2 * m.num_edges(), -1);
  for (auto e : m.edges()) {
    const auto h = m.halfedge(e);
    const std::int64_t a = r.vertex_row[m.source(h).idx()], b = r.vertex_row[m.target(h).idx()];
    r.edges[2 * e.idx()] = std::min(a, b);
    r.edges[2 * e.idx() + 1] = std::max(a, b);
  }
  return r;
}

/// A mesh read or built as the tool does, with its provenance and the notes the reader gave.
struct Input_mesh
{
  Mesh mesh;
  Provenance rows;
  std::vector<std::string> notes;
};

/// The reader's notes go to std::cerr (cli_input.h): capture them (one reader at a time).
std::mutex cerr_mutex;

/// Reads or builds the mesh (without the GIL): a file with the tool's read_soup and
/// mesh_from_soup (= its read_mesh), a soup with check_faces and mesh_from_soup.
Input_mesh input_mesh(Mesh_argument a, const std::string& name, bool quiet)
{
  Input_mesh r;
  std::ostringstream captured;
  {
    std::lock_guard<std::mutex> lock(cerr_mutex);
    std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
    try {
      std::string what = name;
      if (a.file) {
        what = name + " ('" + a.path + "')";
        a.soup = pmsum_cli::read_soup(a.path, what);
      } else {
        pmsum_cli::input_internal::check_faces(a.soup, what);
      }
      r.mesh = pmsum_cli::mesh_from_soup(a.soup, what, quiet);
    } catch (...) {
      std::cerr.rdbuf(old);
      throw;
    }
    std::cerr.rdbuf(old);
  }
  std::istringstream lines(captured.str());
  const std::string prefix = "pmsum: note: ";
  for (std::string line; std::getline(lines, line);)
    if (!line.empty()) r.notes.push_back(line.compare(0, prefix.size(), prefix) == 0 ? line.substr(prefix.size()) : line);
  r.rows = provenance(r.mesh, a.soup);
  return r;
}

/// A path that does not exist: FileNotFoundError (before the reader's generic message).
void check_exists(const Mesh_argument& a, const std::string& name)
{
  std::error_code ec;
  if (a.file && !std::filesystem::exists(a.path, ec)) {
    py::object e = py::module_::import("builtins").attr("FileNotFoundError")(
      ENOENT, "cannot read " + name + ": no such file", a.path);
    PyErr_SetObject(py::type::handle_of(e).ptr(), e.ptr());
    throw py::error_already_set();
  }
}

/// The reader's notes as Python warnings (pmsum.InputWarning).
void warn_notes(const std::vector<std::string>& notes)
{
  for (const std::string& n : notes)
    if (PyErr_WarnEx(input_warning_type.ptr(), n.c_str(), 2) < 0) throw py::error_already_set();
}

/// The mesh as numpy arrays: vertices (n, 3), faces (m, 3).
py::tuple mesh_arrays(const Mesh& m)
{
  std::vector<double> v;
  std::vector<std::int64_t> f;
  std::vector<std::int64_t> index(m.num_vertices(), -1);
  std::int64_t n = 0;
  for (auto x : m.vertices()) {
    index[x.idx()] = n++;
    const auto& p = m.point(x);
    v.insert(v.end(), {p.x(), p.y(), p.z()});
  }
  for (auto face : m.faces())
    for (auto x : CGAL::vertices_around_face(m.halfedge(face), m)) f.push_back(index[x.idx()]);
  const py::ssize_t nf = py::ssize_t(m.number_of_faces());
  return py::make_tuple(to_array(std::move(v), {py::ssize_t(n), 3}), to_array(std::move(f), {nf, nf ? py::ssize_t(f.size()) / nf : 3}));
}

// ---------------------------------------------------------------------------------------
// Output

py::dict statistics_dict(const CGAL::Pmsum::Statistics& s)
{
  py::dict d;
  d["samples_p"] = s.samples_p;
  d["samples_q"] = s.samples_q;
  d["feature_pairs"] = s.feature_pairs;
  d["candidates"] = s.candidates;
  d["octree_leaves"] = s.octree_leaves;
  d["octree_certified_leaves"] = s.octree_certified_leaves;
  d["candidates_certified"] = s.candidates_certified;
  d["candidates_reused"] = s.candidates_reused;
  d["candidates_covered"] = s.candidates_covered;
  d["candidates_in_patch_pairs"] = s.candidates_in_patch_pairs;
  d["cd_queries"] = s.cd_queries;
  d["triangle_pairs"] = s.triangle_pairs;
  d["containment_tests"] = s.containment_tests;
  d["corner_tests"] = s.corner_tests;
  d["trim_segments"] = s.trim_segments;
  d["island_cells"] = s.island_cells;
  d["trim_queries"] = s.trim_queries;
  d["trim_points"] = s.trim_points;
  d["output_points"] = s.output_points;
  d["seconds_setup"] = s.seconds_setup;
  d["seconds_normal_filter"] = s.seconds_normal_filter;
  d["seconds_octree_filter"] = s.seconds_octree_filter;
  d["seconds_cd_filter"] = s.seconds_cd_filter;
  return d;
}

/// The provenance arrays of one side of the records (built without the GIL).
struct Feature_columns
{
  std::vector<std::int8_t> dimension;
  std::vector<std::int64_t> index, vertices;
  std::vector<double> weights;
};

/// The arrays of the records (built without the GIL).
struct Record_columns
{
  std::vector<double> points, normals;
  Feature_columns p, q;
  bool with_q = true;
  std::size_t n = 0;
};

void add_feature(Feature_columns& c, const Feature& f, const Provenance& rows)
{
  auto row = [&](std::size_t i, const std::vector<std::int64_t>& table) {
    return i < table.size() ? table[i] : std::int64_t(-1);
  };
  c.dimension.push_back(std::int8_t(f.dimension));
  c.index.push_back(f.dimension == 0   ? row(f.vertex.idx(), rows.vertex_row)
                    : f.dimension == 1 ? (f.halfedge.idx() < 2 * (rows.edges.size() / 2) ? std::int64_t(f.halfedge.idx() / 2) : -1)
                    : f.dimension == 2 ? row(f.face.idx(), rows.face_row)
                                       : -1);
  for (int i = 0; i < 3; ++i) {
    const double w = f.rational_weights ? CGAL::to_double((*f.rational_weights)[i]) : double(f.weights[i]) / double(f.denominator);
    // (the weights are those of the sample the point was found from: over a face's vertices
    // for an edge or a vertex sample too; or the exact weights of a trim point, or of a point
    // of a flat region triangulated again, over the mesh's feature that holds it)
    c.vertices.push_back(w != 0 ? row(f.vertices[i].idx(), rows.vertex_row) : -1);
    c.weights.push_back(w);
  }
}

Record_columns columns(const std::vector<Record>& records, const Provenance& p, const Provenance* q)
{
  Record_columns c;
  c.n = records.size();
  c.with_q = q != nullptr;
  c.points.reserve(3 * c.n);
  c.normals.reserve(3 * c.n);
  for (const Record& r : records) {
    c.points.insert(c.points.end(), {r.point.x(), r.point.y(), r.point.z()});
    c.normals.insert(c.normals.end(), {r.normal.x(), r.normal.y(), r.normal.z()});
    add_feature(c.p, r.origin_p, p);
    if (q) add_feature(c.q, r.origin_q, *q);
  }
  return c;
}

void put_feature(py::dict& d, const std::string& side, Feature_columns&& f, std::size_t n)
{
  const py::ssize_t k = py::ssize_t(n);
  d[("origin_" + side + "_dimension").c_str()] = to_array(std::move(f.dimension), {k});
  d[("origin_" + side + "_index").c_str()] = to_array(std::move(f.index), {k});
  d[("origin_" + side + "_vertices").c_str()] = to_array(std::move(f.vertices), {k, 3});
  d[("origin_" + side + "_weights").c_str()] = to_array(std::move(f.weights), {k, 3});
}

py::array_t<std::int64_t> edges_array(const Provenance& rows)
{
  std::vector<std::int64_t> e = rows.edges;
  const py::ssize_t n = py::ssize_t(e.size() / 2);
  return to_array(std::move(e), {n, 2});
}

py::dict records_dict(Record_columns&& c, const Provenance& p, const Provenance* q)
{
  py::dict d;
  const py::ssize_t n = py::ssize_t(c.n);
  d["points"] = to_array(std::move(c.points), {n, 3});
  d["normals"] = to_array(std::move(c.normals), {n, 3});
  put_feature(d, "p", std::move(c.p), c.n);
  d["p_edges"] = edges_array(p);
  if (q) {
    put_feature(d, "q", std::move(c.q), c.n);
    d["q_edges"] = edges_array(*q);
  }
  return d;
}

// ---------------------------------------------------------------------------------------
// Option checks (the tool's, under the Python names)

void check_positive(double x, const std::string& name)
{
  if (!(x > 0) || !std::isfinite(x)) {
    std::ostringstream s;
    s << name << " must be a positive number, got " << std::setprecision(17) << x;
    throw Usage_error(s.str());
  }
}

void check_threads(int threads)
{
  if (threads < 0 || threads > 1024) throw Usage_error("threads must be 0 (all cores) or a positive integer up to 1024");
}

// ---------------------------------------------------------------------------------------
// minkowski_sum

py::dict minkowski_sum(const py::object& P, const py::object& Q, double d, bool relative, std::optional<double> scale_q,
                       bool negate_p, bool normal_filter, bool cd_filter, bool octree_filter, bool all_candidates,
                       bool trim_points, bool islands, bool merge_flat_regions, std::optional<std::vector<double>> levels,
                       int threads, bool force, bool quiet, const py::object& progress)
{
  // The checks of read_sum_input, before any reading.
  check_positive(d, "d");
  check_threads(threads);
  if (scale_q) check_positive(*scale_q, "scale_q");
  if (levels) {
    double previous = std::numeric_limits<double>::infinity();
    for (double x : *levels) {
      if (!(x > d) || !(x < previous) || !std::isfinite(x))
        throw Usage_error("levels must be decreasing distances larger than d");
      previous = x;
    }
    if (levels->empty()) throw Usage_error("levels needs at least one distance larger than d");
  }
  Mesh_argument ap = mesh_argument(P, "P"), aq = mesh_argument(Q, "Q");
  check_exists(ap, "P");
  check_exists(aq, "Q");
  Interruptible cb(progress);
  struct Level
  {
    double d;
    CGAL::Pmsum::Statistics stats;
    std::vector<Record> records;
  };
  struct Result
  {
    Input_mesh p, q;
    double d = 0;
    CGAL::Pmsum::Statistics stats;
    std::vector<Record> records;
    std::vector<Level> levels;
    Record_columns columns;
    std::vector<Record_columns> level_columns;
  } r;
  released(cb, [&] {
    r.p = input_mesh(std::move(ap), "P", quiet);
    r.q = input_mesh(std::move(aq), "Q", quiet);
    pmsum_cli::Sum_input in;
    in.P = std::move(r.p.mesh);
    in.Q = std::move(r.q.mesh);
    if (scale_q) pmsum_cli::scale_mesh(in.Q, *scale_q);
    in.d_argument = d;
    in.relative = relative;
    in.negate = negate_p;
    in.normal_filter = normal_filter;
    in.cd_filter = cd_filter;
    in.octree_filter = octree_filter;
    in.covering_net = !all_candidates;
    in.trim_points = trim_points;
    in.islands = islands;
    in.merge_flat = merge_flat_regions;
    in.force = force;
    in.quiet = true; // no progress bar
    in.threads = threads;
    in.callback = cb.function();
    in.diagonal = pmsum_cli::sum_diagonal(pmsum_cli::PMP::bbox(in.P), pmsum_cli::PMP::bbox(in.Q));
    in.d = relative ? d * in.diagonal : d;
    if (levels)
      for (double x : *levels) in.coarser_d.push_back(relative ? x * in.diagonal : x);
    r.d = in.d;
    r.records = pmsum_cli::compute_sum(in, r.stats, [&](std::size_t k, const CGAL::Pmsum::Statistics& s, std::vector<Record>&& level) {
      r.levels.push_back({in.coarser_d[k], s, std::move(level)});
    });
    r.columns = columns(r.records, r.p.rows, &r.q.rows);
    for (const Level& l : r.levels) r.level_columns.push_back(columns(l.records, r.p.rows, &r.q.rows));
  });
  warn_notes(r.p.notes);
  warn_notes(r.q.notes);
  py::dict out = records_dict(std::move(r.columns), r.p.rows, &r.q.rows);
  out["negated_p"] = negate_p;
  out["d"] = r.d;
  out["statistics"] = statistics_dict(r.stats);
  if (levels) {
    py::list ls;
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
      py::dict l = records_dict(std::move(r.level_columns[k]), r.p.rows, &r.q.rows);
      l["negated_p"] = negate_p;
      l["d"] = r.levels[k].d;
      l["statistics"] = statistics_dict(r.levels[k].stats);
      ls.append(l);
    }
    out["levels"] = ls;
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// offset (the tool's `offset` command)

py::dict offset(const py::object& P, double radius, double d, bool relative, bool cube, bool erode, double sphere_error,
                int threads, bool quiet, const py::object& progress)
{
  check_positive(radius, "radius");
  check_positive(d, "d");
  check_threads(threads);
  if (!(sphere_error > 0 && sphere_error < 1)) throw Usage_error("sphere_error must be in (0, 1)");
  Mesh_argument ap = mesh_argument(P, "P");
  check_exists(ap, "P");
  Interruptible cb(progress);
  struct Result
  {
    Input_mesh p;
    double r = 0, d = 0, inner = 0;
    std::size_t ball_faces = 0;
    CGAL::Pmsum::Statistics stats;
    std::vector<K::Point_3> eroded;
    Record_columns columns;
  } r;
  released(cb, [&] {
    r.p = input_mesh(std::move(ap), "P", quiet);
    r.r = radius;
    r.d = d;
    if (relative) {
      const double diag = pmsum_cli::sum_diagonal(pmsum_cli::PMP::bbox(r.p.mesh));
      r.r *= diag;
      r.d *= diag;
    }
    Mesh B;
    r.inner = r.r;
    if (cube) {
      const double x = r.r;
      B = pmsum_shapes::to_mesh<Mesh>(pmsum_shapes::box({-x, -x, -x}, {x, x, x}));
    } else {
      r.inner = CGAL::make_icosphere(r.r, sphere_error, B);
    }
    r.ball_faces = B.number_of_faces();
    if (erode) {
      if (!CGAL::is_closed(r.p.mesh)) throw pmsum_cli::Error("erode needs a closed mesh");
      CGAL::point_erosion<CGAL::Sequential_tag>(r.p.mesh, B, r.d, std::back_inserter(r.eroded));
    } else {
      pmsum_cli::Sum_input in;
      in.P = r.p.mesh;
      in.Q = std::move(B);
      in.d = r.d;
      in.quiet = true;
      in.threads = threads;
      in.callback = cb.function();
      r.columns = columns(pmsum_cli::compute_sum(in, r.stats), r.p.rows, nullptr);
    }
  });
  warn_notes(r.p.notes);
  py::dict out;
  if (erode) {
    out["points"] = points_array(r.eroded);
    out["normals"] = to_array(std::vector<double>(3 * r.eroded.size(), 0.), {py::ssize_t(r.eroded.size()), 3});
  } else {
    out = records_dict(std::move(r.columns), r.p.rows, nullptr);
    out["statistics"] = statistics_dict(r.stats);
  }
  out["erode"] = erode;
  out["r"] = r.r;
  out["d"] = r.d;
  out["ball_inradius"] = r.inner;
  out["ball_faces"] = r.ball_faces;
  return out;
}

// ---------------------------------------------------------------------------------------
// Penetration depth

class Py_penetration_depth
{
public:
  using PD = CGAL::Penetration_depth<Mesh, Mesh>;

  Py_penetration_depth(const py::object& P, const py::object& Q, double d, bool relative,
                       std::optional<double> scale_q, int threads, bool quiet, const py::object& progress)
  {
    check_positive(d, "d");
    check_threads(threads);
    if (scale_q) check_positive(*scale_q, "scale_q");
    Mesh_argument ap = mesh_argument(P, "P"), aq = mesh_argument(Q, "Q");
    check_exists(ap, "P");
    check_exists(aq, "Q");
    Interruptible cb(progress);
    Input_mesh p, q;
    released(cb, [&] {
      p = input_mesh(std::move(ap), "P", quiet);
      q = input_mesh(std::move(aq), "Q", quiet);
      if (scale_q) pmsum_cli::scale_mesh(q.mesh, *scale_q);
      m_d = relative ? d * pmsum_cli::sum_diagonal(pmsum_cli::PMP::bbox(p.mesh), pmsum_cli::PMP::bbox(q.mesh)) : d;
      const auto np = CGAL::parameters::statistics(m_stats).callback(cb.function());
      pmsum_cli::with_threads(threads, [&](auto tag) { m_pd.emplace(PD::make<decltype(tag)>(p.mesh, q.mesh, m_d, np)); });
    });
    warn_notes(p.notes);
    warn_notes(q.notes);
  }

  /// query (exact overlap + nearest contact) or nearest_contact, at one or several translations.
  py::dict answer(const py::handle& at, bool exact)
  {
    const auto [ts, single] = translations(at, "at");
    std::vector<PD::Result> rs(ts.size());
    {
      py::gil_scoped_release nogil;
      std::lock_guard<std::mutex> lock(m_mutex); // query() is not thread-safe
      for (std::size_t i = 0; i < ts.size(); ++i) {
        const K::Point_3 t(ts[i][0], ts[i][1], ts[i][2]);
        rs[i] = exact ? m_pd->query(t) : m_pd->nearest_contact(t);
      }
    }
    std::vector<bool> overlapping;
    std::vector<double> depths, directions, contacts;
    for (const auto& r : rs) {
      overlapping.push_back(r.overlapping);
      depths.push_back(r.depth);
      directions.insert(directions.end(), {r.direction.x(), r.direction.y(), r.direction.z()});
      contacts.insert(contacts.end(), {r.contact.x(), r.contact.y(), r.contact.z()});
    }
    const py::ssize_t k = py::ssize_t(rs.size());
    py::array_t<bool> ov(k);
    for (py::ssize_t i = 0; i < k; ++i) ov.mutable_data()[i] = overlapping[std::size_t(i)];
    py::dict out;
    if (single) {
      out["overlapping"] = bool(overlapping[0]);
      out["depths"] = depths[0];
      out["directions"] = to_array(std::move(directions), {3});
      out["contacts"] = to_array(std::move(contacts), {3});
    } else {
      out["overlapping"] = ov;
      out["depths"] = to_array(std::move(depths), {k});
      out["directions"] = to_array(std::move(directions), {k, 3});
      out["contacts"] = to_array(std::move(contacts), {k, 3});
    }
    return out;
  }

  bool overlaps(const py::handle& at)
  {
    const auto [ts, single] = translations(at, "at");
    if (!single) throw Usage_error("overlaps takes one translation (x, y, z)");
    py::gil_scoped_release nogil;
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_pd->overlaps(K::Point_3(ts[0][0], ts[0][1], ts[0][2]));
  }

  py::array_t<double> contact_points() const { return points_array(m_pd->contact_points()); }
  std::size_t number_of_contact_points() const { return m_pd->number_of_contact_points(); }
  double d() const { return m_d; }
  py::dict statistics() const { return statistics_dict(m_stats); }

private:
  std::optional<PD> m_pd;
  double m_d = 0;
  CGAL::Pmsum::Statistics m_stats;
  std::mutex m_mutex;
};

// ---------------------------------------------------------------------------------------
// Motion planning

class Py_motion_planner
{
public:
  using Planner = CGAL::Translational_motion_planner<Mesh, Mesh>;

  Py_motion_planner(const py::object& robot, const py::object& obstacle, double d, bool relative, unsigned k, int threads,
                    bool quiet, const py::object& progress)
  {
    check_positive(d, "d");
    check_threads(threads);
    if (k < 1 || k > 1000) throw Usage_error("k must be a positive integer up to 1000");
    Mesh_argument ar = mesh_argument(robot, "ROBOT"), ao = mesh_argument(obstacle, "OBSTACLE");
    check_exists(ar, "ROBOT");
    check_exists(ao, "OBSTACLE");
    Interruptible cb(progress);
    Input_mesh r, o;
    released(cb, [&] {
      r = input_mesh(std::move(ar), "ROBOT", quiet);
      o = input_mesh(std::move(ao), "OBSTACLE", quiet);
      m_d = relative ? d * pmsum_cli::sum_diagonal(pmsum_cli::PMP::bbox(r.mesh), pmsum_cli::PMP::bbox(o.mesh)) : d;
      const auto np = CGAL::parameters::roadmap_neighbors(k).callback(cb.function());
      pmsum_cli::with_threads(threads, [&](auto tag) { m_planner.emplace(Planner::make<decltype(tag)>(r.mesh, o.mesh, m_d, np)); });
    });
    warn_notes(r.notes);
    warn_notes(o.notes);
  }

  /// The path (k, 3) from start to goal, or None.
  py::object plan(const py::handle& start, const py::handle& goal)
  {
    const auto s = translations(start, "start"), g = translations(goal, "goal");
    if (!s.second || !g.second) throw Usage_error("start and goal must be translations (x, y, z)");
    Planner::Result r;
    {
      py::gil_scoped_release nogil;
      std::lock_guard<std::mutex> lock(m_mutex); // plan() is not thread-safe
      const auto& a = s.first[0];
      const auto& b = g.first[0];
      r = m_planner->plan(K::Point_3(a[0], a[1], a[2]), K::Point_3(b[0], b[1], b[2]));
      m_length = r.found ? r.length : -1;
    }
    if (!r.found) return py::none();
    return points_array(r.path);
  }

  bool is_free(const py::handle& t)
  {
    const auto [ts, single] = translations(t, "t");
    if (!single) throw Usage_error("is_free takes one translation (x, y, z)");
    py::gil_scoped_release nogil;
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_planner->is_free(K::Point_3(ts[0][0], ts[0][1], ts[0][2]));
  }

  py::dict statistics()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    const auto& s = m_planner->statistics();
    py::dict d;
    d["contact_points"] = s.contact_points;
    d["nodes"] = s.nodes;
    d["roadmap_edges"] = s.roadmap_edges;
    d["nodes_checked"] = s.nodes_checked;
    d["nodes_rejected"] = s.nodes_rejected;
    d["edges_checked"] = s.edges_checked;
    d["edges_invalid"] = s.edges_invalid;
    d["search_iterations"] = s.search_iterations;
    d["shortcut_tests"] = s.shortcut_tests;
    d["seconds_contact_space"] = s.seconds_contact_space;
    d["seconds_roadmap"] = s.seconds_roadmap;
    d["seconds_query"] = s.seconds_query;
    return d;
  }

  py::array_t<double> nodes()
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return points_array(m_planner->nodes());
  }
  double d() const { return m_d; }
  double length() const { return m_length; }

private:
  std::optional<Planner> m_planner;
  double m_d = 0, m_length = -1;
  std::mutex m_mutex;
};

py::tuple read_mesh(const py::object& path, bool quiet)
{
  Mesh_argument a = mesh_argument(path, "mesh");
  if (!a.file) throw py::type_error("read_mesh takes a file path");
  check_exists(a, "mesh");
  Interruptible cb{py::none()};
  Input_mesh m = released(cb, [&] { return input_mesh(std::move(a), "mesh", quiet); });
  warn_notes(m.notes);
  return mesh_arrays(m.mesh);
}

const char* const mesh_argument_doc =
  "P, Q (and robot, obstacle) are each either a file path (str or os.PathLike: .off, .obj, .ply,\n"
  "  .stl, read exactly as the pmsum tool reads it), or a pair (vertices, faces) of arrays:\n"
  "  vertices (n, 3) numbers, faces (m, 3) integer vertex indices (or (m, k) polygons), or an\n"
  "  object with `vertices` and `faces` attributes (e.g. a trimesh.Trimesh). Arrays go through\n"
  "  the tool's checks and repairs: non-triangle faces are triangulated, closed meshes oriented\n"
  "  outward (an InputWarning says so; quiet=True silences these notes).\n";

} // namespace

PYBIND11_MODULE(pmsum, m)
{
  m.doc() = "CGAL_pmsum: points exactly on the boundary of a Minkowski sum of polyhedra, covering it "
            "within a distance d; offsets, penetration depth and translational motion planning.";
  m.attr("__version__") = CGAL_PMSUM_VERSION;
  m.attr("CGAL_VERSION") = CGAL_VERSION_STR;
#ifdef CGAL_LINKED_WITH_TBB
  m.attr("WITH_TBB") = true;
#else
  m.attr("WITH_TBB") = false;
#endif

  // Exceptions: the library's message, unchanged.
  auto exception = [&](const char* name, PyObject* base, const char* doc) {
    PyObject* type = PyErr_NewExceptionWithDoc((std::string("pmsum.") + name).c_str(), doc, base, nullptr);
    if (!type) throw py::error_already_set();
    m.add_object(name, py::handle(type)); // the module holds the reference
    return py::handle(type);
  };
  invalid_input_type = exception("InvalidInput", PyExc_ValueError,
                                 "Input the library or the reader refuses (CGAL::Pmsum::Invalid_input, a malformed "
                                 "file or array, a bad option value). A ValueError.");
  too_large_type = exception("TooLarge", PyExc_RuntimeError,
                             "A run refused for its size before the work (CGAL::Pmsum::Too_large: d too small; the "
                             "tool's refusal of an output that may exceed the memory available, unless force=True). "
                             "A RuntimeError.");
  cancelled_type = exception("OperationCancelled", PyExc_RuntimeError,
                             "The progress function returned a false value (CGAL::Pmsum::Operation_cancelled). "
                             "A RuntimeError.");
  input_warning_type = exception("InputWarning", PyExc_UserWarning,
                                 "A note of the reader: faces triangulated, a mesh reoriented, edges split.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const CGAL::Pmsum::Too_large& e) {
      PyErr_SetString(too_large_type.ptr(), e.what());
    } catch (const CGAL::Pmsum::Invalid_input& e) {
      PyErr_SetString(invalid_input_type.ptr(), e.what());
    } catch (const CGAL::Pmsum::Operation_cancelled& e) {
      PyErr_SetString(cancelled_type.ptr(), e.what());
    } catch (const pmsum_cli::Refused& e) {
      PyErr_SetString(too_large_type.ptr(), e.what());
    } catch (const pmsum_cli::Usage_error& e) {
      PyErr_SetString(invalid_input_type.ptr(), e.what());
    } catch (const pmsum_cli::Error& e) {
      PyErr_SetString(invalid_input_type.ptr(), e.what());
    }
  });

  m.def("minkowski_sum", &minkowski_sum, py::arg("P"), py::arg("Q"), py::arg("d"), py::kw_only(),
        py::arg("relative") = false, py::arg("scale_q") = py::none(), py::arg("negate_p") = false,
        py::arg("normal_filter") = true, py::arg("cd_filter") = true, py::arg("octree_filter") = true,
        py::arg("all_candidates") = false, py::arg("trim_points") = true, py::arg("islands") = true,
        py::arg("merge_flat_regions") = true, py::arg("levels") = py::none(), py::arg("threads") = 1, py::arg("force") = false, py::arg("quiet") = false,
        py::arg("progress") = py::none(),
        (std::string(
           "Points exactly on the boundary of P + Q (or -P + Q with negate_p), covering it within d:\n"
           "the same points, in the same order, as `pmsum sum P Q -d D` with the same options.\n\n") +
         mesh_argument_doc +
         "Options (the tool's, in snake case; --no-X is X=False):\n"
         "  d                covering distance (> 0); relative=True: a fraction of the diagonal of the\n"
         "                   bounding box of P + Q (--relative)\n"
         "  scale_q          multiply Q's coordinates by this first (--scale-q)\n"
         "  negate_p         boundary of -P + Q, the contact space of robot P among obstacles Q (--negate-p)\n"
         "  normal_filter, cd_filter, octree_filter   the filters (--no-normal-filter, ...)\n"
         "  all_candidates   every boundary candidate instead of the (d/2, d)-net (--all-candidates)\n"
         "  trim_points      exact points on the trim curves (--no-trim-points)\n"
         "  islands          search pieces inside one lattice cell (--no-islands)\n"
         "  merge_flat_regions  triangulate flat regions cut into many triangles again first\n"
         "                   (--no-merge-flat-regions)\n"
         "  levels           coarse to fine: larger covering distances first (--levels), same unit as d\n"
         "  threads          worker threads; 0 = all cores (the tool's default), 1 = sequential.\n"
         "                   The output does not depend on it.\n"
         "  force            run even if the output may exceed the memory available (--force)\n"
         "  quiet            no InputWarning for the reader's notes\n"
         "  progress         called with the fraction done (in [0, 1]); return False to cancel\n"
         "                   (OperationCancelled). Ctrl-C raises KeyboardInterrupt.\n\n"
         "Returns a dict of numpy arrays (n = number of points):\n"
         "  points (n, 3), normals (n, 3) unit outward normals;\n"
         "  origin_p_dimension (n,) int8: the feature of P the point comes from, 0 vertex, 1 edge, 2 face;\n"
         "  origin_p_index (n,) int64: vertex -> row of P's vertices; face -> row of P's faces (a\n"
         "    triangle of a triangulated polygon: the polygon's row); edge -> row of p_edges;\n"
         "  origin_p_vertices (n, 3) int64, origin_p_weights (n, 3): the sample of P is\n"
         "    sum(weights[i] * vertices_of_P[origin_p_vertices[i]]) (exact barycentric weights,\n"
         "    rounded; slots of weight 0 have the vertex -1); the vertices of nonzero weight are\n"
         "    those of the feature;\n"
         "  p_edges (E, 2) int64: the vertex rows (smaller first) of each edge of P's mesh;\n"
         "  the same for Q (origin_q_*, q_edges); then 'negated_p', 'd' (the absolute covering\n"
         "  distance), 'statistics' (counters and seconds), and with levels 'levels': one such dict\n"
         "  per coarser level.\n"
         "Rows are those of the file (vertices and faces in file order) or of the arrays. When the\n"
         "reader changed the mesh (vertices of no face dropped, a vertex split), a vertex maps to a row\n"
         "with its exact coordinates.")
          .c_str());

  m.def("offset", &offset, py::arg("P"), py::arg("radius"), py::arg("d"), py::kw_only(), py::arg("relative") = false,
        py::arg("cube") = false, py::arg("erode") = false, py::arg("sphere_error") = 0.02, py::arg("threads") = 1,
        py::arg("quiet") = false, py::arg("progress") = py::none(),
        "Points covering the boundary of P + ball(radius) within d, as `pmsum offset` (the same points):\n"
        "the ball is CGAL::make_icosphere(radius, sphere_error), whose inradius is within sphere_error\n"
        "(relative) of radius, so every point lies at a distance in [ball_inradius, r] from P.\n"
        "cube=True: the cube [-radius, radius]^3 instead (exact). erode=True: the erosion of the\n"
        "closed P instead (normals 0; not cancellable). relative=True: radius and d are fractions of\n"
        "P's bounding-box diagonal.\n"
        "Returns a dict: points, normals, origin_p_* and p_edges as minkowski_sum (not for erode),\n"
        "r and d (absolute), ball_inradius, ball_faces, erode, statistics.");

  py::class_<Py_penetration_depth>(m, "PenetrationDepth",
                                   "Translational penetration depth of the moving solid P into the fixed solid Q, from\n"
                                   "points covering the contact space (the boundary of -P + Q) within d, as `pmsum pd`:\n"
                                   "the depth is within d of the exact one; overlap itself is decided exactly.")
    .def(py::init<const py::object&, const py::object&, double, bool, std::optional<double>, int, bool, const py::object&>(),
         py::arg("P"), py::arg("Q"), py::arg("d"), py::kw_only(), py::arg("relative") = false,
         py::arg("scale_q") = py::none(), py::arg("threads") = 1, py::arg("quiet") = false,
         py::arg("progress") = py::none(),
         "The contact space of P (moving) and Q (fixed) with covering distance d; threads, quiet and\n"
         "progress as for minkowski_sum.")
    .def("query", [](Py_penetration_depth& self, const py::handle& at) { return self.answer(at, true); }, py::arg("at"),
         "query(at): at is a translation (3,) of P or an array (k, 3) of them. Returns a dict: overlapping\n"
         "(bool, exact), depths (0 where free), directions (unit: translate P by depth * direction to\n"
         "separate it; 0 where free) and contacts (the nearest contact configuration; at where free);\n"
         "shapes (), (3,) for one translation, (k,), (k, 3) for k.")
    .def("nearest_contact", [](Py_penetration_depth& self, const py::handle& at) { return self.answer(at, false); },
         py::arg("at"), "nearest_contact(at): as query, the nearest contact point whether or not P overlaps Q "
                        "(overlapping is always False).")
    .def("overlaps", &Py_penetration_depth::overlaps, py::arg("at"), "overlaps(at): exact overlap test at one translation.")
    .def_property_readonly("contact_points", &Py_penetration_depth::contact_points, "the contact points (n, 3)")
    .def_property_readonly("number_of_contact_points", &Py_penetration_depth::number_of_contact_points)
    .def_property_readonly("d", &Py_penetration_depth::d, "the covering distance (absolute)")
    .def_property_readonly("statistics", &Py_penetration_depth::statistics, "statistics of the contact space");

  m.def(
    "penetration_depth",
    [](const py::object& P, const py::object& Q, double d, const py::handle& at, bool relative, std::optional<double> scale_q,
       int threads, bool quiet) {
      Py_penetration_depth pd(P, Q, d, relative, scale_q, threads, quiet, py::none());
      return pd.answer(at, true);
    },
    py::arg("P"), py::arg("Q"), py::arg("d"), py::arg("at"), py::kw_only(), py::arg("relative") = false,
    py::arg("scale_q") = py::none(), py::arg("threads") = 1, py::arg("quiet") = false,
    "PenetrationDepth(P, Q, d, ...).query(at): a dict of overlapping, depths, directions, contacts.\n"
    "Build a PenetrationDepth to query the same pair many times.");

  py::class_<Py_motion_planner>(m, "MotionPlanner",
                                "Paths of a robot translating among fixed obstacles, on a roadmap over points covering\n"
                                "the contact space within d, as `pmsum plan`. Sound (every segment of a returned path\n"
                                "is free, checked exactly), not complete.")
    .def(py::init<const py::object&, const py::object&, double, bool, unsigned, int, bool, const py::object&>(),
         py::arg("robot"), py::arg("obstacle"), py::arg("d"), py::kw_only(), py::arg("relative") = false,
         py::arg("k") = 12, py::arg("threads") = 1, py::arg("quiet") = false, py::arg("progress") = py::none(),
         "k: neighbours per roadmap node (-k); relative: d is a fraction of the diagonal of the bounding\n"
         "box of -robot + obstacle.")
    .def("plan", &Py_motion_planner::plan, py::arg("start"), py::arg("goal"),
         "plan(start, goal): the path (k, 3) of translations of the robot from start to goal, or None\n"
         "when the roadmap joins none (which does not prove that none exists). Raises InvalidInput\n"
         "when start or goal is not free.")
    .def("is_free", &Py_motion_planner::is_free, py::arg("t"), "is_free(t): exact test that translation t is free.")
    .def_property_readonly("statistics", &Py_motion_planner::statistics)
    .def_property_readonly("nodes", &Py_motion_planner::nodes, "the roadmap's nodes (n, 3)")
    .def_property_readonly("d", &Py_motion_planner::d, "the covering distance (absolute)")
    .def_property_readonly("last_path_length", &Py_motion_planner::length,
                           "length of the path of the last plan() (-1 if none was found)");

  m.def(
    "plan",
    [](const py::object& robot, const py::object& obstacle, const py::handle& start, const py::handle& goal, double d,
       bool relative, unsigned k, int threads, bool quiet) {
      Py_motion_planner planner(robot, obstacle, d, relative, k, threads, quiet, py::none());
      return planner.plan(start, goal);
    },
    py::arg("robot"), py::arg("obstacle"), py::arg("start"), py::arg("goal"), py::arg("d"), py::kw_only(),
    py::arg("relative") = false, py::arg("k") = 12, py::arg("threads") = 1, py::arg("quiet") = false,
    "MotionPlanner(robot, obstacle, d, ...).plan(start, goal): a path (k, 3) or None.");

  m.def("read_mesh", &read_mesh, py::arg("path"), py::kw_only(), py::arg("quiet") = false,
        "(vertices (n, 3), faces (m, 3)) of the mesh as the pmsum tool\n"
        "reads it (checked, triangulated, closed meshes oriented outward).");
}
