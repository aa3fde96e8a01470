#!/usr/bin/python3
"""Speed benchmarks of CGAL_pmsum, side by side in one run (issue 4).

    benchmark/run_benchmarks.py [--build BUILD_DIR] [--only net filters octree multiresolution goals threads peers pd plan]

Writes benchmark/results/NAME.md (a table) and NAME.png (matplotlib) for
  net              the default output, a (d/2, d)-net, against every boundary candidate
                   (--all-candidates) on the validation suite at d = 1% and the goal pairs at
                   0.5%: points, points / ideal, spacing, CD queries, seconds, exactness and
                   coverage (pmsum validate), 1 vs 2 threads, Nef and Manifold as ratios
  filters          time and CD queries: CD only, CD + normal, CD + normal + octree
  octree           the octree filter at 1-2%: certified candidates, CD queries saved, same output
  multiresolution  d = 5%, 1%, 0.5%, 0.1% of the diagonal: points and seconds, each d alone and
                   coarse to fine (pmsum sum --levels)
  goals            knot1 + knot2 and armadillo + sphere at 0.5% (CGAL demo data)
  threads          1 and 2 threads (and more where the machine has them): seconds and speedup
  peers            CGAL Nef minkowski_sum_3 (where it finishes in 10 minutes) and Manifold's
                   minkowskiSum (npm manifold-3d, installed here with npm), as ratios
  pd               penetration-depth queries per second (benchmark/pd_queries.cpp), and against
                   FCL on convex pairs (benchmark/pd_vs_fcl.cpp; needs Debian's libfcl-dev)
  plan             translational motion planning against OMPL's RRTConnect and PRM, 20 seeds
                   (benchmark/plan_vs_ompl.cpp; installs Debian's libompl-dev if missing)
Needs Debian's python3-matplotlib; the peers need node and npm.
"""
import argparse
import hashlib
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
    # CGAL demo data (libcgal-demo's data.tar.gz), for the goals of issue 4
    "knot1+knot2": ("cgal:knot1.off", "cgal:knot2.off", []),
    "armadillo+sphere": ("cgal:armadillo.off", "cgal:sphere.off", ["--scale-q", "8"]),
}
sys.path.insert(0, os.path.join(HERE, "validation"))
sys.path.insert(0, os.path.join(HERE, "speed"))
from run_suite import SUITE  # noqa: E402  (the validation suite's pairs, one definition)
import manifold as manifold_minkowski  # noqa: E402  (Manifold's minkowskiSum, installed with npm)

MANIFOLD_VERSION = manifold_minkowski.VERSION

for _name, _p, _q, _d, _extra, _slow in SUITE:
    PAIRS.setdefault(_name, (_p, _q, _extra))
CGAL_DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
PEER_PAIRS = [p for p in ["knot1+tetrahedron", "elephant+octahedron", "cross+star", "l-shape+tetrahedron", "hooks",
                           "blocks+cube", "difficult-void", "frame+knot", "open-cube+ellipsoid"]]


