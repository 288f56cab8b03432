// Gravity deposition of a placed assembly in a cylinder with a floor (specimen stage 2, simplest
// form).
#pragma once

#include "dem/core/world.h"
#include "dem/specimen/placement.h"

#include <vector>

namespace clumpkit::dem {

/// Contact parameters for deposition: the initial values of Jin et al. 2017 §4.1 (kn = ks = 1e6
/// N/m, μ = 0.8) with viscous normal damping β = 0.5 and light PFC local damping α = 0.1. Measured
/// on 150 soil spheres (tests/dem/specimen/deposition_test.cpp): this reaches a mean
/// unbalanced-force ratio of 1e-3 in about 130k steps, while local damping alone (α = 0.3 or 0.7,
/// with or without β) had not in 400k steps, because strong local damping also brakes the fall
/// under gravity.
inline ContactParams deposition_contact() {
  ContactParams p;
  p.damping_ratio = 0.5;
  p.local_damping = 0.1;
  return p;
}

/// Settings of a gravity deposition (SI).
struct DepositionSpec {
  double radius = 0.0;  ///< cylinder radius (m), axis x = y = 0
  ContactParams contact = deposition_contact();
  /// Time step = safety × critical_timestep(world), in kTimestepSafety.
  double timestep_safety = 0.2;
};

/// Builds a World from bodies (at the origin, unrotated, with their masses) moved to their
/// placements (a soil sphere keeps the identity orientation): each body keeps its spheres, mass
/// properties, kind and template identity. Walls: the floor plane z = 0 (normal +z) and the inside
/// of the cylinder of spec.radius around the z-axis. Gravity −9.81 m/s² along z, contact =
/// spec.contact, time step = spec.timestep_safety × critical_timestep(world). Throws InvalidInput
/// for mismatched sizes, a body without spheres, a non-positive radius or a safety factor outside
/// kTimestepSafety.
World make_deposition_world(const std::vector<Body>& bodies,
                            const std::vector<Placement>& placements, const DepositionSpec& spec);

}  // namespace clumpkit::dem
