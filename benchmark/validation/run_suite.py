#!/usr/bin/python3
"""Validation suite: CGAL_pmsum against CGAL's exact Nef Minkowski sum (issue 3).

    benchmark/validation/run_suite.py [--build BUILD_DIR] [--quick] [--only NAME ...]
(--only reruns some pairs; the table keeps the other pairs' rows from their saved reports)

For each pair it runs `pmsum validate` (exactness of every point by Nef point location,
coverage of every shell of the exact boundary), or `pmsum sum` where Nef cannot be used (open
meshes), and writes into benchmark/validation/results/:
  results.md    the table (pair, facets, d, points, exactness failures, worst coverage per
                shell / d, shells covered, our seconds, Nef seconds, ratio)
  NAME.png      the points, coloured by the exact shell they lie on
  NAME.json     pmsum's report
--quick skips the pairs whose Nef sum takes minutes. Needs Debian's python3-matplotlib.
The procedural models come from `pmsum generate`; CGAL demo models from data/ or, for those
not bundled, from libcgal-demo's /usr/share/doc/libcgal-dev/data.tar.gz.
"""
import argparse
import json
import os
import subprocess
import sys
import tarfile
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RESULTS = os.path.join(HERE, "results")
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"

# name, P, Q, d (fraction of the sum's diagonal), extra pmsum arguments, slow (Nef takes minutes)
# P/Q: a `pmsum generate` preset, "data:FILE" (bundled), or "cgal:FILE" (libcgal-demo).
SUITE = [
    ("hooks", "hook-a", "hook-b", 0.03, [], False),
    ("hooks-contact", "hook-a", "hook-b", 0.03, ["--negate-p"], False),
    ("grates", "grate-a", "grate-b", 0.05, [], False),
    ("blocks+cube", "blocks", "cube", 0.02, [], False),
    ("blocks+0.95cube", "blocks", "cube-0.95", 0.01, [], False),
    ("easy-void", "hollow-box", "cube-large", 0.05, [], False),
    ("difficult-void", "plates", "cube-small", 0.02, [], False),
    ("l-shape+tetrahedron", "l-shape", "tetrahedron", 0.02, [], False),
    ("l-shape-contact", "l-shape", "cube-small", 0.02, ["--negate-p"], False),
    ("open-cube+ellipsoid", "open-cube", "ellipsoid", 0.01, [], False),  # no Nef: open
    ("frame+knot", "frame", "knot", 0.02, [], True),
    ("cross+star", "data:cross.off", "data:star.off", 0.01, [], False),
    ("joint+tetrahedron", "cgal:joint.off", "data:tetrahedron.off", 0.01, ["--scale-q", "0.0625"], False),
    ("part+icosahedron", "cgal:part.off", "data:icosahedron.off", 0.01, ["--scale-q", "0.03125"], False),
    ("anchor+octahedron", "cgal:anchor.off", "data:octahedron.off", 0.01, ["--scale-q", "0.03125"], True),
    ("eight+icosahedron", "cgal:eight.off", "data:icosahedron.off", 0.01, ["--scale-q", "0.0625"], True),
    ("knot1+tetrahedron", "data:knot1.off", "data:tetrahedron.off", 0.01, ["--scale-q", "0.03125"], True),
    ("elephant+octahedron", "data:elephant.off", "data:octahedron.off", 0.01, ["--scale-q", "0.0078125"], True),
    # narrow passages 1/2000 wide (issue 12): about d/700 (tunnel) and d/300 (slot, slit, sliver)
    ("narrow-tunnel", "tunnel", "tunnel-cube", 0.04, [], False),
    ("narrow-tunnel-rotated", "tunnel-rotated", "tunnel-cube-rotated", 0.04, [], False),
    ("narrow-slot", "slot", "slot-cube", 0.04, [], False),
    ("narrow-slit", "slit", "slot-cube", 0.04, [], False),
    ("narrow-sliver", "slot", "slot-cube-tilted", 0.04, [], False),
]
OPEN = {"open-cube"}


def shape_path(spec, pmsum, work):
    if spec.startswith("data:"):
        return os.path.join(ROOT, "data", spec[5:])
    if spec.startswith("cgal:"):
        name = spec[5:]
        path = os.path.join(work, name)
        if not os.path.exists(path):
            if not os.path.exists(CGAL_DATA):
                return None
            with tarfile.open(CGAL_DATA) as tar:
                member = tar.getmember("data/meshes/" + name)
                with open(path, "wb") as f:
                    f.write(tar.extractfile(member).read())
        return path
    path = os.path.join(work, spec + ".off")
    if not os.path.exists(path):
        subprocess.run([pmsum, "generate", spec, "-o", path], check=True)
    return path


def faces(path):
    with open(path) as f:
        tokens = f.read().split()
    return int(tokens[2]) if tokens[0] == "OFF" else 0


