// The cone penetrometer wall against closed forms: a sphere on the cone feels kn·δ along the
// cone's normal, one sliding on the shaft feels μ times its normal force along the axis, and one
// carried over the cone–shaft junction keeps a continuous force counted on one part only.
#include "dem/core/wall.h"
#include "dem/core/world.h"
#include "dem/measure/stress.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clumpkit::dem {
namespace {

constexpr double kDiameter = 0.018;  // m: the 18 mm cone of the CPT chamber
constexpr double kProbeRadius = 0.5 * kDiameter;
constexpr double kKn = 1e5;  // N/m
constexpr double kMu = 0.5;

// Cone of 60°: its side makes 30° with the axis; its outward meridian normal is (cos 30°, −sin
// 30°).
const double kShoulder = kProbeRadius / std::tan(M_PI / 6.0);  // height of the cone–shaft junction

WorldOptions probe_options() {
  WorldOptions o;
  o.contact.kn = kKn;
  o.contact.ks = kKn;
  o.contact.friction = kMu;
  o.contact.damping_ratio = 0.0;
  o.gravity = Vec3::Zero();
  o.timestep = 1e-6;
  o.skin = 1e-3;
  return o;
}

// A sphere so heavy that a few steps of contact force do not move it measurably.
Body heavy_sphere(const Vec3& centre, double r) {
  Body b = make_sphere_body(centre, r, 1e12);
  return b;
}

TEST(ProbeWall, ProfileIsTheConeAndItsShaft) {
  const Wall w = Wall::probe(Vec3(0.1, 0.2, 0.3), kDiameter, 60.0);
  ASSERT_EQ(w.kind, Wall::Kind::probe);
  ASSERT_EQ(w.profile.size(), 2u);
  EXPECT_EQ(w.profile[0], Eigen::Vector2d(0.0, 0.0));
  EXPECT_NEAR(w.profile[1].x(), kProbeRadius, 1e-15);
  EXPECT_NEAR(w.profile[1].y(), kProbeRadius * std::sqrt(3.0), 1e-15);
  EXPECT_EQ(w.sleeve_from, 1);
  EXPECT_THROW(Wall::probe(Vec3::Zero(), 0.0, 60.0), InvalidInput);
  EXPECT_THROW(Wall::probe(Vec3::Zero(), kDiameter, 180.0), InvalidInput);
  EXPECT_THROW(Wall::probe(Vec3::Zero(), kDiameter, 0.0), InvalidInput);
  Wall bad = w;
  bad.profile[1].y() = -1.0;  // heights must not decrease
  EXPECT_THROW(validate_probe_profile(bad), InvalidInput);
  World world(probe_options());
  EXPECT_THROW(world.add_wall(bad), InvalidInput);
}

// A sphere on the cone's side, δ deep, at an azimuth off the axes: the normal force is kn·δ
// along the cone's outward normal, and the probe feels it on its tip only.
TEST(ProbeWall, SphereOnTheConeFeelsKnDeltaAlongTheConeNormal) {
  const Vec3 apex(0.01, -0.02, 0.05);
  const double r = 0.004, delta = 1e-4, phi = 40.0 * M_PI / 180.0;
  const Vec3 e_rho(std::cos(phi), std::sin(phi), 0.0);
  const Vec3 n = std::cos(M_PI / 6.0) * e_rho - std::sin(M_PI / 6.0) * Vec3::UnitZ();
  const double rho0 = 0.004;  // the foot point on the cone, halfway up the tip
  const Vec3 foot = apex + rho0 * e_rho + rho0 * std::sqrt(3.0) * Vec3::UnitZ();
  const Vec3 centre = foot + (r - delta) * n;

  const WallHit hit = wall_hit(Wall::probe(apex, kDiameter, 60.0), centre, r);
  ASSERT_TRUE(hit.touching);
  EXPECT_NEAR(hit.overlap, delta, 1e-15);
  EXPECT_NEAR((hit.normal - n).norm(), 0.0, 1e-14);
  EXPECT_EQ(hit.part, ProbePart::tip);

  World world(probe_options());
  const int probe = world.add_wall(Wall::probe(apex, kDiameter, 60.0));
  world.add_body(heavy_sphere(centre, r));
  world.step(1);
  ASSERT_EQ(world.wall_contacts().size(), 1u);
  const ContactState& s = world.wall_contacts()[0].state;
  EXPECT_NEAR(s.normal_force, kKn * delta, 1e-12 * kKn * delta);
  const ProbeForces f = probe_forces(world, probe);
  EXPECT_NEAR((f.tip + kKn * delta * n).norm(), 0.0, 1e-12 * kKn * delta);
  EXPECT_EQ(f.sleeve, Vec3::Zero());
  EXPECT_GT(f.tip.z(), 0.0);  // the soil holds the cone up: kn·δ·sin 30°
  EXPECT_NEAR(f.tip.z(), 0.5 * kKn * delta, 1e-12 * kKn * delta);
  EXPECT_THROW(probe_forces(world, 7), InvalidInput);
}

// A sphere pressed on the shaft while the probe is pushed down: once sliding, the axial force on
// the sleeve is μ times the normal force, and nothing reaches the tip.
TEST(ProbeWall, SphereOnTheShaftGivesMuTimesTheNormalForceOnTheSleeve) {
  const double r = 0.003, delta = 5e-5;
  const Vec3 e_rho = Vec3(1.0, 1.0, 0.0).normalized();
  World world(probe_options());
  const int probe =
      world.add_wall(Wall::probe(Vec3::Zero(), kDiameter, 60.0, Vec3(0.0, 0.0, -0.02)));
  world.add_body(heavy_sphere((kProbeRadius + r - delta) * e_rho + 0.05 * Vec3::UnitZ(), r));
  world.step(2000);  // ks·v·dt = 2e-3 N per step: sliding (μ·kn·δ = 2.5 N) after 1,250 steps
  ASSERT_EQ(world.wall_contacts().size(), 1u);
  const ContactState& s = world.wall_contacts()[0].state;
  EXPECT_NEAR(s.normal_force, kKn * delta, 1e-5 * kKn * delta);  // the sphere crept 1e-10 m
  const ProbeForces f = probe_forces(world, probe);
  EXPECT_EQ(f.tip, Vec3::Zero());
  EXPECT_NEAR(f.sleeve.z(), kMu * s.normal_force, 1e-9 * s.normal_force);    // friction resists
  EXPECT_NEAR(f.sleeve.dot(e_rho), -s.normal_force, 1e-9 * s.normal_force);  // pushed inward
}

// A sphere carried round the cone–shaft junction at a constant distance from the profile: the
// overlap and the force stay the same, the normal turns without a jump, and the contact moves
// from the tip to the sleeve once, never on both.
TEST(ProbeWall, JunctionKeepsAContinuousForceOnOnePartAtATime) {
  const double r = 0.003, delta = 1e-4, gap = r - delta;
  const Wall wall = Wall::probe(Vec3::Zero(), kDiameter, 60.0);
  const Eigen::Vector2d corner(kProbeRadius, kShoulder);
  const Eigen::Vector2d cone_n(std::cos(M_PI / 6.0), -std::sin(M_PI / 6.0));
  const Eigen::Vector2d cone_t(std::sin(M_PI / 6.0), std::cos(M_PI / 6.0));  // up the cone
  // The path: along the cone's side, round the corner's fan, up the shaft (meridian x–z).
  std::vector<Eigen::Vector2d> path;
  for (int k = 0; k <= 20; ++k)
    path.push_back(corner - (0.004 * (20 - k) / 20.0) * cone_t + gap * cone_n);
  const double a0 = std::atan2(cone_n.y(), cone_n.x());
  for (int k = 1; k < 60; ++k) {
    const double a = a0 * (60 - k) / 60.0;  // from the cone's normal to the shaft's (0 rad)
    path.push_back(corner + gap * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  for (int k = 0; k <= 20; ++k) path.push_back(corner + Eigen::Vector2d(gap, 0.004 * k / 20.0));

  int switches = 0;
  ProbePart last = ProbePart::tip;
  Vec3 last_normal = Vec3::Zero();
  for (std::size_t k = 0; k < path.size(); ++k) {
    const Vec3 c(path[k].x(), 0.0, path[k].y());
    const WallHit hit = wall_hit(wall, c, r);
    ASSERT_TRUE(hit.touching) << k;
    EXPECT_NEAR(hit.overlap, delta, 1e-12) << k;
    if (k > 0) {
      EXPECT_LT((hit.normal - last_normal).norm(), 0.03) << k;  // ≤ 1.75° per step
    }
    if (k > 0 && hit.part != last) ++switches;
    last = hit.part;
    last_normal = hit.normal;

    // The same sphere in a world: the probe's force is all on the part wall_hit names.
    World world(probe_options());
    const int probe = world.add_wall(wall);
    world.add_body(heavy_sphere(c, r));
    world.step(1);
    const ProbeForces f = probe_forces(world, probe);
    const Vec3 total = wall_force(world, probe);
    EXPECT_NEAR(total.norm(), kKn * delta, 1e-9 * kKn * delta) << k;
    EXPECT_EQ(f.tip + f.sleeve, total) << k;
    EXPECT_TRUE(f.tip == Vec3::Zero() || f.sleeve == Vec3::Zero()) << k;
    EXPECT_EQ(hit.part == ProbePart::tip ? f.sleeve : f.tip, Vec3::Zero()) << k;
  }
  EXPECT_EQ(switches, 1);
  EXPECT_EQ(last, ProbePart::sleeve);
}

// A centre pushed inside the probe is pushed out: the overlap exceeds the radius and the normal
// points out of the solid.
TEST(ProbeWall, CentreInsideTheProbeIsPushedOut) {
  const Wall wall = Wall::probe(Vec3::Zero(), kDiameter, 60.0);
  const WallHit hit = wall_hit(wall, Vec3(kProbeRadius - 0.001, 0.0, 0.05), 0.002);
  EXPECT_NEAR(hit.overlap, 0.003, 1e-15);
  EXPECT_NEAR((hit.normal - Vec3::UnitX()).norm(), 0.0, 1e-15);
  EXPECT_EQ(hit.part, ProbePart::sleeve);
  // Below the apex, on the axis: the apex is the closest point, the normal straight down.
  const WallHit below = wall_hit(wall, Vec3(0.0, 0.0, -0.001), 0.002);
  EXPECT_NEAR(below.overlap, 0.001, 1e-15);
  EXPECT_NEAR((below.normal + Vec3::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_EQ(below.part, ProbePart::tip);
}

}  // namespace
}  // namespace clumpkit::dem
