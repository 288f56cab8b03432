// The exact power-diagram engine and analytic slicing, two independent methods, agree on random
// clumps of 50, 200 and 1000 balls.
#include "geom/random.h"
#include "geom/volume/slicing.h"
#include "geom/volume/union_of_balls.h"

#include "../../sanitized.h"

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
  // The slicing's time grows about as n^2.3 (more events, each slice O(m^2) in its m disks), so
  // the 1000-ball clump is ~95 % of the test (18 s in Release). The sanitizer pass slices 500
  // balls instead (a quarter of the time, the same code on a many-ball clump); the Release pass
  // runs 1000.
  const int largest = kSanitized ? 500 : 1000;
  for (int n : {50, 200, largest}) {
    const Clump c = random_clump(n, 7 + n);
    const MassProperties e = union_properties(c).mass;
    const MassProperties s = union_properties_by_slicing(c);
    EXPECT_NEAR(s.volume, e.volume, 1e-9 * e.volume) << n;
    const double len = std::cbrt(e.volume);
    EXPECT_LT((s.centroid - e.centroid).norm(), 1e-9 * len) << n;
    EXPECT_LT((s.inertia - e.inertia).norm(), 1e-9 * e.inertia.norm()) << n;
  }
}
