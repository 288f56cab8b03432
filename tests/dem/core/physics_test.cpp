// Physics tests of the lean DEM engine against analytic answers.
#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "geom/errors.h"
#include "geom/random.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>

namespace clumpkit::dem {
namespace {

constexpr double kRadius = 0.01;    // m
constexpr double kDensity = 2650;   // kg/m³
constexpr double kStiffness = 1e5;  // N/m
constexpr double kG = 9.81;

double sphere_mass() {
  return 4.0 / 3.0 * M_PI * std::pow(kRadius, 3) * kDensity;
}

TEST(DemContact, RestitutionFormulaRoundTrips) {
  for (double e : {0.1, 0.5, 0.9, 1.0})
    EXPECT_NEAR(restitution_from_damping_ratio(damping_ratio_from_restitution(e)), e, 1e-14);
  EXPECT_DOUBLE_EQ(damping_ratio_from_restitution(1.0), 0.0);
  EXPECT_THROW(damping_ratio_from_restitution(0.0), InvalidInput);
  EXPECT_THROW(damping_ratio_from_restitution(1.5), InvalidInput);
}

TEST(DemContact, LocalDampingOpposesVelocitySign) {
  const Vec3 f = local_damping(Vec3(2.0, -4.0, 1.0), Vec3(1.0, 1.0, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(f.x(), 1.0);   // 2 − 0.5·2
  EXPECT_DOUBLE_EQ(f.y(), -6.0);  // −4 − 0.5·4
  EXPECT_DOUBLE_EQ(f.z(), 1.0);   // v = 0: untouched
}

TEST(DemContact, ShearHistoryRotatesWithContactPlane) {
  ContactParams p;
  p.kn = 1e5;
  p.ks = 1e5;
  p.friction = 10.0;
  ContactState s;
  s.shear = Vec3(3.0, 0.0, 0.0);
  // The normal tilts from z to a direction in the x–z plane: the shear stays tangent, same size.
  const Vec3 n = Vec3(0.3, 0.0, 1.0).normalized();
  update_contact(s, n, 1e-4, Vec3::Zero(), Vec3::Zero(), 1.0, p, 1e-5);
  EXPECT_NEAR(s.shear.dot(n), 0.0, 1e-14);
  EXPECT_NEAR(s.shear.norm(), 3.0, 1e-14);
  EXPECT_NEAR(s.normal_force, 10.0, 1e-12);
}

TEST(DemBody, ClumpBodyKeepsSphereWorldPositions) {
  Clump clump{{Sphere{Vec3(0.1, 0.2, 0.3), 0.05}, Sphere{Vec3(0.16, 0.2, 0.31), 0.04},
               Sphere{Vec3(0.1, 0.25, 0.28), 0.03}}};
  const Body b = make_clump_body(clump, 2000.0);
  for (std::size_t k = 0; k < clump.spheres.size(); ++k) {
    const Vec3 world = b.position + b.orientation * b.spheres[k].center;
    EXPECT_NEAR((world - clump.spheres[k].center).norm(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(b.spheres[k].radius, clump.spheres[k].radius);
  }
  EXPECT_GT(b.mass, 0.0);
  EXPECT_LE(b.moments.x(), b.moments.y());
  EXPECT_LE(b.moments.y(), b.moments.z());
  const Body s = make_sphere_body(Vec3::Zero(), 0.5, 1000.0);
  EXPECT_NEAR(s.mass, 4.0 / 3.0 * M_PI * 0.125 * 1000.0, 1e-9);
  EXPECT_THROW(make_sphere_body(Vec3::Zero(), -1.0, 1000.0), InvalidInput);
}

// A sphere resting on the floor under gravity settles to the overlap δ = m·g / kn.
TEST(DemPhysics, RestingSphereOverlapIsWeightOverStiffness) {
  WorldOptions o;
  o.contact.kn = kStiffness;
  o.contact.ks = kStiffness;
  o.contact.damping_ratio = 0.5;
  const double m = sphere_mass();
  o.timestep = 0.05 * std::sqrt(m / kStiffness);
  World world(o);
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  world.add_body(make_sphere_body(Vec3(0.0, 0.0, kRadius), kRadius, kDensity));
  // ζ·ω0·t ≈ 0.5·0.05·steps: 3000 steps damp the oscillation by e^-75.
  world.step(3000);
  const double expected = m * kG / kStiffness;
  const double overlap = kRadius - world.bodies()[0].position.z();
  EXPECT_NEAR(overlap / expected, 1.0, 1e-6);
  ASSERT_EQ(world.wall_contacts().size(), 1u);
  EXPECT_NEAR(world.wall_contacts()[0].state.normal_force / (m * kG), 1.0, 1e-6);
  EXPECT_LT(mean_unbalanced_force_ratio(world), 1e-6);
  EXPECT_LT(kinetic_energy(world), 1e-15);
}

// Head-on collision of two equal spheres: the rebound/approach speed ratio equals the
// restitution implied by the damping ratio, e = exp(−βπ/sqrt(1−β²)).
TEST(DemPhysics, HeadOnCollisionGivesRestitutionOfDamping) {
  for (double e : {0.9, 0.5, 0.2}) {
    WorldOptions o;
    o.gravity = Vec3::Zero();
    o.contact.kn = kStiffness;
    o.contact.ks = kStiffness;
    o.contact.friction = 0.5;
    o.contact.damping_ratio = damping_ratio_from_restitution(e);
    const double m = sphere_mass();
    o.timestep = 0.005 * std::sqrt(m / kStiffness);
    World world(o);
    const double v0 = 0.1;
    Body a = make_sphere_body(Vec3(-kRadius - 1e-4, 0, 0), kRadius, kDensity);
    Body b = make_sphere_body(Vec3(kRadius + 1e-4, 0, 0), kRadius, kDensity);
    a.velocity = Vec3(v0, 0, 0);
    b.velocity = Vec3(-v0, 0, 0);
    world.add_body(a);
    world.add_body(b);
    bool touched = false;
    for (int s = 0; s < 20000 && (!touched || !world.contacts().empty()); ++s) {
      world.step();
      touched = touched || !world.contacts().empty();
    }
    ASSERT_TRUE(touched);
    ASSERT_TRUE(world.contacts().empty());
    const double rebound = world.bodies()[1].velocity.x() - world.bodies()[0].velocity.x();
    EXPECT_NEAR(rebound / (2 * v0), e, 0.01 * e) << "e = " << e;
    // Momentum is conserved exactly (equal and opposite contact forces).
    EXPECT_NEAR(world.bodies()[0].velocity.x() + world.bodies()[1].velocity.x(), 0.0, 1e-15);
  }
}

// A free, undamped three-sphere clump spinning about a non-principal axis keeps its kinetic
// energy and angular momentum while its angular velocity precesses.
TEST(DemPhysics, FreeClumpKeepsEnergyAndAngularMomentum) {
  Clump clump{{Sphere{Vec3(0, 0, 0), 0.01}, Sphere{Vec3(0.012, 0, 0), 0.007},
               Sphere{Vec3(0, 0.009, 0.003), 0.005}}};
  WorldOptions o;
  o.gravity = Vec3::Zero();
  const Vec3 omega0(10.0, 20.0, 30.0);
  o.timestep = 1e-3 / omega0.norm();  // 1 mrad per step
  World world(o);
  Body b = make_clump_body(clump, kDensity);
  b.angular_velocity = omega0;
  world.add_body(b);
  const double e0 = kinetic_energy(world);
  const Vec3 l0 = world.bodies()[0].angular_momentum();
  world.step(20000);
  const Body& after = world.bodies()[0];
  EXPECT_NEAR(kinetic_energy(world) / e0, 1.0, 1e-4);
  EXPECT_LT((after.angular_momentum() - l0).norm() / l0.norm(), 1e-4);
  // Not a trivial steady spin: ω has turned away from ω0.
  EXPECT_GT(std::acos(after.angular_velocity.normalized().dot(omega0.normalized())), 0.05);
  EXPECT_NEAR(after.orientation.norm(), 1.0, 1e-12);
}

// A 2×2 four-sphere clump on the floor with gravity tilted by θ (the incline): it slides with
// a = g·(sinθ − μ·cosθ) when tanθ > μ and stays put when tanθ < μ.
double incline_run(double theta, double mu, double* acceleration) {
  WorldOptions o;
  o.gravity = kG * Vec3(std::sin(theta), 0.0, -std::cos(theta));
  o.contact.kn = kStiffness;
  o.contact.ks = kStiffness;
  o.contact.friction = mu;
  o.contact.damping_ratio = 0.5;
  o.timestep = 0.05 * std::sqrt(sphere_mass() / kStiffness);
  World world(o);
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  const double a = 0.9 * kRadius;
  Clump clump;
  for (double x : {-a, a})
    for (double y : {-a, a}) clump.spheres.push_back(Sphere{Vec3(x, y, kRadius), kRadius});
  world.add_body(make_clump_body(clump, kDensity));
  const double x0 = world.bodies()[0].position.x();
  const double t1 = 0.05, t2 = 0.2;
  world.step(static_cast<int>(t1 / o.timestep));
  const double v1 = world.bodies()[0].velocity.x(), time1 = world.time();
  world.step(static_cast<int>((t2 - t1) / o.timestep));
  *acceleration = (world.bodies()[0].velocity.x() - v1) / (world.time() - time1);
  EXPECT_EQ(world.wall_contacts().size(), 4u);
  return world.bodies()[0].position.x() - x0;
}

TEST(DemPhysics, BlockOnInclineSlidesExactlyAboveFrictionAngle) {
  const double mu = 0.5;
  const double phi = std::atan(mu);
  const double degree = M_PI / 180.0;
  double acceleration = 0.0;
  const double slide_theta = phi + 3 * degree;
  const double slid = incline_run(slide_theta, mu, &acceleration);
  const double expected = kG * (std::sin(slide_theta) - mu * std::cos(slide_theta));
  EXPECT_NEAR(acceleration / expected, 1.0, 0.02);
  EXPECT_GT(slid, 0.5 * 0.5 * expected * 0.2 * 0.2);
  const double stuck = incline_run(phi - 3 * degree, mu, &acceleration);
  // Sticking: only the elastic shear deflection m·g·sinθ/ks-ish (µm), against ~1 cm sliding.
  EXPECT_LT(std::abs(stuck), 1e-5);
  EXPECT_LT(std::abs(acceleration), 1e-3 * expected);
}

// Changing μ keeps the shear history: |Fs| after the rescale = min(|Fs| before, μ_new·Fn).
TEST(DemPhysics, FrictionChangeKeepsShearHistory) {
  WorldOptions o;
  const double theta = std::atan(0.2);
  o.gravity = kG * Vec3(std::sin(theta), 0.0, -std::cos(theta));
  o.contact.kn = kStiffness;
  o.contact.ks = kStiffness;
  o.contact.friction = 0.5;
  o.contact.damping_ratio = 0.7;
  o.contact.local_damping = 0.5;  // settles the (undamped) shear-spring oscillation
  o.timestep = 0.05 * std::sqrt(sphere_mass() / kStiffness);
  World world(o);
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  Body b = make_sphere_body(Vec3(0, 0, kRadius), kRadius, kDensity);
  b.rotation_locked = true;  // a sliding block, not a rolling ball
  world.add_body(b);
  world.step(2000);
  ASSERT_EQ(world.wall_contacts().size(), 1u);
  const ContactState before = world.wall_contacts()[0].state;
  const double ratio = before.shear.norm() / before.normal_force;
  ASSERT_GT(ratio, 0.05);  // a real shear history exists
  ASSERT_LT(ratio, 0.45);

  world.rescale_friction(0.45);  // above the mobilised ratio: nothing changes
  EXPECT_EQ(world.wall_contacts()[0].state.shear, before.shear);
  world.rescale_friction(0.1);  // below: clamped onto the new Coulomb limit, same direction
  const ContactState after = world.wall_contacts()[0].state;
  EXPECT_NEAR(after.shear.norm(), 0.1 * before.normal_force, 1e-12 * before.normal_force);
  EXPECT_NEAR(after.shear.normalized().dot(before.shear.normalized()), 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(world.options().contact.friction, 0.1);
  // The contact keeps its (clamped) history in the next step, and now slides.
  world.step();
  ASSERT_EQ(world.wall_contacts().size(), 1u);
  const ContactState next = world.wall_contacts()[0].state;
  EXPECT_NEAR(next.shear.norm(), 0.1 * next.normal_force, 1e-9 * next.normal_force);
}

// A pile of spheres and clumps falling into a cylinder: bit-identical for 1 and 2 threads.
World make_pile() {
  WorldOptions o;
  o.contact.kn = kStiffness;
  o.contact.ks = kStiffness;
  o.contact.friction = 0.5;
  o.contact.damping_ratio = 0.3;
  o.contact.local_damping = 0.2;
  o.skin = 0.2 * kRadius;
  World world(o);
  const double rc = 0.06;
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  world.add_wall(Wall::cylinder(0.0, 0.0, rc));
  Rng rng(7);
  int placed = 0;
  for (int layer = 0; layer < 12; ++layer)
    for (int ix = -2; ix <= 2; ++ix)
      for (int iy = -2; iy <= 2; ++iy) {
        const double dy = rng.uniform(-1e-3, 1e-3);  // y before x, as GCC drew them (Rng::uniform)
        const double dx = rng.uniform(-1e-3, 1e-3);
        const Vec3 c(ix * 0.022 + dx, iy * 0.022 + dy, 0.012 + layer * 0.025);
        if (std::hypot(c.x(), c.y()) > rc - 0.016) continue;
        if (placed++ % 5 == 0) {
          Clump clump{{Sphere{c + Vec3(-0.004, 0, 0), 0.007}, Sphere{c + Vec3(0.004, 0, 0), 0.006},
                       Sphere{c + Vec3(0, 0.004, 0.002), 0.005}}};
          Body b = make_clump_body(clump, kDensity);
          b.angular_velocity = 10.0 * rng.unit_vector();
          b.velocity = Vec3(0.0, 0.0, -1.0);
          world.add_body(b);
        } else {
          Body b = make_sphere_body(c, rng.uniform(0.6, 1.0) * kRadius, kDensity);
          b.velocity = Vec3(0.0, 0.0, -1.0) + 0.3 * rng.unit_vector();
          world.add_body(b);
        }
      }
  world.options().timestep = 0.2 * critical_timestep(world);
  return world;
}

TEST(DemPhysics, ResultsAreBitIdenticalForOneAndTwoThreads) {
  std::vector<World> runs;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    World world = make_pile();
    world.step(10000);
    runs.push_back(std::move(world));
  }
  const World& a = runs[0];
  const World& b = runs[1];
  ASSERT_GT(a.contacts().size(), 20u);
  ASSERT_GT(a.wall_contacts().size(), 5u);
  EXPECT_LT(a.neighbour_builds(), a.steps());  // the Verlet skin saves rebuilds
  // Everything stays inside the cylinder (up to the contact overlap) and above the floor.
  for (const Body& body : a.bodies())
    for (const Sphere& s : body.spheres) {
      const Vec3 c = body.position + body.orientation * s.center;
      EXPECT_LT(std::hypot(c.x(), c.y()) + s.radius, 0.06 + 1e-3);
      EXPECT_GT(c.z() - s.radius, -1e-3);
    }
  ASSERT_EQ(a.bodies().size(), b.bodies().size());
  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  for (std::size_t k = 0; k < a.bodies().size(); ++k) {
    const Body& p = a.bodies()[k];
    const Body& q = b.bodies()[k];
    EXPECT_EQ(std::memcmp(p.position.data(), q.position.data(), sizeof(double) * 3), 0);
    EXPECT_EQ(std::memcmp(p.velocity.data(), q.velocity.data(), sizeof(double) * 3), 0);
    EXPECT_EQ(std::memcmp(p.orientation.coeffs().data(), q.orientation.coeffs().data(),
                          sizeof(double) * 4),
              0);
    EXPECT_EQ(std::memcmp(p.angular_velocity.data(), q.angular_velocity.data(), sizeof(double) * 3),
              0);
  }
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    EXPECT_EQ(a.contacts()[k].i, b.contacts()[k].i);
    EXPECT_EQ(a.contacts()[k].j, b.contacts()[k].j);
    EXPECT_EQ(a.contacts()[k].state.shear, b.contacts()[k].state.shear);
  }
  // Contacts are sorted by (i, j) and never within one body.
  for (std::size_t k = 0; k < a.contacts().size(); ++k) {
    EXPECT_NE(a.sphere_body(a.contacts()[k].i), a.sphere_body(a.contacts()[k].j));
    if (k > 0) {
      EXPECT_LT(std::make_pair(a.contacts()[k - 1].i, a.contacts()[k - 1].j),
                std::make_pair(a.contacts()[k].i, a.contacts()[k].j));
    }
  }
}

// A top platen (plane wall moving down) squeezing a sphere against the floor: the platen moves
// by v·t and the two walls share the squeeze, so each overlap is v·t/2 and Fn ≈ kn·v·t/2.
TEST(DemWorld, MovingPlatenSqueezesSphere) {
  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.contact.kn = kStiffness;
  o.contact.ks = kStiffness;
  o.contact.damping_ratio = 0.7;
  o.timestep = 0.05 * std::sqrt(sphere_mass() / kStiffness);
  World world(o);
  const double v = 1e-3;
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  const int top =
      world.add_wall(Wall::plane(Vec3(0, 0, 2 * kRadius), -Vec3::UnitZ(), Vec3(0, 0, -v)));
  world.add_body(make_sphere_body(Vec3(0, 0, kRadius), kRadius, kDensity));
  world.step(30000);
  const double squeeze = v * world.time();
  EXPECT_NEAR(world.walls()[top].point.z(), 2 * kRadius - squeeze, 1e-12);
  ASSERT_EQ(world.wall_contacts().size(), 2u);
  for (const WallContact& c : world.wall_contacts())
    EXPECT_NEAR(c.state.normal_force / (kStiffness * squeeze / 2), 1.0, 0.02);
  EXPECT_NEAR(world.bodies()[0].position.z(), kRadius - squeeze / 2, 0.02 * squeeze);
}

TEST(DemWorld, CriticalTimestepAndBadInput) {
  WorldOptions o;
  o.contact.kn = kStiffness;
  o.contact.ks = kStiffness;
  World world(o);
  world.add_body(make_sphere_body(Vec3::Zero(), kRadius, kDensity));
  // Sphere: translation sqrt(m/kn); rotation sqrt(0.4·m·r²/(kn·r²)) is the smaller.
  EXPECT_NEAR(critical_timestep(world), std::sqrt(0.4 * sphere_mass() / kStiffness), 1e-15);
  EXPECT_THROW(world.add_body(Body{}), InvalidInput);
  EXPECT_THROW(world.rescale_friction(-1.0), InvalidInput);
  WorldOptions bad;
  bad.timestep = 0.0;
  EXPECT_THROW(World{bad}, InvalidInput);
  for (double fraction : {0.0, -0.5, 1.5, std::nan("")}) {
    WorldOptions near;
    near.near_skin_fraction = fraction;
    EXPECT_THROW(World{near}, InvalidInput) << fraction;
  }
  EXPECT_THROW(Wall::cylinder(0, 0, 0), InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
