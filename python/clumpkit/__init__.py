"""clumpkit from Python: irregular particles, clumps of spheres with exact mass properties, and
DEM specimens, with NumPy arrays in and out.

    import clumpkit
    rock = clumpkit.block(L=0.04, W=0.03, H=0.02, seed=7)
    clump = clumpkit.fill(rock, spheres=100)
    props = clumpkit.mass_properties(clump.centres, clump.radii, density=2650.0)

Lengths are in the units of the input (meshes, spheres) or SI (recipes, specimens). Bad input
raises ValueError with the library's message, file trouble OSError; Ctrl-C stops long calls
(KeyboardInterrupt), leaving on disk what the command line leaves.
"""

from ._core import (  # noqa: F401
    __commit__,
    __version__,
    Clump,
    Descriptors,
    Fidelity,
    MassProperties,
    Mesh,
    block,
    box,
    cylinder,
    describe,
    ellipsoid,
    fill,
    hull,
    library,
    mass_properties,
    polyhedron,
    read_mesh,
    read_specimen,
    specimen,
    volume,
)

__all__ = [
    "Clump", "Descriptors", "Fidelity", "MassProperties", "Mesh", "block", "box", "cylinder",
    "describe", "ellipsoid", "fill", "hull", "library", "mass_properties", "polyhedron",
    "read_mesh", "read_specimen", "specimen", "volume",
]
