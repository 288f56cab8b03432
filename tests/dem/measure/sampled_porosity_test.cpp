// Point-sampled porosity (dem/measure/sampled_porosity.h): a sphere's and a lens-shaped union's
// volumes against their closed forms, regions split the count, and the counts do not depend on
// the thread count.
#include "dem/measure/sampled_porosity.h"

#include "geom/errors.h"
#include "geom/random.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

namespace clumpkit::dem {
namespace {

double solid_volume(const SampledRegion& s, double spacing) {
  return double(s.solid) * spacing * spacing * spacing;
}

TEST(SampledPorosity, OneSphereHasItsVolumeToATenthOfAPercent) {
  World world;
  const double r = 0.01;
  world.add_body(make_sphere_body(Vec3(0.0013, -0.0007, 0.0002), r, 2650));
  const double h = 0.1 * r;
  const std::vector<SampledRegion> s = sampled_regions(
      world, Vec3::Constant(-0.02), Vec3::Constant(0.02), h, 1, [](const Vec3&) { return 0; });
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].points, 40L * 40 * 40);
  EXPECT_NEAR(solid_volume(s[0], h) / (4.0 / 3.0 * M_PI * r * r * r), 1.0, 1e-3);
  EXPECT_NEAR(s[0].porosity(), 1.0 - 4.0 / 3.0 * M_PI * r * r * r / std::pow(0.04, 3), 1e-4);
}

// Two bodies overlapping by a lens: the union counts the lens once, V = 2·V_sphere − V_lens with
// V_lens = π (2r − d)² (d² + 4 d r) / (12 d) for equal radii r at distance d.
TEST(SampledPorosity, OverlapsCountOnceAndRegionsSplitTheCount) {
  World world;
  const double r = 0.01, d = 0.012;
  world.add_body(make_sphere_body(Vec3(-0.5 * d, 0.0, 0.0), r, 2650));
  world.add_body(make_sphere_body(Vec3(0.5 * d, 0.0, 0.0), r, 2650));
  const double lens = M_PI * (2 * r - d) * (2 * r - d) * (d * d + 4 * d * r) / (12 * d);
  const double exact = 2.0 * 4.0 / 3.0 * M_PI * r * r * r - lens;
  const double h = 0.08 * r;
  // A grid not aligned with the spheres: the union's volume to a few tenths of a percent (a grid
  // symmetric about their centres errs by 0.7 %: its errors do not average out).
  const Vec3 lo(-0.03 + 0.00013, -0.02 + 0.00031, -0.02 + 0.00017), hi(0.03, 0.02, 0.02);
  const auto halves = [](const Vec3& p) { return p.x() < 0 ? 0 : 1; };
  const std::vector<SampledRegion> shifted = sampled_regions(world, lo, hi, h, 2, halves);
  EXPECT_NEAR((solid_volume(shifted[0], h) + solid_volume(shifted[1], h)) / exact, 1.0, 3e-3);
  // A grid symmetric about x = 0 (76 points: none on the plane) splits the count in equal halves.
  const Vec3 sym(0.0304, 0.02, 0.02);
  const std::vector<SampledRegion> s = sampled_regions(world, -sym, sym, h, 2, halves);
  EXPECT_EQ(s[0].solid, s[1].solid);
  EXPECT_EQ(s[0].points, s[1].points);
  EXPECT_EQ(s[0].points + s[1].points, 76L * 50 * 50);
  // Points of no region are not counted.
  const std::vector<SampledRegion> left =
      sampled_regions(world, -sym, sym, h, 1, [](const Vec3& p) { return p.x() < 0 ? 0 : -1; });
  EXPECT_EQ(left[0].solid, s[0].solid);
  EXPECT_EQ(left[0].points, s[0].points);
}

TEST(SampledPorosity, CountsDoNotDependOnTheThreadCount) {
  World world;
  Rng rng(5);
  for (int k = 0; k < 60; ++k)
    world.add_body(make_sphere_body(rng.uniform(Vec3::Zero(), Vec3::Constant(0.05)),
                                    rng.uniform(0.002, 0.006), 2650));
  std::vector<SampledRegion> a, b;
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return sampled_regions(world, Vec3::Zero(), Vec3::Constant(0.05), 0.0005, 3,
                           [](const Vec3& p) { return int(p.z() / 0.0167); });
  };
  a = run(1);
  b = run(2);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(a[k].points, b[k].points);
    EXPECT_EQ(a[k].solid, b[k].solid);
    EXPECT_GT(a[k].solid, 0);
  }
}

TEST(SampledPorosity, BadArgumentsAreRefused) {
  World world;
  const auto any = [](const Vec3&) { return 0; };
  EXPECT_THROW(sampled_regions(world, Vec3::Zero(), Vec3::Ones(), 0.0, 1, any), InvalidInput);
  EXPECT_THROW(sampled_regions(world, Vec3::Ones(), Vec3::Zero(), 0.1, 1, any), InvalidInput);
  EXPECT_THROW(sampled_regions(world, Vec3::Zero(), Vec3::Ones(), 1e-5, 1, any), InvalidInput);
  EXPECT_THROW(sampled_regions(world, Vec3::Zero(), Vec3::Ones(), 0.1, 0, any), InvalidInput);
  EXPECT_TRUE(std::isnan(
      sampled_regions(world, Vec3::Zero(), Vec3::Ones(), 0.1, 2, [](const Vec3&) { return 0; })[1]
          .porosity()));
}

}  // namespace
}  // namespace clumpkit::dem
