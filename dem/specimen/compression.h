// Gravity-free test specimens at a target porosity: homogeneous compression of a loose random
// packing in a rigid cuboid or cylinder (the preparation of element-test specimens).
#pragma once

#include "dem/core/contact.h"
#include "dem/core/world.h"
#include "dem/run/stage_store.h"
#include "dem/specimen/crushable_particles.h"
#include "dem/specimen/specimen_particles.h"
#include "dem/specimen/zones.h"
#include "geom/range.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// A segment's angle in degrees (CompressionSpec::angle, in radians): 180 is the half cylinder,
/// the widest sector two planes through the axis cut.
inline constexpr Range kSegmentAngleDegrees = open_closed(0, 180);

/// What to build (SI units).
struct CompressionSpec {
  enum class Shape { cuboid, cylinder, segment };
  Shape shape = Shape::cuboid;
  /// Segment: the sector 0 ≤ φ ≤ angle of the cylinder (radians; in degrees, in
  /// kSegmentAngleDegrees).
  double angle = 0.0;
  /// Requested container: cuboid edges (x, y, z); cylinder and segment (diameter, diameter,
  /// height) of the whole cylinder. The
  /// built container keeps these proportions and is scaled (by less than one particle's share)
  /// so that the particles drawn fill it at exactly the target porosity.
  Vec3 size = Vec3(0.1, 0.1, 0.1);
  /// Target: 1 − (solid volume / container volume), in kTargetPorosity.
  double porosity = 0.37;
  /// Interparticle friction during the compression, in kFriction (0: the densest packing the
  /// porosity allows); the specimen keeps contact.friction.
  double friction = 0.0;
  std::vector<ParticleClass> classes;
  std::vector<RockTemplate> templates;
  double soil_density = 2650, rock_density = 2650;  ///< kg/m³, each in kDensity
  ContactParams contact;                            ///< the specimen's law (walls frictionless)
  std::uint64_t seed = 1;
  /// The loose packing starts in the container enlarged by this factor in every direction
  /// (solid fraction (1 − n)/factor³, ≈ 0.23 for n = 0.37): random placement fills it easily.
  double loose_factor = 1.4;
  /// Linear strain of the container per step while it closes (every body's position is mapped
  /// with the walls, so the packing stays homogeneous): 1e-5 keeps the contact overlaps growing
  /// slower than they relax (about 30,000 steps from the loose state).
  double strain_per_step = 1e-5;
  double timestep_safety = 0.2;  ///< time step = safety × critical_timestep, in kTimestepSafety
  /// Relaxation at the final size: until the mean unbalanced-force ratio is below this, or
  /// relax_max_steps.
  double relax_unbalanced = 1e-3;
  long relax_max_steps = 50000;
  /// Variable particle-size zones (CTGU 2017; no regions: one uniform specimen). Each uniform
  /// zone holds `classes` scaled by its λ at `porosity` (similar packings have equal porosity),
  /// a mixed layer both neighbours' particles at mixed_porosity (0: `porosity`; else in
  /// kTargetPorosity); bodies are placed loose in the pre-image of their zone under the
  /// compression's map, so each ends in its zone up to the relaxation's moves, and carry
  /// Body::zone (re-tagged at the end by their final centre). Bounds in metres of the requested
  /// container (`size`).
  ZoneLayout zones;
  double mixed_porosity = 0.0;
  /// Zoned specimens' porosities hold away from walls: each zone's solid is drawn for its volume
  /// less wall_excess × its mean diameter × its wall area (zoned_particles). 0.09 measured: one
  /// zone of 6 mm spheres in a 90° segment (200 mm across, 60 mm high, 2,500 spheres) compressed
  /// to n = 0.39 and 0.38 overall gave 0.3615 and 0.3523 one diameter from the walls, an excess
  /// of 0.094 and 0.091 diameters.
  double wall_excess = 0.09;
  /// A crushable specimen: every class drawn as crushable particles of this material
  /// (crushable_particles: bonded Voronoi cells, each filled with spheres) instead of library
  /// clumps or soil spheres, their bonds following `cohesive`. While the container closes each
  /// particle moves as one piece (its centroid mapped, its cells translated with it), so its
  /// bonds are not strained by the map; they stay intact unless the packing's contacts break
  /// them. Not with zones.
  std::optional<CrushableMaterial> crushable;
  CohesiveParams cohesive;
};

