// The interior axial strain rate (dem/measure/strain_rate.h): the exact slope of an affine
// velocity field, bodies outside the band ignored, a rigid motion read as no strain, and its sum
// over the steps of a uniformly shortening cloud equal to the cloud's logarithmic strain.
#include "dem/measure/strain_rate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clumpkit::dem {
namespace {

// Free spheres (1 mm, 4 mm apart: no contacts) on a 3 × 3 × n grid from z = 0 upward, v_z =
// speed − rate·z, gravity off.
World affine_cloud(int layers, double rate, double speed) {
  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.timestep = 1e-5;
  World world(o);
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        Body b = make_sphere_body(Vec3(0.004 * i, 0.004 * j, 0.004 * k), 0.001, 2650);
        b.velocity = Vec3(0.01 * (i - 1), -0.02 * (j - 1), speed - rate * b.position.z());
        world.add_body(std::move(b));
      }
  return world;
}

TEST(InteriorStrainRate, SlopeOfAnAffineFieldWhateverTheRigidMotion) {
  for (double speed : {0.0, 0.3, -2.0}) {
    const World w = affine_cloud(6, 4.0, speed);
    EXPECT_NEAR(interior_axial_strain_rate(w, -1.0, 1.0), 4.0, 1e-12) << speed;
    EXPECT_NEAR(interior_axial_strain_rate(w, 0.0039, 0.0161), 4.0, 1e-12) << speed;
  }
  // Extension reads negative; no strain reads zero.
  EXPECT_NEAR(interior_axial_strain_rate(affine_cloud(4, -1.5, 0.1), -1.0, 1.0), -1.5, 1e-12);
  EXPECT_EQ(interior_axial_strain_rate(affine_cloud(4, 0.0, 0.7), -1.0, 1.0), 0.0);
}

TEST(InteriorStrainRate, BodiesOutsideTheBandAreIgnored) {
  // Layers 1–3 (z 4–12 mm) shorten at 2/s; layers 0 and 4 (outside) move at anything.
  World w = affine_cloud(5, 2.0, 0.0);
  for (Body& b : w.bodies())
    if (b.position.z() < 0.002 || b.position.z() > 0.014)
      b.velocity.z() = 50.0 * b.position.z() + 3;
  EXPECT_NEAR(interior_axial_strain_rate(w, 0.002, 0.014), 2.0, 1e-12);
  EXPECT_NE(interior_axial_strain_rate(w, -1.0, 1.0), 2.0);
  // One layer (all at one height) or an empty band: no slope.
  EXPECT_EQ(interior_axial_strain_rate(w, 0.003, 0.005), 0.0);
  EXPECT_EQ(interior_axial_strain_rate(w, 0.1, 0.2), 0.0);
}

TEST(InteriorStrainRate, SumOverStepsIsTheLogarithmicStrainOfAShorteningCloud) {
  // Constant velocities v_z = −ε̇·z keep the cloud affine: its height shrinks by 1 − ε̇·t and
  // the slope at time t is ε̇ / (1 − ε̇·t), which integrates to −ln(1 − ε̇·T).
  const double rate = 10.0;
  World w = affine_cloud(6, rate, 0.0);
  const double dt = w.options().timestep;
  const int steps = 2000;  // ε̇·T = 0.2
  double sum = 0;
  for (int k = 0; k < steps; ++k) {
    w.step();
    sum += interior_axial_strain_rate(w, -1.0, 1.0) * dt;
  }
  const double exact = -std::log(1.0 - rate * dt * steps);
  // The sum is a right-endpoint rule: off by about ε̇·dt/2 of the rate's growth (1e-5 here).
  EXPECT_NEAR(sum / exact, 1.0, 1e-4);
  EXPECT_NEAR(-std::expm1(-sum), 0.2, 1e-4);  // the engineering strain the curve reports
}

}  // namespace
}  // namespace clumpkit::dem
