# Copyright (c) 2026 CGAL_pmsum contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Tests of the Python module pmsum (src/python/pmsum_module.cpp). Run by CTest as
#   PYTHONPATH=<build>/python PMSUM_TOOL=<build>/pmsum /usr/bin/python3 -m pytest -q test/python
# The comparisons with the command-line tool are skipped when PMSUM_TOOL is not set.

import os
import pathlib
import re
import signal
import subprocess
import sys
import threading
import time
import warnings

import numpy as np
import pytest

import pmsum

SOURCE = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("PMSUM_DATA_DIR", SOURCE / "data"))
TOOL = os.environ.get("PMSUM_TOOL")
needs_tool = pytest.mark.skipif(not TOOL, reason="PMSUM_TOOL (the pmsum tool) is not set")


# ----------------------------------------------------------------------------------------
# helpers

def box(lo, hi):
    """Closed box, outward oriented: (vertices (8, 3), faces (12, 3))."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    v = np.array([[hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2]] for i in range(8)])
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    f = np.array([t for q in quads for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])], dtype=np.int64)
    return v, f


def read_off(path):
    """A plain OFF reader (vertices, polygons) for the tests' own arrays."""
    tokens = []
    for line in pathlib.Path(path).read_text().splitlines():
        tokens += line.split("#")[0].split()
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    v = np.array(tokens[pos:pos + 3 * nv], float).reshape(nv, 3)
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[pos])
        faces.append([int(x) for x in tokens[pos + 1:pos + 1 + n]])
        pos += 1 + n
    return v, np.array(faces, dtype=np.int64)


def run_tool(*args, check=True):
    r = subprocess.run([TOOL, *map(str, args)], capture_output=True, text=True, timeout=600)
    if check:
        assert r.returncode == 0, r.stderr
    return r


def read_xyz(path):
    """The tool's .xyz: six columns x y z nx ny nz, 17 significant digits (exact doubles)."""
    a = np.loadtxt(path, ndmin=2)
    if a.size == 0:
        return np.zeros((0, 3)), np.zeros((0, 3))
    assert a.shape[1] == 6
    return a[:, :3], a[:, 3:]


def tool_sum(tmp_path, P, Q, d, *options):
    out = tmp_path / "tool.xyz"
    run_tool("sum", P, Q, "-d", repr(float(d)), "-o", out, "--quiet", *options)
    return read_xyz(out)


def distance_to_box(p, lo, hi):
    """Euclidean distance from points (n, 3) to the solid box [lo, hi] (0 inside)."""
    lo, hi = np.asarray(lo), np.asarray(hi)
    return np.linalg.norm(np.maximum(np.maximum(lo - p, p - hi), 0), axis=1)


