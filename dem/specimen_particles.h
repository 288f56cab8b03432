// Particle sets of a specimen layer from a gradation: soil spheres and scaled rock clumps whose
// volumes fill a given solid volume (seed 000 §4.2, "new volumes of each size group").
#pragma once

#include "dem/placement.h"
#include "geom/random.h"
#include "geom/sphere.h"

#include <vector>

namespace clumpkit::dem {

/// One sieve class of the gradation after fines replacement (SI).
struct ParticleClass {
  double min_size = 0.0, max_size = 0.0;  ///< sieve sizes (m)
  double mass_percent = 0.0;              ///< percent of the total solid mass
  bool rock = false;                      ///< rock clumps (true) or soil spheres (false)
};

/// A rock clump of the library: spheres in its principal frame (centroid at the origin), its
/// sieve size W (the intermediate dimension, seed 000 §1.1) and its exact union volume, in the
/// library's units; layer_items scales it to the size it draws.
struct RockTemplate {
  std::vector<Sphere> spheres;
  double sieve_size = 0.0;
  double volume = 0.0;
};

/// The bodies of one layer: placement items (rocks first, largest first, then soil spheres,
/// largest first), which of them are rock, and the template index of each rock (-1 for soil).
struct LayerParticles {
  std::vector<PlacementItem> items;
  std::vector<int> template_index;
  double rock_volume = 0.0, soil_volume = 0.0;  ///< drawn solid volumes (m³)
};

/// Solid volume of each class (m³) for a total solid volume: with mass fractions p_k and
/// densities ρ_k, the total mass is M = V / Σ p_k/ρ_k and class k gets p_k·M/ρ_k.
std::vector<double> class_volumes(const std::vector<ParticleClass>& classes, double solid_volume,
                                  double soil_density, double rock_density);

/// Draws the particles of each class until its volume (class_volumes) is reached: the last
/// particle is kept when that brings the drawn volume closer to the goal. Soil sphere
/// diameters and rock sieve sizes are uniform in the class; a rock is a uniformly chosen
/// template scaled by (drawn size / template sieve size). Classes are drawn in order from one
/// Rng, so the result is fixed by its state. Throws InvalidInput for a rock class without
/// templates, a non-positive volume, size or density.
LayerParticles layer_particles(const std::vector<ParticleClass>& classes,
                               const std::vector<RockTemplate>& templates, double solid_volume,
                               double soil_density, double rock_density, Rng& rng);

}  // namespace clumpkit::dem
