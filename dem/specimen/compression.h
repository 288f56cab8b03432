// Gravity-free test specimens at a target porosity: homogeneous compression of a loose random
// packing in a rigid cuboid or cylinder (the preparation of element-test specimens).
#pragma once

#include "dem/core/contact.h"
#include "dem/core/world.h"
#include "dem/run/stage_store.h"
#include "dem/specimen/specimen_particles.h"

#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// What to build (SI units).
struct CompressionSpec {
  enum class Shape { cuboid, cylinder, segment };
  Shape shape = Shape::cuboid;
  double angle = 0.0;  ///< segment: the sector 0 ≤ φ ≤ angle of the cylinder (radians, (0, π])
  /// Requested container: cuboid edges (x, y, z); cylinder and segment (diameter, diameter,
  /// height) of the whole cylinder. The
  /// built container keeps these proportions and is scaled (by less than one particle's share)
  /// so that the particles drawn fill it at exactly the target porosity.
  Vec3 size = Vec3(0.1, 0.1, 0.1);
  double porosity = 0.37;  ///< target: 1 − (solid volume / container volume)
  /// Interparticle friction during the compression (0: the densest packing the porosity allows);
  /// the specimen keeps contact.friction.
  double friction = 0.0;
  std::vector<ParticleClass> classes;
  std::vector<RockTemplate> templates;
  double soil_density = 2650, rock_density = 2650;  ///< kg/m³
  ContactParams contact;                            ///< the specimen's law (walls frictionless)
  std::uint64_t seed = 1;
  /// The loose packing starts in the container enlarged by this factor in every direction
  /// (solid fraction (1 − n)/factor³, ≈ 0.23 for n = 0.37): random placement fills it easily.
  double loose_factor = 1.4;
  /// Linear strain of the container per step while it closes (every body's position is mapped
  /// with the walls, so the packing stays homogeneous): 1e-5 keeps the contact overlaps growing
  /// slower than they relax (about 30,000 steps from the loose state).
  double strain_per_step = 1e-5;
  double timestep_safety = 0.2;  ///< time step = safety × critical_timestep
  /// Relaxation at the final size: until the mean unbalanced-force ratio is below this, or
  /// relax_max_steps.
  double relax_unbalanced = 1e-3;
  long relax_max_steps = 50000;
};

/// The built specimen.
struct CompressionResult {
  World world;                    ///< bodies at rest in the container, its walls, contact.friction
  Vec3 lo = Vec3::Zero();         ///< container box (cuboid; the cylinder's bounding box)
  Vec3 hi = Vec3::Zero();         ///<
  double radius = 0, height = 0;  ///< cylinder and segment only (m)
  double angle = 0;               ///< segment only (radians)
  double porosity = 0;            ///< 1 − Σ body volumes / container volume
  double mean_stress = 0;         ///< Love–Weber mean stress at the end (Pa, compression +)
  double coordination = 0;        ///< mean contacts per body at the end
  long compression_steps = 0, relax_steps = 0;
  std::string relaxed_by;  ///< "unbalanced_ratio" or "step_cap"
  double timestep = 0;     ///< s
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
/// of a run never stopped. Throws InvalidInput for a bad spec.
CompressionResult compress_specimen(const CompressionSpec& spec, const StageControl& control = {});

/// The resume fingerprint of a compression: FNV-1a 64 (16 hex digits) of the program version and
/// every field of `spec` (doubles exact, templates with all their spheres and mass properties).
std::string compression_fingerprint(const CompressionSpec& spec);

}  // namespace clumpkit::dem
