#!/usr/bin/env python3
# Copyright (c) 2026 CGAL_pmsum contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Example of the Python module pmsum: points on the boundary of knot1 + tetrahedron (the files
# of data/), with their provenance; the contact space -P + Q; a penetration depth query.
#
#   PYTHONPATH=build/python /usr/bin/python3 examples/python_minkowski_sum.py [P] [Q] [d] [-o OUT.xyz]
#
# d is relative (a fraction of the diagonal of the bounding box of P + Q), as `pmsum sum --relative`.

import argparse
import pathlib
import warnings

import numpy as np

import pmsum

DATA = pathlib.Path(__file__).resolve().parent.parent / "data"

parser = argparse.ArgumentParser(description="Points on the boundary of P + Q with the module pmsum")
parser.add_argument("P", nargs="?", default=DATA / "knot1.off")
parser.add_argument("Q", nargs="?", default=DATA / "tetrahedron.off")
parser.add_argument("d", nargs="?", type=float, default=0.02)
parser.add_argument("-o", "--output", help="write the points and normals to this .xyz file")
args = parser.parse_args()

print(f"pmsum {pmsum.__version__} (CGAL {pmsum.CGAL_VERSION})")
# The reader's notes (CGAL's tetrahedron.off is oriented inward: it is reoriented) are warnings.
with warnings.catch_warnings(record=True) as notes:
    warnings.simplefilter("always", pmsum.InputWarning)
    r = pmsum.minkowski_sum(args.P, args.Q, args.d, relative=True, threads=0)
for n in notes:
    print("note:", n.message)

points = r["points"]
print(f"P + Q: {len(points)} points (d = {r['d']:.4g}), "
      f"{r['statistics']['seconds_cd_filter']:.2f} s in the CD filter")
names = {0: "a vertex", 1: "an edge", 2: "a face"}
for side in ("p", "q"):
    dim, count = np.unique(r[f"origin_{side}_dimension"], return_counts=True)
    print(f"  from features of {side.upper()}: " + ", ".join(f"{c} on {names[k]}" for k, c in zip(dim, count)))
lo, hi = points.min(axis=0), points.max(axis=0)
print(f"  bounding box {np.round(lo, 4)} .. {np.round(hi, 4)}")

# The contact space of the robot P among the obstacle Q.
contact = pmsum.minkowski_sum(args.P, args.Q, args.d, relative=True, negate_p=True, threads=0, quiet=True)
print(f"-P + Q: {len(contact['points'])} points")

# Penetration depth of P translated by t into Q.
pd = pmsum.PenetrationDepth(args.P, args.Q, args.d, relative=True, threads=0, quiet=True)
t = np.zeros(3)
q = pd.query(t)
if q["overlapping"]:
    print(f"penetration depth at t = 0: {q['depths']:.4f} along {np.round(q['directions'], 3)}")
else:
    print("P and Q do not overlap at t = 0")

if args.output:
    np.savetxt(args.output, np.hstack([points, r["normals"]]), fmt="%.17g")
    print(f"wrote {args.output}")
