// farthest_pair against the plain double loop it replaces: the same pair (ties included) on
// random clouds, integer grids full of equal distances and duplicated points, and the exact
// diameter of a large cloud on a sphere.
#include "geom/descriptors/farthest_pair.h"
#include "geom/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace clumpkit;

namespace {

FarthestPair double_loop(const std::vector<Vec3>& pts) {
  FarthestPair best;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const double d2 = (pts[j] - pts[i]).squaredNorm();
      if (d2 > best.squared_distance) best = {i, j, d2};
    }
  return best;
}

void expect_same(const FarthestPair& a, const FarthestPair& b, const char* what) {
  EXPECT_EQ(a.i, b.i) << what;
  EXPECT_EQ(a.j, b.j) << what;
  EXPECT_EQ(a.squared_distance, b.squared_distance) << what;
}

}  // namespace

TEST(FarthestPair, SamePairAsTheDoubleLoopTiesIncluded) {
  Rng rng(42);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 2 + std::size_t(rng.uniform(0.0, 1500.0));
    std::vector<Vec3> cloud(n), grid(n);
    for (std::size_t k = 0; k < n; ++k) {
      cloud[k] = rng.uniform(Vec3(-1, -2, -0.5), Vec3(1, 2, 0.5));
      // Integer points of a 4 x 4 x 4 grid: hundreds of pairs share the largest distance, and
      // points repeat.
      grid[k] = rng.uniform(Vec3::Zero(), Vec3::Constant(4)).array().floor().matrix();
    }
    expect_same(farthest_pair(cloud), double_loop(cloud), "random cloud");
    expect_same(farthest_pair(grid), double_loop(grid), "integer grid");
  }
  const std::vector<Vec3> same(100, Vec3(1, 2, 3));
  expect_same(farthest_pair(same), double_loop(same), "one point repeated");
  EXPECT_EQ(farthest_pair({Vec3(1, 1, 1)}).squared_distance, 0.0);
  EXPECT_EQ(farthest_pair({}).squared_distance, 0.0);
}

// 200,000 points on a sphere of radius 3 with one antipodal pair planted: the diameter is 6 to
// rounding, found without the 2·10¹⁰ pair checks of the double loop.
TEST(FarthestPair, DiameterOfALargeSphereCloud) {
  Rng rng(7);
  std::vector<Vec3> pts;
  for (int k = 0; k < 200000; ++k) {
    Vec3 p = rng.uniform(Vec3::Constant(-1), Vec3::Constant(1));
    if (p.norm() < 1e-3 || p.norm() > 1) continue;
    pts.push_back(2.9 * p.normalized());
  }
  const Vec3 axis = Vec3(1, 2, 3).normalized();
  pts.insert(pts.begin() + 1000, 3.0 * axis);
  pts.push_back(-3.0 * axis);
  const FarthestPair f = farthest_pair(pts);
  EXPECT_NEAR(std::sqrt(f.squared_distance), 6.0, 1e-12);
  EXPECT_EQ(f.i, 1000u);
  EXPECT_EQ(f.j, pts.size() - 1);
}
