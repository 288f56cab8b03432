"""The Python module's overhead (issue: no per-sphere Python objects): mass_properties on 10⁶
spheres from NumPy against the C++ call's own time, and read_specimen of the quick specimen.

    PYTHONPATH=build/python python3 tests/bench/python_bench.py [--spheres N] [--specimen DIR]

The C++ time is the `seconds` that measure_volume reports around union_properties (the same
spheres, the same process), and `clumpkit volume --method exact --json` on the same spheres
written to a CSV; the quick specimen is built with `clumpkit specimen` when DIR lacks it."""
import argparse
import os
import statistics
import subprocess
import sys
import time

import numpy as np

import clumpkit

root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
p = argparse.ArgumentParser()
p.add_argument("--spheres", type=int, default=1_000_000)
p.add_argument("--repeats", type=int, default=3)
p.add_argument("--specimen", default="/tmp/clumpkit-python-bench/quick")
p.add_argument("--binary", default=os.path.join(root, "build", "io", "clumpkit"))
a = p.parse_args()

# Spheres of radius 0.5–1 on a jittered lattice of spacing 1: each overlaps its neighbours.
g = np.random.default_rng(1)
side = int(round(a.spheres ** (1 / 3)))
n = side ** 3
grid = np.stack(np.meshgrid(*[np.arange(side, dtype=float)] * 3, indexing="ij"), -1).reshape(-1, 3)
centres = grid + g.uniform(-0.25, 0.25, (n, 3))
radii = g.uniform(0.5, 1.0, n)

py, cpp = [], []
for _ in range(a.repeats):
    t0 = time.perf_counter()
    props = clumpkit.mass_properties(centres, radii)
    py.append(time.perf_counter() - t0)
    cpp.append(clumpkit.volume(centres, radii)["seconds"])
csv = "/tmp/clumpkit-python-bench-spheres.csv"
np.savetxt(csv, np.column_stack([centres, radii]), delimiter=",", header="x,y,z,r", comments="",
           fmt="%.17g")
import json
cli = json.loads(subprocess.run([a.binary, "volume", csv, "--json"], check=True,
                                capture_output=True, text=True).stdout)["exact"]["seconds"]
tp, tc = statistics.median(py), statistics.median(cpp)
print(f"mass_properties, {n} spheres: Python call {tp:.3f} s, C++ union_properties {tc:.3f} s "
      f"(median of {a.repeats}), ratio {tp / tc:.4f}; clumpkit volume --method exact {cli:.3f} s; "
      f"volume {props.volume:.9g}")

spec = a.specimen
if not os.path.exists(os.path.join(spec, "specimen.csv")):
    os.makedirs(os.path.dirname(spec), exist_ok=True)
    subprocess.run([a.binary, "specimen", "--quiet", "--recipe",
                    os.path.join(root, "assets", "recipes", "quick-specimen.toml"), "--out", spec],
                   check=True, cwd=os.path.join(root, "assets", "recipes"))
times = []
for _ in range(5):
    t0 = time.perf_counter()
    s = clumpkit.read_specimen(spec)
    times.append(time.perf_counter() - t0)
print(f"read_specimen {spec}: {len(s['id'])} bodies, {len(s['sphere_radii'])} spheres, "
      f"median of 5 {statistics.median(times):.4f} s (min {min(times):.4f})")
sys.stdout.flush()
