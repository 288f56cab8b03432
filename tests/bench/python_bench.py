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

py, cpp, within = [], [], []
for _ in range(a.repeats):
    t0 = time.perf_counter()
    props = clumpkit.mass_properties(centres, radii)
    py.append(time.perf_counter() - t0)
    t0 = time.perf_counter()
    inner = clumpkit.volume(centres, radii)["seconds"]
    within.append((time.perf_counter() - t0) / inner)
    cpp.append(inner)
csv = "/tmp/clumpkit-python-bench-spheres.csv"
np.savetxt(csv, np.column_stack([centres, radii]), delimiter=",", header="x,y,z,r", comments="",
           fmt="%.17g")
import json
cli = json.loads(subprocess.run([a.binary, "volume", csv, "--json"], check=True,
                                capture_output=True, text=True).stdout)["exact"]["seconds"]
tp, tc = statistics.median(py), statistics.median(cpp)
print(f"mass_properties, {n} spheres: Python call {tp:.3f} s, C++ union_properties {tc:.3f} s "
      f"(median of {a.repeats}, interleaved), ratio {tp / tc:.4f}; within one volume() call, "
      f"Python wall / C++ union_properties: median {statistics.median(within):.4f} "
      f"(max {max(within):.4f}); clumpkit volume --method exact {cli:.3f} s; "
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

# Ctrl-C latency: _thread.interrupt_main() from a timer thread while a fill (3000 spheres at 90
# voxels, 20 s uninterrupted) or the quick-rocks library runs; time until KeyboardInterrupt.
import _thread
import shutil
import threading


def latency(call, after):
    sent = []
    timer = threading.Timer(after, lambda: (sent.append(time.perf_counter()),
                                            _thread.interrupt_main()))
    timer.start()
    t0 = time.perf_counter()
    try:
        call()
        raise RuntimeError("not interrupted")
    except KeyboardInterrupt:
        raised = time.perf_counter()
    timer.join()
    return raised - sent[0], raised - t0


rock = clumpkit.block(0.04, 0.03, 0.02, seed=7)
for after in (0.5, 3.0, 6.0):
    lat, total = latency(lambda: clumpkit.fill(rock, spheres=3000, voxels=90), after)
    print(f"fill interrupted at {after} s: KeyboardInterrupt {lat:.3f} s after the signal "
          f"(call {total:.2f} s)")
out = "/tmp/clumpkit-python-bench/rocks"
shutil.rmtree(out, ignore_errors=True)
shutil.rmtree(out + ".partial", ignore_errors=True)
recipe = os.path.join(root, "assets", "recipes", "quick-rocks.toml")
lat, total = latency(lambda: clumpkit.library(recipe, out, threads=1), 0.3)
kept = len([n for n in os.listdir(out + ".partial/particles") if n.endswith(".json")])
t0 = time.perf_counter()
r = clumpkit.library(recipe, out)
print(f"library (1 thread) interrupted at 0.3 s: KeyboardInterrupt {lat:.3f} s after the signal, {kept} "
      f"particles kept; the rerun resumed {r['resumed']} and finished {r['particles']} in "
      f"{time.perf_counter() - t0:.2f} s")