class Runner:
    def __init__(self, build):
        self.pmsum = os.path.join(build, "pmsum")
        self.work = tempfile.mkdtemp()

    def path(self, spec):
        if spec.startswith("data:"):
            return os.path.join(DATA, spec[5:])
        if spec.startswith("cgal:"):
            p = os.path.join(self.work, spec[5:])
            if not os.path.exists(p):
                import tarfile
                with tarfile.open(CGAL_DATA) as t:
                    member = t.getmember("data/meshes/" + spec[5:])
                    with open(p, "wb") as f:
                        f.write(t.extractfile(member).read())
            return p
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
        r = json.load(open(js))
        with open(os.path.join(self.work, "out.ply"), "rb") as f:
            r["sha256"] = hashlib.sha256(f.read()).hexdigest()
        return r


    def validate(self, pair, d, extra=(), threads=2, timeout=3600):
        """pmsum validate (exactness and coverage against Nef); the exact sum is cached per pair."""
        ps, qs, args = PAIRS[pair]
        js = os.path.join(self.work, "validate.json")
        exact = os.path.join(self.work, pair + ".nef3")
        cache = ["--exact", exact] if os.path.exists(exact) else ["--save-exact", exact]
        cmd = [self.pmsum, "validate", self.path(ps), self.path(qs), "-d", str(d), "--relative", "--quiet",
               "--threads", str(threads), "--json", js, *cache, *args, *extra]
        try:
            subprocess.run(cmd, timeout=timeout, stdout=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return None
        return json.load(open(js)) if os.path.exists(js) else None


def write(name, header, rows, note=""):
    with open(os.path.join(RESULTS, name + ".md"), "w") as f:
        f.write(f"# {name}\n\n{note}\n\n| " + " | ".join(header) + " |\n|" + "---|" * len(header) + "\n")
        for r in rows:
            f.write("| " + " | ".join(str(x) for x in r) + " |\n")
    print(f"wrote {name}.md")


def fmt(x, digits=3):
    return "–" if x is None else f"{x:.{digits}g}"


def log_bars_per_pair(ax, labels):
    """Log scale, one tick per pair (slanted names), legend: the bar charts of filters and octree."""
    ax.set_yscale("log")
    ax.set_xticks(list(range(len(labels))))
    ax.set_xticklabels(labels, rotation=40, ha="right", fontsize=8)
    ax.legend(fontsize=8)


NO_NEF = {"open-cube+ellipsoid"}  # open mesh: Nef's sum is not defined for it
GOAL_PAIRS = [("knot1+knot2", 0.005), ("armadillo+sphere", 0.005)]  # Nef does not finish in 10 minutes
ALL_CANDIDATES_TIMEOUT = 90  # the paper's full output takes minutes on the box-built pairs at 1%


def bench_net(run):
    """Issue 10: the default (d/2, d)-net against every boundary candidate, side by side."""
    cases = [(name, 0.01) for name, *_ in SUITE] + GOAL_PAIRS
    rows, plot = [], []
    for pair, d in cases:
        print("net:", pair, flush=True)
        net = run.sum(pair, d, threads=2)
        one = run.sum(pair, d, threads=1)
        full = run.sum(pair, d, ["--all-candidates"], threads=2, timeout=ALL_CANDIDATES_TIMEOUT)
        v = None if pair in NO_NEF or (pair, d) in GOAL_PAIRS else run.validate(pair, d)
        m = None if pair in NO_NEF else manifold(run, pair, timeout=300)
        ours = net["seconds"]["total"]
        nef = v and v["seconds"]["nef"]
        ms = m and m.get("seconds")
        # ideal = area / (2.598 d^2): the exact area (Nef), else Manifold's mesh of the sum
        area_ideal = v and v["ideal_points"]
        if not area_ideal and m and m.get("surface_area"):
            area_ideal = m["surface_area"] / (2.598 * net["d"] ** 2)
        exact = "–" if not v else f"{v['exactness_failures']} / {v['shells_covered']} of {v['shells']}"
        full = full or {"output_points": None, "cd_queries": None, "seconds": {"total": None}}
        rows.append([pair, d, full["output_points"] or f"> {ALL_CANDIDATES_TIMEOUT} s", net["output_points"],
                     fmt(area_ideal and net["output_points"] / area_ideal),
                     fmt(v and v["minimum_spacing_over_d"]), fmt(v and v["worst_coverage_over_d"]), exact,
                     full["cd_queries"] or "–", net["cd_queries"], net["candidates_covered"],
                     fmt(full["seconds"]["total"]), fmt(ours), fmt(nef), fmt(nef and nef / ours), fmt(ms),
                     fmt(ms and ms / ours), "yes" if net["sha256"] == one["sha256"] else "NO"])
        plot.append((pair, full["output_points"] or float("nan"), net["output_points"], area_ideal))
    write("net", ["pair", "d", "points (all candidates)", "points (net)", "points / ideal", "min spacing / d",
                  "worst coverage / d", "exactness failures / shells covered", "CD queries (all)",
                  "CD queries (net)", "candidates covered (untested)", "all s", "net s", "Nef s", "Nef / net",
                  "Manifold s", "Manifold / net", "1 = 2 threads"], rows,
          "Issue 10. 2 threads, d a fraction of the diagonal of the sum's box. Points / ideal: ideal = area of the "
          "exact boundary (Nef; Manifold's mesh of the sum where Nef does not finish) / (2.598 d^2). Spacing, "
          "coverage and exactness from `pmsum validate` (Nef) on the default output. Nef: CGAL minkowski_sum_3, one "
          f"thread; Manifold {MANIFOLD_VERSION} (npm manifold-3d). Targets: points <= 8 x ideal, faster than Nef and "
          "Manifold on every pair, >= 100 x Nef where Nef takes >= 10 s, goal pairs <= 3 s.")
    fig, ax = plt.subplots(figsize=(10, 4.5))
    x = range(len(plot))
    ax.bar([i - 0.2 for i in x], [p[1] for p in plot], 0.4, label="all boundary candidates")
    ax.bar([i + 0.2 for i in x], [p[2] for p in plot], 0.4, label="default: (d/2, d)-net")
    ax.plot(list(x), [p[3] or float("nan") for p in plot], "k_", markersize=14, label="ideal d-covering")
    ax.set_ylabel("output points")
    log_bars_per_pair(ax, [p[0] for p in plot])
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "net.png"))


