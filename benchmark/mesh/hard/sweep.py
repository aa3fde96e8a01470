#!/usr/bin/python3
"""A sweep of `pmsum mesh` over variants of the validation suite's pairs that the mesh table
never runs: d scaled, and P turned by a seeded random rotation (in doubles, 17 digits). One row
per run: the mesh's size, Euler characteristic, shells and the level it came from (`c`: crease
points kept, `p`: plane by plane), or the exit code and the last line of the error. With
--validate, each turned run is also checked against Nef (`pmsum validate --mesh`).

    /usr/bin/python3 benchmark/mesh/hard/sweep.py --pmsum build/pmsum --work /tmp/sweep [--slow] [--seeds S ...]

--seeds S ...: instead of the variants below, P turned by each seed's rotation, at the row's d.

Shapes made of boxes that touch along faces are refused once turned ("components overlap":
the rounding makes them cross), as a user's turned assembly would be.
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from run_mesh import read_off  # noqa: E402  (it puts benchmark/validation on the path)
from run_suite import OPEN, SUITE, shape_path  # noqa: E402

# name, factor on d, rotation seed (None: P as it is)
VARIANTS = [("d x 1.5", 1.5, None), ("d x 0.7", 0.7, None), ("P turned (7)", 1.0, 7), ("P turned (11), d x 1.3", 1.3, 11)]


def turned(path, seed, work):
    """P turned by the rotation of `seed` (the Q of a QR of a normal random matrix, det +1)."""
    out = os.path.join(work, "turned%d-%s" % (seed, os.path.basename(path)))
    if os.path.exists(out):
        return out
    points, faces = read_off(path)
    q, _ = np.linalg.qr(np.random.default_rng(seed).normal(size=(3, 3)))
    if np.linalg.det(q) < 0:
        q[:, 0] *= -1
    with open(out, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        for p in np.array(points) @ q.T:
            o.write("%.17g %.17g %.17g\n" % tuple(p))
        for f in faces:
            o.write("%d %s\n" % (len(f), " ".join(map(str, f))))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pmsum", required=True)
    ap.add_argument("--work", required=True, help="folder for the shapes and the meshes")
    ap.add_argument("--slow", action="store_true", help="the pairs whose Nef sum takes minutes (else the others)")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--validate", action="store_true", help="check the turned runs against Nef too")
    ap.add_argument("--only", nargs="*", help="these pairs (the suite's names) alone")
    ap.add_argument("--seeds", nargs="*", type=int, help="P turned by these seeds, at the row's d (not VARIANTS)")
    a = ap.parse_args()
    variants = [("P turned (%d)" % s, 1.0, s) for s in a.seeds] if a.seeds else VARIANTS
    os.makedirs(a.work, exist_ok=True)
    for name, P, Q, d, extra, slow in SUITE:
        if P in OPEN or (a.only and name not in a.only) or (not a.only and slow != a.slow):
            continue
        p, q = shape_path(P, a.pmsum, a.work), shape_path(Q, a.pmsum, a.work)
        for variant, factor, seed in variants:
            pv = turned(p, seed, a.work) if seed is not None else p
            common = [pv, q, "-d", str(d * factor), "--relative", "--threads", "1"] + extra
            out = os.path.join(a.work, "mesh")
            start = time.time()
            try:
                r = subprocess.run([a.pmsum, "mesh"] + common + ["-o", out + ".off", "--json", out + ".json"],
                                   capture_output=True, text=True, timeout=a.timeout)
            except subprocess.TimeoutExpired:
                print("%-22s %-24s past %.0f s" % (name, variant, a.timeout), flush=True)
                continue
            seconds = time.time() - start
            if r.returncode:
                last = r.stderr.strip().splitlines()[-1][:160] if r.stderr.strip() else ""
                print("%-22s %-24s exit %d after %.1f s: %s" % (name, variant, r.returncode, seconds, last), flush=True)
                continue
            m = json.load(open(out + ".json"))["mesh"]
            level = "%d%s%s" % (m["refinements"], "c" if m["crease_points"] else "", "p" if m["by_planes"] else "")
            row = "%-22s %-24s %6d vertices, Euler characteristic %3d, %d shells, level %-3s %.1f s" % (
                name, variant, m["vertices"], m["euler_characteristic"], m["shells"], level, seconds)
            if a.validate and seed is not None:
                v = subprocess.run([a.pmsum, "validate"] + common + ["--mesh"], capture_output=True, text=True)
                keep = [l.split(None, 2)[-1] for l in v.stdout.splitlines() if l.strip().startswith(("mesh topology", "mesh distance"))]
                row += " | Nef: " + ("; ".join(k[:70] for k in keep) if keep else "exit %d" % v.returncode)
            print(row, flush=True)


if __name__ == "__main__":
    main()
