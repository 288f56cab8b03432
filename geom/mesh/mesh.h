// Triangle surface mesh: the one geometry type every shape generator and descriptor works on.
#pragma once

#include "geom/vec.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit {

/// Indexed triangle mesh. Triangles are counter-clockwise seen from outside (outward normals).
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

/// Topological and geometric health of a mesh, as checked on reading and in tests.
struct MeshCheck {
  bool closed = false;      ///< every edge is shared by exactly two triangles
  bool manifold = false;    ///< no edge is shared by more than two triangles, no vertex fan splits
  bool oriented = false;    ///< every edge is used once in each direction
  bool degenerate = false;  ///< some triangle has (near) zero area or repeated indices
  double volume = 0.0;      ///< signed volume (positive for outward orientation)
  int boundary_edges = 0;   ///< edges used by one triangle only
  int nonmanifold_edges = 0;  ///< edges used by three or more triangles
};

/// Signed volume by the divergence theorem (sum of signed tetrahedra against the origin).
double signed_volume(const Mesh& mesh);

/// Total surface area.
double surface_area(const Mesh& mesh);

/// Area-weighted centroid of the enclosed solid (uniform density).
Vec3 solid_centroid(const Mesh& mesh);

/// Second moment tensor of the enclosed solid about its centroid, unit density:
/// inertia tensor I = ∫(r²δ - r rᵀ) dV. Exact for the polyhedron (tetrahedral decomposition).
Mat3 solid_inertia(const Mesh& mesh);
/// The same about a centroid already known (solid_centroid(mesh)): one pass over the mesh less.
Mat3 solid_inertia(const Mesh& mesh, const Vec3& centroid);

/// Checks closedness, manifoldness, orientation consistency and degeneracy by edge counting.
MeshCheck check_mesh(const Mesh& mesh);

/// Appends `other`'s vertices and triangles to `mesh` (indices shifted): its shells beside
/// mesh's, as one file of several shells holds them.
void append_mesh(Mesh& mesh, const Mesh& other);

/// Flips all triangles (reverses orientation).
void flip_orientation(Mesh& mesh);

/// Puts the mesh in a canonical order: vertices sorted lexicographically, each triangle rotated to
/// start at its smallest index, triangles sorted. Geometry is unchanged. Libraries that order
/// their output by memory address (CGAL's hulls) give different orders run to run; after this,
/// the same geometry always gives the same bytes and the same floating-point sums.
void canonicalize(Mesh& mesh);

/// Position of each point in lexicographic (x, y, z) order: the relabelling canonicalize() uses.
std::vector<int> lexicographic_rank(const std::vector<Vec3>& points);

/// Applies x -> R x + t to every vertex.
void transform(Mesh& mesh, const Mat3& rotation, const Vec3& translation);

/// Axis-aligned bounding box corners (min, max).
std::array<Vec3, 2> bounding_box(const Mesh& mesh);

/// One use of an undirected edge by a triangle: key = (lower vertex << 32) | higher vertex.
struct EdgeUse {
  std::uint64_t key = 0;
  int face = -1;
};
/// Every triangle's three edges, ordered by (key, face), so the uses of one edge are adjacent:
/// a counting sort by the lower vertex, then each vertex's few uses in place (linear time; a
/// global sort was a tenth of describing a 10⁵-triangle mesh).
std::vector<EdgeUse> edge_uses(const Mesh& mesh);

}  // namespace clumpkit
