// Rigid-body time integration of one body per step: leapfrog translation, ω = L/I for isotropic
// bodies, and the explicit-midpoint quaternion update for general ones (World::step calls these).
#pragma once

#include "dem/core/body.h"
#include "geom/mesh/mesh.h"

#include <Eigen/Geometry>

#include <cmath>

namespace clumpkit::dem {

/// Rotation by the rotation vector phi (angle |phi| about phi/|phi|) as a unit quaternion.
inline Eigen::Quaterniond rotation_quaternion(const Vec3& phi) {
  const double angle = phi.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  const double h = 0.5 * angle;
  const Vec3 axis = phi * (std::sin(h) / angle);
  return Eigen::Quaterniond(std::cos(h), axis.x(), axis.y(), axis.z());
}

/// Leapfrog (velocities at half steps): v += F·dt/m, then x += v·dt.
inline void leapfrog_translate(Vec3& position, Vec3& velocity, const Vec3& force, double mass,
                               double dt) {
  velocity += force * (dt / mass);
  position += velocity * dt;
}

/// Spin of an isotropic body (a sphere): ω = (I·ω + T·dt)/I, i.e. L += T·dt with ω = L/I in
/// every orientation.
inline void spin_isotropic(Vec3& angular_velocity, const Vec3& torque, double inertia, double dt) {
  angular_velocity = (inertia * angular_velocity + torque * dt) / inertia;
}

/// Rotation of a general rigid body over dt with principal `moments` (body frame) under
/// `torque` (world): L += T·dt, then dq/dt = ½·ω ⊗ q with ω = ω(q, L) and L held over the step,
/// by the explicit midpoint (three fixed-point passes for the half-step orientation); ω is then
/// that of the new orientation. An isotropic body takes the same path exactly when
/// `isotropic` is set: ω = L/I whatever q, one rotation by dt·ω.
/// (Inline, as all of this header: it runs once per body and step.)
inline void rotate_rigid_body(Eigen::Quaterniond& orientation, Vec3& angular_velocity,
                              const Vec3& moments, const Vec3& torque, double dt, bool isotropic) {
  const Eigen::Quaterniond q0 = orientation;
  if (isotropic) {
    spin_isotropic(angular_velocity, torque, moments.x(), dt);
    orientation = (rotation_quaternion(dt * angular_velocity) * q0).normalized();
    return;
  }
  const Vec3 momentum = angular_momentum(moments, q0, angular_velocity) + torque * dt;
  Vec3 omega = angular_velocity_for(moments, momentum, q0);
  for (int pass = 0; pass < 3; ++pass) {
    const Eigen::Quaterniond half = (rotation_quaternion(0.5 * dt * omega) * q0).normalized();
    omega = angular_velocity_for(moments, momentum, half);
  }
  orientation = (rotation_quaternion(dt * omega) * q0).normalized();
  angular_velocity = angular_velocity_for(moments, momentum, orientation);
}

}  // namespace clumpkit::dem
