// Shells of a closed surface that pass through each other joined into their union.
#pragma once

#include "geom/mesh/mesh.h"

namespace clumpkit {

/// Joins the shells of a closed manifold `mesh` that cross each other into one by their union
/// (CGAL PMP corefine_and_compute_union, exact predicates): two closed spheres through each
/// other become the surface of their union, the lens counted once. A group of crossing shells
/// is left as it is (for the wrap) when one of them crosses itself or faces inward (a void),
/// or when the union fails. Returns the number of shells that were
/// joined into another.
int unite_crossing_shells(Mesh& mesh);

}  // namespace clumpkit
