# %% [markdown]
# # clumpkit in a notebook: fill a rock, weigh the clump exactly, plot coverage against spheres
#
# Cells in the percent format (VS Code, Spyder, Jupytext open it as a notebook); as a script:
#
#     PYTHONPATH=build/python python3 examples/notebook.py [coverage.png]
#
# Lengths in metres, density in kg/m³.

# %%
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import clumpkit

# %% A rock block of Jin et al. 2017 (L, W, H; edges split in Nd = 3) and its descriptors
rock = clumpkit.block(0.040, 0.030, 0.020, nd=3, seed=7)
d = clumpkit.describe(rock)
print(f"block: volume {d.volume * 1e6:.3f} cm³, sphericity {d.sphericity:.3f}, "
      f"weighted roundness {d.weighted_roundness:.3f}")

# %% Fill it with 200 spheres; the fill's coverage after each sphere comes with the clump
clump = clumpkit.fill(rock, spheres=200)
print(f"{len(clump)} spheres, covered {clump.fidelity.covered_fraction:.4f}, "
      f"overshoot {clump.fidelity.overshoot_fraction:.4f}")

# %% Exact mass properties of the union (overlaps counted once) against the rock's
exact = clumpkit.mass_properties(clump.centres, clump.radii, density=2650.0)
naive = 2650.0 * 4.0 / 3.0 * np.pi * np.sum(clump.radii ** 3)
print(f"clump mass {exact.mass * 1e3:.3f} g (the sum of the spheres: {naive * 1e3:.3f} g), "
      f"rock {2650.0 * d.volume * 1e3:.3f} g; principal moments {exact.principal_moments}")

# %% Coverage against sphere count
fig, ax = plt.subplots(figsize=(5, 3.5))
ax.plot(np.arange(1, len(clump) + 1), clump.coverage_curve)
ax.set_xscale("log")
ax.set_xlabel("spheres")
ax.set_ylabel("covered fraction of the rock")
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
out = sys.argv[1] if len(sys.argv) > 1 else "coverage.png"
fig.savefig(out, dpi=120)
print("wrote", out)