/// One region of a zoned specimen, as built.
struct ZoneResult {
  double inner = 0, outer = 0;  ///< bounds of the zone coordinate (m)
  double volume = 0;            ///< inside the container (m³)
  double target_porosity = 0;
  double solid_goal = 0, solid_drawn = 0;  ///< m³
  /// Measured by sampled_regions (points a tenth of the smallest diameter apart) over the part of
  /// the region at least `margin` (its largest body diameter) from every wall; NaN when nothing is
  /// left.
  double porosity = 0, margin = 0;
  long count = 0;      ///< bodies whose final centre lies in the region (their zone)
  long left_zone = 0;  ///< bodies placed in this region whose centre ended in another
  /// Of those, the ones that ended more than their own diameter beyond the region's bounds
  /// (migrated, not just nudged across a bound).
  long migrated = 0;
  /// Of those, the ones whose diameter lies outside the range drawn for the region they ended
  /// in and that ended more than the largest diameter of either region beyond the bound: a body
  /// where its size does not belong (a small sphere of a mixed layer in a core of the same
  /// spheres is not one, nor one in a pocket of the large spheres' first layer at the bound).
  long mis_zoned = 0;
};

/// The porosities a compression can aim at (CompressionSpec::porosity, and mixed_porosity when
/// not 0): looser than 0.9 is no packing, denser than 0.2 beyond any packing of these particles.
/// The one range of a target porosity (recipes read their keys in it, validate the spec).
inline constexpr Range kTargetPorosity = open(0.2, 0.9);

/// The built specimen.
struct CompressionResult {
  World world;                    ///< bodies at rest in the container, its walls, contact.friction
  Vec3 lo = Vec3::Zero();         ///< container box (cuboid; the cylinder's bounding box)
  Vec3 hi = Vec3::Zero();         ///<
  double radius = 0, height = 0;  ///< cylinder and segment only (m)
  double angle = 0;               ///< segment only (radians)
  double porosity = 0;            ///< 1 − Σ body volumes / container volume
  double target_porosity = 0;     ///< the spec's
  double mean_stress = 0;         ///< Love–Weber mean stress at the end (Pa, compression +)
  double coordination = 0;        ///< mean contacts per body at the end
  long compression_steps = 0, relax_steps = 0;
  std::string relaxed_by;                           ///< "unbalanced_ratio" or "step_cap"
  double timestep = 0;                              ///< s
  std::vector<ZoneResult> zones;                    ///< zoned specimens only, innermost first
  long mis_zoned = 0, migrated = 0, left_zone = 0;  ///< Σ over the zones
};

/// Draws the particles of spec.classes for the target porosity (layer_particles with the solid
/// volume of the container), places them at random in the container enlarged by loose_factor
/// (place_in_box; the box grows by 10 % while it is too crowded), then closes the rigid
/// frictionless walls at strain_per_step while mapping every body's position with them (an
/// affine, isotropic compression: no density gradient from the walls) at spec.friction, gravity
/// off, and relaxes at the final size. The container's final volume is Σ body volumes / (1 − n),
/// so the porosity is the target exactly. A porosity above the packing's jamming porosity at
/// spec.friction leaves bodies without contacts (mean_stress 0): the caller should say so.
/// Deterministic for any thread count. Runs as the resumable stage "compression" of
/// control.store (opened with compression_fingerprint(spec)): checkpoints every
/// control.checkpoint_every_seconds and when the interrupter, told "compression" and the
/// fraction done, asks to stop (then Interrupted is thrown); the world at the end of the
/// relaxation is kept with the finished stage. Continued from the store, it ends with the bytes
/// of a run never stopped. Zoned specimens: see CompressionSpec::zones (dem/specimen/
/// zoned_packing.h draws and places them). Throws InvalidInput for a bad spec (validate_zones
/// for the layout, with the largest class size as the core diameter).
CompressionResult compress_specimen(const CompressionSpec& spec, const StageControl& control = {});

/// The resume fingerprint of a compression: FNV-1a 64 (16 hex digits) of the program version and
/// every field of `spec` (doubles exact, templates with all their spheres and mass properties).
std::string compression_fingerprint(const CompressionSpec& spec);

}  // namespace clumpkit::dem