def picture(xyz, png, title):
    pts = [list(map(float, line.split())) for line in open(xyz)]
    step = max(1, len(pts) // 80000)
    pts = pts[::step]
    fig = plt.figure(figsize=(5, 5), dpi=100)
    ax = fig.add_subplot(projection="3d")
    colours = [p[6] if len(p) > 6 else 0 for p in pts]
    ax.scatter([p[0] for p in pts], [p[1] for p in pts], [p[2] for p in pts], c=colours, cmap="tab10",
               vmin=0, vmax=9, s=0.2, linewidths=0)
    ax.set_title(title, fontsize=9)
    ax.set_box_aspect(tuple(max(1e-9, max(p[c] for p in pts) - min(p[c] for p in pts)) for c in range(3)))
    ax.view_init(elev=25, azim=35)
    ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true", help="skip pairs whose Nef sum takes minutes")
    ap.add_argument("--only", nargs="*", help="run only these pairs")
    args = ap.parse_args()
    pmsum = os.path.join(args.build, "pmsum")
    os.makedirs(RESULTS, exist_ok=True)
    work = tempfile.mkdtemp()
    rows = []
    for name, ps, qs, d, extra, slow in SUITE:
        if args.only and name not in args.only:
            # keep the row of an earlier run, if its report is there
            old = os.path.join(RESULTS, name + ".json")
            if os.path.exists(old):
                rep = json.load(open(old))
                if "faces" in rep:
                    rows.append((name, rep))
            continue
        if args.quick and slow:
            rows.append((name, "skipped (--quick: Nef takes minutes)"))
            continue
        p, q = shape_path(ps, pmsum, work), shape_path(qs, pmsum, work)
        if p is None or q is None:
            rows.append((name, "skipped (CGAL demo data not installed: apt-get install libcgal-demo)"))
            continue
        js = os.path.join(RESULTS, name + ".json")
        xyz = os.path.join(work, name + ".xyz")
        is_open = ps in OPEN or qs in OPEN
        # one thread: Nef is sequential, the comparison is per core
        cmd = [pmsum, "sum" if is_open else "validate", p, q, "-d", str(d), "--relative", "--quiet", "--threads", "1",
               "--json", js, *extra]
        cmd += ["-o", xyz] if is_open else ["--shell-points", xyz]
        print("suite:", name, flush=True)
        t = time.time()
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode not in (0, 4):
            rows.append((name, f"error (exit {r.returncode}): {r.stderr.strip()}"))
            continue
        report = json.load(open(js))
        report["wall_seconds"] = time.time() - t
        report["faces"] = (faces(p), faces(q))
        json.dump(report, open(js, "w"), indent=1)  # with the facet counts, for later --only runs
        rows.append((name, report))
        picture(xyz, os.path.join(RESULTS, name + ".png"), f"{name}: {report['output_points']:,} points")

    with open(os.path.join(RESULTS, "results.md"), "w") as out:
        out.write("# Validation suite: CGAL_pmsum against CGAL's exact Nef Minkowski sum\n\n")
        out.write("d is a fraction of the diagonal of the sum's bounding box. Exactness failures: output points "
                  "not on the exact boundary (Nef point location of each point's exact value). Coverage: per "
                  "shell of the exact boundary (o = outer, v = void), the largest distance from a point of the "
                  "shell (sampled at d/8) to the nearest output point, divided by d; < 1 means covered. "
                  "Seconds on this machine (2 cores, one thread).\n\n")
        out.write("| pair | facets P+Q | d | points | exactness failures | worst coverage per shell / d | "
                  "shells covered | ours s | Nef s | Nef/ours |\n|---|---|---|---|---|---|---|---|---|---|\n")
        for name, rep in rows:
            if isinstance(rep, str):
                out.write(f"| {name} | | | | | {rep} | | | | |\n")
                continue
            fp, fq = rep["faces"]
            if rep["command"] == "sum":
                out.write(f"| {name} | {fp}+{fq} | {rep['d_argument']} | {rep['output_points']} | no Nef (open mesh) | "
                          f"| | {rep['seconds']['total']:.2f} | | |\n")
                continue
            shells = ", ".join(f"{'v' if s['void'] else 'o'} {s['worst_over_d']:.2f}" for s in rep["shell_coverage"])
            ours, nef = rep["seconds"]["ours"], rep["seconds"]["nef"]
            out.write(f"| {name} | {fp}+{fq} | {rep['d_argument']} | {rep['output_points']} | "
                      f"{rep['exactness_failures']} | {shells} | {rep['shells_covered']}/{rep['shells']} | "
                      f"{ours:.2f} | {nef:.2f} | {nef / ours if ours > 0 else 0:.3g} |\n")
        out.write("\nPictures: `NAME.png` (points coloured by the exact shell they are nearest to).\n")
    print("wrote", os.path.join(RESULTS, "results.md"))
    failed = [n for n, r in rows if not isinstance(r, str) and r["command"] == "validate" and not r["ok"]]
    if failed:
        print("validation FAILED for:", ", ".join(failed))
        return 4
    return 0


if __name__ == "__main__":
    sys.exit(main())
