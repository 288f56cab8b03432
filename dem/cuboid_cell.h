// A cuboid cell of six servo-controlled plane walls: geometry, stresses and consolidation.
#pragma once

#include "dem/servo.h"
#include "dem/world.h"

#include <array>
#include <functional>

namespace clumpkit::dem {

/// The six walls of an axis-aligned box, in the order −x, +x, −y, +y, −z, +z (inward normals).
struct CuboidCell {
  std::array<int, 6> walls{};
};

/// Adds six frictionless plane walls around the box [lo, hi] and returns them. Throws InvalidInput
/// for an empty box.
CuboidCell add_cuboid_walls(World& world, const Vec3& lo, const Vec3& hi);

/// Current edge lengths of the box (m), from its walls' positions.
Vec3 cell_lengths(const World& world, const CuboidCell& cell);

/// Stress on each axis (Pa, compression positive): the mean of the two opposite walls' normal
/// stresses, each over the current area of its face.
Vec3 cell_wall_stress(const World& world, const CuboidCell& cell);

/// Love–Weber stress of the bodies inside the box, over the box volume (dem/stress.h).
Mat3 cell_love_weber_stress(const World& world, const CuboidCell& cell);

/// Settings of servo_consolidate.
struct ConsolidationSettings {
  Vec3 target = Vec3::Zero();  ///< stress per axis (Pa), compression positive
  ServoGain gain;              ///< servo gain and speed limit
  /// Equilibrium: every axis within this fraction of its target and the mean unbalanced-force
  /// ratio below `unbalanced`, checked every `check_every` steps.
  double tolerance = 0.005;
  double unbalanced = 1e-3;
  int check_every = 100;
  long long max_steps = 2'000'000;
};

/// Outcome of servo_consolidate.
struct ConsolidationResult {
  bool reached = false;  ///< stopped at equilibrium (else max_steps, or asked to stop)
  long long steps = 0;
  Vec3 stress = Vec3::Zero();  ///< cell_wall_stress at the end
  double unbalanced = 0.0;     ///< mean_unbalanced_force_ratio at the end
};

/// Drives all six walls by stress servos (each wall by its own stress and contact stiffness,
/// speeds updated every step) until equilibrium; the walls stop at the end. `stop`, asked every
/// check, ends the run early when it returns true (an interrupt).
ConsolidationResult servo_consolidate(World& world, const CuboidCell& cell,
                                      const ConsolidationSettings& settings,
                                      const std::function<bool()>& stop = {});

/// One step with every wall's speed from its servo (the six walls toward `target` per axis).
void servo_step(World& world, const CuboidCell& cell, const Vec3& target, const ServoGain& gain);

}  // namespace clumpkit::dem