def box_surface_samples(lo, hi, n):
    """n x n samples on each face of the box [lo, hi]."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    s = []
    for axis in range(3):
        a, b = [c for c in range(3) if c != axis]
        u, w = np.meshgrid(np.linspace(lo[a], hi[a], n), np.linspace(lo[b], hi[b], n))
        for side in (lo[axis], hi[axis]):
            pts = np.zeros((n * n, 3))
            pts[:, axis] = side
            pts[:, a] = u.ravel()
            pts[:, b] = w.ravel()
            s.append(pts)
    return np.concatenate(s)


def nearest_distances(samples, points):
    """For each sample, the distance to the nearest point (brute force)."""
    d2 = ((samples[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
    return np.sqrt(d2.min(axis=1))


def samples_of(result, side, vertices):
    """The samples of P (side 'p') or Q ('q') rebuilt from the provenance arrays."""
    idx = result[f"origin_{side}_vertices"]
    w = result[f"origin_{side}_weights"]
    used = idx >= 0
    pts = np.where(used[:, :, None], vertices[np.where(used, idx, 0)], 0.0)
    return (w[:, :, None] * pts).sum(axis=1)


# ----------------------------------------------------------------------------------------
# the module

def test_version_matches_header():
    text = (SOURCE / "include" / "CGAL_pmsum" / "version.h").read_text()
    assert pmsum.__version__ == re.search(r'#define CGAL_PMSUM_VERSION "([0-9.]+)"', text).group(1)


def test_exception_hierarchy():
    assert issubclass(pmsum.InvalidInput, ValueError)
    assert issubclass(pmsum.TooLarge, RuntimeError)
    assert issubclass(pmsum.OperationCancelled, RuntimeError)
    assert issubclass(pmsum.InputWarning, UserWarning)


# ----------------------------------------------------------------------------------------
# minkowski_sum: closed forms

CUBE = box([0, 0, 0], [1, 1, 1])
HALF = box([0, 0, 0], [0.5, 0.5, 0.5])
SUM_LO, SUM_HI = np.zeros(3), np.full(3, 1.5)


def test_cube_plus_cube_points_on_exact_boundary():
    r = pmsum.minkowski_sum(CUBE, HALF, 0.2)
    p, n = r["points"], r["normals"]
    assert p.shape[1] == 3 and p.shape == n.shape and len(p) > 100
    # every point on the boundary of [0, 1.5]^3: inside, and on a face exactly
    assert np.all(p >= SUM_LO) and np.all(p <= SUM_HI)
    assert np.all(np.any((p == SUM_LO) | (p == SUM_HI), axis=1))
    # unit normals pointing outward
    assert np.allclose(np.linalg.norm(n, axis=1), 1)
    assert np.all(((p - 0.75) * n).sum(axis=1) > 0)
    assert r["d"] == 0.2 and r["negated_p"] is False
    assert r["statistics"]["output_points"] == len(p)


def test_cube_plus_cube_covers_the_boundary():
    d = 0.2
    r = pmsum.minkowski_sum(CUBE, HALF, d)
    samples = box_surface_samples(SUM_LO, SUM_HI, 31)
    assert nearest_distances(samples, r["points"]).max() <= d
    # the (d/2, d)-net: no two points closer than d/2
    p = r["points"]
    d2 = ((p[:, None] - p[None]) ** 2).sum(axis=2)
    np.fill_diagonal(d2, np.inf)
    assert np.sqrt(d2.min()) >= d / 2 - 1e-12


def test_negated_and_relative():
    # -P + Q for P = [0, 1]^3, Q = [0, .5]^3: [-1, 0.5]^3
    r = pmsum.minkowski_sum(CUBE, HALF, 0.1, relative=True, negate_p=True)
    assert r["negated_p"] is True
    assert r["d"] == pytest.approx(0.1 * np.sqrt(3) * 1.5)
    p = r["points"]
    assert np.all(p >= -1) and np.all(p <= 0.5)
    assert np.all(np.any((p == -1) | (p == 0.5), axis=1))


def test_provenance_rebuilds_the_points():
    P = read_off(DATA / "cross.off")
    Q = read_off(DATA / "star.off")
    r = pmsum.minkowski_sum(P, Q, 0.08, quiet=True)
    n = len(r["points"])
    for side, mesh in (("p", P), ("q", Q)):
        dim, index, verts = r[f"origin_{side}_dimension"], r[f"origin_{side}_index"], r[f"origin_{side}_vertices"]
        assert dim.shape == (n,) and set(np.unique(dim)) <= {0, 1, 2}
        assert np.all(index >= 0)
        # weights: barycentric, over the feature's vertices
        assert np.allclose(r[f"origin_{side}_weights"].sum(axis=1), 1)
        assert np.array_equal(verts >= 0, r[f"origin_{side}_weights"] != 0)
        # the vertices of nonzero weight are those of the feature
        edges, faces = r[f"{side}_edges"], mesh[1]
        for i in range(n):
            used = set(verts[i][verts[i] >= 0])
            feature = {0: lambda k: {k}, 1: lambda k: set(edges[k]), 2: lambda k: set(faces[k])}[dim[i]](index[i])
            assert used <= feature and (dim[i] > 0 or used == feature)
    rebuilt = samples_of(r, "p", P[0]) + samples_of(r, "q", Q[0])
    assert np.allclose(rebuilt, r["points"], atol=1e-12)


def test_provenance_rows_of_arrays_with_unused_vertices():
    # vertex rows of the arrays, also when rows of no face are dropped by the reader
    v, f = box([0, 0, 0], [1, 1, 1])
    v2 = np.concatenate([[[9.0, 9.0, 9.0]], v, [[7.0, 7.0, 7.0]]])
    r1 = pmsum.minkowski_sum((v, f), HALF, 0.3)
    r2 = pmsum.minkowski_sum((v2, f + 1), HALF, 0.3)
    # the same boundary (the reader renumbers the vertices it keeps: the points may come in
    # another order)
    assert np.array_equal(np.unique(r1["points"], axis=0), np.unique(r2["points"], axis=0))
    assert np.allclose(samples_of(r2, "p", v2) + samples_of(r2, "q", HALF[0]), r2["points"])
    vertex = r2["origin_p_dimension"] == 0
    assert vertex.any() and set(r2["origin_p_index"][vertex]) <= set(range(1, 9))
    assert np.all(r2["p_edges"] >= 1) and np.all(r2["p_edges"] <= 8)
    e = r2["p_edges"]
    assert np.all(np.any(v2[e[:, 0]] != v2[e[:, 1]], axis=1))


def test_threads_do_not_change_the_output():
    a = pmsum.minkowski_sum(DATA / "cross.off", DATA / "star.off", 0.05, relative=True, threads=1)
    b = pmsum.minkowski_sum(DATA / "cross.off", DATA / "star.off", 0.05, relative=True, threads=0)
    assert np.array_equal(a["points"], b["points"])
    assert np.array_equal(a["origin_q_index"], b["origin_q_index"])


def test_arrays_give_the_points_of_the_file():
    for name in ("cross", "icosahedron", "octahedron"):
        a = pmsum.minkowski_sum(DATA / f"{name}.off", DATA / "star.off", 0.05, relative=True)
        b = pmsum.minkowski_sum(read_off(DATA / f"{name}.off"), read_off(DATA / "star.off"), 0.05, relative=True)
        assert np.array_equal(a["points"], b["points"])
        assert np.array_equal(a["origin_p_index"], b["origin_p_index"])


def test_inputs_path_like_list_and_object():
    class Mesh:
        vertices, faces = HALF
    r1 = pmsum.minkowski_sum(str(DATA / "icosahedron.off"), Mesh(), 0.1)
    r2 = pmsum.minkowski_sum(DATA / "icosahedron.off", [HALF[0].tolist(), HALF[1].tolist()], 0.1)
    assert np.array_equal(r1["points"], r2["points"])


# ----------------------------------------------------------------------------------------
# minkowski_sum: the same points, in the same order, as `pmsum sum`

TOOL_CASES = [
    ("cross", "star", 0.05, {"relative": True}),
    ("star", "cross", 0.04, {"relative": True, "negate_p": True}),
    ("icosahedron", "octahedron", 0.1, {"scale_q": 0.5, "all_candidates": True}),
    ("tetrahedron", "icosahedron", 0.15, {"trim_points": False}),
    ("l_and_box_sharing_edge", "octahedron", 0.05, {"relative": True, "islands": False, "octree_filter": False}),
    ("open_cube", "icosahedron", 5.0, {"threads": 0}),
    ("cross", "star", 0.05, {"relative": True, "merge_flat_regions": False}),
]


def cli_options(options):
    args = []
    for key, value in options.items():
        flag = {"relative": "--relative", "negate_p": "--negate-p", "all_candidates": "--all-candidates"}.get(key)
        if flag:
            args += [flag] if value else []
        elif key in ("trim_points", "islands", "octree_filter", "normal_filter", "cd_filter", "merge_flat_regions"):
            args += [] if value else ["--no-" + key.replace("_", "-")]
        elif key == "scale_q":
            args += ["--scale-q", repr(value)]
        elif key == "threads":
            args += ["--threads", str(value)] if value else []
        elif key == "levels":
            args += ["--levels", ",".join(map(repr, value))]
        else:
            raise KeyError(key)
    return args


@needs_tool
@pytest.mark.parametrize("p,q,d,options", TOOL_CASES, ids=[f"{c[0]}+{c[1]}" for c in TOOL_CASES])
def test_same_points_as_the_tool(tmp_path, p, q, d, options):
    P, Q = DATA / f"{p}.off", DATA / f"{q}.off"
    tool_points, tool_normals = tool_sum(tmp_path, P, Q, d, *cli_options(options))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", pmsum.InputWarning)
        r = pmsum.minkowski_sum(P, Q, d, **options)
    assert len(tool_points) > 0
    assert np.array_equal(r["points"], tool_points)
    assert np.array_equal(r["normals"], tool_normals)


@needs_tool
def test_same_levels_as_the_tool(tmp_path):
    P, Q = DATA / "cross.off", DATA / "star.off"
    out = tmp_path / "tool.xyz"
    run_tool("sum", P, Q, "-d", "0.03", "--relative", "--levels", "0.1,0.06", "-o", out, "--quiet")
    r = pmsum.minkowski_sum(P, Q, 0.03, relative=True, levels=[0.1, 0.06])
    assert np.array_equal(r["points"], read_xyz(out)[0])
    assert len(r["levels"]) == 2
    for k in range(2):
        assert np.array_equal(r["levels"][k]["points"], read_xyz(tmp_path / f"tool.level{k}.xyz")[0])
    assert r["levels"][0]["d"] > r["levels"][1]["d"] > r["d"]


# ----------------------------------------------------------------------------------------
# errors

def test_faces_out_of_range():
    v, f = CUBE
    f = f.copy()
    f[3, 1] = 8
    with pytest.raises(ValueError, match=r"P face 3 names vertex 8 \(counting from 0\), but there are only 8 vertices"):
        pmsum.minkowski_sum((v, f), HALF, 0.1)
    f[3, 1] = -1
    with pytest.raises(ValueError, match="P face 3 names a vertex with a negative index"):
        pmsum.minkowski_sum((v, f), HALF, 0.1)
    f[3, 1] = f[3, 0]
    with pytest.raises(ValueError, match="P face 3 has fewer than three distinct vertices"):
        pmsum.minkowski_sum((v, f), HALF, 0.1)


@pytest.mark.parametrize("mesh", [
    (np.zeros((8, 2)), CUBE[1]),                       # vertices not (n, 3)
    (CUBE[0], CUBE[1][:, :2]),                         # faces (m, 2)
    (CUBE[0], CUBE[1].astype(float)),                  # faces not integers
    (CUBE[0], np.array([0, 1, 2])),                    # faces 1-D
    (np.array([["a", "b", "c"]]), CUBE[1]),            # vertices not numbers
    (CUBE[0], np.zeros((0, 3), dtype=np.int64)),       # no faces
])
def test_bad_arrays_raise_value_error(mesh):
    with pytest.raises(ValueError):
        pmsum.minkowski_sum(mesh, HALF, 0.1)


def test_bad_arguments():
    with pytest.raises(TypeError):
        pmsum.minkowski_sum(42, HALF, 0.1)
    with pytest.raises(TypeError):
        pmsum.minkowski_sum((CUBE[0], CUBE[1], CUBE[1]), HALF, 0.1)
    for d in (0.0, -1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="d must be a positive number"):
            pmsum.minkowski_sum(CUBE, HALF, d)
    with pytest.raises(ValueError, match="levels"):
        pmsum.minkowski_sum(CUBE, HALF, 0.1, levels=[0.05])
    with pytest.raises(ValueError, match="threads"):
        pmsum.minkowski_sum(CUBE, HALF, 0.1, threads=-1)
    nan = CUBE[0].copy()
    nan[0, 0] = np.nan
    with pytest.raises(ValueError, match="not finite"):
        pmsum.minkowski_sum((nan, CUBE[1]), HALF, 0.1)


def test_files_missing_and_malformed(tmp_path):
    with pytest.raises(FileNotFoundError):
        pmsum.minkowski_sum(tmp_path / "missing.off", HALF, 0.1)
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(ValueError, match=r"cannot read P \('.*bad.off'\): the OFF header declares 3 vertices"):
        pmsum.minkowski_sum(bad, HALF, 0.1)


def write_off(path, v, f):
    with open(path, "w") as out:
        out.write(f"OFF\n{len(v)} {len(f)} 0\n")
        for p in v:
            out.write(" ".join(repr(float(x)) for x in p) + "\n")
        for t in f:
            out.write(f"{len(t)} " + " ".join(map(str, t)) + "\n")


def test_library_errors_keep_the_library_message(tmp_path):
    # two closed boxes that overlap: refused by the library's checks (CGAL::Pmsum::Invalid_input)
    v1, f1 = box([0, 0, 0], [1, 1, 1])
    v2, f2 = box([0.5, 0.5, 0.5], [1.5, 1.5, 1.5])
    v, f = np.concatenate([v1, v2]), np.concatenate([f1, f2 + 8])
    with pytest.raises(pmsum.InvalidInput) as info:
        pmsum.minkowski_sum((v, f), HALF, 0.1)
    message = str(info.value)
    assert message.startswith("P") and "overlap" in message
    if TOOL:
        write_off(tmp_path / "overlap.off", v, f)
        write_off(tmp_path / "half.off", *HALF)
        r = run_tool("sum", tmp_path / "overlap.off", tmp_path / "half.off", "-d", "0.1", "-o", tmp_path / "o.xyz",
                     "--quiet", check=False)
        assert r.returncode == 1
        # the tool names the mesh with its file; the rest of the message is the same
        tool_message = r.stderr.strip().removeprefix("pmsum: error: ")
        assert tool_message.replace(f"P ('{tmp_path / 'overlap.off'}')", "P") == message


def test_cancel_and_progress():
    seen = []
    r = pmsum.minkowski_sum(DATA / "cross.off", DATA / "star.off", 0.05, relative=True, progress=seen.append)
    assert len(r["points"]) > 0 and seen and all(0 <= x <= 1 for x in seen) and seen == sorted(seen)
    with pytest.raises(pmsum.OperationCancelled):
        pmsum.minkowski_sum(DATA / "cross.off", DATA / "star.off", 0.05, relative=True, progress=lambda f: False)

    def fail(f):
        raise ZeroDivisionError("from progress")
    with pytest.raises(ZeroDivisionError, match="from progress"):
        pmsum.minkowski_sum(DATA / "cross.off", DATA / "star.off", 0.05, relative=True, progress=fail)


def test_ctrl_c_interrupts_a_long_run(tmp_path):
    # SIGINT (Ctrl-C) during a run of about a minute: KeyboardInterrupt within a second or so
    script = tmp_path / "long_run.py"
    script.write_text(
        "import pmsum, sys\n"
        "print('started', flush=True)\n"
        "try:\n"
        f"    pmsum.minkowski_sum({str(DATA / 'knot1.off')!r}, {str(DATA / 'elephant.off')!r}, 0.004, relative=True)\n"
        "    print('finished')\n"
        "except KeyboardInterrupt:\n"
        "    print('interrupted')\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(pathlib.Path(pmsum.__file__).parent),
                                                       os.environ.get("PYTHONPATH", "")]))
    child = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, text=True, env=env)
    assert child.stdout.readline().strip() == "started"
    time.sleep(4)  # past the input checks (the progress callback, which checks for signals, comes after)
    signalled = time.perf_counter()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=120)
    assert out.strip() == "interrupted"
    assert time.perf_counter() - signalled < 10


def test_gil_is_released():
    # While a sum runs in a thread, the main thread keeps running Python code.
    done = threading.Event()
    result = {}

    def work():
        result["r"] = pmsum.minkowski_sum(DATA / "cross.off", DATA / "star.off", 0.02, relative=True)
        done.set()

    ticks = 0
    t = threading.Thread(target=work)
    start = time.perf_counter()
    t.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    t.join()
    elapsed = time.perf_counter() - start
    if elapsed > 0.5:  # long enough to tell: with the GIL held, the loop would stall
        assert ticks > 0.2 * elapsed / 0.0011
    assert len(result["r"]["points"]) > 0


def test_reader_notes_are_warnings():
    with pytest.warns(pmsum.InputWarning, match="was not oriented outward"):
        v, f = pmsum.read_mesh(DATA / "tetrahedron.off")
    assert v.shape == (4, 3) and f.shape == (4, 3)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pmsum.read_mesh(DATA / "tetrahedron.off", quiet=True)
    # quads are triangulated; a face row names the quad
    v, f = box([0, 0, 0], [1, 1, 1])
    quads = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])
    with pytest.warns(pmsum.InputWarning, match="triangulated 6 non-triangle faces"):
        r = pmsum.minkowski_sum(DATA / "icosahedron.off", (v, quads), 0.2)
    faces = r["origin_q_dimension"] == 2
    assert faces.any() and set(r["origin_q_index"][faces]) <= set(range(6))
    for i in np.nonzero(faces)[0]:
        used = r["origin_q_vertices"][i]
        assert set(used[used >= 0]) <= set(quads[r["origin_q_index"][i]])


# ----------------------------------------------------------------------------------------
# offset

def test_offset_of_a_box_lies_between_inradius_and_r():
    lo, hi = [0, 0, 0], [1, 2, 0.5]
    r = pmsum.offset(box(lo, hi), 0.3, 0.1)
    assert r["r"] == 0.3 and 0.3 * 0.98 <= r["ball_inradius"] < 0.3 and r["ball_faces"] > 20
    dist = distance_to_box(r["points"], lo, hi)
    assert np.all(dist >= r["ball_inradius"] - 1e-12) and np.all(dist <= r["r"] + 1e-12)
    assert len(r["points"]) > 50 and r["origin_p_dimension"].shape == (len(r["points"]),)


def test_cube_offset_and_erosion():
    lo, hi = np.array([0, 0, 0.0]), np.array([1, 2, 0.5])
    r = pmsum.offset(box(lo, hi), 0.25, 0.1, cube=True)
    p = r["points"]
    # the box grown by 0.25 in the maximum norm: [lo - .25, hi + .25], on its boundary
    assert np.all(p >= lo - 0.25) and np.all(p <= hi + 0.25)
    assert np.all(np.any(np.isclose(p, lo - 0.25, rtol=0, atol=1e-12) | np.isclose(p, hi + 0.25, rtol=0, atol=1e-12), axis=1))
    e = pmsum.offset(box(lo, hi), 0.1, 0.05, erode=True)
    q = e["points"]
    assert e["erode"] and len(q) > 0 and np.all(e["normals"] == 0)
    # points whose ball lies inside the box, on the erosion's boundary: distance to the box's
    # boundary between the ball's inradius and r
    depth = np.minimum(q - lo, hi - q).min(axis=1)
    assert np.all(depth >= e["ball_inradius"] - 1e-12) and np.all(depth <= 0.1 + 1e-12)


@needs_tool
@pytest.mark.parametrize("options", [[], ["--cube"], ["--erode"], ["--relative", "--sphere-error", "0.05"]])
def test_offset_same_points_as_the_tool(tmp_path, options):
    mesh = DATA / "cross.off"
    if "--erode" in options:  # (the cross's arms are 0.2 thick: its erosion by 0.1 is empty)
        mesh = tmp_path / "box.off"
        write_off(mesh, *box([0, 0, 0], [1, 0.75, 0.5]))
    out = tmp_path / "tool.xyz"
    radius, d = (0.05, 0.04) if "--relative" in options else (0.1, 0.08)
    run_tool("offset", mesh, "-r", radius, "-d", d, "-o", out, "--quiet", *options)
    tool_points, tool_normals = read_xyz(out)
    r = pmsum.offset(mesh, radius, d, cube="--cube" in options, erode="--erode" in options,
                     relative="--relative" in options, sphere_error=0.05 if "--sphere-error" in options else 0.02)
    assert len(tool_points) > 0
    assert np.array_equal(r["points"], tool_points)
    assert np.array_equal(r["normals"], tool_normals)


# ----------------------------------------------------------------------------------------
# penetration depth

def test_penetration_depth_of_two_cubes():
    d = 0.05
    pd = pmsum.PenetrationDepth(CUBE, CUBE, d)
    assert pd.d == d and pd.number_of_contact_points == len(pd.contact_points) > 0
    r = pd.query([0.7, 0.2, 0.1])
    # the shortest separating translation: +x by 1 - 0.7
    assert r["overlapping"] is True
    assert 0.3 <= r["depths"] <= 0.3 + d
    assert np.allclose(r["directions"], [1, 0, 0], atol=0.2)
    assert np.allclose(r["contacts"], np.array([0.7, 0.2, 0.1]) + r["depths"] * r["directions"])
    many = pd.query(np.array([[0.7, 0.2, 0.1], [2.0, 0, 0], [0.1, -0.6, 0.05]]))
    assert many["overlapping"].tolist() == [True, False, True]
    assert many["depths"].shape == (3,) and many["directions"].shape == (3, 3)
    assert many["depths"][1] == 0
    assert 0.4 <= many["depths"][2] <= 0.4 + d  # -y by 1 - 0.6
    assert pd.overlaps([0.5, 0.5, 0.5]) and not pd.overlaps([1.0, 0, 0])  # touching is not overlap
    near = pd.nearest_contact([2.0, 0, 0])
    assert near["overlapping"] is False and 1.0 <= near["depths"] <= 1.0 + d
    f = pmsum.penetration_depth(CUBE, CUBE, d, [0.7, 0.2, 0.1])
    assert f["depths"] == r["depths"]
    with pytest.raises(ValueError):
        pd.query([[1, 2]])
    with pytest.raises(ValueError):
        pd.query([np.nan, 0, 0])


@needs_tool
def test_penetration_depth_as_the_tool(tmp_path):
    P, Q = DATA / "cross.off", DATA / "star.off"
    at = [[0.05, 0.0, 0.0], [0.0, 0.1, 0.02], [5.0, 5.0, 5.0]]
    args = ["pd", P, Q, "-d", "0.05", "--relative", "--quiet"]
    for t in at:
        args += ["--at", *map(repr, t)]
    lines = run_tool(*args).stdout.splitlines()
    r = pmsum.penetration_depth(P, Q, 0.05, np.array(at), relative=True)
    for line, overlapping, depth in zip(lines, r["overlapping"], r["depths"]):
        words = line.split()
        assert (words[3] == "overlap") == overlapping
        if overlapping:
            assert float(words[4]) == pytest.approx(depth, rel=1e-9)


# ----------------------------------------------------------------------------------------
# motion planning

ROBOT = box([0, 0, 0], [1, 1, 1])
SLAB = box([-2, -2, 0], [3, 3, 1])  # the robot must go around it
START, GOAL = [0, 0, 2], [0, 0, -2]


def robot_overlaps_slab(t):
    """Exact for boxes: the interiors of robot + t and the slab overlap iff they do on every axis."""
    t = np.atleast_2d(t)
    lo, hi = SLAB[0].min(axis=0), SLAB[0].max(axis=0)
    return np.all((t < hi) & (t + 1 > lo), axis=1)


def test_plan_around_a_slab():
    start, goal = np.array(START, float), np.array(GOAL, float)
    path = pmsum.plan(ROBOT, SLAB, start, goal, 0.5)
    assert path is not None and path.shape[1] == 3 and len(path) >= 3
    assert np.array_equal(path[0], start) and np.array_equal(path[-1], goal)
    # every point of every segment free (sampled; the planner checks them exactly)
    for a, b in zip(path[:-1], path[1:]):
        s = np.linspace(0, 1, 500)[:, None]
        assert not robot_overlaps_slab(a + s * (b - a)).any()
    planner = pmsum.MotionPlanner(ROBOT, SLAB, 0.5, k=8)
    path2 = planner.plan(start, goal)
    assert path2 is not None
    assert planner.last_path_length == pytest.approx(np.linalg.norm(np.diff(path2, axis=0), axis=1).sum())
    assert planner.last_path_length > 4  # around the slab, not through it
    assert planner.is_free(START) and not planner.is_free([0, 0, 0.5])
    assert planner.statistics["nodes"] == len(planner.nodes) > 0
    with pytest.raises(pmsum.InvalidInput, match="the start configuration is not free"):
        planner.plan([0, 0, 0.5], goal)


@needs_tool
def test_plan_as_the_tool(tmp_path):
    write_off(tmp_path / "robot.off", *ROBOT)
    write_off(tmp_path / "slab.off", *SLAB)
    out = run_tool("plan", tmp_path / "robot.off", tmp_path / "slab.off", "--start", *START, "--goal", *GOAL,
                   "-d", 0.5, "--threads", 1, "--quiet").stdout
    tool_path = np.array([[float(x) for x in line.split()] for line in out.splitlines()])
    path = pmsum.plan(tmp_path / "robot.off", tmp_path / "slab.off", START, GOAL, 0.5)
    assert np.array_equal(path, tool_path)