def bench_filters(run):
    d = 0.05  # "CD only" tests every sample pair: m * n queries
    rows, labels, series = [], [], {"CD": ([], []), "CD + normal": ([], []), "CD + normal + octree": ([], [])}
    for pair in ["l-shape+tetrahedron", "cross+star", "hooks", "blocks+cube", "difficult-void", "frame+knot",
                 "knot1+tetrahedron", "elephant+octahedron"]:
        print("filters:", pair, flush=True)
        o = run.sum(pair, d)
        n = run.sum(pair, d, ["--no-octree-filter"])
        c = run.sum(pair, d, ["--no-normal-filter", "--no-octree-filter"], timeout=600)
        rows.append([pair, o["p"]["samples"], o["q"]["samples"], o["output_points"],
                     fmt(c and c["seconds"]["total"]), c and c["cd_queries"] or "timeout",
                     fmt(n["seconds"]["total"]), n["cd_queries"], fmt(o["seconds"]["total"]), o["cd_queries"],
                     o["candidates_certified"], fmt(c and c["seconds"]["total"] / o["seconds"]["total"])])
        labels.append(pair)
        for name, r in [("CD", c), ("CD + normal", n), ("CD + normal + octree", o)]:
            series[name][0].append(r and r["seconds"]["total"] or float("nan"))
            series[name][1].append(r and r["cd_queries"] or float("nan"))
    write("filters", ["pair", "samples P", "samples Q", "points", "CD only s", "CD only queries", "CD+normal s",
                      "CD+normal queries", "CD+normal+octree s", "CD+normal+octree queries", "certified (skipped)",
                      "speedup of all filters"], rows,
          f"Paper Fig. 5. d = {d} of the diagonal, one thread. The output is the same with and without the "
          "octree filter; at this coarse d it has few cells to certify (see octree.md at 1%).")
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    x = range(len(labels))
    for k, (a, title) in enumerate(zip(ax, ["seconds", "CD queries"])):
        for j, (name, ys) in enumerate(series.items()):
            a.bar([i + (j - 1) * 0.27 for i in x], ys[k], 0.27, label=name)
        a.set_title(title)
        log_bars_per_pair(a, labels)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "filters.png"))


