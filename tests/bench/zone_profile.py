#!/usr/bin/env python3
"""Porosity against the zone coordinate of a radially zoned specimen (a cylinder or a segment
about the z-axis): the solid in annuli of width --bin, counted only at points --margin or more
from every wall, by sampling each sphere with --samples points (Monte Carlo; overlaps count
twice, which a compressed specimen's 0.1 % overlaps make negligible), over the annulus volume
that the same margin leaves (sampled too).

    PYTHONPATH=build/python python3 tests/bench/zone_profile.py SPECIMEN_DIR [--margin 0.012]
        [--bin 0.0025]

Prints one line per annulus: inner and outer radius (mm), porosity. Reads the specimen with the
clumpkit module (scripts/test builds it into build/python).
"""
import argparse
import json
import math

import clumpkit
import numpy as np


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("specimen")
    p.add_argument("--margin", type=float, default=0.012, help="m from every wall (default 0.012)")
    p.add_argument("--bin", type=float, default=0.0025, help="annulus width, m (default 0.0025)")
    p.add_argument("--samples", type=int, default=3000, help="points per sphere (default 3000)")
    a = p.parse_args()
    c = json.load(open(f"{a.specimen}/report.json"))["container"]
    if c["shape"] not in ("cylinder", "segment"):
        raise SystemExit(f"{a.specimen}/report.json: container.shape: {c['shape']} is not radial")
    R, H, m = 0.5 * c["diameter"], c["height"], a.margin
    angle = math.radians(c.get("angle_deg", 360.0))

    def kept(x, y, z):  # at least the margin from floor, top, outer wall and radial walls
        ok = (z > m) & (z < H - m) & (np.hypot(x, y) < R - m)
        if c["shape"] == "segment":  # planes φ = 0 and φ = angle
            ok &= (y > m) & (np.sin(angle) * x - np.cos(angle) * y > m)
        return ok

    rng = np.random.default_rng(1)
    edges = np.arange(0.0, R + 1e-12, a.bin)
    solid = np.zeros(len(edges) - 1)
    s = clumpkit.read_specimen(a.specimen)
    for (x0, y0, z0), r0 in zip(s["sphere_centres"], s["sphere_radii"]):
        u = rng.normal(size=(a.samples, 3))
        u *= (r0 * rng.random(a.samples) ** (1 / 3) / np.linalg.norm(u, axis=1))[:, None]
        x, y, z = x0 + u[:, 0], y0 + u[:, 1], z0 + u[:, 2]
        ok = kept(x, y, z)
        solid += np.histogram(np.hypot(x[ok], y[ok]), edges)[0] * (4 / 3 * math.pi * r0**3 /
                                                                    a.samples)
    n = 4_000_000  # the annuli's kept volume: points in the box [−R, R]² × [0, H]
    x, y, z = rng.uniform(-R, R, n), rng.uniform(-R, R, n), rng.uniform(0, H, n)
    ok = kept(x, y, z)
    volume = np.histogram(np.hypot(x[ok], y[ok]), edges)[0] * (4 * R * R * H / n)
    for lo, hi, s, v in zip(edges[:-1], edges[1:], solid, volume):
        if v > 0:
            print(f"{1000 * lo:6.1f} {1000 * hi:6.1f} mm  n = {1 - s / v:.4f}")


if __name__ == "__main__":
    main()
