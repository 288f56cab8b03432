// The rigid-body integrator against analytic motion: uniform acceleration, constant torque on a
// sphere, torque-free rotation of an asymmetric top (L exact, energy bounded, stable axes).
#include "dem/core/integrator.h"

#include "dem/core/body.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clumpkit::dem {
namespace {

TEST(Integrator, RotationQuaternionOfAQuarterTurn) {
  const Eigen::Quaterniond q = rotation_quaternion(Vec3(0, 0, M_PI / 2));
  EXPECT_LT((q * Vec3::UnitX() - Vec3::UnitY()).norm(), 1e-15);
  EXPECT_NEAR(q.norm(), 1.0, 1e-15);
  EXPECT_EQ(rotation_quaternion(Vec3::Zero()).w(), 1.0);
}

// Leapfrog under a constant force: v_n = n·a·dt, x_n = a·dt²·n(n+1)/2 (velocity first).
TEST(Integrator, LeapfrogUnderConstantForceMatchesItsClosedForm) {
  Vec3 x = Vec3::Zero(), v = Vec3::Zero();
  const Vec3 force(0.0, 0.0, -9.81 * 2.0);
  const double mass = 2.0, dt = 1e-3;
  const int n = 1000;
  for (int k = 0; k < n; ++k) leapfrog_translate(x, v, force, mass, dt);
  EXPECT_NEAR(v.z(), -9.81 * n * dt, 1e-12);
  EXPECT_NEAR(x.z(), -9.81 * dt * dt * n * (n + 1) / 2.0, 1e-12);
  EXPECT_EQ(x.x(), 0.0);
}

// A sphere under a constant torque about a fixed axis: ω = T·t/I and the turned angle
// Σ ω_k·dt, exactly as for the translation.
TEST(Integrator, IsotropicBodyUnderConstantTorque) {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Vec3 omega = Vec3::Zero();
  const Vec3 moments(0.4, 0.4, 0.4), torque(0, 0, 0.2);
  const double dt = 1e-3;
  const int n = 500;
  for (int k = 0; k < n; ++k) rotate_rigid_body(q, omega, moments, torque, dt, true);
  EXPECT_NEAR(omega.z(), 0.2 / 0.4 * n * dt, 1e-12);
  const double angle = 0.5 * dt * dt * n * (n + 1) / 2.0;  // Σ k·(T/I)·dt·dt
  EXPECT_LT((q * Vec3::UnitX() - Vec3(std::cos(angle), std::sin(angle), 0)).norm(), 1e-10);
  // The general path gives the same motion for an isotropic body.
  Eigen::Quaterniond q2 = Eigen::Quaterniond::Identity();
  Vec3 omega2 = Vec3::Zero();
  for (int k = 0; k < n; ++k) rotate_rigid_body(q2, omega2, moments, torque, dt, false);
  EXPECT_LT((omega2 - omega).norm(), 1e-12);
  EXPECT_LT(q2.angularDistance(q), 1e-10);
}

// Torque-free asymmetric top: angular momentum conserved up to accumulated rounding, kinetic energy
// to the midpoint's second order, and rotation about the largest-moment axis stays there (stable).
TEST(Integrator, TorqueFreeAsymmetricTopConservesMomentumAndEnergy) {
  const Vec3 moments(1.0, 2.0, 3.0);
  Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  Vec3 omega = q * Vec3(0.2, 3.0, 0.1);  // near the unstable middle axis: it tumbles
  const Vec3 L0 = angular_momentum(moments, q, omega);
  const double E0 = 0.5 * omega.dot(L0);
  const double dt = 1e-3;
  double worst_energy = 0.0;
  for (int k = 0; k < 20000; ++k) {
    rotate_rigid_body(q, omega, moments, Vec3::Zero(), dt, false);
    const Vec3 L = angular_momentum(moments, q, omega);
    ASSERT_LT((L - L0).norm(), 1e-9 * L0.norm()) << "step " << k;  // rounding only
    worst_energy = std::max(worst_energy, std::abs(0.5 * omega.dot(L) / E0 - 1.0));
  }
  EXPECT_LT(worst_energy, 1e-4);
  EXPECT_NEAR(q.norm(), 1.0, 1e-14);

  // Spin about the largest-moment axis with a small wobble stays close to it.
  Eigen::Quaterniond p = Eigen::Quaterniond::Identity();
  Vec3 w(0.01, 0.0, 2.0);
  for (int k = 0; k < 20000; ++k) rotate_rigid_body(p, w, moments, Vec3::Zero(), dt, false);
  EXPECT_GT((p * Vec3::UnitZ()).normalized().dot(angular_momentum(moments, p, w).normalized()),
            0.999);
}

}  // namespace
}  // namespace clumpkit::dem