def bench_octree(run):
    """The octree filter at d = 1% and 2 threads: candidates certified interior, CD queries saved."""
    rows, labels, ratio = [], [], []
    for pair, d in [("hooks", 0.02), ("blocks+cube", 0.01), ("difficult-void", 0.01), ("frame+knot", 0.01),
                    ("cross+star", 0.01), ("knot1+tetrahedron", 0.01), ("elephant+octahedron", 0.01),
                    ("knot1+knot2", 0.02)]:
        print("octree:", pair, flush=True)
        o = run.sum(pair, d, threads=2)
        n = run.sum(pair, d, ["--no-octree-filter"], threads=2)
        same = o["sha256"] == n["sha256"]
        rows.append([pair, d, o["output_points"], o["candidates"], o["candidates_certified"],
                     f"{100 * o['candidates_certified'] / max(1, o['candidates']):.0f}%", n["cd_queries"],
                     o["cd_queries"], fmt(o["cd_queries"] / max(1, o["output_points"])), fmt(n["seconds"]["total"]),
                     fmt(o["seconds"]["total"]), fmt(o["seconds"]["octree_filter"]), "yes" if same else "NO"])
        labels.append(pair)
        ratio.append((n["cd_queries"] / max(1, o["output_points"]), o["cd_queries"] / max(1, o["output_points"])))
    write("octree", ["pair", "d", "points", "candidates", "certified", "certified %", "CD queries without",
                     "CD queries with", "CD queries / point", "s without", "s with", "octree s", "same output"], rows,
          "The octree filter (complete: cells certified interior are skipped, all others tested; holes need no "
          "seeds), 2 threads, d as a fraction of the diagonal.")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    x = range(len(labels))
    ax.bar([i - 0.2 for i in x], [r[0] for r in ratio], 0.4, label="without octree")
    ax.bar([i + 0.2 for i in x], [r[1] for r in ratio], 0.4, label="with octree")
    ax.axhline(2, color="k", ls=":", label="goal: 2 CD queries per point")
    ax.set_ylabel("CD queries per output point")
    log_bars_per_pair(ax, labels)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "octree.png"))


def bench_multiresolution(run):
    ds = [0.05, 0.01, 0.005, 0.001]
    threads = os.cpu_count() or 1
    rows, series = [], {}
    for pair in ["knot1+tetrahedron", "elephant+octahedron"]:
        single = []
        for d in ds:
            print("multiresolution:", pair, d, flush=True)
            single.append(run.sum(pair, d, threads=threads))
        print("multiresolution: coarse to fine", pair, flush=True)
        c2f = run.sum(pair, ds[-1], ["--levels", ",".join(str(d) for d in ds[:-1])], threads=threads)
        levels = c2f["levels"] if c2f else []
        total_single = total_c2f = 0
        for d, r, lv in zip(ds, single, levels + [None] * len(ds)):
            total_single += r["seconds"]["total"] if r else float("nan")
            total_c2f += lv["seconds"] if lv else float("nan")
            rows.append([pair, d, r and r["output_points"], r and r["cd_queries"], fmt(r and r["seconds"]["total"]),
                         fmt(total_single), lv and lv["output_points"], lv and lv["candidates_reused"],
                         lv and lv["cd_queries"], fmt(lv and lv["seconds"]), fmt(total_c2f)])
            series.setdefault(pair, []).append((d, r and r["seconds"]["total"], total_single, total_c2f))
    write("multiresolution", ["pair", "d / diagonal", "points", "CD queries", "seconds", "all levels so far s",
                              "coarse-to-fine points", "reused candidates", "CD queries", "level s",
                              "all levels so far s"], rows,
          f"Paper Fig. 8, {threads} threads. Left: each d computed on its own. Right: one coarse-to-fine run "
          "(pmsum sum --levels), each level reusing the normal filter, trees, certificate and the coarser "
          "level's decisions; its resolutions are multiples of the coarser level's, hence a few more points.")
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for pair, pts in series.items():
        line, = ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=pair + " (one d)")
        ax.loglog([p[0] for p in pts], [p[2] for p in pts], "s:", color=line.get_color(),
                  label=pair + " (all d so far, separately)")
        ax.loglog([p[0] for p in pts], [p[3] for p in pts], "^--", color=line.get_color(),
                  label=pair + " (all d so far, coarse to fine)")
    ax.set_xlabel("d / diagonal")
    ax.set_ylabel("seconds")
    ax.invert_xaxis()
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "multiresolution.png"))


