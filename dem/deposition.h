// Gravity deposition of a placed assembly in a cylinder with a floor (specimen stage 2, simplest
// form).
#pragma once

#include "dem/placement.h"
#include "dem/run.h"
#include "dem/world.h"

#include <vector>

namespace clumpkit::dem {

/// Contact parameters for deposition: issue 5 defaults (kn = ks = 1e6 N/m, μ = 0.8) with
/// viscous normal damping β = 0.5 and light PFC local damping α = 0.1. Measured on 150 soil
/// spheres (tests/dem/deposition_test.cpp): this reaches a mean unbalanced-force ratio of 1e-3
/// in about 130k steps, while local damping alone (α = 0.3 or 0.7, with or without β) had not
/// in 400k steps, because strong local damping also brakes the fall under gravity.
inline ContactParams deposition_contact() {
  ContactParams p;
  p.damping_ratio = 0.5;
  p.local_damping = 0.1;
  return p;
}

/// Settings of a gravity deposition (SI).
struct DepositionSpec {
  double radius = 0.0;         ///< cylinder radius (m), axis x = y = 0
  double soil_density = 2700;  ///< kg/m³, bodies of one sphere
  double rock_density = 2870;  ///< kg/m³, clumps (bodies of several spheres)
  ContactParams contact = deposition_contact();
  double timestep_safety = 0.2;    ///< time step = safety × critical_timestep(world)
  long max_steps = 200000;         ///< step cap of deposit()
  double unbalanced_ratio = 1e-3;  ///< deposit() stops once the mean ratio is below this
};

/// Builds a World from placed items: an item of one sphere becomes a sphere body of soil
/// density, an item of several spheres a clump body of rock density (exact union mass
/// properties, spheres in the principal frame, placed so its spheres land where the placement
/// puts them). Walls: the floor plane z = 0 (normal +z) and the inside of the cylinder of
/// spec.radius around the z-axis. Gravity −9.81 m/s² along z, contact = spec.contact,
/// time step = spec.timestep_safety × critical_timestep(world). Throws InvalidInput for
/// mismatched sizes, an item without spheres, a non-positive radius or safety factor.
World make_deposition_world(const std::vector<PlacementItem>& items,
                            const std::vector<Placement>& placements, const DepositionSpec& spec);

/// Runs `world` (run_until) until the mean unbalanced-force ratio is below
/// spec.unbalanced_ratio or spec.max_steps steps were taken; returns the outcome
/// (stopped_by "unbalanced_ratio" or "step_cap").
RunOutcome deposit(World& world, const DepositionSpec& spec);

/// Porosity estimate of the cylindrical sub-region r < radius (around the z-axis),
/// z in [z_lo, z_hi]: the fraction of the points of a cubic lattice of the given spacing (cell
/// centres of a grid anchored at (−radius, −radius, z_lo)) inside the region that lie in no
/// sphere of any body. Overlaps (clump spheres, contacts) count once. An estimate whose error
/// shrinks with the spacing; exact sphere–region volumes are future work. Throws InvalidInput
/// for non-positive radius or spacing, z_hi <= z_lo, or a region holding no lattice point.
double lattice_porosity(const World& world, double radius, double z_lo, double z_hi,
                        double spacing);

}  // namespace clumpkit::dem
