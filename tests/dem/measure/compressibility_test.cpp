// Compression index and yield stress against curves built from their definitions.
#include "dem/measure/compressibility.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit::dem;

TEST(Compressibility, TheIndexIsTheSlopeOfALogLinearCurve) {
  // e = 0.8 − 0.25·log10(σ/1e5) from 0.1 to 10 MPa: Cc = 0.25 over any range.
  std::vector<double> e, s;
  for (int k = 0; k <= 40; ++k) {
    s.push_back(1e5 * std::pow(10.0, k / 20.0));
    e.push_back(0.8 - 0.25 * std::log10(s.back() / 1e5));
  }
  EXPECT_NEAR(compression_index(e, s, 1e6, 1e7), 0.25, 1e-12);
  EXPECT_NEAR(compression_index(e, s, 1e5, 1e7), 0.25, 1e-12);
  EXPECT_TRUE(std::isnan(compression_index(e, s, 2e7, 3e7)));  // no point there
}

TEST(Compressibility, TheYieldStressIsWhereTheTwoBranchesCross) {
  // A recompression branch of slope 0.02 and a virgin branch of slope 0.3 crossing at 1.5 MPa,
  // sampled every 1/10 decade from 0.1 to 10 MPa (the knee between two samples).
  const double yield = 1.5e6;
  std::vector<double> e, s;
  for (int k = 0; k <= 20; ++k) {
    s.push_back(1e5 * std::pow(10.0, k / 10.0));
    const double x = std::log10(s.back() / yield);
    e.push_back(0.7 - (x < 0 ? 0.02 : 0.3) * x);
  }
  EXPECT_NEAR(yield_stress(e, s) / yield, 1.0, 1e-9);
  // A straight line has no knee: both fits agree and the lines are parallel (or nearly).
  EXPECT_TRUE(std::isnan(yield_stress({0.5, 0.4, 0.3}, {1e5, 1e6, 1e7})));
}
