// Weibull statistics of particle crushing strengths (Hu et al. 2023 eqs. 12–14; McDowell & Amon
// 2000): least-squares and maximum-likelihood fits, bootstrap intervals, the size law.
#pragma once

#include "geom/random.h"
#include "geom/range.h"

#include <utility>
#include <vector>

namespace clumpkit::dem {

/// Survival probability Ps(σ) = exp(−(σ/σ0)^m) (eq. 12): σ0 the characteristic strength (Ps =
/// 1/e), m the Weibull modulus.
struct WeibullFit {
  double sigma0 = 0.0;
  double modulus = 0.0;
};

/// Every fit takes the strengths of the particles that failed and, optionally, the largest
/// stress carried by each particle that did not fail within the test (it tipped over, or was
/// pressed flat without a load drop): a right-censored sample, whose strength is known only to
/// lie above that stress. Leaving survivors out would bias σ0 low; counting them as failures at
/// that stress would too. Without survivors the fits are the plain ones.

/// Plotting positions of the failures, ascending: (σ_i, Ps_i). Without survivors Ps_i =
/// 1 − i/(N + 1) (McDowell & Amon 2000's ranking); with them Johnson's adjusted rank replaces
/// i: over all N samples in ascending order (a failure before a survivor of the same stress),
/// each failure with reverse rank r (N for the smallest) takes rank (r·j + N + 1)/(r + 1) after
/// the previous failure's j (0 before the first), so each survivor spreads its probability over
/// the failures above it.
std::vector<std::pair<double, double>> weibull_plotting_positions(
    const std::vector<double>& failed, const std::vector<double>& survived = {});

/// Least squares of ln ln(1/Ps) on ln σ over the plotting positions: the slope is m, and σ0 =
/// exp(−b/m) for the intercept b. Throws InvalidInput for fewer than 3 failures, a value that is
/// not positive and finite, or failures all equal.
WeibullFit weibull_least_squares(const std::vector<double>& failed,
                                 const std::vector<double>& survived = {});

/// Maximum likelihood, r failures among N samples (a survivor c contributes its survival
/// exp(−(c/σ0)^m) to the likelihood): m solves Σ_N x^m·ln x / Σ_N x^m − 1/m = mean_r(ln σ)
/// (bisection on a bracket grown from m = 1, to 1e-12 relative), σ0 = (Σ_N x^m / r)^(1/m), the
/// sums over failures and survivors alike. Same refusals as above.
WeibullFit weibull_maximum_likelihood(const std::vector<double>& failed,
                                      const std::vector<double>& survived = {});

enum class WeibullMethod { least_squares, maximum_likelihood };

/// The number of bootstrap resamples weibull_bootstrap takes (the percentiles of its intervals
/// are read off them).
inline constexpr Range kBootstrapResamples = integers_from(10);

/// A fit with percentile bootstrap intervals: `resamples` draws of N samples with replacement
/// (from `rng`, in order, over the failures then the survivors), each fitted; the interval holds
/// the central `level` of the fitted values (0.9: the 5th and 95th percentiles). Resamples with
/// fewer than 3 failures or failures all equal are drawn again. `resamples` in
/// kBootstrapResamples.
struct WeibullEstimate {
  WeibullFit fit;
  double sigma0_lo = 0.0, sigma0_hi = 0.0;
  double modulus_lo = 0.0, modulus_hi = 0.0;
};
WeibullEstimate weibull_bootstrap(const std::vector<double>& failed,
                                  const std::vector<double>& survived, WeibullMethod method,
                                  int resamples, Rng& rng, double level = 0.9);
inline WeibullEstimate weibull_bootstrap(const std::vector<double>& strengths, WeibullMethod method,
                                         int resamples, Rng& rng, double level = 0.9) {
  return weibull_bootstrap(strengths, {}, method, resamples, rng, level);
}

/// One bootstrap resample of a set: N draws with replacement over the failures then the
/// survivors, drawn again until it holds at least 3 failures that are not all equal. The
/// failures' and the survivors' draws are returned apart.
std::pair<std::vector<double>, std::vector<double>> weibull_resample(
    const std::vector<double>& failed, const std::vector<double>& survived, Rng& rng);

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
