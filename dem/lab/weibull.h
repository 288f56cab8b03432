// Weibull statistics of particle crushing strengths (Hu et al. 2023 eqs. 12–14; McDowell & Amon
// 2000): least-squares and maximum-likelihood fits, bootstrap intervals, the size law.
#pragma once

#include "geom/random.h"

#include <vector>

namespace clumpkit::dem {

/// Survival probability Ps(σ) = exp(−(σ/σ0)^m) (eq. 12): σ0 the characteristic strength (Ps =
/// 1/e), m the Weibull modulus.
struct WeibullFit {
  double sigma0 = 0.0;
  double modulus = 0.0;
};

/// Least squares of ln ln(1/Ps) on ln σ with the strengths sorted ascending and Ps_i =
/// 1 − i/(N + 1) (McDowell & Amon 2000's ranking): the slope is m, and σ0 = exp(−b/m) for the
/// intercept b. Throws InvalidInput for fewer than 3 strengths or one that is not positive and
/// finite, or strengths all equal.
WeibullFit weibull_least_squares(const std::vector<double>& strengths);

/// Maximum likelihood: m solves Σσ^m·ln σ / Σσ^m − 1/m = mean(ln σ) (bisection on a bracket
/// grown from m = 1, to 1e-12 relative), σ0 = (Σσ^m / N)^(1/m). Same refusals as above.
WeibullFit weibull_maximum_likelihood(const std::vector<double>& strengths);

enum class WeibullMethod { least_squares, maximum_likelihood };

/// A fit with percentile bootstrap intervals: `resamples` draws of N strengths with replacement
/// (from `rng`, in order), each fitted; the interval holds the central `level` of the fitted
/// values (0.9: the 5th and 95th percentiles). Resamples whose strengths are all equal are drawn
/// again.
struct WeibullEstimate {
  WeibullFit fit;
  double sigma0_lo = 0.0, sigma0_hi = 0.0;
  double modulus_lo = 0.0, modulus_hi = 0.0;
};
WeibullEstimate weibull_bootstrap(const std::vector<double>& strengths, WeibullMethod method,
                                  int resamples, Rng& rng, double level = 0.9);

/// Size law σ0 = k·D^−α (eq. 14): least squares of ln σ0 on ln D. Units are the caller's (Hu et
/// al. 2023 fit k = 101.7, α = 0.68 with D in mm and σ0 in MPa; their Table 1 gives k = 99.0,
/// α = 0.674 by this fit). Throws InvalidInput for fewer than 2 points, sizes all equal, or a
/// value that is not positive and finite.
struct SizeLaw {
  double coefficient = 0.0;  ///< k
  double exponent = 0.0;     ///< α (positive when strength falls with size)
};
SizeLaw size_law(const std::vector<double>& diameters, const std::vector<double>& sigma0);

/// Spearman's rank correlation of x and y (ties share their mean rank); throws InvalidInput for
/// lengths that differ or fewer than 2 points.
double spearman(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace clumpkit::dem
