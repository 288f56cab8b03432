// A bounded convex polyhedron as the intersection of half-spaces n·x ≤ h, by polar duality.
#pragma once

#include "geom/mesh/mesh.h"

#include <vector>

namespace clumpkit {

/// The half-space n·x ≤ offset (n need not be unit).
struct Halfspace {
  Vec3 normal;
  double offset = 0.0;
};

/// Intersection of the half-spaces as a closed, outward-oriented convex triangle mesh. `interior`
/// must lie strictly inside every half-space and the intersection must be bounded (a caller's
/// promise: the parent's own planes, say). About the interior point p each plane maps to the
/// dual point n/(h − n·p); each facet of the dual points' hull is a corner where its three planes
/// meet, solved from them in index order so that the result does not depend on how the hull
/// code orders its work; redundant planes fall inside the dual hull. Throws InvalidInput when p
/// is not strictly inside a half-space.
Mesh intersect_halfspaces(const std::vector<Halfspace>& halfspaces, const Vec3& interior);

}  // namespace clumpkit
