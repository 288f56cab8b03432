#!/usr/bin/env python3
"""The ends of an oedometer's holds ([test] hold_stresses), side by side for several runs: at each
hold the axial stress, strain, void ratio, whether it ended at equilibrium, Hardin's Br, Einav's
B and Marsal's Bg (crushable specimens), then each run's compression index and yield stress from
the holds (report.json compression_index_held, yield_stress_held) and from the continuous curve.
With two runs, the second's relative difference from the first on each figure.
    tests/bench/oedometer_holds.py TEST_DIR [TEST_DIR ...]
Each TEST_DIR a `clumpkit test oedometer` folder run with hold_stresses.
"""
import json
import os
import sys


def load(folder):
    with open(os.path.join(folder, "report.json")) as f:
        r = json.load(f)
    if "holds" not in r:
        sys.exit(f"{folder}: report.json has no holds (run with [test] hold_stresses)")
    return r


def rel(a, b):
    return (b - a) / a if a else float("nan")


def main():
    folders = sys.argv[1:]
    if not folders:
        sys.exit(__doc__)
    reports = [load(f) for f in folders]
    for folder, r in zip(folders, reports):
        print(f"{folder}: {r['steps']} loading steps, lambda {r.get('density_scaling', '?')}, "
              f"I held {r.get('inertial_number_held', 'off')}")
        print("  sv_MPa   strain   e        eq  Br        B         Bg")
        for h in r["holds"]:
            print(f"  {h['axial_stress'] / 1e6:7.3f}  {h['axial_strain']:.4f}  {h['void_ratio']:.4f}"
                  f"  {'y' if h['equilibrium'] else 'n'}   {h.get('hardin_br', 0):.3e} "
                  f"{h.get('einav_b', 0):.3e} {h.get('marsal_bg', 0):.3e}")
        print(f"  held: Cc {r['compression_index_held']}, yield {r['yield_stress_held']} Pa; "
              f"curve: Cc {r['compression_index']}, yield {r['yield_stress']} Pa")
    if len(reports) == 2:
        a, b = reports
        print(f"{folders[1]} against {folders[0]} (relative):")
        for ha, hb in zip(a["holds"], b["holds"]):
            line = f"  {ha['axial_stress'] / 1e6:7.3f} MPa: e {rel(ha['void_ratio'], hb['void_ratio']):+.4f}"
            if "hardin_br" in ha:
                line += (f", Br {rel(ha['hardin_br'], hb['hardin_br']):+.4f}"
                         f", B {rel(ha['einav_b'], hb['einav_b']):+.4f}"
                         f", Bg {rel(ha['marsal_bg'], hb['marsal_bg']):+.4f}")
            print(line)
        for key in ("compression_index_held", "yield_stress_held", "compression_index",
                    "yield_stress"):
            print(f"  {key}: {b[key] / a[key]:.4f} x")


if __name__ == "__main__":
    main()
