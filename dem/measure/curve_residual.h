// The residual between two test curves over their common range (CTGU 2017, eq. 4).
#pragma once

#include <limits>
#include <vector>

namespace clumpkit::dem {

/// A curve y(x), x strictly increasing.
struct Curve {
  std::vector<double> x, y;
};

/// What curve_residual measured. CTGU 2017's eq. 4 compares a curve b (a zoned or scaled model)
/// with a reference a at equally spaced x; its printed form is garbled between the absolute and
/// the relative square, so both are given.
struct CurveResidual {
  double from = 0.0, to = 0.0;  ///< the common range of x (within the window)
  int points = 0;               ///< points sampled, the range's ends included
  double residual_abs = 0.0;    ///< mean over the points of (b − a)²
  double residual_rel = 0.0;    ///< mean of ((b − a) / a)² over the points where a ≠ 0
  int relative_points = 0;      ///< the points where a ≠ 0
};

/// Throws InvalidInput unless the curve has at least two points, equal lengths, finite values
/// and strictly increasing x; `name` leads the message.
void validate_curve(const Curve& c, const char* name);

/// The value of `c` at `x` by linear interpolation between its neighbouring points; x within
/// [c.x.front(), c.x.back()].
double interpolate(const Curve& c, double x);

/// Residual of b against a at `points` (≥ 2) equally spaced x over the overlap of their ranges
/// (both ends included) within the window [x_from, x_to], each curve linearly interpolated. The
/// window leaves out a part both curves hold, e.g. the first diameter of a penetration curve,
/// where the reference's near-zero values dominate the relative residual. Throws InvalidInput
/// for invalid curves, fewer than 2 points, a NaN bound, or nothing left to compare.
CurveResidual curve_residual(const Curve& a, const Curve& b, int points,
                             double x_from = -std::numeric_limits<double>::infinity(),
                             double x_to = std::numeric_limits<double>::infinity());

}  // namespace clumpkit::dem
