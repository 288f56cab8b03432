// The crushing peak rule on synthetic curves: a clean brittle drop, a noisy plateau, a double
// peak, a drop that recovers, a collapse without a split, and a whole particle tipping over.
#include "dem/lab/crush_peak.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit::dem;

namespace {

constexpr double kD = 0.0275;   // m
constexpr double kStep = 1e-5;  // m of travel per sample

// A curve from force values at equal travel steps; split from sample `split_at` on.
std::vector<CrushSample> curve(const std::vector<double>& force, std::size_t split_at = 1u << 30) {
  std::vector<CrushSample> c;
  for (std::size_t i = 0; i < force.size(); ++i) c.push_back({i * kStep, force[i], i >= split_at});
  return c;
}

}  // namespace

TEST(CrushPeak, CleanBrittleDrop) {
  // Linear to 5.7 kN at sample 70 (0.7 mm), then a drop to 1 kN, split at the drop.
  std::vector<double> f;
  for (int i = 0; i <= 70; ++i) f.push_back(5700.0 * i / 70);
  for (int i = 0; i < 20; ++i) f.push_back(1000.0);
  const CrushPeak p = crushing_peak(curve(f, 71), kD);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.index, 70u);
  EXPECT_DOUBLE_EQ(p.force, 5700.0);
  EXPECT_DOUBLE_EQ(p.travel, 70 * kStep);
  EXPECT_EQ(p.detected, 71u);
  EXPECT_EQ(p.by, "split");
}

TEST(CrushPeak, NoisyPlateauIsNotAPeakUntilTheRealDrop) {
  // Rising with ±20 % noise (drops of up to a third of the running maximum never reach 35 %)
  // and split flags that come only at the final drop.
  std::vector<double> f;
  for (int i = 0; i < 400; ++i)
    f.push_back(3000.0 * (1 - std::exp(-i / 50.0)) * (1 + 0.2 * std::sin(1.7 * i)));
  double top = 0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f[i] > top) top = f[i], at = i;
  f.push_back(0.5 * top);
  const CrushPeak p = crushing_peak(curve(f, 400), kD);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.index, at);
  EXPECT_DOUBLE_EQ(p.force, top);
  EXPECT_EQ(p.detected, 400u);
}

TEST(CrushPeak, DoublePeakTakesTheOneThatFails) {
  // 4 kN, a 30 % drop (a corner chipped: not enough), up to 6 kN, then a 50 % drop with a split.
  std::vector<double> f = {0, 1000, 2000, 3000, 4000, 2800, 2800, 3500, 5000, 6000, 3000, 2000};
  const CrushPeak p = crushing_peak(curve(f, 5), kD);  // "split" already true at the first drop
  ASSERT_TRUE(p.found);
  EXPECT_DOUBLE_EQ(p.force, 6000.0);
  EXPECT_EQ(p.detected, 10u);
}

TEST(CrushPeak, DropThatRecoversBeforeCollapseIsNotFailure) {
  // A 40 % drop without a split that recovers within 0.05·D of travel (137 samples): not
  // failure; the later drop that stays low for 0.05·D is a collapse.
  std::vector<double> f = {0, 2000, 4000, 2400, 2400, 3000, 4500};
  for (int i = 0; i < 200; ++i) f.push_back(2000.0);
  const CrushPeak p = crushing_peak(curve(f), kD);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.by, "collapse");
  EXPECT_DOUBLE_EQ(p.force, 4500.0);
  EXPECT_EQ(p.index, 6u);
  // The collapse is declared once 0.05·D = 1.375 mm of travel has passed below the threshold.
  EXPECT_GE((p.detected - 7) * kStep, 0.05 * kD - 1e-12);
  EXPECT_LT((p.detected - 8) * kStep, 0.05 * kD);
  // Without the long low tail nothing is found.
  EXPECT_FALSE(crushing_peak(curve({0, 2000, 4000, 2400, 2400, 3000, 4500}), kD).found);
}

TEST(CrushPeak, APlatenGoneFreeAfterAChipIsNotACollapse) {
  // The first touching corner chips off at 140 N and the platen travels free (F = 0) for more
  // than 0.05·D before it meets the particle again: that travel is not in contact, so no
  // collapse; the particle's own failure comes later.
  std::vector<double> f = {0, 60, 100, 140, 90, 40};
  for (int i = 0; i < 200; ++i) f.push_back(0.0);
  for (double x : {50.0, 500.0, 1500.0, 3000.0, 4000.0, 1000.0}) f.push_back(x);
  const CrushPeak p = crushing_peak(curve(f), kD);
  EXPECT_FALSE(p.found);  // no split and no long low tail in contact yet
  for (int i = 0; i < 200; ++i) f.push_back(1000.0);
  const CrushPeak q = crushing_peak(curve(f), kD);
  ASSERT_TRUE(q.found);
  EXPECT_EQ(q.by, "collapse");
  EXPECT_DOUBLE_EQ(q.force, 4000.0);
  // Brushing a loose chip (10 N, under 10 % of the 140 N peak) is not loading the particle
  // either; with the contact fraction 0 it would be, and the chip would be the peak.
  std::vector<double> g = {0, 60, 100, 140, 90, 40};
  for (int i = 0; i < 200; ++i) g.push_back(10.0);
  g.push_back(3000.0);
  EXPECT_FALSE(crushing_peak(curve(g), kD).found);
  const CrushPeak chip = crushing_peak(curve(g), kD, PeakRule{0.35, 0.05, 0.0});
  ASSERT_TRUE(chip.found);
  EXPECT_DOUBLE_EQ(chip.force, 140.0);
}

TEST(CrushPeak, AWholeParticleThatTipsOverHasNotCollapsed) {
  // An elongated particle stood on its end carries 300 N, tips over and is pushed along at
  // 150 N: with every cell still bonded (whole) that is no collapse however long it lasts; once
  // a piece has broken off, the low stretch is one.
  std::vector<double> f = {0, 100, 200, 300};
  for (int i = 0; i < 300; ++i) f.push_back(150.0);
  std::vector<CrushSample> c = curve(f);
  for (CrushSample& s : c) s.whole = true;
  EXPECT_FALSE(crushing_peak(c, kD).found);
  for (std::size_t i = 250; i < c.size(); ++i) c[i].whole = false;
  const CrushPeak p = crushing_peak(c, kD);
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.by, "collapse");
  EXPECT_EQ(p.detected, 250u);
  EXPECT_DOUBLE_EQ(p.force, 300.0);
}

TEST(CrushPeak, BadRule) {
  EXPECT_THROW(crushing_peak({}, kD, PeakRule{1.0, 0.02}), clumpkit::InvalidInput);
  EXPECT_THROW(crushing_peak({}, kD, PeakRule{0.35, 0.0}), clumpkit::InvalidInput);
  EXPECT_THROW(crushing_peak({}, kD, PeakRule{0.35, 0.02, 0.7}), clumpkit::InvalidInput);
  EXPECT_THROW(crushing_peak({}, -1.0), clumpkit::InvalidInput);
  EXPECT_FALSE(crushing_peak({}, kD).found);
}
