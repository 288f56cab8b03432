// Exact sphere–region volumes, porosity and coordination number of a region (dem/measure/
// region_volume.h).
#include "dem/measure/region_volume.h"

#include "dem/core/world.h"
#include "geom/errors.h"
#include "geom/volume/union_of_balls.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace clumpkit::dem {
namespace {

Body ball(const Vec3& c, double r) {
  Body b;
  b.spheres = {{Vec3::Zero(), r}};
  b.position = c;
  b.mass = 1;
  b.moments = Vec3::Ones();
  b.volume = 4.0 / 3.0 * M_PI * r * r * r;
  return b;
}

// A three-sphere clump straddling the side wall r = 0.5 and the plane z = 0.5.
Body cut_clump() {
  Body c;
  c.spheres = {
      {Vec3(-0.05, 0, 0), 0.08}, {Vec3(0.05, 0.02, 0), 0.07}, {Vec3(0, -0.04, 0.05), 0.06}};
  c.mass = 1;
  c.moments = Vec3::Ones();
  c.position = Vec3(0.48, 0.0, 0.5);
  c.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  return c;
}

TEST(RegionVolume, SphereInsideCutByPlaneAndOutside) {
  const CylinderRegion region{0.5, 0.0, 1.0};
  const double r = 0.1, v = 4.0 / 3.0 * M_PI * r * r * r;
  EXPECT_DOUBLE_EQ(body_region_volume(ball(Vec3(0, 0, 0.5), r), v, region), v);
  EXPECT_EQ(body_region_volume(ball(Vec3(0, 0, 1.2), r), v, region), 0.0);
  // Cut through the centre by the top plane: half. Below the floor z = 0 a cap of height h,
  // πh²(3r − h)/3, is cut off.
  EXPECT_NEAR(body_region_volume(ball(Vec3(0.1, 0, 1.0), r), v, region), 0.5 * v, 1e-9 * v);
  const double h = 0.04;
  EXPECT_NEAR(body_region_volume(ball(Vec3(0, 0.2, r - h), r), v, region),
              v - M_PI * h * h * (3 * r - h) / 3, 1e-9 * v);
}

// A single sphere takes the closed forms (the cap between the planes, the lens of its slice and
// the region's disk at the side wall); the same sphere given twice takes the clump's union of
// disks: both agree to the quadrature's tolerance, wherever the region cuts the sphere.
TEST(RegionVolume, OneSphereAgreesWithTheUnionOfDisksPath) {
  const CylinderRegion region{0.5, 0.0, 1.0};
  const double r = 0.1, v = 4.0 / 3.0 * M_PI * r * r * r;
  for (double rho : {0.0, 0.3, 0.42, 0.45, 0.5, 0.55, 0.59})
    for (double z : {0.5, 0.95, 1.0, 1.07, 0.03, -0.05}) {
      const Body one = ball(Vec3(rho * 0.6, rho * 0.8, z), r);
      Body two = one;
      two.spheres.push_back(two.spheres.front());
      const double fast = body_region_volume(one, v, region);
      const double general = body_region_volume(two, v, region);
      EXPECT_NEAR(fast, general, 2e-9 * v) << rho << " " << z;
      EXPECT_GE(fast, 0.0);
      EXPECT_LE(fast, v * (1 + 1e-12));
    }
}

TEST(RegionVolume, ComplementaryRegionsAddUpForACutClump) {
  // A three-sphere clump straddling the region's side wall and a horizontal plane: the parts in
  // complementary regions add up to the exact union volume.
  Body c = cut_clump();
  const double v = union_properties(Clump{c.spheres}).mass.volume;
  const double lower = body_region_volume(c, v, {0.5, 0.0, 0.5});
  const double upper = body_region_volume(c, v, {0.5, 0.5, 1.0});
  const double wide = body_region_volume(c, v, {2.0, 0.0, 1.0});
  EXPECT_NEAR(wide, v, 1e-12 * v);
  EXPECT_GT(lower, 0.1 * v);
  EXPECT_GT(upper, 0.1 * v);
  EXPECT_LT(lower + upper, v);  // part of it lies outside r = 0.5
  // Outside the cylinder r < 0.5 but inside r < 2: a ring. Ring = wide − (lower + upper).
  const double outer_ring = wide - lower - upper;
  EXPECT_GT(outer_ring, 0.05 * v);
  // The same body moved to the axis lies wholly inside: its exact volume.
  c.position = Vec3(0, 0, 0.5);
  EXPECT_DOUBLE_EQ(body_region_volume(c, v, {0.5, 0.0, 1.0}), v);
  // Halves by the plane z = 0.5 through a clump centred there, mirrored in z: a sphere pair
  // symmetric about the plane gives equal halves.
  Body s;
  s.spheres = {{Vec3(0, 0, 0.03), 0.05}, {Vec3(0, 0, -0.03), 0.05}};
  s.mass = 1;
  s.moments = Vec3::Ones();
  s.position = Vec3(0.1, 0.1, 0.5);
  const double vs = union_properties(Clump{s.spheres}).mass.volume;
  EXPECT_NEAR(body_region_volume(s, vs, {0.5, 0.0, 0.5}), 0.5 * vs, 1e-9 * vs);
}

// Several ranges at once, each piece of the body's height integrated once: the same parts as one
// range at a time, complementary ranges adding up to the whole, for a clump and a sphere cut by
// the side wall.
TEST(RegionVolume, SeveralRangesAtOnceAgreeWithOneAtATime) {
  Body c = cut_clump();
  const double vc = union_properties(Clump{c.spheres}).mass.volume;
  const std::vector<std::array<double, 2>> ranges = {{0.0, 0.5}, {0.5, 1.0}, {0.45, 0.52},
                                                     {0.0, 1.0}, {0.9, 1.0}, {0.47, 0.5}};
  for (const Body& b : {c, ball(Vec3(0.3, 0.4, 0.49), 0.06)}) {
    const double v = b.spheres.size() == 1 ? b.volume : vc;
    std::vector<double> out;
    body_region_volumes(b, v, 0.5, ranges, out);
    ASSERT_EQ(out.size(), ranges.size());
    for (std::size_t k = 0; k < ranges.size(); ++k)
      EXPECT_NEAR(out[k], body_region_volume(b, v, {0.5, ranges[k][0], ranges[k][1]}), 4e-9 * v)
          << k;
    EXPECT_NEAR(out[0] + out[1], out[3], 2e-9 * v);
    EXPECT_GT(out[2], 0.1 * v);
    EXPECT_EQ(out[4], 0.0);
  }
}

TEST(RegionVolume, PorosityAndCoordinationOfASimpleWorld) {
  World world;
  const double r = 0.01;
  // Three balls in a row touching with a small overlap, inside a region; one far away.
  world.add_body(ball(Vec3(0, 0, 0.05), r));
  world.add_body(ball(Vec3(0.0199, 0, 0.05), r));
  world.add_body(ball(Vec3(0.0398, 0, 0.05), r));
  world.add_body(ball(Vec3(0.3, 0.3, 0.05), r));
  world.options().gravity = Vec3::Zero();
  world.step(1);
  const auto volumes = body_volumes(world);
  const double v = 4.0 / 3.0 * M_PI * r * r * r;
  for (double x : volumes) EXPECT_DOUBLE_EQ(x, v);
  const CylinderRegion region{0.1, 0.0, 0.1};
  EXPECT_NEAR(region_porosity(world, volumes, region), 1.0 - 3 * v / region.volume(), 1e-12);
  // Middle ball touches two, the ends one each: mean 4/3.
  EXPECT_NEAR(coordination_number(world, region), 4.0 / 3.0, 1e-15);
  EXPECT_THROW(region_porosity(world, volumes, {0.1, 0.1, 0.1}), InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
