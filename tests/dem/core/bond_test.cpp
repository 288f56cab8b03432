// Bonds between rigid bodies: the face's stiffness and strength, balance of forces and moments,
// no force under a rigid motion (and forces that turn with one), fragments.
#include "dem/core/bond.h"

#include "geom/random.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

constexpr double kA = 0.0065;  // m: cube edge, Hu et al. 2023's cell size

// Two cubic cells side by side along x, bonded on their shared face x = a/2 by four points (the
// centres of the face's quarters, a²/4 each).
struct Pair {
  Body a, b;
  Bond bond;
};
Pair cubes(double factor = 1.0) {
  Pair p;
  p.a = make_sphere_body(Vec3::Zero(), 0.5 * kA, 2650);
  p.b = make_sphere_body(Vec3(kA, 0, 0), 0.5 * kA, 2650);
  std::vector<Vec3> points;
  for (double y : {-0.25 * kA, 0.25 * kA})
    for (double z : {-0.25 * kA, 0.25 * kA}) points.emplace_back(0.5 * kA, y, z);
  p.bond =
      make_bond(p.a, p.b, 0, 1, Vec3::UnitX(), points, std::vector<double>(4, kA * kA / 4), factor);
  return p;
}

// Σ (τ_i + x_i × F_i) and Σ F_i of a bond's wrench: both zero for an internal force pair.
void expect_balanced(const BondWrench& w, const Body& a, const Body& b, double scale) {
  EXPECT_LT((w.force_a + w.force_b).norm(), 1e-12 * scale);
  const Vec3 moment =
      w.torque_a + a.position.cross(w.force_a) + w.torque_b + b.position.cross(w.force_b);
  EXPECT_LT(moment.norm(), 1e-12 * scale * kA);
}

}  // namespace

TEST(Bond, FaceStiffnessAndStrength) {
  const CohesiveParams law;
  Pair p = cubes();
  const double area = kA * kA;
  // Opening u (below onset): b is pulled back by K_I·u·A, a forward; no torque by symmetry.
  const double u = 0.5 * law.sigma_n / law.kn;
  p.b.position.x() += u;
  BondWrench w = bond_wrench(p.bond, law, p.a, p.b);
  EXPECT_NEAR(w.force_b.x() / (-law.kn * u * area), 1.0, 1e-12);
  EXPECT_NEAR(w.force_b.tail<2>().norm(), 0.0, 1e-9);
  EXPECT_LT(w.torque_b.norm(), 1e-12);
  expect_balanced(w, p.a, p.b, law.sigma_n * area);
  // Slip s along y: K_II·s·A against it, and the couple of a force on the face.
  Pair q = cubes();
  const double s = 0.5 * law.sigma_t / law.kt;
  q.b.position.y() += s;
  w = bond_wrench(q.bond, law, q.a, q.b);
  EXPECT_NEAR(w.force_b.y() / (-law.kt * s * area), 1.0, 1e-12);
  EXPECT_GT(w.torque_b.norm(), 0.0);
  expect_balanced(w, q.a, q.b, law.sigma_t * area);
  // The face's strength: the largest stress over an opening sweep is σ_eI (× the face's factor),
  // reached at δ_e, and the face is broken at δ_u.
  for (double factor : {1.0, 0.8}) {
    Pair r = cubes(factor);
    double peak = 0;
    const double du = law.sigma_n / law.kn / 1000;
    for (int k = 1; k <= 3000; ++k) {
      r.b.position.x() = kA + k * du;
      peak = std::max(peak, -bond_wrench(r.bond, law, r.a, r.b).force_b.x() / area);
    }
    EXPECT_NEAR(peak / (factor * law.sigma_n), 1.0, 1e-3) << factor;
    EXPECT_FALSE(r.bond.holds());
  }
  EXPECT_DOUBLE_EQ(bond_stiffness(p.bond, law), area * law.kt);
}

