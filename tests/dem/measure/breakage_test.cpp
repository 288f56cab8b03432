// Grading and breakage indices against closed forms: Hardin's halving, Einav's mixture of the
// initial and the ultimate grading, Marsal's moved fraction, and what no breakage gives.
#include "dem/measure/breakage.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// `n` pieces following the ultimate grading F_u(d) = (d/dM)^a at the midpoints of n equal
// steps of F, each carrying `volume`/n.
std::vector<SievedPiece> einav_ultimate_pieces(double dM, double a, int n, double volume) {
  std::vector<SievedPiece> p;
  for (int j = 0; j < n; ++j) p.push_back({volume / n, dM * std::pow((j + 0.5) / n, 1.0 / a)});
  return p;
}

}  // namespace

TEST(Breakage, AnUnbrokenAssemblyHasNoBreakage) {
  const std::vector<SievedPiece> g{{1.0, 0.02}, {2.0, 0.03}, {0.5, 0.04}};
  const std::vector<double> sieves = sieve_series(1e-3, 0.05, std::sqrt(2.0));
  EXPECT_EQ(hardin_breakage(g, g), 0.0);
  EXPECT_EQ(einav_breakage(g, g), 0.0);
  EXPECT_EQ(marsal_breakage(g, g, sieves), 0.0);
}

TEST(Breakage, PassingCountsThePiecesBelowEachOpening) {
  // A piece passes when its intermediate dimension is below the opening, not equal to it.
  const std::vector<SievedPiece> g{{1.0, 0.01}, {3.0, 0.02}, {4.0, 0.04}};
  const std::vector<double> f = passing(g, {0.01, 0.015, 0.02, 0.05});
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0], 0.0);
  EXPECT_DOUBLE_EQ(f[1], 0.125);
  EXPECT_DOUBLE_EQ(f[2], 0.125);
  EXPECT_DOUBLE_EQ(f[3], 1.0);
  const std::vector<double> s = sieve_series(1e-3, 0.04, 2.0);
  ASSERT_EQ(s.size(), 6u);  // 1.25, 2.5, 5, 10, 20, 40 mm
  EXPECT_DOUBLE_EQ(s.front(), 0.04 / 32);
  EXPECT_EQ(s.back(), 0.04);
}

TEST(Breakage, HardinsBrOfParticlesHalvedIsLogTwoOverTheirPotential) {
  // Every 30 mm piece split into two of 15 mm: B_p falls by log10 2 of log10(30/0.074).
  const double d0 = 0.03;
  const std::vector<SievedPiece> before{{1.0, d0}, {1.0, d0}};
  const std::vector<SievedPiece> after{{0.5, d0 / 2}, {0.5, d0 / 2}, {0.5, d0 / 2}, {0.5, d0 / 2}};
  EXPECT_NEAR(hardin_breakage(before, after), std::log10(2.0) / std::log10(d0 / 7.4e-5), 1e-14);
  // All ground to silt: Br = 1.
  EXPECT_DOUBLE_EQ(hardin_breakage(before, {{2.0, 5e-5}}), 1.0);
}

TEST(Breakage, EinavsBIsTheWeightOfTheUltimateGradingInTheMixture) {
  // Current = (1 − B)·initial + B·ultimate (Einav 2007's assumption) gives B back; the
  // ultimate grading is sampled by 10⁵ pieces at its quantiles.
  const double dM = 0.04, a = 0.5;
  const std::vector<SievedPiece> initial{{1.0, dM}, {1.0, 0.03}, {1.0, 0.02}};
  for (double b : {0.0, 0.1, 0.3, 1.0}) {
    std::vector<SievedPiece> current;
    if (b < 1)
      for (const SievedPiece& p : initial) current.push_back({p.volume * (1 - b), p.size});
    if (b > 0)
      for (const SievedPiece& p : einav_ultimate_pieces(dM, a, 100000, 3.0 * b))
        current.push_back(p);
    EXPECT_NEAR(einav_breakage(initial, current), b, 1e-9) << "B = " << b;
  }
  // A measure of areas in the semi-log plot: the same B when every size and d_m scale together.
  std::vector<SievedPiece> current = einav_ultimate_pieces(dM, a, 1000, 1.5);
  current.push_back({1.5, 0.03});
  BreakageLimits scaled;
  scaled.silt *= 10;
  std::vector<SievedPiece> initial10 = initial, current10 = current;
  for (SievedPiece& p : initial10) p.size *= 10;
  for (SievedPiece& p : current10) p.size *= 10;
  EXPECT_NEAR(einav_breakage(initial10, current10, scaled), einav_breakage(initial, current),
              1e-12);
}

TEST(Breakage, MarsalsBgIsTheFractionThatLeftItsSieve) {
  // Sieves 10, 20, 40 mm; everything retained on 20 mm at first; then 0.2 moves down to the
  // 10 mm sieve and 0.1 to the pan.
  const std::vector<double> sieves{0.01, 0.02, 0.04};
  const std::vector<SievedPiece> before{{1.0, 0.03}};
  const std::vector<SievedPiece> after{{0.7, 0.03}, {0.2, 0.015}, {0.1, 0.001}};
  EXPECT_NEAR(marsal_breakage(before, after, sieves), 0.3, 1e-15);
  // Conservation: the passing fractions reach 1 above every piece.
  EXPECT_DOUBLE_EQ(passing(after, sieves).back(), 1.0);
}

TEST(Breakage, BadPiecesAndSievesAreRefused) {
  const std::vector<SievedPiece> g{{1.0, 0.02}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(passing({}, {0.01}), InvalidInput);
  EXPECT_THROW(passing({{-1.0, 0.02}}, {0.01}), InvalidInput);
  EXPECT_THROW(passing({{1.0, nan}}, {0.01}), InvalidInput);
  EXPECT_THROW(passing(g, {0.02, 0.01}), InvalidInput);
  EXPECT_THROW(sieve_series(0.02, 0.01, 2.0), InvalidInput);
  EXPECT_THROW(sieve_series(0.001, 0.01, 1.0), InvalidInput);
  EXPECT_THROW(hardin_breakage({{1.0, 1e-5}}, g), InvalidInput);  // no potential
  BreakageLimits bad;
  bad.fractal_dimension = 3;
  EXPECT_THROW(einav_breakage(g, g, bad), InvalidInput);
}
