// Servo control of rigid walls to a target stress (the servo mechanism of PFC's element tests).
#pragma once

#include "dem/core/world.h"

namespace clumpkit::dem {

/// Gain settings of a stress servo.
struct ServoGain {
  /// α: the fraction of the stress error the wall may close in one step if the packing kept its
  /// stiffness (PFC's relaxation factor); below 1 for stability, 0.5 by default.
  double relaxation = 0.5;
  double max_speed = 0.0;  ///< |v| limit (m/s); > 0
};

/// Speed of a wall along its inward normal (m/s, positive: into the packing) that drives the
/// stress it feels towards `target`: v = α·A·(σ_target − σ) / (k·dt), the wall displacement that
/// would close the error α-fold against the stiffness k of its contacts (PFC: G = α·A/(k·N_c·dt)),
/// clamped to ±max_speed; with no contact (k = 0) the wall closes in at max_speed, or backs away
/// at it when the target is not compressive. Throws InvalidInput for a non-positive area, step
/// or speed limit, or α outside (0, 1].
double servo_speed(double stress, double target, double area, double stiffness, double dt,
                   const ServoGain& gain);

/// Moves wall `wall` inward at `speed` (m/s): a plane along its normal, a cylinder by shrinking
/// its radius (radial_velocity = −speed).
void set_wall_speed(World& world, int wall, double speed);

}  // namespace clumpkit::dem
