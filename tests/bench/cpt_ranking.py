#!/usr/bin/env python3
"""CTGU 2017's ranking of the CPT groups with its realisation noise: per group the mean residual
e(X, A) over seeds with a 90 % bootstrap interval (seeds resampled with replacement), the paired
differences C − D and B − E (the paper: D closer to A than C, E closer than B) with theirs, and,
where an interval does not exclude 0, the number of seeds that would make it (normal approximation
n = (1.645 s / |mean|)²).

    tests/bench/cpt_ranking.py [--clumpkit BIN] [--from DEPTH] [--residuals CSV] [DIR ...]

DIR: folders written by tests/bench/cpt_groups.sh (X{seed}-test/curve.csv, Aprime{seed}-test/...);
each seed found there with A and another group counts, e(X, A) from `clumpkit compare-curves A X
--x depth_m --y qc_pa --points 200 [--from DEPTH]` (residual_rel). --residuals adds recorded
residuals (CSV seed,group,from_m,e_rel: pushes whose curves are gone, such as
tests/bench/cpt_residuals_recorded.csv, seeds 1–3 of RESULTS.md), the rows of the same --from used
as given. Writes a Markdown
table and the verdicts on stdout; --json FILE also writes them as JSON.
"""
import argparse
import csv
import glob
import json
import math
import os
import random
import re
import subprocess
import sys

GROUPS = ["B", "C", "D", "E", "Aprime"]
PAIRS = [("C", "D"), ("B", "E")]  # CTGU 2017: the second of each pair is closer to A
BOOTSTRAP = 20000
Z90 = 1.6449


def residual(binary, a, b, start):
    cmd = [binary, "compare-curves", a, b, "--x", "depth_m", "--y", "qc_pa", "--points", "200",
           "--json"]
    if start > 0:
        cmd += ["--from", repr(start)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return json.loads(out)["residual_rel"]


def from_folders(binary, folders, start):
    """{(seed, group): e} from the curves of cpt_groups.sh's folders."""
    found = {}
    for folder in folders:
        for a in glob.glob(os.path.join(folder, "A[0-9]*-test", "curve.csv")):
            seed = int(re.match(r"A(\d+)-test", os.path.basename(os.path.dirname(a))).group(1))
            for g in GROUPS:
                b = os.path.join(folder, f"{g}{seed}-test", "curve.csv")
                if os.path.exists(b):
                    found[(seed, g)] = residual(binary, a, b, start)
    return found


def from_table(path):
    with open(path) as f:
        return {(int(r["seed"]), r["group"], float(r["from_m"])): float(r["e_rel"])
                for r in csv.DictReader(f)}


def mean(xs):
    return sum(xs) / len(xs)


def sd(xs):
    m = mean(xs)
    return math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else float("nan")


def interval(xs, rng):
    """90 % percentile interval of the mean over seeds resampled with replacement."""
    means = sorted(mean([rng.choice(xs) for _ in xs]) for _ in range(BOOTSTRAP))
    return means[int(0.05 * BOOTSTRAP)], means[int(0.95 * BOOTSTRAP) - 1]


def seeds_needed(xs):
    """Seeds for a 90 % interval of the mean of xs to exclude 0 (normal approximation)."""
    m, s = mean(xs), sd(xs)
    if len(xs) < 2 or m == 0 or math.isnan(s):
        return None
    return max(len(xs), math.ceil((Z90 * s / abs(m)) ** 2))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("folders", nargs="*")
    p.add_argument("--clumpkit", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "../../build/io/clumpkit"))
    p.add_argument("--from", dest="start", type=float, default=0.0,
                   help="depth [m] where the residual starts (0: the surface)")
    p.add_argument("--residuals", help="CSV seed,group,from_m,e_rel of recorded residuals")
    p.add_argument("--json", help="also write the results here")
    args = p.parse_args()
    e = from_folders(args.clumpkit, args.folders, args.start)
    if args.residuals:
        for (seed, group, start), value in from_table(args.residuals).items():
            if start == args.start:
                e.setdefault((seed, group), value)
    rng = random.Random(2017)  # the bootstrap is part of the result: same numbers every run
    result = {"from_m": args.start, "groups": {}, "pairs": {}}
    print(f"Residual_rel e(X, A) from {args.start} m; 90 % bootstrap intervals over seeds "
          f"({BOOTSTRAP} resamples)\n")
    print("| group | seeds | e per seed | mean | 90 % interval |")
    print("|---|---|---|---|---|")
    for g in GROUPS:
        seeds = sorted(s for (s, h) in e if h == g)
        if not seeds:
            continue
        xs = [e[(s, g)] for s in seeds]
        lo, hi = interval(xs, rng)
        result["groups"][g] = {"seeds": seeds, "e": xs, "mean": mean(xs), "interval": [lo, hi]}
        name = "A′ (floor)" if g == "Aprime" else g
        print(f"| {name} | {' '.join(map(str, seeds))} | {' '.join(f'{x:.3f}' for x in xs)} | "
              f"{mean(xs):.3f} | [{lo:.3f}, {hi:.3f}] |")
    print("\n| pair | seeds | mean of e(first) − e(second) | 90 % interval | group intervals | verdict | seeds for 90 % |")
    print("|---|---|---|---|---|---|---|")
    for a, b in PAIRS:
        seeds = sorted(s for (s, h) in e if h == a and (s, b) in e)
        if len(seeds) < 2:
            continue
        d = [e[(s, a)] - e[(s, b)] for s in seeds]
        lo, hi = interval(d, rng)
        ga, gb = result["groups"][a]["interval"], result["groups"][b]["interval"]
        apart = ga[1] < gb[0] or gb[1] < ga[0]
        if lo > 0:
            verdict = f"{b} closer to A than {a} (CTGU 2017's order)"
        elif hi < 0:
            verdict = f"{a} closer to A than {b} (against CTGU 2017)"
        else:
            verdict = "not separated: the interval holds 0"
        need = seeds_needed(d) if lo <= 0 <= hi else len(seeds)
        result["pairs"][f"{a}-{b}"] = {"seeds": seeds, "differences": d, "mean": mean(d),
                                       "interval": [lo, hi], "group_intervals_apart": apart,
                                       "verdict": verdict, "seeds_needed": need}
        print(f"| {a} − {b} | {len(seeds)} | {mean(d):+.3f} | [{lo:+.3f}, {hi:+.3f}] | "
              f"{'apart' if apart else 'overlap'} | {verdict} | {need} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
    return 0 if e else 1


if __name__ == "__main__":
    sys.exit(main())
