// Tests of the non-overlapping random placement in a cylinder (first step of a specimen build).
#include "dem/specimen/placement.h"
#include "geom/errors.h"
#include "geom/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace clumpkit::dem {
namespace {

constexpr double kPlacementCylinder = 0.1;  // m

/// 20 three-sphere clumps (largest first, as callers pass them) then 300 soil spheres of
/// radius 5–10 mm, sorted by decreasing size.
std::vector<PlacementItem> make_items() {
  Rng rng(7);
  std::vector<PlacementItem> items;
  for (int i = 0; i < 20; ++i) {
    const double r = rng.uniform(0.008, 0.012);
    const double a = 0.8 * r;
    PlacementItem clump;
    clump.spheres = {
        {Vec3(-a, 0.0, 0.0), r}, {Vec3(0.0, 0.0, 0.0), 1.1 * r}, {Vec3(a, 0.0, 0.0), r}};
    clump.bounding_radius = a + r;
    items.push_back(clump);
  }
  std::vector<double> soil;
  for (int i = 0; i < 300; ++i) soil.push_back(rng.uniform(0.005, 0.010));
  std::sort(soil.rbegin(), soil.rend());
  for (double r : soil) items.push_back({{{Vec3::Zero(), r}}, r});
  return items;
}

std::vector<std::vector<Sphere>> world_spheres(const std::vector<PlacementItem>& items,
                                               const std::vector<Placement>& placements) {
  std::vector<std::vector<Sphere>> out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::vector<Sphere> spheres;
    for (const Sphere& s : items[i].spheres)
      spheres.push_back({placements[i].orientation * s.center + placements[i].position, s.radius});
    out.push_back(spheres);
  }
  return out;
}

TEST(Placement, NoOverlapsAllInsideAndHeightCoversTops) {
  const auto items = make_items();
  Rng rng(2024);
  double height = -1.0;
  const auto placements = place_in_cylinder(items, kPlacementCylinder, rng, 200, &height);
  ASSERT_EQ(placements.size(), items.size());
  const auto world = world_spheres(items, placements);
  double top = 0.0;
  for (std::size_t i = 0; i < world.size(); ++i) {
    for (const Sphere& s : world[i]) {
      EXPECT_LE(std::hypot(s.center.x(), s.center.y()) + s.radius, kPlacementCylinder + 1e-12);
      EXPECT_GE(s.center.z() - s.radius, -1e-12);
      top = std::max(top, s.center.z() + s.radius);
    }
    for (std::size_t j = 0; j < i; ++j)
      for (const Sphere& a : world[i])
        for (const Sphere& b : world[j])
          ASSERT_GE((a.center - b.center).norm(), a.radius + b.radius - 1e-12)
              << "items " << i << " and " << j;
  }
  EXPECT_GE(height, top);
  EXPECT_NEAR(height, top, 1e-15);
  // Loosely packed from the bottom up: far below a stack of the items one per layer.
  EXPECT_LT(height, 1.0);
}

TEST(Placement, DeterministicForSeed) {
  const auto items = make_items();
  Rng a(11), b(11), c(12);
  const auto pa = place_in_cylinder(items, kPlacementCylinder, a);
  const auto pb = place_in_cylinder(items, kPlacementCylinder, b);
  const auto pc = place_in_cylinder(items, kPlacementCylinder, c);
  ASSERT_EQ(pa.size(), pb.size());
  bool differs = false;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i].position, pb[i].position);
    EXPECT_EQ(pa[i].orientation.coeffs(), pb[i].orientation.coeffs());
    differs = differs || pa[i].position != pc[i].position;
  }
  EXPECT_TRUE(differs);
}

TEST(Placement, OrientationsAreUnitAndUniform) {
  const auto items = make_items();
  Rng rng(5);
  const auto placements = place_in_cylinder(items, kPlacementCylinder, rng);
  Vec3 mean = Vec3::Zero();
  for (const Placement& p : placements) {
    EXPECT_NEAR(p.orientation.norm(), 1.0, 1e-14);
    mean += p.orientation * Vec3::UnitX();
  }
  mean /= static_cast<double>(placements.size());
  // 320 directions: each mean component has standard deviation 1/sqrt(3·320) ≈ 0.032.
  EXPECT_LT(mean.norm(), 0.2);

  // Many draws: mean axis direction ~ 0, second moments ~ 1/3 (isotropy).
  Rng draws(99);
  const int n = 200000;
  Vec3 sum = Vec3::Zero();
  Vec3 sq = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Quaterniond q = uniform_orientation(draws);
    EXPECT_NEAR(q.norm(), 1.0, 1e-14);
    const Vec3 x = q * Vec3::UnitX();
    sum += x;
    sq += x.cwiseProduct(x);
  }
  sum /= n;
  sq /= n;
  EXPECT_LT(sum.norm(), 0.01);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(sq[k], 1.0 / 3.0, 0.01);
}

TEST(Placement, EdgeCasesAndInvalidInput) {
  Rng rng(1);
  double height = -1.0;
  EXPECT_TRUE(place_in_cylinder({}, kPlacementCylinder, rng, 200, &height).empty());
  EXPECT_EQ(height, 0.0);
  // An item exactly as wide as the cylinder sits on the axis.
  const std::vector<PlacementItem> wide = {
      {{{Vec3::Zero(), kPlacementCylinder}}, kPlacementCylinder}};
  const auto p = place_in_cylinder(wide, kPlacementCylinder, rng);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NEAR(std::hypot(p[0].position.x(), p[0].position.y()), 0.0, 1e-12);
  // Two of them stack.
  const std::vector<PlacementItem> two = {wide[0], wide[0]};
  const auto q = place_in_cylinder(two, kPlacementCylinder, rng, 5, &height);
  EXPECT_GE(std::abs(q[1].position.z() - q[0].position.z()), 2 * kPlacementCylinder - 1e-12);
  EXPECT_GE(height, 4 * kPlacementCylinder - 1e-12);

  EXPECT_THROW(place_in_cylinder(wide, 0.0, rng), InvalidInput);
  EXPECT_THROW(place_in_cylinder(wide, kPlacementCylinder, rng, 0), InvalidInput);
  EXPECT_THROW(place_in_cylinder({{{}, 0.01}}, kPlacementCylinder, rng), InvalidInput);
  EXPECT_THROW(place_in_cylinder({{{{Vec3::Zero(), -1.0}}, 0.01}}, kPlacementCylinder, rng),
               InvalidInput);
  EXPECT_THROW(place_in_cylinder({{{{Vec3::Zero(), 0.2}}, 0.2}}, kPlacementCylinder, rng),
               InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
