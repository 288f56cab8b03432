// The closed shells of a mesh as one solid read by orientation: components, nesting, crossings.
#pragma once

#include "geom/mesh/mesh.h"

#include <string>
#include <vector>

namespace clumpkit {

/// One connected component of a mesh's triangles (joined through shared vertices).
struct Shell {
  std::vector<int> triangles;  ///< indices into mesh.triangles
  double volume = 0;           ///< signed: positive when it faces outward
  int depth = 0;               ///< how many other shells enclose it
  int parent = -1;             ///< the smallest shell that encloses it (-1: none)
};

/// The shells of `mesh`, in the order of their first triangle. Depth and parent come from the
/// winding number of one vertex of each shell against every other shell whose box holds it, so
/// they are right for shells that do not cross each other.
std::vector<Shell> mesh_shells(const Mesh& mesh);

/// Winding number of the closed surface made of `triangles` of `mesh` about `p` (the sum of
/// the triangles' solid angles over 4π, Van Oosterom & Strackee 1983): ±1 inside (the sign of
/// its orientation), 0 outside.
double winding_number(const Mesh& mesh, const std::vector<int>& triangles, const Vec3& p);

/// Reads the shells of a closed manifold mesh as one solid by their orientation, the way the
/// volume, the fill's ray parity and the fidelity report all see it: shells at depth 0 face
/// outward, a shell inside one shell faces inward (a void), a shell inside a void outward (an
/// island), and so on. Shells at depth 0 that face inward are flipped (returns true when any
/// was); `shells` (if given) receives their number. Throws InvalidInput, naming the shells
/// (counting from 1, in file order), for two shells whose surfaces cross or touch (CGAL PMP
/// do_intersect; their overlap would count twice) other than at corners they have at one
/// position (lobes touching along an edge or at a vertex overlap nowhere: their volumes add) and
/// for a nested shell that faces the same way as its parent (a solid inside a solid).
bool orient_shells(Mesh& mesh, std::size_t* shells = nullptr);

}  // namespace clumpkit
