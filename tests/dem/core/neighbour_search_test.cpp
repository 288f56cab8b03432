// Tests of the neighbour search against brute force: the skin list of a polydisperse cloud with
// clumps (dense cell table and sorted-key paths) and the near-list filter.
#include "dem/core/neighbour_search.h"
#include "geom/random.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace clumpkit::dem {
namespace {

struct Cloud {
  std::vector<Vec3> position;
  std::vector<double> radius;
  std::vector<int> body;
};

// n spheres of radius 0.5–30 mm (log-uniform-ish: most small, a few large) in a box of side
// `side` (m) offset by `origin`; every fourth body is a three-sphere clump.
Cloud cloud(int n, double side, const Vec3& origin, std::uint64_t seed) {
  Rng rng(seed);
  Cloud c;
  int body = 0;
  while (static_cast<int>(c.position.size()) < n) {
    const int parts = body % 4 == 3 ? 3 : 1;
    const Vec3 centre = origin + rng.uniform(Vec3::Constant(0), Vec3::Constant(side));
    for (int p = 0; p < parts; ++p) {
      const double u = rng.uniform();
      c.radius.push_back(u < 0.9 ? rng.uniform(0.0005, 0.004) : rng.uniform(0.004, 0.03));
      c.position.push_back(
          centre +
          (p == 0 ? Vec3::Zero() : rng.uniform(Vec3::Constant(-0.004), Vec3::Constant(0.004))));
      c.body.push_back(body);
    }
    ++body;
  }
  return c;
}

std::vector<std::pair<int, int>> brute_force(const Cloud& c, double skin) {
  std::vector<std::pair<int, int>> out;
  const int n = static_cast<int>(c.position.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double r = c.radius[i] + c.radius[j] + skin;
      if (c.body[i] != c.body[j] && (c.position[j] - c.position[i]).squaredNorm() < r * r)
        out.push_back({i, j});
    }
  return out;
}

TEST(NeighbourSearch, SkinPairsAreExactlyTheBruteForcePairs) {
  NeighbourGrid grid;  // reused across calls, as the world does
  std::vector<std::pair<int, int>> pairs;
  for (double skin : {0.0, 0.0005, 0.004}) {
    const Cloud c = cloud(3000, 0.12, Vec3(-0.05, 0.02, 0.0), 7);
    find_skin_pairs(c.position, c.radius, c.body, skin, grid, pairs);
    const auto want = brute_force(c, skin);
    EXPECT_GT(want.size(), 1000u);
    EXPECT_EQ(pairs, want) << "skin " << skin;
  }
}

// Two clusters a kilometre apart: the cell table would be huge, so the search takes its
// sorted-key path; the pairs are still exactly the brute-force ones.
TEST(NeighbourSearch, SparseWorldUsesSortedKeysAndFindsTheSamePairs) {
  Cloud c = cloud(800, 0.05, Vec3::Zero(), 8);
  const Cloud far = cloud(800, 0.05, Vec3(1000.0, -500.0, 300.0), 9);
  const int offset = c.body.back() + 1;
  for (std::size_t k = 0; k < far.position.size(); ++k) {
    c.position.push_back(far.position[k]);
    c.radius.push_back(far.radius[k]);
    c.body.push_back(far.body[k] + offset);
  }
  NeighbourGrid grid;
  std::vector<std::pair<int, int>> pairs;
  find_skin_pairs(c.position, c.radius, c.body, 0.002, grid, pairs);
  const auto want = brute_force(c, 0.002);
  EXPECT_GT(want.size(), 500u);
  EXPECT_EQ(pairs, want);
  EXPECT_TRUE(grid.cell_start.empty());  // no dense table was built
}

TEST(NeighbourSearch, NearFilterKeepsExactlyThePairsWithinTheNearSkin) {
  const Cloud c = cloud(2000, 0.1, Vec3::Zero(), 10);
  NeighbourGrid grid;
  std::vector<std::pair<int, int>> skin_pairs, near_pairs;
  find_skin_pairs(c.position, c.radius, c.body, 0.004, grid, skin_pairs);
  std::vector<std::uint8_t> keep;
  filter_pairs(skin_pairs, c.position, c.radius, 0.0005, keep, near_pairs);
  EXPECT_EQ(near_pairs, brute_force(c, 0.0005));
  EXPECT_LT(near_pairs.size(), skin_pairs.size());
  // Tiny inputs: nothing to pair.
  find_skin_pairs({Vec3::Zero()}, {0.01}, {0}, 0.001, grid, skin_pairs);
  EXPECT_TRUE(skin_pairs.empty());
}

}  // namespace
}  // namespace clumpkit::dem
