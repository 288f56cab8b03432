// The values a parameter may take: one interval, owned by the engine that checks it and quoted
// by the recipe reference, so that the recipe, the engine and the docs cannot disagree.
#pragma once

#include <limits>
#include <string>

namespace clumpkit {

/// An interval of allowed values, each end open or closed (an infinite end is always open), of
/// reals or of integers. NaN is in no range.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = true;
  bool hi_open = true;
  bool integer = false;

  bool contains(double x) const;
  /// As the recipe reference and the messages print it: "[0, 1)", ">= 0", "> 0", "integer in
  /// [1, 100]", "integer >= 1".
  std::string text() const;
};

/// [lo, hi]
constexpr Range closed(double lo, double hi) {
  return {lo, hi, false, false, false};
}
/// (lo, hi)
constexpr Range open(double lo, double hi) {
  return {lo, hi, true, true, false};
}
/// (lo, hi]
constexpr Range open_closed(double lo, double hi) {
  return {lo, hi, true, false, false};
}
/// [lo, hi)
constexpr Range closed_open(double lo, double hi) {
  return {lo, hi, false, true, false};
}
/// >= lo
constexpr Range at_least(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), false, true, false};
}
/// > lo
constexpr Range above(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), true, true, false};
}
/// The integers in [lo, hi].
constexpr Range integers(double lo, double hi) {
  return {lo, hi, false, false, true};
}
/// The integers >= lo.
constexpr Range integers_from(double lo) {
  return {lo, std::numeric_limits<double>::infinity(), false, true, true};
}

/// "must be in [0, 1)" (or "must be an integer in [1, 100]", "must be >= 0"): why `x` is outside
/// `r`, for the caller to prefix with the file and field and to follow with the value as given;
/// empty when `x` is in `r`.
std::string outside(const Range& r, double x);

/// Throws InvalidInput "NAME: must be in RANGE, got X" when `x` is outside `r`.
void require(const Range& r, double x, const std::string& name);

}  // namespace clumpkit
