// The particles of a crushable specimen: parents of Hu et al. 2023's kind (spheres cut by random
// planes), each cut into bonded Voronoi cells filled with spheres, drawn for a solid volume.
#pragma once

#include "dem/core/crushable.h"
#include "dem/specimen/placement.h"
#include "dem/specimen/specimen_particles.h"
#include "geom/cells/voronoi_cells.h"
#include "geom/fill/fill_options.h"
#include "geom/range.h"
#include "geom/shapes/distribution.h"
#include "geom/shapes/polyhedron.h"

#include <cstdint>
#include <vector>

namespace clumpkit::dem {

/// How each crushable particle is made (SI).
struct CrushableMaterial {
  /// The parent's shape (make_polyhedron; its diameter is drawn from the classes).
  PolyhedronParams shape;
  CellOptions cells;  ///< the cells of each parent (cell_size in m, or a count)
  int face_subdivision = 0;
  Distribution strength = default_strength_factor();  ///< each face's strength factor
  /// The spheres of each cell (cell_clump_body): fill.spheres in kCellSpheres,
  /// fill.field.voxels in kCellVoxels.
  FillOptions fill;
  double density = 2650;  ///< kg/m³
};

/// The spheres filling each cell (CrushableMaterial::fill.spheres; 0, the fill's "no budget",
/// is none here: every cell gets a budget).
inline constexpr Range kCellSpheres = integers(1, 100);
/// Voxels across each cell's fill grid (CrushableMaterial::fill.field.voxels), a narrower range
/// than the fill's own kFieldVoxels.
inline constexpr Range kCellVoxels = integers(8, 200);

/// Throws InvalidInput naming the field for a material that cannot make particles (the fill's
/// sphere budget and voxels outside kCellSpheres and kCellVoxels among them).
void validate(const CrushableMaterial& material);

/// The crushable particles of `classes` (all of them rock: a class's sizes are the parents'
/// volume-equivalent diameters D, as Hu et al. 2023 size theirs) whose solid volume fills
/// `solid_volume` as class_volumes shares it (density `material.density` for every class):
/// diameters uniform in each class, drawn from `rng` in class order until the class's volume is
/// reached (the last one kept when that brings the class closer to it). Particle i then takes
/// its shape, cells and bond strengths from streams of its own (seed, 2^32 + 3i … 3i + 2), so the
/// particles are built in parallel with the same result for any thread count. Largest first; each
/// in its parent's principal frame (crushable_bodies, filled cells). Throws InvalidInput for a soil
/// class, bad sizes, a cell size that leaves fewer than two cells in a parent, and what the fill
/// throws.
std::vector<CrushableBodies> crushable_particles(const std::vector<ParticleClass>& classes,
                                                 double solid_volume,
                                                 const CrushableMaterial& material,
                                                 std::uint64_t seed, Rng& rng);

/// What placement needs of a particle: all its cells' spheres in its frame and their bounding
/// radius.
PlacementItem placement_item(const CrushableBodies& particle);

/// Σ volume of the particle's cells (the parent's volume).
double particle_volume(const CrushableBodies& particle);

}  // namespace clumpkit::dem
