#!/usr/bin/python3
"""Renders the user manual's figures from pmsum runs on bundled data.

    doc/make_figures.py [BUILD_DIR]      (needs Debian's python3-matplotlib)

Each figure runs `pmsum sum ... -o X.xyz` and draws the points, shaded by their normals.
"""
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
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
PMSUM = os.path.join(BUILD, "pmsum")
DATA = os.path.join(ROOT, "data")
OUT = os.path.join(HERE, "figures")


def run(name, args):
    work = tempfile.mkdtemp()
    xyz, js = os.path.join(work, name + ".xyz"), os.path.join(work, name + ".json")
    subprocess.run([PMSUM, "sum", *args, "-o", xyz, "--json", js, "--quiet"], check=True)
    pts = [list(map(float, line.split())) for line in open(xyz)]
    return pts, json.load(open(js))


def draw(ax, pts, title, max_points=60000, elev=25, azim=35, size=0.3):
    step = max(1, len(pts) // max_points)
    sel = pts[::step]
    light = (0.4, 0.5, 0.77)
    shade = [max(0.15, n[3] * light[0] + n[4] * light[1] + n[5] * light[2]) for n in sel]
    ax.scatter([p[0] for p in sel], [p[1] for p in sel], [p[2] for p in sel], c=shade, cmap="copper",
               s=size, linewidths=0, vmin=0, vmax=1)
    ax.set_title(title, fontsize=9)
    ax.view_init(elev=elev, azim=azim)
    ax.set_box_aspect(tuple(max(1e-9, max(p[c] for p in sel) - min(p[c] for p in sel)) for c in range(3)))
    ax.set_axis_off()


def figure(name, panels):
    fig = plt.figure(figsize=(4.5 * len(panels), 4.5), dpi=110)
    for i, (args, title, kw) in enumerate(panels):
        pts, js = run(f"{name}{i}", args)
        ax = fig.add_subplot(1, len(panels), i + 1, projection="3d")
        draw(ax, pts, f"{title}\n{js['output_points']:,} points, {js['seconds']['total']:.2f} s", **kw)
    fig.tight_layout()
    path = os.path.join(OUT, name + ".png")
    fig.savefig(path)
    print("wrote", path)


def main():
    os.makedirs(OUT, exist_ok=True)
    figure("knot1_tetrahedron", [
        ([os.path.join(DATA, "knot1.off"), os.path.join(DATA, "tetrahedron.off"), "--scale-q", "0.03125",
          "-d", "0.01", "--relative"], "knot1 ⊕ tetrahedron, d = 1%", {}),
        ([os.path.join(DATA, "knot1.off"), os.path.join(DATA, "tetrahedron.off"), "--scale-q", "0.03125",
          "-d", "0.01", "--relative", "--negate-p"], "−knot1 ⊕ tetrahedron (contact space)", {}),
    ])
    figure("open_cube_ellipsoid", [
        ([os.path.join(DATA, "open_cube.off"), os.path.join(DATA, "ellipsoid.off"), "--scale-q", "16",
          "-d", "0.01", "--relative"], "open cube ⊕ ellipsoid (paper Fig. 7)", {"elev": 40}),
    ])


if __name__ == "__main__":
    main()
