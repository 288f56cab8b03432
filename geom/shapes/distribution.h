// Scalar probability distributions for recipe parameters, sampled with our own seeded Rng.
#pragma once

#include "geom/random.h"

#include <string>

namespace clumpkit {

/// A recipe parameter: a constant or a random draw. The lognormal is truncated to [min, max] by
/// redrawing (Jin et al. 2017 fit L/H with a lognormal). `integers` draws uniformly from
/// {a, ..., b}.
struct Distribution {
  enum class Kind { Constant, Uniform, Normal, Lognormal, Integers };
  Kind kind = Kind::Constant;
  double a = 0.0;  ///< constant value; uniform/integers lower bound; normal mean; lognormal mu
  double b = 0.0;  ///< uniform/integers upper bound; normal sd; lognormal sigma
  double min = -1e300, max = 1e300;  ///< truncation (normal, lognormal)
};

Distribution constant(double value);

/// Checks the parameters (finite, a ≤ b, sigma ≥ 0, non-empty truncation window); throws
/// InvalidInput whose message starts with `field`.
void validate(const Distribution& d, const std::string& field);

/// One draw. Truncated draws redraw up to 10000 times, then throw NumericError.
double sample(const Distribution& d, Rng& rng);

/// Smallest and largest value the distribution can return (for checks before any draw).
double lower_bound(const Distribution& d);
double upper_bound(const Distribution& d);

/// Human-readable form, e.g. "uniform(0.02, 0.04)".
std::string describe(const Distribution& d);

}  // namespace clumpkit
