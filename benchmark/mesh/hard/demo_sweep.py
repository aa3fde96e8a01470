#!/usr/bin/python3
"""A sweep of `pmsum mesh` over CGAL's demo models (data/meshes of libcgal-demo) plus a small
tetrahedron, octahedron or cube (scaled to 5% of the model's diagonal), at d = 1.5% and 3%
(tetrahedron) or 2% (the others) of the sum's diagonal, one thread. One row per run: the exit
code and seconds, the mesh's Euler characteristic, shells and level (`c`: crease points kept,
`p`: plane by plane), or the error; and the model's own Euler characteristic (V - E + F of its
faces), which the sum's equals unless the tool closes a hole of the model or joins two of its
parts: a difference is a run to validate against Nef (`pmsum validate ... --mesh`), not an error.

    /usr/bin/python3 benchmark/mesh/hard/demo_sweep.py --pmsum build/pmsum --work /tmp/demo_sweep [--models M ...]

The models are read from the demo archive (`/usr/share/doc/libcgal-dev/data.tar.gz`, extracted
into the work folder once); the default list: closed models that the suite does not use.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tarfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from run_mesh import read_off  # noqa: E402

DATA = os.path.join(HERE, "..", "..", "..", "data")
MODELS = ["tripod", "u", "cactus", "hand", "couplingdown", "femur", "dino", "fandisk", "bear", "bunny00", "handle", "knot",
          "sphere", "ellipsoid", "3torus", "pinion_small", "rotor_small", "spool", "dragknob", "beam", "turbine"]
# tool, d (fractions of the sum's diagonal)
TOOLS = [("tetrahedron", ["0.015", "0.03"]), ("octahedron", ["0.02"]), ("cube", ["0.02"])]


def diagonal(points):
    return math.dist([min(p[c] for p in points) for c in range(3)], [max(p[c] for p in points) for c in range(3)])


def euler(points, faces):
    sides = {tuple(sorted((f[k], f[(k + 1) % len(f)]))) for f in faces for k in range(len(f))}
    return len(points) - len(sides) + len(faces)


def tool_path(name, pmsum, work):
    path = os.path.join(DATA, name + ".off")
    if not os.path.exists(path):  # (no cube in data/: the generated one)
        path = os.path.join(work, name + ".off")
        if not os.path.exists(path):
            subprocess.run([pmsum, "generate", name, "-o", path], check=True, capture_output=True)
    return path


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pmsum", required=True)
    ap.add_argument("--work", required=True, help="folder for the models and the meshes")
    ap.add_argument("--models", nargs="*", default=MODELS)
    ap.add_argument("--archive", default="/usr/share/doc/libcgal-dev/data.tar.gz")
    ap.add_argument("--timeout", type=float, default=400)
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    meshes = os.path.join(a.work, "data", "meshes")
    if not os.path.isdir(meshes):
        with tarfile.open(a.archive) as t:
            t.extractall(a.work, members=[m for m in t.getmembers() if m.name.startswith("data/meshes/")])
    for model in a.models:
        p = os.path.join(meshes, model + ".off")
        points, faces = read_off(p)
        for tool, ds in TOOLS:
            q = tool_path(tool, a.pmsum, a.work)
            scale = 0.05 * diagonal(points) / diagonal(read_off(q)[0])
            for d in ds:
                out = os.path.join(a.work, "mesh")
                if os.path.exists(out + ".json"):
                    os.remove(out + ".json")
                start = time.time()
                try:
                    r = subprocess.run([a.pmsum, "mesh", p, q, "-d", d, "--relative", "--scale-q", "%.6g" % scale, "--threads", "1",
                                        "-o", out + ".off", "--json", out + ".json", "--quiet"],
                                       capture_output=True, text=True, timeout=a.timeout)
                except subprocess.TimeoutExpired:
                    print("%-14s %-11s d %-5s past %.0f s" % (model, tool, d, a.timeout), flush=True)
                    continue
                row = "%-14s %-11s d %-5s --scale-q %-9.6g model's Euler characteristic %4d: " % (
                    model, tool, d, scale, euler(points, faces))
                if r.returncode:
                    last = r.stderr.strip().splitlines()[-1][:160] if r.stderr.strip() else ""
                    print(row + "exit %d after %.1f s: %s" % (r.returncode, time.time() - start, last), flush=True)
                    continue
                m = json.load(open(out + ".json"))["mesh"]
                level = "%d%s%s" % (m["refinements"], "c" if m["crease_points"] else "", "p" if m["by_planes"] else "")
                print(row + "%6d vertices, Euler characteristic %4d, %d shells, level %-3s %.1f s" % (
                    m["vertices"], m["euler_characteristic"], m["shells"], level, time.time() - start), flush=True)


if __name__ == "__main__":
    main()
