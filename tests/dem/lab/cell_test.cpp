// The test cell (dem/lab/cell.h) under servo control: a servo wall holds its target stress at
// equilibrium, and the Love–Weber stress of the settled packing equals the walls' stress.
#include "dem/lab/cell.h"
#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "tests/dem/loose_packing.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace clumpkit;
using namespace clumpkit::dem;

TEST(DemServo, SpeedClosesTheErrorAgainstTheContactStiffness) {
  ServoGain g;
  g.relaxation = 0.5;
  g.max_speed = 1.0;
  // Under-stressed by 1 kPa on 1 m² against 1e6 N/m in a 1e-4 s step: move in 0.5·1e3/1e6 m
  // in that step, 5 m/s, clamped to 1.
  EXPECT_DOUBLE_EQ(servo_speed(99e3, 100e3, 1.0, 1e6, 1e-4, g), 1.0);
  EXPECT_DOUBLE_EQ(servo_speed(99.99e3, 100e3, 1.0, 1e6, 1e-4, g), 0.05);
  EXPECT_DOUBLE_EQ(servo_speed(100.01e3, 100e3, 1.0, 1e6, 1e-4, g), -0.05);
  EXPECT_DOUBLE_EQ(servo_speed(0, 100e3, 1.0, 0.0, 1e-4, g), 1.0);  // no contact: close in
  g.relaxation = 0;
  EXPECT_THROW(servo_speed(0, 1, 1, 1, 1, g), InvalidInput);
}

TEST(DemServo, SettledIsotropicPackingHoldsItsTargetAndLoveWeberMatchesTheWalls) {
  // Under the sanitizers a 7 × 7 × 7 packing (343 spheres; equilibrium in 16,900 steps, ~3x less
  // work): the same servo and the same checks, Love–Weber's equality with the walls being statics
  // at any size. The Release pass settles 10 × 10 × 10 spheres.
  const int n = kSanitized ? 7 : 10;
  test::LoosePacking p = test::loose_packing(n, n, n, 1.0, true);
  // Every wall under a stress servo (drive_cell, as the consolidation of an element test) until
  // every wall is within 0.5 % of the target and the unbalanced-force ratio below 1e-3.
  const double target = 100e3;
  const Control confine{Control::Mode::stress, target, 0.0};
  ServoGain gain;
  gain.max_speed = 0.2;
  const std::vector<int> walls = cell_walls(p.cell);
  const auto wall_stresses = [&] {
    const Vec3 l = cell_lengths(p.world, p.cell);
    std::vector<double> s;
    for (int a = 0; a < 3; ++a)
      for (int side = 0; side < 2; ++side)
        s.push_back(wall_stress(p.world, walls[2 * a + side], l[(a + 1) % 3] * l[(a + 2) % 3]));
    return s;
  };
  long long steps = 0;
  bool reached = false;
  while (!reached && steps < 2'000'000) {
    for (int k = 0; k < 100; ++k) drive_cell(p.world, p.cell, confine, confine, gain, 1);
    steps += 100;
    reached = mean_unbalanced_force_ratio(p.world) <= 1e-3;
    for (double s : wall_stresses()) reached = reached && std::abs(s / target - 1.0) <= 0.005;
  }
  const Vec3 stress = cell_axis_stress(p.world, p.cell);
  std::printf(
      "consolidated in %lld steps: wall stress %.1f %.1f %.1f Pa, unbalanced %.2e, Z %.2f\n", steps,
      stress.x(), stress.y(), stress.z(), mean_unbalanced_force_ratio(p.world),
      coordination_number(p.world));
  ASSERT_TRUE(reached);
  // Every wall, not only each axis' mean, within 1 % of the target.
  for (double s : wall_stresses()) EXPECT_NEAR(s, target, 1e3);
  EXPECT_NEAR(lateral_stress(p.world, p.cell), target, 1e3);
  EXPECT_NEAR(axial_stress(p.world, p.cell), target, 1e3);
  // Love–Weber over the cell: the diagonal equals the wall stress within 2 % and the mean
  // stress is the target. (The off-diagonal need not vanish: the walls' normal pressures are not
  // uniform, and their moments give the average a shear part of ~1 %.)
  const Mat3 lw = cell_love_weber_stress(p.world, p.cell);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(lw(a, a) / stress[a], 1.0, 0.02);
  EXPECT_NEAR(mean_stress(lw), 100e3, 2e3);
  EXPECT_NEAR((lw - lw.transpose()).norm(), 0.0, 1e-9);  // symmetrised
  std::printf("Love-Weber diagonal %.1f %.1f %.1f Pa, off-diagonal max %.1f Pa\n", lw(0, 0),
              lw(1, 1), lw(2, 2), (lw - Mat3(lw.diagonal().asDiagonal())).cwiseAbs().maxCoeff());
}

