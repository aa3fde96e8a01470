#!/usr/bin/python3
"""`mpirun -np K pmsum sum` (issue 14): strong scaling here, and the partitioner simulated for many K.

    benchmark/mpi/run_mpi.py [--build BUILD_DIR] [--repeats N]

Needs the tool built with -DCGAL_PMSUM_WITH_MPI=ON (the README's test command builds it so),
Open MPI's mpirun, and Debian's python3-matplotlib. Writes into benchmark/mpi/results/:
  results.md    two tables:
                - strong scaling, side by side in one run, per pair: one process on one thread,
                  two ranks of one thread each (mpirun -np 2), and for comparison one process on
                  two threads (TBB); median wall seconds of --repeats runs (default 5), the
                  ratios of the medians and of the fastest runs, and whether the two-rank output
                  is byte-identical to one process's (it must be);
                - the partitioner alone (benchmark/mpi/balance.cpp, built on demand) on real models
                  at a fine d, for K = 1 ... 256: the largest rank's share of the work x K (1 is a
                  perfect balance), and the critical share x K (the ranks wait for each other after
                  every wave of pieces of feature pairs, so the decision stage takes at least that
                  share of one process's time: the speed-up of the decisions is at most
                  1 / critical share; each piece taken in the wave's order, largest first, by the
                  rank that is free first, as the ranks take them from their shared counter,
                  with its candidates as its time)
  results.json  the same figures;  balance.png  both shares against K
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RESULTS = os.path.join(HERE, "results")
DATA = os.path.join(ROOT, "data")

# (name, P, Q, relative d, extra arguments)
SCALING = [
    ("knot1 + tetrahedron/32", "knot1.off", "tetrahedron.off", 0.003, ["--scale-q", "0.03125"]),
    ("elephant + octahedron/128", "elephant.off", "octahedron.off", 0.004, ["--scale-q", "0.0078125"]),
    ("hooks", "gen:hook-a", "gen:hook-b", 0.02, []),
]
# (name, P, Q, relative d, scale of Q)
BALANCE = [
    ("knot1 + tetrahedron/32", "knot1.off", "tetrahedron.off", 0.001, 0.03125),
    ("elephant + octahedron/128", "elephant.off", "octahedron.off", 0.002, 0.0078125),
    ("hooks", "gen:hook-a", "gen:hook-b", 0.005, 1.0),
]
KS = [1, 2, 4, 8, 16, 32, 64, 128, 256]


def mpirun(k):
    cmd = ["mpirun", "--oversubscribe", "-np", str(k)]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    return cmd


def shape(name, pmsum, tmp):
    if name.startswith("gen:"):
        path = os.path.join(tmp, name[4:] + ".off")
        if not os.path.exists(path):
            subprocess.run([pmsum, "generate", name[4:], "-o", path], check=True)
        return path
    return os.path.join(DATA, name)


def timed(cmd):
    start = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def scaling(pmsum, tmp, repeats):
    rows = []
    for name, p, q, d, extra in SCALING:
        base = [pmsum, "sum", shape(p, pmsum, tmp), shape(q, pmsum, tmp), "-d", str(d), "--relative", "--quiet"] + extra
        runs = {
            "1 process, 1 thread": lambda out: base + ["--threads", "1", "-o", out],
            "2 ranks, 1 thread each": lambda out: mpirun(2) + base + ["--threads", "1", "-o", out],
            "1 process, 2 threads": lambda out: base + ["--threads", "2", "-o", out],
        }
        seconds = {k: [] for k in runs}
        for _ in range(repeats):  # interleaved, so that the machine's drift hits all alike
            for k, cmd in runs.items():
                seconds[k].append(timed(cmd(os.path.join(tmp, k.replace(" ", "_").replace(",", "") + ".ply"))))
        one = os.path.join(tmp, "1_process_1_thread.ply")
        two = os.path.join(tmp, "2_ranks_1_thread_each.ply")
        identical = open(one, "rb").read() == open(two, "rb").read()
        subprocess.run(mpirun(2) + base + ["--threads", "1", "-o", two, "--json", os.path.join(tmp, "two.json")],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        j = json.load(open(os.path.join(tmp, "two.json")))
        median = {k: statistics.median(v) for k, v in seconds.items()}
        fastest = {k: min(v) for k, v in seconds.items()}
        rows.append({
            "pair": name, "d_relative": d, "feature_pairs": j["feature_pairs"], "candidates": j["candidates"],
            "output_points": j["output_points"], "seconds": median, "all_seconds": seconds,
            "speedup_2_ranks": median["1 process, 1 thread"] / median["2 ranks, 1 thread each"],
            "speedup_2_threads": median["1 process, 1 thread"] / median["1 process, 2 threads"],
            "fastest_speedup_2_ranks": fastest["1 process, 1 thread"] / fastest["2 ranks, 1 thread each"],
            "fastest_speedup_2_threads": fastest["1 process, 1 thread"] / fastest["1 process, 2 threads"],
            "identical": identical, "ranks": j["ranks"],
        })
        print(f"{name}: 1 rank {median['1 process, 1 thread']:.2f} s, 2 ranks {median['2 ranks, 1 thread each']:.2f} s "
              f"({rows[-1]['speedup_2_ranks']:.2f}x, fastest runs {rows[-1]['fastest_speedup_2_ranks']:.2f}x), 2 threads {median['1 process, 2 threads']:.2f} s, "
              f"identical {identical}", flush=True)
    return rows


def balance(build, pmsum, tmp):
    subprocess.run(["cmake", "--build", build, "--target", "mpi_balance"], check=True, stdout=subprocess.DEVNULL)
    rows = []
    for name, p, q, d, scale in BALANCE:
        out = subprocess.run([os.path.join(build, "mpi_balance"), shape(p, pmsum, tmp), shape(q, pmsum, tmp), str(d), str(scale)]
                             + [str(k) for k in KS], check=True, capture_output=True, text=True).stdout
        sim = [json.loads(line) for line in out.splitlines()]
        rows.append({"pair": name, "d_relative": d, "simulation": sim})
        print(f"{name}: " + ", ".join(f"K={s['k']} {s['largest_share'] * s['k']:.2f}/{s['critical_share'] * s['k']:.2f}"
                                       for s in sim), flush=True)
    return rows


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), dpi=100)
    for r in rows:
        ks = [s["k"] for s in r["simulation"]]
        axes[0].plot(ks, [s["largest_share"] * s["k"] for s in r["simulation"]], marker="o", label=r["pair"])
        axes[1].plot(ks, [1 / s["critical_share"] for s in r["simulation"]], marker="o", label=r["pair"])
    axes[0].axhline(1.25, color="grey", linestyle="--", label="target 1.25")
    axes[0].set(xscale="log", xlabel="K ranks", ylabel="largest share x K", title="total work of the largest rank")
    axes[1].plot(KS, KS, color="grey", linestyle="--", label="ideal K")
    axes[1].set(xscale="log", yscale="log", xlabel="K ranks", ylabel="1 / critical share",
                title="bound on the decisions' speed-up (waves)")
    for ax in axes:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--repeats", type=int, default=5)
    a = ap.parse_args()
    pmsum = os.path.join(a.build, "pmsum")
    os.makedirs(RESULTS, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        scale = scaling(pmsum, tmp, a.repeats)
        bal = balance(a.build, pmsum, tmp)
    json.dump({"scaling": scale, "balance": bal, "cores": os.cpu_count()}, open(os.path.join(RESULTS, "results.json"), "w"), indent=1)
    plot(bal, os.path.join(RESULTS, "balance.png"))
    with open(os.path.join(RESULTS, "results.md"), "w") as f:
        f.write("# mpirun -np K pmsum sum: scaling and balance\n\n")
        f.write(f"Made by `benchmark/mpi/run_mpi.py` on {os.cpu_count()} cores, median of {a.repeats} runs, "
                "wall seconds of the whole command (mpirun's start included). Speed-ups: of the medians, and of "
                "the fastest runs (the host's other load only slows a run down, and a two-rank run on both cores "
                "more than a one-thread run: the fastest run is the best estimate of the cost on a quiet machine).\n\n")
        f.write("## Strong scaling here (K = 1, 2)\n\n")
        f.write("| pair | d (rel.) | feature pairs | candidates | points | 1 process, 1 thread (s) | 2 ranks (s) | "
                "speed-up (median / fastest) | 1 process, 2 threads (s) | speed-up (median / fastest) | ranks' candidates | "
                "output identical |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in scale:
            s = r["seconds"]
            f.write(f"| {r['pair']} | {r['d_relative']} | {r['feature_pairs']} | {r['candidates']} | {r['output_points']} | "
                    f"{s['1 process, 1 thread']:.2f} | {s['2 ranks, 1 thread each']:.2f} | "
                    f"{r['speedup_2_ranks']:.2f} / {r['fastest_speedup_2_ranks']:.2f} | "
                    f"{s['1 process, 2 threads']:.2f} | {r['speedup_2_threads']:.2f} / {r['fastest_speedup_2_threads']:.2f} | "
                    f"{' / '.join(str(x['candidates']) for x in r['ranks'])} | {'yes' if r['identical'] else 'NO'} |\n")
        f.write("\n## The partitioner alone, simulated (largest share x K / critical share x K)\n\n")
        f.write("| pair | d (rel.) | feature pairs | pieces | candidates | waves | " + " | ".join(f"K={k}" for k in KS) + " |\n")
        f.write("|---|---|---|---|---|---|" + "---|" * len(KS) + "\n")
        for r in bal:
            s0 = r["simulation"][0]
            f.write(f"| {r['pair']} | {r['d_relative']} | {s0['feature_pairs']} | {s0['pieces']} | {s0['candidates']} | "
                    f"{s0['waves']} | "
                    + " | ".join(f"{s['largest_share'] * s['k']:.2f} / {s['critical_share'] * s['k']:.1f}" for s in r["simulation"])
                    + " |\n")
        f.write("\n![balance](balance.png)\n")
    print("written to", RESULTS)


if __name__ == "__main__":
    sys.exit(main())
