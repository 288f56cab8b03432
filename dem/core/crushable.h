// A crushable particle in the DEM (Hu et al. 2023): each Voronoi cell a rigid body with its exact
// mass properties, its corners for the platens and a sphere inside it for contacts between
// fragments, bonded to its neighbours on their shared faces.
#pragma once

#include "dem/core/world.h"
#include "geom/cells/cell_bonds.h"
#include "geom/cells/voronoi_cells.h"
#include "geom/fill/fill_options.h"

#include <vector>

namespace clumpkit::dem {

/// The body of one cell at `density` (kg/m³), in its principal frame (centroid at the origin,
/// inertia axes along x, y, z with ascending moments, right-handed), placed where the cell is:
/// mass ρ·V, principal moments ρ·I, its corners (Body::vertices), and one sphere: the largest
/// centred on the centroid inside the cell (radius the centroid's distance to the nearest face
/// plane), so that two cells' spheres never overlap while the cells do not. Lengths in the
/// cell's units (metres for the DEM). Throws InvalidInput for a density outside kDensity, or a
/// cell without volume.
Body cell_body(const Cell& cell, double density);

/// The body of one cell for a packing (a crushable particle among others): cell_body's mass
/// properties and pose, its spheres the project's fill of the cell (fill of cell_mesh with
/// `fill`; overshoot within its contract) so that other particles' cells meet the cell's shape,
/// not one inner sphere, and without corners: its spheres meet every wall, as a clump's do.
/// Spheres of two bonded cells overlap across their face; the World keeps such pairs apart while
/// the bond holds. Throws what cell_body and fill throw.
Body cell_clump_body(const Cell& cell, double density, const FillOptions& fill);

/// `o` for a world of cell_clump_body cells bonded by `law`: the law on every bond, broken bonds
/// exerting nothing (WorldOptions::broken_bonds_act: the cells' spheres touch once a bond stops
/// holding) and no sorting (bodies keep their indices: each particle's cells stay together, and
/// the breakage measures find their reference poses).
WorldOptions cell_packing_options(WorldOptions o, const CohesiveParams& law);

/// Adds one bond per shared face to `world`, whose bodies 0… are the cells in order at the
/// cells' positions (make_bond with the face's integration points and strength factor). Throws
/// InvalidInput from add_bond.
void add_cell_bonds(World& world, const std::vector<CellBond>& bonds);

/// A crushable particle apart from any world: its cells' bodies where the cells are (the parent's
/// frame), in cell order, and one bond per shared face (make_bond with the face's integration
/// points and strength factor; body indices within the particle). A bond keeps its points and
/// normal in its bodies' frames, so the particle may be moved rigidly anywhere
/// (add_crushable) with its bonds at rest.
struct CrushableBodies {
  std::vector<Body> cells;
  std::vector<Bond> bonds;
};

/// The particle's bodies: cell_clump_body with `fill`, or cell_body (one inner sphere and the
/// corners, for the platens of the crushing rig) without. Throws what they throw.
CrushableBodies crushable_bodies(const Tessellation& cells, const std::vector<CellBond>& bonds,
                                 double density, const FillOptions* fill = nullptr);

/// Adds the particle to `world` moved by x → q·x + t (its bodies' poses composed with it, its
/// bonds renumbered to the world's bodies) and returns the index of its first body. Throws
/// InvalidInput from add_body and add_bond.
int add_crushable(World& world, const CrushableBodies& particle, const Eigen::Quaterniond& q,
                  const Vec3& t);

/// A world holding the particle where its cells are: one body per cell (cell_body, in cell
/// order) and one bond per shared face, with the given options (their cohesive law). Throws
/// InvalidInput from add_body and add_bond.
World crushable_particle(const Tessellation& cells, const std::vector<CellBond>& bonds,
                         double density, const WorldOptions& options);

}  // namespace clumpkit::dem
