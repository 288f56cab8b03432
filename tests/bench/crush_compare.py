#!/usr/bin/env python3
"""Compares two sets of a `clumpkit crush` run: the ratio of their Weibull σ0 (least squares on
ln ln(1/Ps) as report.json: Ps = 1 − i/(N+1), Johnson's adjusted ranks when some particles did
not fail, those entering as right-censored at the largest stress they carried) and the one-sided
bootstrap probability that the first is weaker, P(σ0,A < σ0,B), from independent resamples of
each set. When SET_B has survivors, the figures are printed again with each of SET_B's survivors
counted as a failure at its largest stress, a strength it is known to exceed: a lower bound on
SET_B's σ0, for a claim that SET_A is weaker which does not lean on the censored fit of SET_B.
    tests/bench/crush_compare.py DIR SET_A SET_B [RESAMPLES]
"""
import clumpkit_csv
import math
import random
import sys


def sigma0(samples):
    """samples: (stress, failed) pairs; None when the failures cannot be fitted."""
    s = sorted(samples, key=lambda p: (p[0], not p[1]))
    n = len(s)
    x, y, rank = [], [], 0.0
    for i, (v, failed) in enumerate(s):
        if not failed:
            continue
        reverse = n - i
        rank = (reverse * rank + n + 1) / (reverse + 1)
        x.append(math.log(v))
        y.append(math.log(math.log(1.0 / (1.0 - rank / (n + 1)))))
    if len(x) < 3:
        return None
    mx, my = sum(x) / len(x), sum(y) / len(y)
    sxx = sum((a - mx) ** 2 for a in x)
    if sxx == 0:
        return None
    m = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx
    return math.exp(mx - my / m)


def compare(a, b, sa, sb, resamples, label):
    rng = random.Random(1)
    below = done = 0
    while done < resamples:
        ra = sigma0([rng.choice(sa) for _ in sa])
        rb = sigma0([rng.choice(sb) for _ in sb])
        if ra is None or rb is None:
            continue
        done += 1
        below += ra < rb
    s0a, s0b = sigma0(sa), sigma0(sb)
    fa, fb = sum(f for _, f in sa), sum(f for _, f in sb)
    print(f"{label}{a}: sigma0 {s0a / 1e6:.3f} MPa ({fa} of {len(sa)} failed); {b}: sigma0 "
          f"{s0b / 1e6:.3f} MPa ({fb} of {len(sb)}); ratio {s0a / s0b:.3f}; "
          f"P({a} < {b}) = {below / resamples:.3f}")


def main():
    out, a, b = sys.argv[1], sys.argv[2], sys.argv[3]
    resamples = int(sys.argv[4]) if len(sys.argv) > 4 else 2000
    sets = {}
    if True:
        for row in clumpkit_csv.rows(f"{out}/results.csv"):
            d = float(row["diameter"])
            if row["failed"] == "1":
                sets.setdefault(row["set"], []).append((float(row["strength"]), True))
            elif float(row["max_force"]) > 0:
                sets.setdefault(row["set"], []).append((float(row["max_force"]) / d / d, False))
    sa, sb = sets[a], sets[b]
    compare(a, b, sa, sb, resamples, "")
    if not all(f for _, f in sb):
        compare(a, b, sa, [(v, True) for v, _ in sb], resamples,
                f"{b}'s survivors as failures: ")


if __name__ == "__main__":
    main()
