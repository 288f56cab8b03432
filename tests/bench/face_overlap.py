#!/usr/bin/env python3
"""How much of a crushable specimen's compression is its cells overlapping across their faces.

A bonded cell pair in compression is held by the cohesive law's normal stiffness alone (Hu et al.
2023: no damage in compression), so the two rigid cells overlap by the compressive opening over
the face. The void ratio of `clumpkit test` (the laboratory's: solid volume = mass / density)
counts that volume as solid twice. This script measures it at the end of a test:

    overlap V_o = sum over the bonds' integration points of area * max(0, -opening)

with the opening measured along the bond normal between the point as carried by cell a and as
carried by cell b, the cells' poses fitted (Kabsch) to their spheres in fragments.vtp. Points
whose two carried positions have slid apart by more than --slide (default 1 mm) along the face
are left out: their cells no longer face each other there. It prints, per test folder, the last
row's vertical stress and void ratio e, V_o over the cells' volume, and the void ratio on the
cells' union e_u = (1 + e) / (1 - V_o / V_s) - 1; with several folders, the slope of e and of
e_u against log10(sigma_v) between consecutive ones (folders of one specimen, in stress order).

    tests/bench/face_overlap.py [--slide M] SPECIMEN_DIR TEST_DIR [TEST_DIR ...]

SPECIMEN_DIR holds the specimen.csv and bonds.csv the tests started from. Needs python3-numpy.
"""
import argparse
import clumpkit_csv
import math
import os
import sys

import numpy as np


def read_specimen(path):
    """Bodies' positions, rotation matrices and volumes; spheres' bodies (from 0) and centres."""
    with open(path) as f:
        lines = f.read().split("\n")
    k = lines.index("# spheres")
    bodies = [l.split(",") for l in lines[4:k] if l.strip()]
    pos = np.array([[float(v) for v in b[3:6]] for b in bodies])
    quat = np.array([[float(v) for v in b[6:10]] for b in bodies])
    vol = np.array([float(b[11]) for b in bodies])
    sph = np.array([[float(v) for v in l.split(",")] for l in lines[k + 2:] if l.strip()])
    return pos, np.array([rotation(q / np.linalg.norm(q)) for q in quat]), vol, sph[:, 1].astype(int) - 1, sph[:, 2:5]


def rotation(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def read_bonds(path):
    """Per integration point: cell a, cell b, normal in a's frame, point in a's and b's frame, area."""
    with open(path) as f:
        lines = f.read().split("\n")
    kb, kp = lines.index("# bonds"), lines.index("# points")
    bonds = np.array([[float(v) for v in l.split(",")] for l in lines[kb + 2:kp] if l.strip()])
    pts = np.array([[float(v) for v in l.split(",")] for l in lines[kp + 2:] if l.strip()])
    i = pts[:, 0].astype(int) - 1
    return (bonds[i, 1].astype(int) - 1, bonds[i, 2].astype(int) - 1, bonds[i, 3:6], pts[:, 1:4],
            pts[:, 4:7], pts[:, 7])


def vtp_array(text, name):
    """The values of fragments.vtp's data array `name` ("Points" for the sphere centres), as text."""
    i = text.find("<DataArray", text.find("<Points>")) if name == "Points" else text.find('Name="%s"' % name)
    if i < 0:
        sys.exit("fragments.vtp: no array %s" % name)
    i = text.find(">", i) + 1
    return text[i:text.find("</DataArray>", i)].split()


def fitted_poses(local, body, x, n):
    """Each body's rotation and translation carrying its spheres' body-frame centres to x."""
    rot, trans = np.zeros((n, 3, 3)), np.zeros((n, 3))
    order = np.argsort(body, kind="stable")
    start = np.searchsorted(body[order], np.arange(n + 1))
    for b in range(n):
        idx = order[start[b]:start[b + 1]]
        p, q = local[idx], x[idx]
        pc, qc = p.mean(0), q.mean(0)
        u, _, vt = np.linalg.svd((p - pc).T @ (q - qc))
        d = np.sign(np.linalg.det(vt.T @ u.T))
        rot[b] = vt.T @ np.diag([1, 1, d]) @ u.T
        trans[b] = qc - rot[b] @ pc
    return rot, trans


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--slide", type=float, default=1e-3, help="face slide (m) beyond which a point is left out")
    ap.add_argument("specimen")
    ap.add_argument("tests", nargs="+")
    a = ap.parse_args()
    pos, rot0, vol, sbody, sx = read_specimen(os.path.join(a.specimen, "specimen.csv"))
    ba, bb, normal, pa_local, pb_local, area = read_bonds(os.path.join(a.specimen, "bonds.csv"))
    local = np.einsum("nji,nj->ni", rot0[sbody], sx - pos[sbody])
    rows = []
    for folder in a.tests:
        with open(os.path.join(folder, "fragments.vtp")) as f:
            text = f.read()
        x = np.array(vtp_array(text, "Points"), float).reshape(-1, 3)
        if not np.array_equal(np.array(vtp_array(text, "body"), int) - 1, sbody):
            sys.exit("%s/fragments.vtp: spheres not those of %s/specimen.csv" % (folder, a.specimen))
        rot, trans = fitted_poses(local, sbody, x, len(vol))
        pa = np.einsum("nij,nj->ni", rot[ba], pa_local) + trans[ba]
        pb = np.einsum("nij,nj->ni", rot[bb], pb_local) + trans[bb]
        nrm = np.einsum("nij,nj->ni", rot[ba], normal)
        gap = pb - pa
        opening = np.einsum("ni,ni->n", gap, nrm)
        slide = np.linalg.norm(gap - opening[:, None] * nrm, axis=1)
        kept = slide < a.slide
        fraction = float((area * np.maximum(0.0, -opening))[kept].sum() / vol.sum())
        last = clumpkit_csv.rows(os.path.join(folder, "curve.csv"))[-1]
        sv, n = float(last["axial_stress"]), float(last["porosity"])
        e = n / (1 - n)
        eu = (1 + e) / (1 - fraction) - 1
        rows.append((sv, e, eu))
        print("%s: sigma_v %.4g MPa, e %.4f, face overlap %.4f of the cells (%d of %d points kept), e_u %.4f"
              % (folder, sv / 1e6, e, fraction, kept.sum(), len(kept), eu))
    for (s0, e0, u0), (s1, e1, u1) in zip(rows, rows[1:]):
        d = math.log10(s1 / s0)
        print("%.4g -> %.4g MPa: slope of e %.4f, of e_u %.4f per decade" % (s0 / 1e6, s1 / 1e6, (e0 - e1) / d, (u0 - u1) / d))


if __name__ == "__main__":
    main()
