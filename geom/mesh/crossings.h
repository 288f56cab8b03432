// Crossing faces of a closed surface: found, split by shell, and mended locally inside a shell.
#pragma once

#include "geom/mesh/mesh.h"

#include <vector>

namespace clumpkit {

/// The pairs of faces of a closed mesh that cross, split by where they lie. Faces that only touch
/// at corners they have at one position (the copies of a vertex split between two shells) do not
/// count.
struct Crossings {
  int within_shells = 0;      ///< pairs whose faces lie on one shell (folds, a patch through it)
  int between_shells = 0;     ///< pairs on two shells (shells through each other)
  Vec3 first = Vec3::Zero();  ///< centroid of a face of the first pair (when there is one)
  int total() const { return within_shells + between_shells; }
};

/// Finds the crossings of `mesh` (CGAL PMP self_intersections, filtered by faces_only_touch).
/// Shells are the components joined through shared vertices (mesh_shells).
Crossings find_crossings(const Mesh& mesh);

/// One round of the local mend on one shell: the crossing pairs before and after.
struct CrossingRound {
  int shell = 0;  ///< counting from 1, in the order of the shells' first triangles
  int pairs_before = 0, pairs_after = 0;
};

/// Removes the crossings within each shell of a closed manifold `mesh` locally, in rounds of
/// CGAL 5.5 PMP experimental::remove_self_intersections (the crossing faces and a few rings
/// around them removed, then the region smoothed or its hole refilled), repeated while a round
/// shrinks the shell's crossings, at most `max_rounds` rounds a shell. Shells without crossings
/// of their own are left as they are, and the shells' crossings with each other are not looked
/// at (unite_crossing_shells' job). Returns the rounds run, in order.
std::vector<CrossingRound> mend_crossings_locally(Mesh& mesh, int max_rounds = 4);

}  // namespace clumpkit
