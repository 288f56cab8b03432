// Primitive closed meshes: box, cylinder, icosphere, ellipsoid, octahedron and torus, for tests,
// benchmarks, simple particles and test specimens (the Brazilian disc).
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/range.h"

namespace clumpkit {

/// Axis-aligned box with edge lengths `size`, centred at the origin; 12 outward triangles.
Mesh make_box(const Vec3& size);

/// The sides make_cylinder takes (and a crushing recipe's cylinders).
inline constexpr Range kCylinderSides = integers(3, 100000);
/// The sides make_torus takes around its ring and around its tube.
inline constexpr Range kTorusSides = integers(3, 10000);

/// Right prism over a regular polygon of `sides` sides inscribed in the circle of `diameter`
/// (vertex at +x), axis along z, centred at the origin: a cylinder to within
/// 1 − sin(2π/n)/(2π/n) of its volume (0.16 % at 64 sides). The caps are fans from their
/// centres. Throws InvalidInput for sizes that are not positive lengths or sides outside
/// kCylinderSides.
Mesh make_cylinder(double diameter, double height, int sides = 64);

/// Unit-radius icosphere: an icosahedron whose triangles are split in four `level` times,
/// vertices pushed to the sphere. 20·4^level triangles.
Mesh make_icosphere(int level);

/// Ellipsoid with semi-axes (a, b, c) along x, y, z: a scaled icosphere of the given level.
Mesh make_ellipsoid(const Vec3& semi_axes, int level = 4);

/// Regular octahedron with vertices at ±`radius` on each axis (volume 4/3·radius³); 8 triangles.
Mesh make_octahedron(double radius);

/// Torus about z: tube radius `tube` on a ring of radius `ring` (> tube), `ring_sides` ×
/// `tube_sides` quads split in two, vertices on the surface (the volume runs low by the
/// polygons' areas: 2π²·ring·tube² at the limit). Both sides in kTorusSides.
Mesh make_torus(double ring, double tube, int ring_sides = 96, int tube_sides = 48);

}  // namespace clumpkit
