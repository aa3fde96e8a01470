"""Manifold's minkowskiSum (npm manifold-3d, run by node) on two OFF meshes, for the benchmarks
that compare with it (benchmark/run_benchmarks.py, benchmark/mesh/run_mesh.py).

    minkowski_sum(p_off, q_off, scale_q=1, negate_p=False, timeout=600)
        -> {"seconds", "seconds_load", "triangles", "surface_area", "status"},
           {"status": "timeout", "seconds": None, "timeout"}, or None (it failed)

Manifold is not a Debian 12 package: its npm build (WebAssembly) is installed on first use into
benchmark/speed/node/ (not committed). `negate_p` sums -P (a contact space): P's vertices are
negated and its faces reversed into a temporary file, as the script sums P.
"""
import json
import os
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
NODE = os.path.join(HERE, "node")
VERSION = "3.5.4"


def _negated_off(path, out):
    tokens = [t for line in open(path) for t in line.split("#")[0].split()]
    nv, nf = int(tokens[1]), int(tokens[2])
    vals = tokens[4:]
    with open(out, "w") as f:
        f.write(f"OFF\n{nv} {nf} 0\n")
        for i in range(nv):
            f.write(" ".join(repr(-float(v)) for v in vals[3 * i:3 * i + 3]) + "\n")
        k = 3 * nv
        for _ in range(nf):
            n = int(vals[k])
            face = vals[k + 1:k + 1 + n]
            f.write(f"{n} " + " ".join(reversed(face)) + "\n")  # x -> -x reverses orientation
            k += n + 1


def minkowski_sum(p_off, q_off, scale_q=1, negate_p=False, timeout=600):
    if not os.path.exists(os.path.join(NODE, "node_modules", "manifold-3d")):
        os.makedirs(NODE, exist_ok=True)
        subprocess.run(["npm", "install", "--prefix", NODE, "--no-audit", "--no-fund", f"manifold-3d@{VERSION}"],
                       check=True, capture_output=True)
    script = os.path.join(NODE, "manifold_minkowski.mjs")  # beside its node_modules
    with open(os.path.join(HERE, "manifold_minkowski.mjs")) as src, open(script, "w") as dst:
        dst.write(src.read())
    with tempfile.TemporaryDirectory() as work:
        if negate_p:
            _negated_off(p_off, os.path.join(work, "minus_p.off"))
            p_off = os.path.join(work, "minus_p.off")
        try:
            out = subprocess.run(["node", script, p_off, q_off, str(scale_q)], capture_output=True, text=True,
                                 timeout=timeout, check=True)
            return json.loads(out.stdout)
        except subprocess.TimeoutExpired:
            return {"status": "timeout", "seconds": None, "timeout": timeout}
        except (subprocess.SubprocessError, ValueError):
            return None
