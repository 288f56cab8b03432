#!/usr/bin/env python3
"""The oedometer figures of crushable specimens at chosen vertical stresses: void ratio, bonds and
particles broken, Hardin's Br, Einav's B, Marsal's Bg, the input work and the broken fraction of
each size class, read at the first curve row at or above each stress (rows every record_every
steps), then each folder's compression index and yield stress (report.json) and, for a pair,
their ratios.
    tests/bench/oedometer_breakage.py STRESSES_MPA TEST_DIR [TEST_DIR ...]
STRESSES_MPA is a comma-separated list (e.g. 1.6,3.2,6.4,16); each TEST_DIR a `clumpkit test
oedometer` folder of a crushable specimen (or of its unbreakable control).
"""
import clumpkit_csv
import json
import os
import sys


def table(folder, stresses):
    rows = clumpkit_csv.rows(os.path.join(folder, "curve.csv"))
    print(f"{folder}:")
    print("  sv_MPa  e       bonds  particles  Br        B         Bg        W_kJ/m3  by class")
    for s in stresses:
        row = next((r for r in rows if float(r["axial_stress"]) >= s * 1e6), None)
        if row is None:
            print(f"  {s:6.3g}  (not reached: top {max(float(r['axial_stress']) for r in rows) / 1e6:.4g} MPa)")
            continue
        n = float(row["porosity"])
        classes = " ".join(f"{float(row[f'broken_class_{c}']):.3f}" for c in range(1, 5))
        print(f"  {float(row['axial_stress']) / 1e6:6.3f}  {n / (1 - n):.4f}  "
              f"{int(float(row['bonds_broken'])):5d}  {int(float(row['particles_broken'])):9d}  "
              f"{float(row['hardin_br']):.3e} {float(row['einav_b']):.3e} "
              f"{float(row['marsal_bg']):.3e} {float(row['work']) / 1e3:8.2f}  {classes}")
    with open(os.path.join(folder, "report.json")) as f:
        rep = json.load(f)
    return rep.get("compression_index"), rep.get("yield_stress")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    stresses = [float(s) for s in sys.argv[1].split(",")]
    found = []
    for folder in sys.argv[2:]:
        cc, sy = table(folder, stresses)
        found.append((folder, cc, sy))
        print(f"  compression index (last decade) {cc}, yield stress {sy} Pa")
    if len(found) == 2 and all(x[1] and x[2] for x in found):
        (a, cca, sya), (b, ccb, syb) = found
        print(f"Cc {a} / {b} = {cca / ccb:.3f}; yield stress {a} / {b} = {sya / syb:.3f}")


if __name__ == "__main__":
    main()