TEST(Bond, RigidMotionCarriesNoForceAndTurnsTheForces) {
  const CohesiveParams law;
  Rng rng(17);
  const Pair ref = cubes();
  Pair opened = cubes();
  opened.b.position += Vec3(2e-5, 1e-5, -0.5e-5);  // some opening and slip, below onset
  const BondWrench w0 = bond_wrench(opened.bond, law, opened.a, opened.b);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Quaterniond q = rng.normal_quaternion().normalized();
    const Vec3 t = rng.uniform(Vec3(-1, -1, -1), Vec3(1, 1, 1));
    // Intact and unloaded, moved together: no force.
    Pair p = ref;
    for (Body* body : {&p.a, &p.b}) {
      body->position = q * body->position + t;
      body->orientation = q * body->orientation;
    }
    const BondWrench w = bond_wrench(p.bond, law, p.a, p.b);
    const double scale = 1e-9 * law.sigma_n * kA * kA;
    EXPECT_LT(w.force_a.norm() + w.force_b.norm(), scale);
    EXPECT_LT(w.torque_a.norm() + w.torque_b.norm(), scale * kA);
    EXPECT_EQ(p.bond.points[0].state.damage, 0.0);
    // Loaded, then moved: the same forces, turned by q.
    Pair o = opened;
    for (Body* body : {&o.a, &o.b}) {
      body->position = q * body->position + t;
      body->orientation = q * body->orientation;
    }
    const BondWrench m = bond_wrench(o.bond, law, o.a, o.b);
    EXPECT_LT((m.force_b - q * w0.force_b).norm(), 1e-6 * w0.force_b.norm());
    EXPECT_LT((m.torque_b - q * w0.torque_b).norm(), 1e-6 * w0.torque_b.norm() + 1e-15);
  }
}

TEST(Bond, FailureModeIsTheJumpsDirectionWhenTheFaceBroke) {
  const CohesiveParams law;
  // b pulled away along a direction at angle θ to the face normal, in small steps until the bond
  // breaks: the mix s² = sin²θ at failure, mode I below 30°, mode II above 60°, mixed between.
  // Compression with slip breaks in mode II (s² = 1).
  struct Case {
    double angle_deg;
    double dn_sign;
    BondFailure mode;
  };
  for (const Case c : {Case{0, 1, BondFailure::mode_i}, Case{20, 1, BondFailure::mode_i},
                       Case{45, 1, BondFailure::mixed}, Case{70, 1, BondFailure::mode_ii},
                       Case{90, 1, BondFailure::mode_ii}, Case{80, -1, BondFailure::mode_ii}}) {
    Pair p = cubes();
    EXPECT_EQ(failure_mode(p.bond), BondFailure::intact);
    const double t = c.angle_deg * M_PI / 180;
    const Vec3 dir(c.dn_sign * std::cos(t), std::sin(t), 0.0);
    const double step = 2.0 * law.g_t / law.sigma_t / 2000;  // beyond δ_u of either mode in 4000
    for (int k = 1; k <= 4000 && p.bond.holds(); ++k) {
      p.b.position = Vec3(kA, 0, 0) + k * step * dir;
      bond_wrench(p.bond, law, p.a, p.b);
    }
    ASSERT_FALSE(p.bond.holds()) << c.angle_deg;
    const double s2 = c.dn_sign > 0 ? std::pow(std::sin(t), 2) : 1.0;
    for (const BondPoint& q : p.bond.points)
      EXPECT_NEAR(q.state.failure_mix, s2, 1e-9) << c.angle_deg;
    EXPECT_EQ(failure_mode(p.bond), c.mode) << c.angle_deg;
  }
}

TEST(Bond, FragmentsAreTheComponentsOfHoldingBonds) {
  Pair p = cubes();
  Bond held = p.bond, broken = p.bond, other = p.bond;
  for (BondPoint& q : broken.points) q.state.damage = 1.0;
  broken.points[0].state.damage = 1.0;
  held.a = 1, held.b = 0;
  broken.a = 1, broken.b = 2;
  other.a = 4, other.b = 3;
  EXPECT_EQ(fragments(5, {held, broken, other}), (std::vector<int>{0, 0, 2, 3, 3}));
  EXPECT_EQ(fragments(5, {other, broken, held}), (std::vector<int>{0, 0, 2, 3, 3}));
  broken.points[2].state.damage = 0.9;  // one point still holds: the bond holds
  EXPECT_EQ(fragments(5, {held, broken, other}), (std::vector<int>{0, 0, 0, 3, 3}));
  EXPECT_EQ(fragments(3, {}), (std::vector<int>{0, 1, 2}));
  // Numbered from 1 in the order of their smallest body, as the VTP and the pages colour them.
  EXPECT_EQ(fragment_ordinals(fragments(5, {held, broken, other})),
            (std::vector<int>{1, 1, 1, 2, 2}));
  broken.points[2].state.damage = 1.0;
  EXPECT_EQ(fragment_ordinals(fragments(5, {other, broken, held})),
            (std::vector<int>{1, 1, 2, 3, 3}));
  EXPECT_EQ(fragment_ordinals({}), std::vector<int>{});
}
