// CGAL-backed mesh operations: convex hull, self-intersection test, outward re-orientation.
#pragma once

#include "geom/mesh/mesh.h"

#include <vector>

namespace clumpkit {

/// Convex hull of a point set as an outward-oriented triangle mesh (the hull facets of a CGAL
/// Triangulation_3 of the points; exact predicates). Coplanar hull points are all kept.
/// Throws InvalidInput if the points span less than three dimensions.
Mesh convex_hull(const std::vector<Vec3>& points);

/// True if any two non-adjacent triangles intersect (CGAL PMP::does_self_intersect).
bool self_intersects(const Mesh& mesh);

/// Makes the orientation of a closed manifold mesh consistent and outward (CGAL PMP
/// orient_polygon_soup + orient_to_bound_a_volume). Returns true if any triangle was flipped.
/// Throws InvalidInput when that needs duplicated vertices (not manifold) or when the closed
/// surface intersects itself.
bool orient_outward(Mesh& mesh);

}  // namespace clumpkit
