// Primitive closed meshes: box, icosphere and ellipsoid, for tests and simple particles.
#pragma once

#include "geom/mesh/mesh.h"

namespace clumpkit {

/// Axis-aligned box with edge lengths `size`, centred at the origin; 12 outward triangles.
Mesh make_box(const Vec3& size);

/// Unit-radius icosphere: an icosahedron whose triangles are split in four `level` times,
/// vertices pushed to the sphere. 20·4^level triangles.
Mesh make_icosphere(int level);

/// Ellipsoid with semi-axes (a, b, c) along x, y, z: a scaled icosphere of the given level.
Mesh make_ellipsoid(const Vec3& semi_axes, int level = 4);

}  // namespace clumpkit
