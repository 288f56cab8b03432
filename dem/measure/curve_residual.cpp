#include "dem/measure/curve_residual.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {

void validate_curve(const Curve& c, const char* name) {
  const std::string who(name);
  if (c.x.size() != c.y.size())
    throw InvalidInput(who + ": x and y differ in length (" + std::to_string(c.x.size()) + " and " +
                       std::to_string(c.y.size()) + ")");
  if (c.x.size() < 2)
    throw InvalidInput(who + ": a curve needs at least 2 points, got " +
                       std::to_string(c.x.size()));
  for (std::size_t k = 0; k < c.x.size(); ++k) {
    if (!std::isfinite(c.x[k]) || !std::isfinite(c.y[k]))
      throw InvalidInput(who + ": point " + std::to_string(k + 1) + " is not finite");
    if (k > 0 && !(c.x[k] > c.x[k - 1]))
      throw InvalidInput(who + ": x must increase strictly (point " + std::to_string(k + 1) +
                         " does not)");
  }
}

double interpolate(const Curve& c, double x) {
  // The first point at or beyond x, and the segment that ends there.
  const auto it = std::lower_bound(c.x.begin(), c.x.end(), x);
  if (it == c.x.begin()) return c.y.front();
  if (it == c.x.end()) return c.y.back();
  const std::size_t k = static_cast<std::size_t>(it - c.x.begin());
  if (*it == x) return c.y[k];
  const double t = (x - c.x[k - 1]) / (c.x[k] - c.x[k - 1]);
  return c.y[k - 1] + t * (c.y[k] - c.y[k - 1]);
}

CurveResidual curve_residual(const Curve& a, const Curve& b, int points, double x_from,
                             double x_to) {
  validate_curve(a, "curve a");
  validate_curve(b, "curve b");
  if (points < 2)
    throw InvalidInput("curve residual: points must be at least 2, got " + std::to_string(points));
  if (std::isnan(x_from) || std::isnan(x_to))
    throw InvalidInput("curve residual: the window's bounds must be numbers");
  const double lo = std::max(a.x.front(), b.x.front()), hi = std::min(a.x.back(), b.x.back());
  if (!(hi > lo)) throw InvalidInput("curve residual: the curves' x ranges do not overlap");
  CurveResidual r;
  r.from = std::max(lo, x_from);
  r.to = std::min(hi, x_to);
  if (!(r.to > r.from))
    throw InvalidInput("curve residual: the window [" + format_number(x_from) + ", " +
                       format_number(x_to) + "] leaves nothing of the overlap [" +
                       format_number(lo) + ", " + format_number(hi) + "]");
  r.points = points;
  double abs_sum = 0.0, rel_sum = 0.0;
  for (int k = 0; k < points; ++k) {
    // The last point is the range's end exactly, not from + (points − 1)·step.
    const double x = k == points - 1 ? r.to : r.from + (r.to - r.from) * k / (points - 1);
    const double ya = interpolate(a, x), yb = interpolate(b, x);
    abs_sum += (yb - ya) * (yb - ya);
    if (ya != 0.0) {
      rel_sum += (yb - ya) / ya * ((yb - ya) / ya);
      ++r.relative_points;
    }
  }
  r.residual_abs = abs_sum / points;
  r.residual_rel = r.relative_points > 0 ? rel_sum / r.relative_points : 0.0;
  return r;
}

}  // namespace clumpkit::dem
