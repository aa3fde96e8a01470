#!/usr/bin/python3
"""Meshes of the Minkowski sum (issue 15): `pmsum validate --mesh` on the validation suite.

    benchmark/mesh/run_mesh.py [--build BUILD_DIR] [--only NAME ...] [--skip-slow]

For each closed pair of the validation suite (benchmark/validation/run_suite.py, one definition)
it runs `pmsum validate P Q -d D --relative --mesh` with the default settings and writes into
benchmark/mesh/results/:
  results.md   per pair: mesh vertices and triangles, the checks (closed, manifold, free of
               self-intersections, bounding a volume), shells against the exact boundary's,
               the Hausdorff distance both ways to the exact Nef boundary / d, the seconds of
               the whole mesh (sum + reconstruction + checks), of Nef and of Manifold's
               minkowskiSum, and their ratios
  NAME.json    pmsum's report;  NAME.png  a picture of the mesh beside Nef's boundary
The exact boundaries are cached in benchmark/mesh/results/cache/ (not committed) so that a
rerun does not recompute Nef; the Nef seconds are those of the run that computed it.
Manifold's minkowskiSum: npm manifold-3d (benchmark/speed/manifold.py, installed on first use).
Needs Debian's python3-matplotlib.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RESULTS = os.path.join(HERE, "results")
PICTURES = "Pictures: `NAME.png` (the mesh beside Nef's boundary)."  # (the notes follow it in results.md)
sys.path.insert(0, os.path.join(ROOT, "benchmark", "validation"))
sys.path.insert(0, os.path.join(ROOT, "benchmark", "speed"))
from run_suite import OPEN, SUITE, shape_path  # noqa: E402
import manifold as manifold_minkowski  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_off(path):
    """Points and faces of an OFF file: OFF, COFF, NOFF... (values after a vertex's three
    coordinates or a face's corners, such as colours, are skipped; # starts a comment)."""
    lines = [l.split("#")[0].split() for l in open(path)]
    rows = iter([l for l in lines if l])
    head = next(rows)
    if not head[0].endswith("OFF"):
        raise ValueError("%s: not an OFF file" % path)
    counts = head[1:] or next(rows)
    nv, nf = int(counts[0]), int(counts[1])
    pts = [tuple(map(float, next(rows)[:3])) for _ in range(nv)]
    tris = []
    for _ in range(nf):
        row = next(rows)
        tris.append(tuple(int(x) for x in row[1:1 + int(row[0])]))
    return pts, tris


def picture(mesh_off, exact_off, png, title):
    fig = plt.figure(figsize=(8, 4), dpi=100)
    for i, (path, label) in enumerate(((mesh_off, "pmsum mesh"), (exact_off, "Nef (exact)"))):
        ax = fig.add_subplot(1, 2, i + 1, projection="3d")
        pts, tris = read_off(path)
        step = max(1, len(tris) // 60000)
        polys = [[pts[v] for v in t] for t in tris[::step]]
        ax.add_collection3d(Poly3DCollection(polys, facecolor="#8fb0d8", edgecolor="#30405080", linewidths=0.05))
        for c, setter in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
            setter(min(p[c] for p in pts), max(p[c] for p in pts))
        ax.set_box_aspect(tuple(max(1e-9, max(p[c] for p in pts) - min(p[c] for p in pts)) for c in range(3)))
        ax.view_init(elev=25, azim=35)
        ax.set_axis_off()
        ax.set_title(f"{label}: {len(tris):,} triangles", fontsize=9)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)


MANIFOLD_TIMEOUT = 300


def manifold_seconds(p, q, extra):
    """Seconds of Manifold's minkowskiSum on the pair; -1 if it ran past MANIFOLD_TIMEOUT;
    None where it failed."""
    scale = extra[extra.index("--scale-q") + 1] if "--scale-q" in extra else "1"
    m = manifold_minkowski.minkowski_sum(p, q, scale, "--negate-p" in extra, MANIFOLD_TIMEOUT)
    if m and m.get("status") == "timeout":
        return -1
    return m["seconds"] if m and m.get("status") == "NoError" else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--only", nargs="*", help="run only these pairs (the others keep their saved rows)")
    ap.add_argument("--skip-slow", action="store_true", help="skip the pairs whose Nef sum takes minutes")
    ap.add_argument("--manifold-only", action="store_true",
                    help="only measure Manifold's minkowskiSum for the saved rows (their pmsum and Nef figures kept)")
    ap.add_argument("--pictures", nargs="*", default=["easy-void", "knot1+tetrahedron", "cross+star", "hooks"])
    args = ap.parse_args()
    pmsum = os.path.join(args.build, "pmsum")
    cache = os.path.join(RESULTS, "cache")
    os.makedirs(cache, exist_ok=True)
    work = tempfile.mkdtemp()
    rows = []
    for name, ps, qs, d, extra, slow in SUITE:
        if ps in OPEN or qs in OPEN:
            continue  # no Nef sum of an open mesh
        js = os.path.join(RESULTS, name + ".json")
        if (args.only and name not in args.only) or (args.skip_slow and slow):
            if os.path.exists(js):
                rows.append((name, json.load(open(js))))
            continue
        p, q = shape_path(ps, pmsum, work), shape_path(qs, pmsum, work)
        if args.manifold_only and p is not None and q is not None and os.path.exists(js):
            print("Manifold:", name, flush=True)
            report = json.load(open(js))
            report["seconds"]["manifold"] = manifold_seconds(p, q, extra)
            json.dump(report, open(js, "w"), indent=1)
            rows.append((name, report))
            continue
        if p is None or q is None:
            rows.append((name, "skipped (CGAL demo data not installed: apt-get install libcgal-demo)"))
            continue
        nef3 = os.path.join(cache, name + ".nef3")
        nef_seconds = os.path.join(cache, name + ".seconds")
        mesh_off, exact_off = os.path.join(work, name + ".off"), os.path.join(work, name + "-exact.off")
        cmd = [pmsum, "validate", p, q, "-d", str(d), "--relative", "--quiet", "--mesh", "--save-mesh", mesh_off,
               "--save-exact-off", exact_off, "--json", js, *extra]
        cmd += ["--exact", nef3] if os.path.exists(nef3) and os.path.exists(nef_seconds) else ["--save-exact", nef3]
        print("mesh:", name, flush=True)
        t = time.time()
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode not in (0, 4):
            rows.append((name, f"error (exit {r.returncode}): {r.stderr.strip()}"))
            continue
        report = json.load(open(js))
        if report["nef_from_file"]:
            report["seconds"]["nef"] = float(open(nef_seconds).read())
        else:
            open(nef_seconds, "w").write(repr(report["seconds"]["nef"]))
        report["wall_seconds"] = time.time() - t
        report["seconds"]["manifold"] = manifold_seconds(p, q, extra)
        json.dump(report, open(js, "w"), indent=1)
        rows.append((name, report))
        if name in args.pictures and report["mesh"]["made"]:
            picture(mesh_off, exact_off, os.path.join(RESULTS, name + ".png"), name)

    # The notes written after the table (what each run measured) are kept.
    results_md = os.path.join(RESULTS, "results.md")
    notes = ""
    if os.path.exists(results_md):
        text = open(results_md).read()
        if PICTURES in text:
            notes = text.split(PICTURES, 1)[1]
    with open(results_md, "w") as out:
        out.write("# Meshes of the sum: `pmsum validate --mesh` on the validation suite\n\n"
                  "Default settings, 2 threads, this machine (2 cores). d is a fraction of the diagonal of the sum's "
                  "bounding box; d used: after refinements (the mesh halves d when a check fails, twice at most). "
                  "Checks: closed, manifold, free of self-intersections (CGAL's `does_self_intersect`), bounding "
                  "a volume. Shells: the mesh's (voids) / the exact boundary's. Distances: Hausdorff, both ways, "
                  "between the mesh and the exact Nef boundary, measured at lattice samples of spacing d/8 on both, "
                  "divided by d; in parentheses the bounds `pmsum mesh` proves and checks before it returns the mesh "
                  "(`mesh_to_boundary_bound`: every point of the mesh is closer than this to an output point; "
                  "`boundary_to_mesh_bound`: every point of the exact boundary is closer than this to the mesh). Mesh s: the whole mesh (sum, reconstruction, checks), as `pmsum mesh` runs it. "
                  "Nef s: `CGAL::minkowski_sum_3`, one thread. Manifold s: Manifold "
                  f"{manifold_minkowski.VERSION}'s `minkowskiSum` (npm manifold-3d, WebAssembly in node, one "
                  f"thread, float32 input), the sum alone (no reading, no checks); > {MANIFOLD_TIMEOUT}: stopped then; – where "
                  "it failed.\n\n")
        out.write("| pair | d | d used | vertices | triangles | checks | shells (voids) mesh / exact | "
                  "mesh→exact / d (proved <) | exact→mesh / d (proved <) | sum s | reconstruction s | mesh s | Nef s | Nef / mesh | "
                  "Manifold s | Manifold / mesh | ok |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for name, rep in rows:
            if isinstance(rep, str):
                out.write(f"| {name} | | | | | {rep} | | | | | | | | | | | |\n")
                continue
            m, s = rep["mesh"], rep["seconds"]
            nef = s["nef"]
            man = s.get("manifold")
            if man == -1:
                man_cols = f"> {MANIFOLD_TIMEOUT} | > {MANIFOLD_TIMEOUT / s['mesh']:.3g}"
            else:
                man_cols = f"{man:.2f} | {man / s['mesh'] if s['mesh'] > 0 else 0:.3g}" if man else "– | –"
            if not m["made"]:
                out.write(f"| {name} | {rep['d_argument']} | | | | no valid mesh: {m['error']} | – / "
                          f"{rep['shells']} ({rep['void_shells']}) | | | {s['mesh_sum']:.2f} | "
                          f"{s['mesh_reconstruction']:.2f} | {s['mesh']:.2f} | {nef:.2f} | | {man_cols} | no |\n")
                continue
            def bound(key):  # (rows saved before the bound was reported have none)
                return f"(< {m[key] / rep['d']:.2f})" if key in m else "(–)"
            checks = "valid" if m["closed"] and m["manifold"] and m["self_intersection_free"] and m["bounds_a_volume"] \
                else "INVALID"
            out.write(f"| {name} | {rep['d_argument']} | {m['covering_distance'] / rep['sum_bbox_diagonal']:.3g} | "
                      f"{m['vertices']} | {m['triangles']} | {checks} | {m['shells']} ({m['void_shells']}) / "
                      f"{rep['shells']} ({rep['void_shells']}) | {m['mesh_to_exact_over_d']:.2f} "
                      f"{bound('mesh_to_boundary_bound')} | {m['exact_to_mesh_over_d']:.2f} "
                      f"{bound('boundary_to_mesh_bound')} | {s['mesh_sum']:.2f} | {s['mesh_reconstruction']:.2f} | "
                      f"{s['mesh']:.2f} | {nef:.2f} | {nef / s['mesh'] if s['mesh'] > 0 else 0:.3g} | "
                      f"{man_cols} | {'yes' if m['ok'] else 'no'} |\n")
        out.write("\n" + PICTURES + (notes if notes else "\n"))
    print("wrote", results_md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
