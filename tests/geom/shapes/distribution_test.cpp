// Tests of the seeded generator and recipe distributions.
#include "geom/shapes/distribution.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

TEST(Rng, StreamsAreReproducibleAndDistinct) {
  Rng a = Rng::stream(5, 3), b = Rng::stream(5, 3), c = Rng::stream(5, 4), d = Rng::stream(6, 3);
  const auto x = a.next();
  EXPECT_EQ(x, b.next());
  EXPECT_NE(x, c.next());
  EXPECT_NE(x, d.next());
}

TEST(Rng, MomentsOfUniformNormalAndSphere) {
  Rng r(42);
  const int n = 200000;
  double su = 0, sn = 0, sn2 = 0;
  Vec3 sv = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    su += r.uniform();
    const double g = r.normal();
    sn += g;
    sn2 += g * g;
    const Vec3 v = r.unit_vector();
    EXPECT_NEAR(v.norm(), 1.0, 1e-12);
    sv += v;
  }
  EXPECT_NEAR(su / n, 0.5, 5e-3);
  EXPECT_NEAR(sn / n, 0.0, 1e-2);
  EXPECT_NEAR(sn2 / n, 1.0, 1e-2);
  EXPECT_LT(sv.norm() / n, 1e-2);
}

TEST(Distribution, TruncatedLognormalStaysInWindowWithRightMedian) {
  Distribution d;
  d.kind = Distribution::Kind::Lognormal;
  d.a = std::log(1.6);
  d.b = 0.25;
  d.min = 1.0;
  d.max = 3.5;
  validate(d, "L_over_H");
  Rng r(9);
  int below = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = sample(d, r);
    ASSERT_GE(x, 1.0);
    ASSERT_LE(x, 3.5);
    below += x < 1.6;
  }
  EXPECT_NEAR(below / 20000.0, 0.5, 0.02);  // truncation is almost symmetric in log space here
}

TEST(Distribution, IntegersCoverTheRange) {
  Distribution d;
  d.kind = Distribution::Kind::Integers;
  d.a = 1;
  d.b = 4;
  Rng r(1);
  int seen[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 4000; ++i) ++seen[static_cast<int>(sample(d, r))];
  EXPECT_EQ(seen[0], 0);
  for (int k = 1; k <= 4; ++k) EXPECT_NEAR(seen[k], 1000, 120);
}

TEST(Distribution, RejectsBadParameters) {
  Distribution d;
  d.kind = Distribution::Kind::Uniform;
  d.a = 2;
  d.b = 1;
  EXPECT_THROW(validate(d, "W"), InvalidInput);
  d.a = NAN;
  EXPECT_THROW(validate(d, "W"), InvalidInput);
  try {
    validate(d, "fraction[0].W");
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind("fraction[0].W:", 0), 0u) << e.what();
  }
}
