// The particles of a zoned specimen (CTGU 2017): each zone's volume in the container, its
// particles drawn from the core gradation scaled by the zone's λ (both neighbours' in a mixed
// layer), and their loose placement with every centre in its zone.
#pragma once

#include "dem/specimen/placement.h"
#include "dem/specimen/specimen_particles.h"
#include "dem/specimen/zones.h"

#include <cstdint>
#include <vector>

namespace clumpkit::dem {

/// A vertical prism standing on z = 0 about the z-axis: a cuboid of edges (size.x, size.y,
/// size.z), a cylinder of diameter size.x, or the sector 0 ≤ φ ≤ angle of that cylinder.
struct Prism {
  enum class Shape { cuboid, cylinder, segment };
  Shape shape = Shape::cuboid;
  Vec3 size = Vec3(0.1, 0.1, 0.1);
  double angle = 0.0;  ///< segment (radians)

  /// The prism scaled by s about the origin (the compression's map).
  Prism scaled(double s) const;
  /// Whether the ball of radius r at c lies inside (r = 0: the point).
  bool holds(const Vec3& c, double r = 0.0) const;
  /// Distance from c (inside) to the nearest wall, top and bottom included.
  double wall_distance(const Vec3& c) const;
  /// Bounding box of the prism.
  void bounds(Vec3& lo, Vec3& hi) const;
  double volume() const;
};

/// Each region's volume inside the prism (m³), for a mixed layer the part weighted by its
/// small-particle fraction, ∫ f dV (0 for uniform zones), and the area of the prism's walls
/// (floor, top, sides) inside it (m²), by midpoint quadrature: 2048² points of the cross-section
/// for radial zones, the cross-section's area times 10⁵ depth points for depth zones, 256³ points
/// for spherical ones (relative error below 1e-4 for zones a few cells wide); the sides by 4096
/// points per edge or arc (times 256 heights unless the zones are radial).
struct ZoneVolumes {
  std::vector<double> volume, small_volume, wall_area;
};
ZoneVolumes zone_volumes(const ZoneLayout& layout, const Prism& prism);

/// The bodies of every region, at the origin and unrotated, each with `zone` set to its region;
/// `small` marks the small particles of mixed layers. Porosities are those of the packing away
/// from walls: next to a flat or gently curved wall a random packing leaves an excess of void
/// equal to a layer `wall_excess` × its mean diameter thick, so a region of wall area A_k, mean
/// diameter d̄_k (by volume) has the effective volume V'_k = V_k − wall_excess·d̄_k·A_k. A uniform
/// region k holds the classes × λ_k at solid volume (1 − porosity)·V'_k; a mixed layer the small
/// classes at (1 − mixed_porosity)·(∫f dV)·V'_k/V_k and the large ones at (1 −
/// mixed_porosity)·(V_k − ∫f dV)·V'_k/V_k. Each
/// region is drawn from its own stream of `seed` (layer_particles), then all bodies are sorted
/// largest first (stable) for placement. Throws InvalidInput for a region without volume in the
/// prism.
struct ZonedParticles {
  std::vector<Body> bodies;
  std::vector<char> small;
  std::vector<double> goal;  ///< per region: the solid volume aimed at (m³)
};
ZonedParticles zoned_particles(const ZoneLayout& layout, const ZoneVolumes& volumes,
                               const std::vector<ParticleClass>& classes,
                               const std::vector<RockTemplate>& templates, double porosity,
                               double mixed_porosity, double wall_excess, double soil_density,
                               double rock_density, std::uint64_t seed);

/// Random loose placement of the bodies in the prism enlarged by `factor` (about the origin):
/// each centre drawn where the compression's map takes it into its body's zone (the layout
/// applied to position / factor), a mixed layer's small particles accepted with probability
/// f(c)/max f and the large ones with (1 − f(c))/max(1 − f), so that a linear fraction keeps
/// its gradient; every body inside the prism and no sphere overlapping. Empty when some body
/// found no room (enlarge the factor). Deterministic for a given Rng state.
std::vector<Placement> place_zoned(const ZonedParticles& particles, const ZoneLayout& layout,
                                   const Prism& prism, double factor, Rng& rng);

}  // namespace clumpkit::dem
