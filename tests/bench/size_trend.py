#!/usr/bin/env python3
"""Do larger particles break first? A trend test on the broken fraction of each size class of a
crushable specimen's element test, and what a Weibull size effect would let 98 particles show.

At each chosen curve row (the first at or above each vertical stress; `end` for the last row) it
prints the particles broken out of each class, the Cochran–Armitage test for a trend in proportion
across the ordered classes (scores: the classes' mid diameters; z and its one-sided p, normal
approximation) and the fractions a Weibull size effect would give at that overall fraction:
P_f(D) = 1 − exp(−c·(D/D_m)^(α·m)) (the particles' stress independent of their size, strength
σ0 ∝ D^−α, Weibull modulus m), c matched to the observed overall fraction. With --power it draws
the classes' counts from those fractions and says how often every class comes out above the one
before and how often the trend test reaches one-sided p < 0.05: how much a specimen of this many
particles can show.

    tests/bench/size_trend.py [--alpha-m 1.34] [--power N] SPECIMEN_DIR TEST_DIR STRESS[,STRESS|end...]

SPECIMEN_DIR holds the specimen.csv the test started from (cell volumes); TEST_DIR the test's
curve.csv (broken_class_*), report.json (breakage.class_bounds) and fragments.vtp (each cell's
particle). Needs python3-numpy (face_overlap.py's readers).
"""
import argparse
import clumpkit_csv
import json
import math
import os
import random

from face_overlap import read_specimen, vtp_array


def class_sizes(specimen, test):
    """Particles in each size class: volume-equivalent diameter of each particle's cells."""
    volume = read_specimen(os.path.join(specimen, "specimen.csv"))[2]
    with open(os.path.join(test, "fragments.vtp")) as f:
        text = f.read()
    particle_of = dict(zip(vtp_array(text, "body"), vtp_array(text, "particle")))  # one per cell
    pvol = {}
    for body, particle in particle_of.items():
        pvol[particle] = pvol.get(particle, 0.0) + volume[int(body) - 1]
    with open(os.path.join(test, "report.json")) as f:
        bounds = json.load(f)["breakage"]["class_bounds"]
    counts = [0] * (len(bounds) - 1)
    for v in pvol.values():
        d = (6 * v / math.pi) ** (1 / 3)
        i = max(0, min(len(counts) - 1, sum(1 for b in bounds[1:-1] if d >= b)))
        counts[i] += 1
    mids = [0.5 * (a + b) for a, b in zip(bounds, bounds[1:])]
    return counts, mids


def trend(k, n, t):
    """Cochran–Armitage z and one-sided p (larger classes break more)."""
    big_n = sum(n)
    p = sum(k) / big_n
    if p <= 0 or p >= 1:
        return float("nan"), float("nan")
    s = sum(ti * (ki - ni * p) for ti, ki, ni in zip(t, k, n))
    v = p * (1 - p) * (sum(ni * ti * ti for ti, ni in zip(t, n)) - sum(ni * ti for ti, ni in zip(t, n)) ** 2 / big_n)
    z = s / math.sqrt(v)
    return z, 0.5 * math.erfc(z / math.sqrt(2))


def weibull_fractions(overall, n, t, am):
    d_m = sum(ni * ti for ni, ti in zip(n, t)) / sum(n)
    lo, hi = 1e-12, 1e6
    for _ in range(200):
        c = math.sqrt(lo * hi)
        f = sum(ni * (1 - math.exp(-c * (ti / d_m) ** am)) for ni, ti in zip(n, t)) / sum(n)
        lo, hi = (c, hi) if f < overall else (lo, c)
    return [1 - math.exp(-c * (ti / d_m) ** am) for ti in t]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--alpha-m", type=float, default=1.34, help="size exponent x Weibull modulus (0.32 x 4.2)")
    ap.add_argument("--power", type=int, default=0, help="draws for the power of the two checks")
    ap.add_argument("specimen")
    ap.add_argument("test")
    ap.add_argument("stresses")
    a = ap.parse_args()
    n, t = class_sizes(a.specimen, a.test)
    rows = clumpkit_csv.rows(os.path.join(a.test, "curve.csv"))
    print("particles by class (mid diameter mm): %s" % ", ".join("%d (%.1f)" % (ni, ti * 1e3) for ni, ti in zip(n, t)))
    rng = random.Random(1)
    for s in a.stresses.split(","):
        row = rows[-1] if s == "end" else next((r for r in rows if float(r["axial_stress"]) >= float(s)), rows[-1])
        k = [round(float(row["broken_class_%d" % (i + 1)]) * ni) for i, ni in enumerate(n)]
        z, p = trend(k, n, t)
        overall = sum(k) / sum(n)
        line = "sigma_v %.3g MPa: broken %s, trend z %.2f (one-sided p %.3f)" % (
            float(row["axial_stress"]) / 1e6, "/".join(map(str, k)), z, p)
        if 0 < overall < 1:
            w = weibull_fractions(overall, n, t, a.alpha_m)
            line += "; Weibull (alpha m %.2f): %s" % (a.alpha_m, ", ".join("%.2f" % v for v in w))
            if a.power:
                rising = significant = 0
                for _ in range(a.power):
                    kk = [sum(rng.random() < wi for _ in range(ni)) for wi, ni in zip(w, n)]
                    f = [ki / ni for ki, ni in zip(kk, n)]
                    rising += all(y > x for x, y in zip(f, f[1:]))
                    significant += trend(kk, n, t)[1] < 0.05
                line += "; every class above the last in %.0f %%, p < 0.05 in %.0f %% of %d draws" % (
                    100 * rising / a.power, 100 * significant / a.power, a.power)
        print(line)


if __name__ == "__main__":
    main()
