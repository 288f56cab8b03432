#!/usr/bin/env python3
"""Hardin's relative breakage Br against the input work per unit volume W for element tests of
crushable specimens, all on one plot, with one hyperbola fitted to every
row of every test together, Br = W / (a + b·W) (the form Lade, Yamamuro & Bopp 1996 fitted to
their tests of all stress paths: Br → 1/b as W grows), by least squares on Br itself (a
log-spaced search for a, b then refined), and per test its own hyperbola, so that whether one
curve holds for all paths can be read from the residuals.
    tests/bench/breakage_work.py OUT.png TEST_DIR [TEST_DIR ...]
Each TEST_DIR is a `clumpkit test` folder of a crushable specimen (curve.csv with hardin_br and
work). Prints a, b and the RMS residual of the joint fit and of each test's own.
"""
import clumpkit_csv
import math
import os
import sys


def rows(folder):
    r = clumpkit_csv.rows(os.path.join(folder, "curve.csv"))
    if not r or "hardin_br" not in r[0]:
        sys.exit(f"{folder}/curve.csv: no breakage columns (not a crushable specimen)")
    return [(float(x["work"]), float(x["hardin_br"])) for x in r]


def rms(points, a, b):
    return math.sqrt(sum((br - w / (a + b * w)) ** 2 for w, br in points) / len(points))


def fit(points):
    """a (Pa) and b of Br = W/(a + bW) minimising the squared error of Br."""
    w_max = max(w for w, _ in points)
    best = None
    for i in range(81):  # a from 1e-2 to 1e2 of the largest work, b from 1 to 1e3
        a = w_max * 10 ** (-2 + i / 20)
        for j in range(61):
            b = 10 ** (j / 20)
            e = rms(points, a, b)
            if best is None or e < best[0]:
                best = (e, a, b)
    _, a, b = best
    step = 0.05
    for _ in range(200):  # pattern search in log a, log b
        improved = False
        for da, db in ((step, 0), (-step, 0), (0, step), (0, -step)):
            a2, b2 = a * 10 ** da, b * 10 ** db
            # Br cannot pass 1, so neither can its limit 1/b: a convex set of points would
            # otherwise drive b to zero (the straight line Br = W/a).
            if b2 >= 1 and rms(points, a2, b2) < rms(points, a, b):
                a, b, improved = a2, b2, True
        if not improved:
            step /= 2
            if step < 1e-6:
                break
    return a, b


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, folders = sys.argv[1], sys.argv[2:]
    data = {f: [p for p in rows(f) if p[0] > 0] for f in folders}
    every = [p for f in folders for p in data[f]]
    if len(every) < 3:
        sys.exit("too few rows with work done")
    a, b = fit(every)
    print(f"joint fit Br = W/(a + b W): a = {a:.6g} Pa, b = {b:.6g} (Br limit {1 / b:.4g}), "
          f"RMS {rms(every, a, b):.4g} over {len(every)} rows")
    for f in folders:
        pts = data[f]
        own = fit(pts)
        print(f"{f}: own fit a = {own[0]:.6g} Pa, b = {own[1]:.6g}, RMS {rms(pts, *own):.4g}; "
              f"RMS against the joint fit {rms(pts, a, b):.4g}")
    try:
        import matplotlib
    except ImportError:
        sys.exit("no plot: matplotlib is missing (scripts/deps installs python3-matplotlib)")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    w_top = max(w for w, _ in every)
    for f in folders:
        pts = data[f]
        ax.plot([w / 1e3 for w, _ in pts], [br for _, br in pts], ".", label=os.path.basename(f))
    xs = [w_top * k / 200 for k in range(201)]
    ax.plot([x / 1e3 for x in xs], [x / (a + b * x) for x in xs], "k-",
            label=f"W/({a / 1e3:.3g} kPa + {b:.3g} W)")
    ax.set_xlabel("input work per unit volume W (kJ/m³)")
    ax.set_ylabel("Hardin's relative breakage Br")
    ax.legend()
    fig.savefig(out, dpi=100)


if __name__ == "__main__":
    main()
