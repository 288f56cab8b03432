#!/usr/bin/env python3
"""Compares two sets of a `clumpkit crush` run: the ratio of their Weibull σ0 (least squares on
ln ln(1/Ps), Ps = 1 − i/(N+1), as report.json) and the one-sided bootstrap probability that the
first is weaker, P(σ0,A < σ0,B), from independent resamples of each set's strengths.
    tests/bench/crush_compare.py DIR SET_A SET_B [RESAMPLES]
"""
import csv
import math
import random
import sys


def sigma0(strengths):
    s = sorted(strengths)
    n = len(s)
    x = [math.log(v) for v in s]
    y = [math.log(math.log(1.0 / (1.0 - (i + 1) / (n + 1)))) for i in range(n)]
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    if sxx == 0:
        return None
    m = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx
    return math.exp(mx - my / m)


def main():
    out, a, b = sys.argv[1], sys.argv[2], sys.argv[3]
    resamples = int(sys.argv[4]) if len(sys.argv) > 4 else 2000
    sets = {}
    with open(f"{out}/results.csv") as f:
        for row in csv.DictReader(f):
            if row["failed"] == "1":
                sets.setdefault(row["set"], []).append(float(row["strength_pa"]))
    sa, sb = sets[a], sets[b]
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
    print(f"{a}: sigma0 {s0a / 1e6:.3f} MPa ({len(sa)} samples); {b}: sigma0 {s0b / 1e6:.3f} MPa "
          f"({len(sb)}); ratio {s0a / s0b:.3f}; P({a} < {b}) = {below / resamples:.3f}")


if __name__ == "__main__":
    main()