TEST(DemCell, CylinderCellSizesAndLoveWeberOfASqueezedSphere) {
  // One sphere of radius r pressed by both platens (overlap δ each) in a cylinder of radius
  // 2r: the platen force F on area A gives σ_a = F/A, and Love–Weber over the cell's volume
  // A·h, with branch vectors of length about r − δ, gives σ_zz = 2F(r − δ)/(A·h) = σ_a
  // (h = 2(r − δ)), up to where in the overlap the contact point sits: O(δ/r) = 1e-3.
  WorldOptions o;
  o.gravity = Vec3::Zero();
  World w(o);
  const double r = 0.01, delta = 1e-5, h = 2 * (r - delta);
  w.add_body(make_sphere_body(Vec3(0, 0, 0.5 * h), r, 2650));
  const TestCell cell = add_cylinder_test_cell(w, 2 * r, 0.0, h);
  w.step(1);
  EXPECT_EQ(cell_walls(cell), (std::vector<int>{cell.lateral[0], cell.bottom, cell.top}));
  EXPECT_EQ(cell_lengths(w, cell), Vec3(4 * r, 4 * r, h));
  EXPECT_NEAR(cell_volume(w, cell), 3.14159265358979323846 * 4 * r * r * h, 1e-18);
  const double sa = axial_stress(w, cell);
  ASSERT_GT(sa, 0.0);
  EXPECT_EQ(lateral_stress(w, cell), 0.0);
  const Mat3 lw = cell_love_weber_stress(w, cell);
  EXPECT_NEAR(lw(2, 2) / sa, 1.0, 1e-3);
  EXPECT_NEAR(lw(0, 0), 0.0, 1e-9 * sa);
  EXPECT_THROW(cell_axis_stress(w, cell), InvalidInput);
}

TEST(DemCell, SegmentCellSizesStressesAndRecord) {
  // A sphere of radius r in the corner of a 60° segment, pressed against the cylinder (overlap
  // δ), not touching the radial planes: the lateral stress is the cylinder's push over the arc
  // θ·R·h, the axial area θR²/2, and the record keeps the angle.
  WorldOptions o;
  o.gravity = Vec3::Zero();
  World w(o);
  const double r = 0.01, delta = 1e-5, R = 0.1, h = 0.05, angle = M_PI / 3.0;
  const Vec3 dir(std::cos(angle / 2), std::sin(angle / 2), 0.0);  // the bisector
  w.add_body(make_sphere_body((R - r + delta) * dir + Vec3(0, 0, 0.5 * h), r, 2650));
  const TestCell cell = add_segment_test_cell(w, R, angle, 0.0, h);
  ASSERT_EQ(cell.lateral.size(), 3u);
  EXPECT_EQ(cell_fraction(cell), 1.0 / 6.0);
  w.step(1);
  EXPECT_NEAR(cell_volume(w, cell), 0.5 * angle * R * R * h, 1e-18);
  ASSERT_EQ(w.wall_contacts().size(), 1u);
  const double push = w.wall_contacts()[0].state.normal_force;
  EXPECT_NEAR(push, o.contact.kn * delta, 1e-9 * push);
  EXPECT_NEAR(lateral_stress(w, cell), push / (angle * R * h), 1e-9 * push / (angle * R * h));
  // The radial planes pass through the axis, inward normals at φ = 0 and φ = θ.
  EXPECT_EQ(w.walls()[cell.lateral[1]].normal, Vec3::UnitY());
  EXPECT_NEAR(
      (w.walls()[cell.lateral[2]].normal - Vec3(std::sin(angle), -std::cos(angle), 0.0)).norm(),
      0.0, 1e-15);
  // Love–Weber counts the sphere inside the sector (its branch vector radial: σ_rr only).
  const Mat3 lw = cell_love_weber_stress(w, cell);
  EXPECT_GT(lw.trace(), 0.0);
  StageRecord rec;
  put_cell(rec, cell);
  const TestCell back = read_cell(rec, "x");
  EXPECT_EQ(back.shape, TestCell::Shape::segment);
  EXPECT_EQ(back.angle, angle);
  EXPECT_EQ(back.lateral, cell.lateral);
  EXPECT_THROW(add_segment_test_cell(w, R, 1.2 * M_PI, 0.0, h), InvalidInput);
  // Driven under stress control, the planes of symmetry stay where they are.
  drive_cell(w, cell, Control{Control::Mode::stress, 1e5, 0.0},
             Control{Control::Mode::stress, 1e5, 0.0}, ServoGain{0.5, 1.0}, 10);
  EXPECT_EQ(w.walls()[cell.lateral[1]].point, Vec3::Zero());
  EXPECT_EQ(w.walls()[cell.lateral[2]].point, Vec3::Zero());
}