def bench_goals(run):
    """The speed goals of issue 4 on CGAL's demo data at d = 0.5%, 2 threads."""
    rows = []
    for pair in ["knot1+knot2", "armadillo+sphere"]:
        print("goals:", pair, flush=True)
        r = run.sum(pair, 0.005, threads=2)
        s = r["seconds"]
        rows.append([pair, r["p"]["faces"], r["q"]["faces"], r["output_points"], r["candidates"],
                     r["candidates_certified"], r["cd_queries"], fmt(r["cd_queries"] / max(1, r["output_points"])),
                     fmt(s["normal_filter"]), fmt(s["octree_filter"]), fmt(s["cd_filter"]), fmt(s["total"]),
                     "yes" if s["total"] <= 10 else "no"])
    write("goals", ["pair", "faces P", "faces Q", "points", "candidates", "certified", "CD queries",
                    "CD queries / point", "normal filter s", "octree s", "CD s", "total s", "<= 10 s"], rows,
          "Issue 4: knot1 + knot2 and armadillo + sphere (x 8) at d = 0.5% of the diagonal in <= 10 s on 2 cores.")


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


def manifold(run, pair, timeout=600):
    """Manifold's minkowskiSum on the pair: {"seconds", "surface_area", ...}, or None."""
    ps, qs, args = PAIRS[pair]
    scale = args[args.index("--scale-q") + 1] if "--scale-q" in args else "1"
    return manifold_minkowski.minkowski_sum(run.path(ps), run.path(qs), scale, "--negate-p" in args, timeout)


def manifold_seconds(run, pair):
    m = manifold(run, pair)
    return m and m["seconds"]


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
    for pair in PEER_PAIRS:
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
    build = os.path.dirname(run.pmsum)
    subprocess.run(["cmake", "--build", build, "--target", "pd_queries", "-j2"], check=True)  # not in 'all'
    exe = os.path.join(build, "pd_queries")
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


def ensure_ompl_benchmark(run):
    """plan_vs_ompl is built only when CMake finds OMPL: install libompl-dev and build it."""
    build = os.path.dirname(run.pmsum)
    exe = os.path.join(build, "plan_vs_ompl")
    if os.path.exists(exe):
        return exe
    if subprocess.run(["dpkg", "-s", "libompl-dev"], capture_output=True).returncode != 0:
        sudo = [] if os.geteuid() == 0 else ["sudo"]
        subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "libompl-dev"], check=True,
                       env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    subprocess.run(["cmake", "-S", ROOT, "-B", build], check=True, capture_output=True)
    subprocess.run(["cmake", "--build", build, "--target", "plan_vs_ompl", "-j2"], check=True)
    return exe


PLAN_PROBLEMS = ["pocket", "slot", "slot-narrow"]


def bench_plan(run, seeds=20, time_limit=10.0):
    """Translational motion planning: ours (deterministic: 3 timed runs) against OMPL's
    RRTConnect and PRM (20 seeds, 10 s each), all with the same exact collision checks."""
    exe = ensure_ompl_benchmark(run)
    runs = []
    for problem in PLAN_PROBLEMS:
        for planner, n in [("pmsum", 3), ("rrtconnect", seeds), ("prm", seeds)]:
            for seed in range(1, n + 1):
                out = subprocess.run([exe, problem, planner, str(seed), str(time_limit)], capture_output=True,
                                     text=True, check=True)
                runs.append(json.loads(out.stdout))
                print(out.stdout.strip())
    with open(os.path.join(RESULTS, "plan_vs_ompl.json"), "w") as f:
        json.dump(runs, f, indent=0)
    report_plan(runs, seeds, time_limit)


