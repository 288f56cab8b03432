// Particle sets of a specimen layer from a gradation: soil spheres and scaled rock clumps whose
// volumes fill a given solid volume (Jin et al. 2017 §4.2, "new volumes of each size group").
#pragma once

#include "dem/core/body.h"
#include "dem/specimen/placement.h"
#include "geom/random.h"
#include "geom/range.h"
#include "geom/sphere.h"
#include "geom/template/clump_template.h"

#include <vector>

namespace clumpkit::dem {

/// One sieve class of the gradation after fines replacement (SI).
struct ParticleClass {
  double min_size = 0.0, max_size = 0.0;  ///< sieve sizes (m)
  double mass_percent = 0.0;              ///< percent of the total solid mass
  bool rock = false;                      ///< rock clumps (true) or soil spheres (false)
};

/// One sieve class of a gradation as measured (SI): sieve sizes and the percent of the total
/// solid mass between them.
struct SieveClass {
  double min_size = 0.0, max_size = 0.0;  ///< m
  double mass_percent = 0.0;
};

/// The size below which soil counts as fines (replace_fines's fines_below, m; finite).
inline constexpr Range kFinesBelow = above(0);
/// The sieve size parting rock classes from soil (replace_fines's soil_rock_threshold, m;
/// finite).
inline constexpr Range kSoilRockThreshold = above(0);
/// The rock's share of a gradation's mass, as a specimen recipe states it: a check of the
/// classes replace_fines makes rock, not an input of the engine.
inline constexpr Range kRockMassFraction = closed(0, 1);

/// The particle classes of a gradation (Jin et al. 2017 §4.1): classes without mass are dropped;
/// the fines (classes whose max size is at most fines_below) are removed and their mass is moved
/// into the class [fines_min, fines_max] (added at the end when the gradation has no such
/// class), so the model needs no particles finer than fines_min; classes whose min size is at
/// least soil_rock_threshold are rock (clumps), the others soil (spheres). Sizes compare with a
/// tolerance of 1e-12 m. Total mass percent is kept. Throws InvalidInput for fines_below outside
/// kFinesBelow or soil_rock_threshold outside kSoilRockThreshold.
std::vector<ParticleClass> replace_fines(const std::vector<SieveClass>& gradation,
                                         double fines_below, double fines_min, double fines_max,
                                         double soil_rock_threshold);

/// A rock clump of the library: its clump template (spheres in the principal frame, exact
/// unit-density volume and principal moments, as the library computed them) and its sieve size
/// W (the intermediate dimension, Jin et al. 2017 §1.1), in the library's units; layer_particles
/// scales it to the size it draws.
struct RockTemplate {
  ClumpTemplate clump;
  double sieve_size = 0.0;
};

/// The bodies of one layer, at the origin and unrotated (rocks first, largest first, then soil
/// spheres, largest first): each rock carries its template index and scale, and mass properties
/// scaled from its template; each soil sphere is a plain sphere body.
struct LayerParticles {
  std::vector<Body> bodies;
  double rock_volume = 0.0, soil_volume = 0.0;  ///< drawn solid volumes (m³)
};

/// What place_in_cylinder needs of each body: its spheres (body frame) and bounding radius.
std::vector<PlacementItem> placement_items(const std::vector<Body>& bodies);

/// Solid volume of each class (m³) for a total solid volume: with mass fractions p_k and
/// densities ρ_k, the total mass is M = V / Σ p_k/ρ_k and class k gets p_k·M/ρ_k.
std::vector<double> class_volumes(const std::vector<ParticleClass>& classes, double solid_volume,
                                  double soil_density, double rock_density);

/// Draws the particles of each class until its volume (class_volumes) is reached: the last
/// particle is kept when that brings the drawn volume closer to the goal. Soil sphere
/// diameters and rock sieve sizes are uniform in the class; a rock is a uniformly chosen
/// template scaled by (drawn size / template sieve size), with density rock_density, a soil
/// sphere has density soil_density. Classes are drawn in order from one
/// Rng, so the result is fixed by its state. Throws InvalidInput for a rock class without
/// templates, a non-positive volume, size or density.
LayerParticles layer_particles(const std::vector<ParticleClass>& classes,
                               const std::vector<RockTemplate>& templates, double solid_volume,
                               double soil_density, double rock_density, Rng& rng);

}  // namespace clumpkit::dem
