# clumpkit in a Yade script: a few rock blocks generated and filled with spheres by clumpkit,
# appended to a Yade simulation as clumps that carry clumpkit's exact mass and principal moments
# (Yade's own clump masses count the members' overlaps by a grid), then dropped on a floor.
#
#   PYTHONPATH=build/python yade -n -x examples/yade_clumps.py [nsteps (100)]
#
# Yade runs its own interpreter (Debian's python3), which finds the module on PYTHONPATH: the
# build tree's build/python, or nothing to set once `pip install .` has put it in site-packages.
# Exit status 0 when every clump's state.mass and principal state.inertia equal clumpkit's to
# 1e-9 after the steps; 1 otherwise.
import math
import os
import sys

import numpy as np

import clumpkit
from yade import utils

NSTEPS = int(sys.argv[1]) if len(sys.argv) > 1 else 100
RHO = 2650.0  # kg/m³, granite
material = O.materials.append(FrictMat(young=5e7, poisson=0.3, frictionAngle=math.atan(0.5),
                                       density=RHO))


def matched_moments(yade_ori, axes, moments):
    """Our principal moments, each on the Yade clump axis nearest our principal axis: Yade puts
    a clump in the principal frame of its own (grid) inertia, a few degrees from the exact one."""
    theirs = yade_ori.toRotationMatrix()
    theirs = np.array([[theirs[i, k] for k in range(3)] for i in range(3)])
    best, best_cos = None, -1.0
    for p in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        worst = min(abs(theirs[:, k].dot(axes[:, p[k]])) for k in range(3))
        if worst > best_cos:
            best, best_cos = p, worst
    return Vector3(*(moments[best[k]] for k in range(3)))


clumps = []
for i in range(4):
    rock = clumpkit.block(0.04, 0.03, 0.02, seed=i + 1)  # metres
    clump = clumpkit.fill(rock, spheres=30)
    exact = clumpkit.mass_properties(clump.centres, clump.radii, density=RHO)
    centres = clump.centres - exact.centroid + np.array([0.06 * i, 0.0, 0.05])
    cid, _ = O.bodies.appendClumped(
        [utils.sphere(Vector3(*c), r, material=material) for c, r in zip(centres, clump.radii)],
        discretization=30)
    state = O.bodies[cid].state
    state.mass = exact.mass
    state.inertia = matched_moments(state.ori, exact.principal_axes, exact.principal_moments)
    clumps.append((cid, exact))
O.bodies.append(utils.wall((0, 0, 0), axis=2, sense=1, material=material))

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(damping=0.3, gravity=(0, 0, -9.81)),
]
O.dt = 0.5 * utils.PWaveTimeStep()
O.run(NSTEPS, True)

worst = 0.0
for cid, exact in clumps:
    state = O.bodies[cid].state
    worst = max(worst, abs(state.mass - exact.mass) / exact.mass)
    ours = sorted(exact.principal_moments)
    theirs = sorted(state.inertia[k] for k in range(3))
    worst = max(worst, max(abs(a - b) / a for a, b in zip(theirs, ours)))
    print("clump %d: mass %.9g kg, moments %s kg m², fell to z = %.4f m"
          % (cid, state.mass, ", ".join("%.6g" % m for m in theirs), state.pos[2]))
ok = worst <= 1e-9 and O.iter == NSTEPS
print("clumpkit example: %d clumps after %d steps, largest relative difference from clumpkit's "
      "mass properties %.3g: %s" % (len(clumps), O.iter, worst, "ok" if ok else "FAILED"))
sys.stdout.flush()
os._exit(0 if ok else 1)
