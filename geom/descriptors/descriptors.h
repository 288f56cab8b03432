// Shape descriptors of a closed triangle mesh: size, form (L, W, H, S-I-L axes), sphericity,
// convexity and weighted roundness.
#pragma once

#include "geom/mesh/mesh.h"

#include <array>

namespace clumpkit {

/// Principal frame of the solid: centroid and inertia axes, with the extents of the mesh along
/// each axis. Columns of `axes` are unit vectors ordered so that extents are S ≤ I ≤ L
/// (column 0 = short axis, column 2 = long axis). The extents are those of the bounding box
/// aligned with the inertia axes (documented choice for S, I, L in Hu et al. 2023).
/// Signs: the largest-magnitude component of each axis is positive, except that column 0 is
/// negated when needed to make `axes` a proper rotation (det = +1).
/// Equal principal moments (relative gap < 1e-8) leave the axes undefined; then the axes in the
/// degenerate plane are those of the smallest enclosing rectangle of the projected vertices, and
/// for an isotropic tensor (cube, sphere) those of the smallest box among candidates with one
/// axis along a face normal (up to 32 normals, largest total face area first). A box therefore
/// keeps its edge directions and a cube has extents (1, 1, 1) in any orientation.
/// Extents within 1e-9 of L of each other are a tie: their axes are ordered by moment of inertia,
/// largest first, so the labels do not depend on the mesh's orientation or triangulation.
struct PrincipalFrame {
  Vec3 centroid = Vec3::Zero();
  Mat3 axes = Mat3::Identity();
  Vec3 extents = Vec3::Zero();  ///< (S, I, L)
};

/// Centroid, inertia axes and extents along them (see PrincipalFrame). Units follow the mesh.
/// Throws InvalidInput for an empty mesh or one with non-positive volume.
PrincipalFrame principal_frame(const Mesh& mesh);

/// L, W, H as measured with a caliper (Jin et al. 2017 §1.1): L the largest dimension (diameter of
/// the vertex set), W the largest dimension in the plane perpendicular to L, H the largest
/// dimension perpendicular to both L and W. Computed on the vertices (exact for polyhedra):
///  - L = max pairwise distance of the convex-hull vertices (farthest_pair.h: exact, pruned);
///  - W = max pairwise distance of the hull vertices projected on the plane ⟂ dir_L
///    (the 2-D diameter of that projection), dir_W = direction of that pair in the plane;
///  - H = extent of the vertices along dir_H = dir_L × dir_W (so H ≤ W ≤ L).
/// Ties (e.g. the four diagonals of a box) take the first pair found. dir_L and dir_W have their
/// largest-magnitude component positive; (dir_L, dir_W, dir_H) is right-handed.
struct CaliperDimensions {
  double L = 0.0, W = 0.0, H = 0.0;
  Vec3 dir_L = Vec3::UnitX(), dir_W = Vec3::UnitY(), dir_H = Vec3::UnitZ();
};
/// Throws InvalidInput for a mesh without vertices.
CaliperDimensions caliper_dimensions(const Mesh& mesh);

/// 2-D roundness C = P²/(4πA) of a simple polygon (Zhang & Zhou 2015 eq. 1). 1 for a circle.
/// Either orientation. Throws InvalidInput for fewer than 3 vertices or zero area.
double polygon_roundness(const std::vector<Eigen::Vector2d>& polygon);

/// Outer silhouette of a closed mesh seen along `direction`: the boundary polygon of the union of
/// the projected triangles, in a 2-D frame of the plane perpendicular to `direction`
/// (counter-clockwise). Exact (no raster): 2-D convex hull for convex meshes, else the outer
/// boundary of the arrangement of projected contour edges.
/// Frame: (u, v, d) is right-handed, d = direction/|direction|, u from the world axis least
/// aligned with d; counter-clockwise in (u, v), i.e. seen from the tip of d. Units follow the mesh.
/// Non-convex path: contour edges (facing of the two triangles differs, or one is edge-on),
/// boundary and non-manifold edges are projected and inserted in a CGAL Arrangement_2 (exact
/// kernel); the result is the inner CCB of the unbounded face, with antenna edges and vertices
/// lying on a straight segment dropped. Holes of the silhouette (e.g. through a ring) are ignored:
/// only the outer boundary is returned. If the projection has several disconnected pieces, the
/// one with the largest area is returned. `convex = true` on a non-convex mesh gives the outline
/// of its convex hull. Throws InvalidInput for a zero or non-finite direction.
std::vector<Eigen::Vector2d> silhouette(const Mesh& mesh, const Vec3& direction, bool convex);

/// Weighted roundness (Zhang & Zhou 2015 eq. 2): R = Σ C_i A_i / Σ A_i over three orthogonal views
/// taken along the principal (inertia) axes. `convex` selects the silhouette path (see silhouette).
struct Roundness {
  double weighted = 1.0;
  std::array<double, 3> view{1.0, 1.0, 1.0};  ///< C along the S, I, L axis respectively
  std::array<double, 3> view_area{0.0, 0.0, 0.0};
};
Roundness weighted_roundness(const Mesh& mesh, const PrincipalFrame& frame, bool convex);

/// All descriptors of one closed, outward-oriented mesh. Units follow the mesh.
struct Descriptors {
  double volume = 0.0;
  double area = 0.0;
  double sphericity = 0.0;            ///< Wadell: π^(1/3) (6V)^(2/3) / A
  double equivalent_diameter = 0.0;   ///< (6V/π)^(1/3)
  double L = 0.0, W = 0.0, H = 0.0;   ///< caliper dimensions, Jin et al. 2017 §1.1
  Vec3 axes = Vec3::Zero();           ///< (S, I, L) principal-axis lengths
  double E = 0.0, F = 0.0, AR = 0.0;  ///< I/L, S/I, S/L (Hu et al. 2023)
  double convexity = 0.0;             ///< V / V_hull
  Roundness roundness;
};

/// Computes every descriptor. Throws InvalidInput for a mesh with non-positive volume.
/// Convexity uses the CGAL convex hull of the vertices; the roundness views use the convex
/// silhouette path when convexity > 1 - 1e-9, else the arrangement path.
Descriptors describe(const Mesh& mesh);

}  // namespace clumpkit
