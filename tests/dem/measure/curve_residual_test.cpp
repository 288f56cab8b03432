// The curve residual (CTGU 2017, eq. 4) against closed forms.
#include "dem/measure/curve_residual.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clumpkit::dem {
namespace {

Curve sampled(double from, double to, int n, double (*f)(double)) {
  Curve c;
  for (int k = 0; k < n; ++k) {
    const double x = from + (to - from) * k / (n - 1);
    c.x.push_back(x);
    c.y.push_back(f(x));
  }
  return c;
}

TEST(CurveResidual, LinearCurvesInterpolateExactly) {
  // a = 2x + 1 on [0, 3] (4 points), b = a + 0.5 on [1, 5] (7 points): on the overlap [1, 3]
  // b − a = 0.5 at every point, and the relative residual is the mean of (0.5 / (2x + 1))².
  const Curve a = sampled(0.0, 3.0, 4, [](double x) { return 2.0 * x + 1.0; });
  const Curve b = sampled(1.0, 5.0, 7, [](double x) { return 2.0 * x + 1.5; });
  const CurveResidual r = curve_residual(a, b, 5);
  EXPECT_EQ(r.from, 1.0);
  EXPECT_EQ(r.to, 3.0);
  EXPECT_EQ(r.points, 5);
  EXPECT_NEAR(r.residual_abs, 0.25, 1e-14);
  double rel = 0.0;
  for (double x : {1.0, 1.5, 2.0, 2.5, 3.0}) rel += std::pow(0.5 / (2.0 * x + 1.0), 2) / 5.0;
  EXPECT_NEAR(r.residual_rel, rel, 1e-15);
  EXPECT_EQ(r.relative_points, 5);
}

TEST(CurveResidual, AWindowNarrowsTheRangeCompared) {
  // The curves of LinearCurvesInterpolateExactly within x in [1.5, 10]: the overlap [1, 3] cut
  // to [1.5, 3], sampled at 1.5, 2.25, 3; b − a is 0.5 everywhere.
  const Curve a = sampled(0.0, 3.0, 4, [](double x) { return 2.0 * x + 1.0; });
  const Curve b = sampled(1.0, 5.0, 7, [](double x) { return 2.0 * x + 1.5; });
  const CurveResidual r = curve_residual(a, b, 3, 1.5, 10.0);
  EXPECT_EQ(r.from, 1.5);
  EXPECT_EQ(r.to, 3.0);
  EXPECT_NEAR(r.residual_abs, 0.25, 1e-14);
  double rel = 0.0;
  for (double x : {1.5, 2.25, 3.0}) rel += std::pow(0.5 / (2.0 * x + 1.0), 2) / 3.0;
  EXPECT_NEAR(r.residual_rel, rel, 1e-15);
  // Both ends inside the overlap; an unbounded window is the overlap.
  const CurveResidual inner = curve_residual(a, b, 2, 2.0, 2.5);
  EXPECT_EQ(inner.from, 2.0);
  EXPECT_EQ(inner.to, 2.5);
  const CurveResidual whole = curve_residual(a, b, 5);
  EXPECT_EQ(curve_residual(a, b, 5, -INFINITY, INFINITY).residual_rel, whole.residual_rel);
  // A window beside the overlap, an empty one, or a NaN bound leaves nothing to compare.
  EXPECT_THROW(curve_residual(a, b, 5, 3.5, 4.0), InvalidInput);
  EXPECT_THROW(curve_residual(a, b, 5, 2.0, 2.0), InvalidInput);
  EXPECT_THROW(curve_residual(a, b, 5, NAN, 2.0), InvalidInput);
}

TEST(CurveResidual, SameCurveIsZeroAndTheAbsoluteResidualIsSymmetric) {
  const Curve a = sampled(0.0, 1.0, 50, [](double x) { return std::sin(3.0 * x); });
  const Curve b = sampled(0.0, 1.0, 31, [](double x) { return std::cos(2.0 * x); });
  EXPECT_EQ(curve_residual(a, a, 200).residual_abs, 0.0);
  EXPECT_EQ(curve_residual(a, a, 200).residual_rel, 0.0);
  EXPECT_NEAR(curve_residual(a, b, 200).residual_abs, curve_residual(b, a, 200).residual_abs,
              1e-15);
  // Refining both curves converges to the integral mean of (cos 2x − sin 3x)² over [0, 1].
  const Curve fa = sampled(0.0, 1.0, 4001, [](double x) { return std::sin(3.0 * x); });
  const Curve fb = sampled(0.0, 1.0, 4001, [](double x) { return std::cos(2.0 * x); });
  double mean = 0.0;
  const int n = 20001;
  for (int k = 0; k < n; ++k) {
    const double x = double(k) / (n - 1);
    mean += std::pow(std::cos(2.0 * x) - std::sin(3.0 * x), 2) / n;
  }
  EXPECT_NEAR(curve_residual(fa, fb, 20001).residual_abs, mean, 1e-6);
}

TEST(CurveResidual, PointsWhereTheReferenceIsZeroAreLeftOutOfTheRelativeMean) {
  const Curve a{{0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}};
  const Curve b{{0.0, 1.0, 2.0}, {1.0, 2.0, 3.0}};
  const CurveResidual r = curve_residual(a, b, 3);
  EXPECT_EQ(r.relative_points, 2);
  EXPECT_NEAR(r.residual_rel, (1.0 + 0.25) / 2.0, 1e-15);
  EXPECT_NEAR(r.residual_abs, 1.0, 1e-15);
}

TEST(CurveResidual, BadCurvesAreRefused) {
  const Curve a{{0.0, 1.0}, {0.0, 1.0}};
  EXPECT_THROW(curve_residual(a, Curve{{0.0}, {1.0}}, 10), InvalidInput);
  EXPECT_THROW(curve_residual(a, Curve{{0.0, 0.0}, {1.0, 2.0}}, 10), InvalidInput);
  EXPECT_THROW(curve_residual(a, Curve{{0.0, 1.0}, {1.0, NAN}}, 10), InvalidInput);
  EXPECT_THROW(curve_residual(a, Curve{{0.0, 1.0}, {1.0}}, 10), InvalidInput);
  EXPECT_THROW(curve_residual(a, Curve{{2.0, 3.0}, {1.0, 2.0}}, 10), InvalidInput);
  EXPECT_THROW(curve_residual(a, a, 1), InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
