// The exact power-diagram engine and analytic slicing, two independent methods, agree on random
// clumps of 50, 200 and 1000 balls.
#include "geom/random.h"
#include "geom/volume/slicing.h"
#include "geom/volume/union_of_balls.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

namespace {
Clump random_clump(int n, std::uint64_t seed) {
  // Centres uniform in a box holding n balls at unit spacing, radii 0.5-1.5: moderate overlap.
  Rng rng(seed);
  const double side = std::cbrt(double(n));
  Clump c;
  for (int i = 0; i < n; ++i)
    c.spheres.push_back(
        Sphere{rng.uniform(Vec3::Constant(0), Vec3::Constant(side)), rng.uniform(0.5, 1.5)});
  return c;
}
}  // namespace

TEST(ExactVsSlicing, RandomClumpsAgreeToOneInABillion) {
  for (int n : {50, 200, 1000}) {
    const Clump c = random_clump(n, 7 + n);
    const MassProperties e = union_properties(c).mass;
    const MassProperties s = union_properties_by_slicing(c);
    EXPECT_NEAR(s.volume, e.volume, 1e-9 * e.volume) << n;
    const double len = std::cbrt(e.volume);
    EXPECT_LT((s.centroid - e.centroid).norm(), 1e-9 * len) << n;
    EXPECT_LT((s.inertia - e.inertia).norm(), 1e-9 * e.inertia.norm()) << n;
  }
}