def report_plan(runs, seeds=20, time_limit=10.0):
    """Table and picture of bench_plan's runs (also: python3 -c 'import run_benchmarks as b, json;
    b.report_plan(json.load(open("results/plan_vs_ompl.json")))' from benchmark/)."""
    import statistics
    rows, labels, rates, times = [], [], [], []
    names = {"pmsum": "CGAL_pmsum (d = 0.5)", "rrtconnect": "OMPL RRTConnect", "prm": "OMPL PRM"}
    for problem in PLAN_PROBLEMS:
        for planner in ["pmsum", "rrtconnect", "prm"]:
            rs = [r for r in runs if r["problem"] == problem and r["planner"] == planner]
            ok = [r for r in rs if r["solved"] and r["verified"]]
            t_all = [r["seconds"] for r in rs]
            t_ok = [r["seconds"] for r in ok]
            rows.append([problem, names[planner], f"{len(ok)}/{len(rs)}",
                         fmt(statistics.mean(t_ok)) if t_ok else "–",
                         fmt(statistics.median(t_ok)) if t_ok else "–",
                         fmt(statistics.median(t_all)),
                         fmt(statistics.mean([r["length"] for r in ok])) if ok else "–"])
            labels.append(f"{problem}\n{planner}")
            rates.append(len(ok) / len(rs))
            times.append(t_all)
    write("plan_vs_ompl", ["problem", "planner", "solved", "mean s (solved)", "median s (solved)",
                           "median s (all runs)", "mean path length"], rows,
          "A unit cube robot, clearance 1/16 (src/shapes/planning_scenes.h). pocket: the paper's Fig. 12(b) kind, the "
          "robot under a lid must slide sideways 1 + 1/16 with clearance 1/16 in y and z, then rise through a "
          "chimney with clearance 1/16 in x and y. slot: a closed room split by a wall with a slot 1 + 1/16 wide; "
          "slot-narrow: the same with a slot 1 + 1/200 wide (clearance d/100 for our d = 0.5). "
          f"One thread, wall clock; OMPL: {seeds} seeds, {time_limit:g} s limit per run, bounds = a box around "
          "the pocket scene / the room's inside; state validity = CGAL_pmsum's exact point test, motion "
          "validator = the exact swept-segment test (no discretisation resolution); every returned path was "
          "re-checked segment by segment (solved = exact solution and verified). CGAL_pmsum's planner is "
          "deterministic (3 identical runs); its time includes the contact space (13k / 20k points) and "
          f"the roadmap. Load average when the report was written: {os.getloadavg()[0]:.1f} on "
          f"{os.cpu_count()} cores.")
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4))
    x = range(len(labels))
    a1.bar(x, rates, color=["C0", "C1", "C2"] * len(PLAN_PROBLEMS))
    a1.set_xticks(list(x))
    a1.set_xticklabels(labels, fontsize=8)
    a1.set_ylabel("success rate")
    a1.set_ylim(0, 1.05)
    a2.boxplot(times, labels=labels)
    a2.set_yscale("log")
    a2.set_ylabel(f"seconds per run (failures at the {time_limit:g} s limit)")
    a2.tick_params(axis="x", labelsize=8)
    fig.suptitle("Translational planning, clearance 1/16: CGAL_pmsum vs OMPL (same exact checks)")
    fig.tight_layout()
    fig.savefig(os.path.join(RESULTS, "plan_vs_ompl.png"), dpi=110)
    print("wrote plan_vs_ompl.png")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--only", nargs="*",
                    default=["net", "filters", "octree", "multiresolution", "threads", "goals", "peers", "pd", "plan"])
    args = ap.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    run = Runner(args.build)
    for b in args.only:
        globals()["bench_" + b](run)
    return 0


if __name__ == "__main__":
    sys.exit(main())
