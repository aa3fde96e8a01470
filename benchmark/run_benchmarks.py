#!/usr/bin/python3
"""Speed benchmarks of CGAL_pmsum, side by side in one run (issue 4).

    benchmark/run_benchmarks.py [--build BUILD_DIR] [--only filters multiresolution threads peers pd]

Writes benchmark/results/NAME.md (a table) and NAME.png (matplotlib) for
  filters          time and CD queries: CD only, CD + normal (CD + normal + octree: not built yet)
  multiresolution  d = 5%, 1%, 0.5%, 0.1% of the diagonal: points and seconds
  threads          1 and 2 threads (and more where the machine has them): seconds and speedup
  peers            CGAL Nef minkowski_sum_3 (where it finishes in 10 minutes) and Manifold's
                   minkowskiSum (npm manifold-3d, installed here with npm), as ratios
  pd               penetration-depth queries per second (benchmark/pd_queries.cpp), and against
                   FCL on convex pairs (benchmark/pd_vs_fcl.cpp; needs Debian's libfcl-dev)
Needs Debian's python3-matplotlib; the peers need node and npm.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
RESULTS = os.path.join(HERE, "results")
DATA = os.path.join(ROOT, "data")
NODE = os.path.join(HERE, "speed", "node")
MANIFOLD_VERSION = "3.5.4"

# name, P, Q (preset or data:FILE), extra args (scale of Q)
PAIRS = {
    "knot1+tetrahedron": ("data:knot1.off", "data:tetrahedron.off", ["--scale-q", "0.03125"]),
    "elephant+octahedron": ("data:elephant.off", "data:octahedron.off", ["--scale-q", "0.0078125"]),
    "cross+star": ("data:cross.off", "data:star.off", []),
    "l-shape+tetrahedron": ("l-shape", "tetrahedron", []),
    "hooks": ("hook-a", "hook-b", []),
    "blocks+cube": ("blocks", "cube", []),
    "difficult-void": ("plates", "cube-small", []),
    "frame+knot": ("frame", "knot", []),
    "open-cube+ellipsoid": ("open-cube", "ellipsoid", []),
}


class Runner:
    def __init__(self, build):
        self.pmsum = os.path.join(build, "pmsum")
        self.work = tempfile.mkdtemp()

    def path(self, spec):
        if spec.startswith("data:"):
            return os.path.join(DATA, spec[5:])
        p = os.path.join(self.work, spec + ".off")
        if not os.path.exists(p):
            subprocess.run([self.pmsum, "generate", spec, "-o", p], check=True)
        return p

    def sum(self, pair, d, extra=(), threads=1, timeout=1800):
        ps, qs, args = PAIRS[pair]
        js = os.path.join(self.work, "run.json")
        cmd = [self.pmsum, "sum", self.path(ps), self.path(qs), "-d", str(d), "--relative", "--quiet",
               "--threads", str(threads), "-o", os.path.join(self.work, "out.ply"), "--json", js, *args, *extra]
        try:
            subprocess.run(cmd, check=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None
        return json.load(open(js))


def write(name, header, rows, note=""):
    with open(os.path.join(RESULTS, name + ".md"), "w") as f:
        f.write(f"# {name}\n\n{note}\n\n| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for r in rows:
            f.write("| " + " | ".join(str(x) for x in r) + " |\n")
    print(f"wrote {name}.md")


def fmt(x, digits=3):
    return "–" if x is None else f"{x:.{digits}g}"


def bench_filters(run):
    d = 0.05  # "CD only" tests every sample pair: m * n queries
    rows, labels, t_cd, t_n, q_cd, q_n = [], [], [], [], [], []
    for pair in ["l-shape+tetrahedron", "cross+star", "hooks", "blocks+cube", "difficult-void", "frame+knot",
                 "knot1+tetrahedron", "elephant+octahedron"]:
        print("filters:", pair, flush=True)
        n = run.sum(pair, d)
        c = run.sum(pair, d, ["--no-normal-filter"], timeout=600)
        rows.append([pair, n["p"]["samples"], n["q"]["samples"], n["output_points"],
                     fmt(c and c["seconds"]["total"]), c and c["cd_queries"] or "timeout",
                     fmt(n["seconds"]["total"]), n["cd_queries"], "not built",
                     fmt(c and c["seconds"]["total"] / n["seconds"]["total"])])
        labels.append(pair)
        t_cd.append(c and c["seconds"]["total"] or float("nan"))
        t_n.append(n["seconds"]["total"])
        q_cd.append(c and c["cd_queries"] or float("nan"))
        q_n.append(n["cd_queries"])
    write("filters", ["pair", "samples P", "samples Q", "points", "CD only s", "CD only queries", "CD+normal s",
                      "CD+normal queries", "CD+normal+octree", "speedup of the normal filter"], rows,
          f"Paper Fig. 5. d = {d} of the diagonal, one thread. The octree filter (issue 4) is not built yet.")
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    x = range(len(labels))
    for a, (y1, y2, title) in zip(ax, [(t_cd, t_n, "seconds"), (q_cd, q_n, "CD queries")]):
        a.bar([i - 0.2 for i in x], y1, 0.4, label="CD")
        a.bar([i + 0.2 for i in x], y2, 0.4, label="CD + normal")
        a.set_yscale("log")
        a.set_title(title)
        a.set_xticks(list(x))
        a.set_xticklabels(labels, rotation=40, ha="right", fontsize=8)
        a.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "filters.png"))


def bench_multiresolution(run):
    rows, series = [], {}
    for pair in ["knot1+tetrahedron", "elephant+octahedron"]:
        for d in [0.05, 0.01, 0.005, 0.001]:
            print("multiresolution:", pair, d, flush=True)
            r = run.sum(pair, d, threads=os.cpu_count() or 1)
            if r is None:
                rows.append([pair, d, "timeout", "", "", ""])
                continue
            rows.append([pair, d, r["output_points"], r["candidates"], r["cd_queries"], fmt(r["seconds"]["total"])])
            series.setdefault(pair, []).append((d, r["seconds"]["total"], r["output_points"]))
    write("multiresolution", ["pair", "d / diagonal", "points", "candidates", "CD queries", "seconds"], rows,
          f"Paper Fig. 8, {os.cpu_count()} threads. A coarse-to-fine mode that reuses the coarser work is not "
          "built yet (issue 4).")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for pair, pts in series.items():
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=pair)
    ax.set_xlabel("d / diagonal")
    ax.set_ylabel("seconds")
    ax.invert_xaxis()
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "multiresolution.png"))


def bench_threads(run):
    counts = sorted({1, 2, os.cpu_count() or 1})
    rows, series = [], {}
    for pair, d in [("knot1+tetrahedron", 0.005), ("elephant+octahedron", 0.005), ("hooks", 0.03)]:
        base = None
        for t in counts:
            print("threads:", pair, t, flush=True)
            r = run.sum(pair, d, threads=t)
            s = r["seconds"]["cd_filter"]
            base = base or s
            rows.append([pair, d, t, r["output_points"], fmt(r["seconds"]["total"]), fmt(s), fmt(base / s)])
            series.setdefault(pair, []).append((t, base / s))
    write("threads", ["pair", "d", "threads", "points", "total s", "CD stage s", "speedup (CD stage)"], rows,
          "Paper Fig. 9. The output file is identical for every thread count.")
    fig, ax = plt.subplots(figsize=(5, 4))
    for pair, pts in series.items():
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=pair)
    ax.plot(counts, counts, "k:", label="linear")
    ax.set_xlabel("threads")
    ax.set_ylabel("speedup")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "threads.png"))


def manifold_seconds(run, pair):
    if not os.path.exists(os.path.join(NODE, "node_modules", "manifold-3d")):
        os.makedirs(NODE, exist_ok=True)
        subprocess.run(["npm", "install", "--prefix", NODE, "--no-audit", "--no-fund", f"manifold-3d@{MANIFOLD_VERSION}"],
                       check=True, capture_output=True)
    script = os.path.join(NODE, "manifold_minkowski.mjs")
    with open(os.path.join(HERE, "speed", "manifold_minkowski.mjs")) as src, open(script, "w") as dst:
        dst.write(src.read())
    ps, qs, args = PAIRS[pair]
    scale = args[1] if args else "1"
    try:
        out = subprocess.run(["node", script, run.path(ps), run.path(qs), scale], capture_output=True, text=True,
                             timeout=600, check=True)
        return json.loads(out.stdout)["seconds"]
    except (subprocess.SubprocessError, ValueError):
        return None


def bench_peers(run):
    # Nef times: from the validation suite's reports when present (single thread, same inputs)
    nef = {}
    vdir = os.path.join(HERE, "validation", "results")
    for pair in PAIRS:
        f = os.path.join(vdir, pair + ".json")
        if os.path.exists(f):
            r = json.load(open(f))
            if "seconds" in r and "nef" in r["seconds"]:
                nef[pair] = r["seconds"]["nef"]
    rows = []
    for pair in PAIRS:
        print("peers:", pair, flush=True)
        ours = run.sum(pair, 0.01, threads=os.cpu_count() or 1)
        t = ours["seconds"]["total"]
        m = manifold_seconds(run, pair) if pair != "open-cube+ellipsoid" else None
        n = nef.get(pair)
        rows.append([pair, ours["output_points"], fmt(t), fmt(n), fmt(n and n / t), fmt(m), fmt(m and m / t),
                     ours["cd_queries"], fmt(ours["cd_queries"] / max(1, ours["output_points"]))])
    write("peers", ["pair", "points (d = 1%)", "ours s", "Nef s", "Nef / ours", "Manifold s", "Manifold / ours",
                    "CD queries", "CD queries / points"], rows,
          f"Ours with {os.cpu_count()} threads at d = 1% of the diagonal; Nef (CGAL minkowski_sum_3, exact, one thread) "
          f"from benchmark/validation/results; Manifold {MANIFOLD_VERSION} (npm manifold-3d, node, float32 mesh sum). "
          "Goals of issue 4: Nef / ours >= 1000, Manifold / ours >= 50, CD queries / points <= 2.")


def bench_pd(run):
    """Penetration-depth queries on a contact space of about a million points (issue 5)."""
    exe = os.path.join(os.path.dirname(run.pmsum), "pd_queries")
    load = os.getloadavg()[0]
    out = subprocess.run([exe, "--benchmark_format=json", "--benchmark_min_time=0.5", "--benchmark_repetitions=3",
                          "--benchmark_report_aggregates_only=true"], capture_output=True, text=True, check=True)
    rep = json.loads(out.stdout)
    rows, names, wall, cpu = [], [], [], []
    for b in rep["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"]
        rows.append([name, f"{b.get('contact_points', 0):,.0f}", f"{b['real_time'] / 1000:.2f}",
                     f"{b['cpu_time'] / 1000:.2f}", f"{1e9 / b['real_time']:,.0f}", fmt(b.get("build_seconds"))])
        names.append(name.replace("BM_", ""))
        wall.append(b["real_time"] / 1000)
        cpu.append(b["cpu_time"] / 1000)
    write("pd", ["benchmark", "contact points", "µs per query", "CPU µs per query", "queries per second", "build s"],
          rows,
          "knot1 (moving) against the octahedron x 1/16, contact space at d = 0.27% of the diagonal, built with "
          f"{os.cpu_count()} threads. Queries: a random contact point moved by up to 5% of the diagonal along each "
          "axis (up to about 18 d from the contact space), or by up to d/2 (shallow). nearest_contact: the exact "
          "nearest contact point (internal/nearest_point_tree.h); query: exact overlap test (the core's CD filter) "
          "and, when overlapping, the nearest contact point. Medians of 3 runs; wall time (µs per query) and CPU "
          f"time; load average when run: {load:.1f} on {os.cpu_count()} cores. Paper: 0.1 ms per query; goal: "
          "<= 2 µs. The FCL comparison on convex pairs is in pd_vs_fcl.md.")
    fig, ax = plt.subplots(figsize=(7, 3))
    y = range(len(names))
    ax.barh([i + 0.2 for i in y], wall, 0.4, label="wall")
    ax.barh([i - 0.2 for i in y], cpu, 0.4, label="CPU")
    ax.axvline(2, color="k", linestyle=":", label="goal 2 µs")
    ax.set_yticks(list(y))
    ax.set_yticklabels(names, fontsize=8)
    ax.set_xlabel("µs per query")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "pd.png"))
    fcl = os.path.join(os.path.dirname(run.pmsum), "pd_vs_fcl")
    if os.path.exists(fcl):
        subprocess.run([fcl, os.path.join(RESULTS, "pd_vs_fcl.md")], check=True, capture_output=True)
        print("wrote pd_vs_fcl.md")
    else:
        print("pd_vs_fcl not built (apt-get install libfcl-dev, then rebuild)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--only", nargs="*", default=["filters", "multiresolution", "threads", "peers", "pd"])
    args = ap.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    run = Runner(args.build)
    for b in args.only:
        globals()["bench_" + b](run)
    return 0


if __name__ == "__main__":
    sys.exit(main())
