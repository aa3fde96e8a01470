#!/usr/bin/env python3
# Copyright (c) 2026 CGAL_pmsum contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Long run of the differential test against CGAL's exact Nef sum.

Runs the "differential" test of test_validation over a seed range, split over processes,
collects one CSV line per case and writes benchmark/results/differential.{md,csv,png}:
outcomes per kind (ok / failed / input refused / Nef failed), worst coverage / d, and the
seconds of the point sum against Nef's. Failing cases are written to DIR/seed-N (P.off,
Q.off, case.txt): copy one into test/differential/cases/ to make it a regression test.

    run_long.py [--build build] [--seeds 0:2000] [--jobs 2] [--failures differential-failures] [--extend]
"""

import argparse
import collections
import csv
import os
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--seeds", default="0:2000", help="first:count")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--failures", default=os.path.abspath("differential-failures"))
    ap.add_argument("--results", default=os.path.join(ROOT, "benchmark", "results"))
    ap.add_argument("--extend", action="store_true",
                    help="keep the cases of the existing differential.csv outside the new seed range")
    a = ap.parse_args()
    first, count = (int(x) for x in a.seeds.split(":"))
    binary = os.path.join(a.build, "test", "test_validation")
    os.makedirs(a.failures, exist_ok=True)
    os.makedirs(a.results, exist_ok=True)
    start = time.monotonic()
    procs, parts = [], []
    per = (count + a.jobs - 1) // a.jobs
    for j in range(a.jobs):
        lo, n = first + j * per, min(per, count - j * per)
        if n <= 0:
            continue
        part = os.path.join(a.failures, "part%d.csv" % j)
        env = dict(os.environ, PMSUM_DIFFERENTIAL_SEEDS="%d:%d" % (lo, n), PMSUM_DIFFERENTIAL_CSV=part,
                   PMSUM_DIFFERENTIAL_OUT=a.failures)
        log = open(os.path.join(a.failures, "part%d.log" % j), "w")
        procs.append(subprocess.Popen([binary, "differential: random solids against the exact Nef sum"],
                                      env=env, stdout=log, stderr=subprocess.STDOUT))
        parts.append(part)
    for p in procs:
        p.wait()
    seconds = time.monotonic() - start
    rows = []
    for part in parts:
        with open(part) as f:
            rows += list(csv.DictReader(f))
        os.remove(part)
    previous = os.path.join(a.results, "differential.csv")
    if a.extend and os.path.exists(previous):
        with open(previous) as f:
            rows += [r for r in csv.DictReader(f) if not first <= int(r["seed"]) < first + count]
    rows.sort(key=lambda r: int(r["seed"]))
    with open(os.path.join(a.results, "differential.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    write_report(rows, seconds, a)
    failed = [r for r in rows if r["status"] == "failed"]
    print("%d cases in %.0f s: %s" % (len(rows), seconds, dict(collections.Counter(r["status"] for r in rows))))
    for r in failed:
        print("FAILED seed %s (%s): off the boundary %s, covered %s of %s shells, worst %s d"
              % (r["seed"], r["kind"], r["off_boundary"], r["covered"], r["shells"], r["worst_over_d"]))
    return 0 if not failed else 1


def write_report(rows, seconds, a):
    kinds = sorted({r["kind"] for r in rows})
    statuses = ["ok", "failed", "refused", "nef failed"]
    lines = ["# Differential test against CGAL's exact Nef Minkowski sum", "",
             "`test/differential/run_long.py --seeds %s --jobs %d`: %d random cases (test/differential.h; this run's "
             "wall time %.0f s). "
             "For each: every output point exactly on the Nef boundary (exact point location) and every shell "
             "(outer boundaries and voids) covered within d (sampled at d/8). `refused`: the input was refused "
             "(only unions, whose rounded vertices may make a degenerate face, may be); `nef failed`: CGAL's "
             "minkowski_sum_3 failed an assertion, crashed or ran past the time limit (not ours)." % (
                 a.seeds + (" and earlier runs (--extend)" if a.extend else ""), a.jobs, len(rows), seconds), "",
             "| kind | cases | " + " | ".join(statuses) + " | contact space | rotated | voids in the sum | "
             "worst coverage / d (max of ok) | Nef s / ours s (median) |",
             "|---|" + "---|" * (len(statuses) + 6)]
    for kind in kinds + ["all"]:
        rs = [r for r in rows if kind in ("all", r["kind"])]
        c = collections.Counter(r["status"] for r in rs)
        ok = [r for r in rs if r["status"] == "ok"]
        ratios = sorted(float(r["seconds_nef"]) / max(float(r["seconds_pmsum"]), 1e-6) for r in ok)
        lines.append("| %s | %d | %s | %d | %d | %d | %.3f | %.1f |" % (
            kind, len(rs), " | ".join(str(c[s]) for s in statuses), sum(r["negate"] == "1" for r in rs),
            sum(r["rotated"] == "1" for r in rs), sum(int(r["voids"]) > 0 for r in rs),
            max((float(r["worst_over_d"]) for r in ok), default=0), ratios[len(ratios) // 2] if ratios else 0))
    failed = [r for r in rows if r["status"] == "failed"]
    lines += ["", "## Failures", ""]
    if not failed:
        lines.append("None.")
    for r in failed:
        lines.append("- seed %s (%s): %s points off the boundary, %s of %s shells covered (voids %s), worst %s d"
                     % (r["seed"], r["kind"], r["off_boundary"], r["covered"], r["shells"], r["voids"],
                        r["worst_over_d"]))
    nef = collections.Counter(r["message"] for r in rows if r["status"] == "nef failed")
    if nef:
        lines += ["", "## Nef failures (CGAL 5.5's minkowski_sum_3)", ""]
        lines += ["- %d × %s" % (n, m) for m, n in nef.most_common()]
    refused = collections.Counter(r["message"].split(" face ")[0] for r in rows if r["status"] == "refused")
    if refused:
        lines += ["", "## Refused inputs", ""]
        lines += ["- %d × %s" % (n, m) for m, n in refused.most_common()]
    lines += ["", "![worst coverage and times](differential.png)", ""]
    with open(os.path.join(a.results, "differential.md"), "w") as f:
        f.write("\n".join(lines))
    plot(rows, kinds, os.path.join(a.results, "differential.png"))


def plot(rows, kinds, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing (use /usr/bin/python3 with python3-matplotlib): no figure")
        return
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    for kind in kinds:
        rs = [r for r in rows if r["kind"] == kind and r["status"] in ("ok", "failed")]
        ax1.hist([min(float(r["worst_over_d"]), 3) for r in rs], bins=60, range=(0, 3), histtype="step", label=kind)
        ax2.loglog([float(r["seconds_nef"]) for r in rs], [float(r["seconds_pmsum"]) for r in rs], ".", ms=3,
                   label=kind)
    ax1.axvline(1, color="k", lw=0.8)
    ax1.set_xlabel("worst distance from the exact boundary to the output / d (clipped at 3)")
    ax1.set_ylabel("cases")
    ax1.legend()
    ax2.set_xlabel("CGAL Nef minkowski_sum_3 (s)")
    ax2.set_ylabel("point sum, default net (s)")
    lo = min(ax2.get_xlim()[0], ax2.get_ylim()[0])
    hi = max(ax2.get_xlim()[1], ax2.get_ylim()[1])
    ax2.plot([lo, hi], [lo, hi], "k-", lw=0.8)
    ax2.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
