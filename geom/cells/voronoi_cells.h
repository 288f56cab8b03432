// Voronoi cells of a convex parent particle (Hu et al. 2023 §2.1): seeds, Lloyd relaxation, the
// cells' convex polyhedra with exact mass properties and the faces they share.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/random.h"
#include "geom/range.h"
#include "geom/shapes/halfspaces.h"
#include "geom/sphere.h"

#include <vector>

namespace clumpkit {

/// A cell size ℓ (CellOptions::cell_size; 0 there: a count instead), in the parent's units; as a
/// length it is further held to geom/limits.h's sizes.
inline constexpr Range kCellSize = above(0);
/// The Lloyd steps after the seeds are drawn (CellOptions::lloyd; 0: raw Poisson–Voronoi cells).
inline constexpr Range kLloydSteps = integers(0, 100);

/// How a parent is cut. Exactly one of `count` and `cell_size` is set (> 0).
struct CellOptions {
  /// Number of cells N.
  int count = 0;
  /// Cell size ℓ, a cell's volume-equivalent diameter: N = round((D/ℓ)³) with D the parent's
  /// volume-equivalent diameter (ℓ = 6.5 mm gives Hu et al. 2023's 75, 114, 165, 229 and 307
  /// cells at 27.5 … 43.9 mm within one cell). Units of the parent; in kCellSize when set.
  double cell_size = 0.0;
  /// Lloyd steps (each seed moved to its cell's centroid) after the uniform random seeds: the
  /// paper's cells are "sub-particles of similar size" (a regularised tessellation); 0 keeps the
  /// raw Poisson–Voronoi cells. In kLloydSteps.
  int lloyd = 3;
};

/// Throws InvalidInput for a count and a size (in kCellSize) both set or neither, a count below
/// 2 or above 100000, a size that is not a positive length, or lloyd outside kLloydSteps.
void validate(const CellOptions& options);

/// One face of a cell: its vertices in order, counter-clockwise seen from outside the cell, and
/// what lies beyond it.
struct CellFace {
  std::vector<int> vertices;
  int neighbour = -1;  ///< index of the cell across the face, or −1 on the parent's surface
};

/// A convex cell: its polyhedron (vertices in the parent's frame and units), the seed it grew
/// from, and its mass properties at unit density (volume, centroid, inertia about the centroid).
struct Cell {
  std::vector<Vec3> vertices;
  std::vector<CellFace> faces;
  Vec3 seed = Vec3::Zero();
  MassProperties mass;
};

/// The cells of one parent, in seed order.
struct Tessellation {
  std::vector<Cell> cells;
  double parent_volume = 0.0;
};

/// The planes of a convex closed mesh's faces as outward half-spaces n·x ≤ h with unit n: one
/// per face, a face being edge-connected triangles whose corners lie within 1e-7 of the mesh's
/// size of one plane (area-weighted), so that the many triangles of one flat face, and their
/// float32-rounded corners, give one plane. Throws InvalidInput when the mesh has no volume or is
/// not convex (its volume more than 1e-6 below its convex hull's, the two named).
std::vector<Halfspace> convex_planes(const Mesh& mesh);

/// Number of cells that `options` asks of a parent of volume `parent_volume`; throws InvalidInput
/// when a cell size gives fewer than two cells (the cell is as large as the parent).
int cell_count(const CellOptions& options, double parent_volume);

/// Cuts the convex closed mesh `parent` into Voronoi cells (voro++, Rycroft 2009): N seeds
/// uniform in the parent, `lloyd` centroidal steps, the cells clipped by the parent's planes.
/// Computed in coordinates scaled to the parent's size (voro++ tolerances are absolute) and
/// scaled back. Deterministic for a given rng state. Throws InvalidInput for a parent that is not
/// convex (convex_planes) and bad options, NumericError if a cell comes out empty.
Tessellation voronoi_cells(const Mesh& parent, const CellOptions& options, Rng& rng);

/// The cells of the given seeds (inside the parent, at least two) after `lloyd` centroidal
/// steps. Throws InvalidInput for a seed outside the parent, what voronoi_cells throws.
Tessellation voronoi_cells(const Mesh& parent, const std::vector<Vec3>& seeds, int lloyd = 0);

/// The same cells computed another way, for cross-checks: each cell as the intersection of the
/// parent's planes and the bisector half-spaces of its seed against every other seed
/// (intersect_halfspaces). O(N²) planes: for tests and small N.
std::vector<Mesh> voronoi_cells_by_halfspaces(const Mesh& parent, const std::vector<Vec3>& seeds);

/// The cell's polyhedron as a closed, outward-oriented triangle mesh (each face fanned from its
/// first vertex).
Mesh cell_mesh(const Cell& cell);

/// Area, centroid and unit normal (outward for the cell whose face it is) of a planar polygon
/// given by its vertices in order (fan triangles from the first vertex; Newell's normal).
struct PolygonProperties {
  double area = 0.0;
  Vec3 centroid = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
};
PolygonProperties polygon_properties(const std::vector<Vec3>& vertices,
                                     const std::vector<int>& polygon);

}  // namespace clumpkit
