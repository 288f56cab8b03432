// Weibull statistics of crushing strengths: the size law of Hu et al. 2023 Table 1, both fits on
// samples of a known Weibull law (also censored), scale invariance, bootstrap coverage, rank
// correlation.
#include "dem/lab/weibull.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// N strengths of Ps = exp(−(σ/σ0)^m) by inversion: σ = σ0·(−ln U)^(1/m).
std::vector<double> weibull_sample(double sigma0, double m, int n, Rng& rng) {
  std::vector<double> s;
  for (int i = 0; i < n; ++i)
    s.push_back(sigma0 * std::pow(-std::log(1.0 - rng.uniform()), 1.0 / m));
  return s;
}

}  // namespace

TEST(Weibull, SizeLawOfTable1) {
  // Hu et al. 2023 Table 1 (D in mm, σ0 in MPa): k = 99.0, α = 0.674 by least squares in log–log
  // (the paper prints k = 101.7, α = 0.68).
  const SizeLaw law = size_law({27.5, 31.6, 35.7, 39.7, 43.9}, {10.5, 10.0, 8.71, 8.04, 7.92});
  EXPECT_NEAR(law.exponent, 0.674, 1e-3);
  EXPECT_NEAR(law.coefficient, 99.0, 0.1);
  // Exact on an exact power law, in any units.
  const SizeLaw exact = size_law({0.01, 0.02, 0.04}, {8e6, 8e6 / std::sqrt(2.0), 4e6});
  EXPECT_NEAR(exact.exponent, 0.5, 1e-12);
  EXPECT_NEAR(exact.coefficient * std::pow(0.01, -0.5) / 8e6, 1.0, 1e-12);
  EXPECT_THROW(size_law({1.0}, {2.0}), InvalidInput);
  EXPECT_THROW(size_law({1.0, 1.0}, {2.0, 3.0}), InvalidInput);
  EXPECT_THROW(size_law({1.0, -2.0}, {2.0, 3.0}), InvalidInput);
}

TEST(Weibull, BothFitsRecoverAKnownLaw) {
  Rng rng(2023);
  const std::vector<double> s = weibull_sample(10.5e6, 4.2, 20000, rng);
  for (const WeibullFit f : {weibull_least_squares(s), weibull_maximum_likelihood(s)}) {
    EXPECT_NEAR(f.sigma0 / 10.5e6, 1.0, 0.01);
    EXPECT_NEAR(f.modulus / 4.2, 1.0, 0.03);
  }
  // Units do not matter: strengths × 1e-6 (MPa) scale σ0 and keep m.
  std::vector<double> mpa = s;
  for (double& v : mpa) v *= 1e-6;
  const WeibullFit a = weibull_maximum_likelihood(s), b = weibull_maximum_likelihood(mpa);
  EXPECT_NEAR(b.sigma0 / (a.sigma0 * 1e-6), 1.0, 1e-9);
  EXPECT_NEAR(b.modulus / a.modulus, 1.0, 1e-9);
  // The likelihood equation holds at the ML modulus.
  const std::vector<double> small = {7.1, 8.4, 9.0, 9.9, 10.4, 11.8, 12.5, 13.0};
  const WeibullFit ml = weibull_maximum_likelihood(small);
  double sw = 0, swl = 0, sl = 0, s0 = 0;
  for (double v : small) {
    sw += std::pow(v, ml.modulus);
    swl += std::pow(v, ml.modulus) * std::log(v);
    sl += std::log(v);
    s0 += std::pow(v, ml.modulus);
  }
  EXPECT_NEAR(swl / sw - 1.0 / ml.modulus - sl / small.size(), 0.0, 1e-9);
  EXPECT_NEAR(ml.sigma0, std::pow(s0 / small.size(), 1.0 / ml.modulus), 1e-9);
  // Least squares on the ranking Ps_i = 1 − i/(N + 1): ln σ = 0, ln 2, 2 ln 2 are evenly spaced,
  // so the slope is (y3 − y1)/(2 ln 2) and the line passes through (ln 2, mean y).
  const WeibullFit ls = weibull_least_squares({4.0, 1.0, 2.0});
  const double y1 = std::log(std::log(4.0 / 3.0)), y2 = std::log(std::log(2.0)),
               y3 = std::log(std::log(4.0));
  EXPECT_NEAR(ls.modulus, (y3 - y1) / std::log(4.0), 1e-12);
  const double mean_y = (y1 + y2 + y3) / 3.0;
  EXPECT_NEAR(std::log(ls.sigma0), std::log(2.0) - mean_y / ls.modulus, 1e-12);
  EXPECT_THROW(weibull_least_squares({1.0, 2.0}), InvalidInput);
  EXPECT_THROW(weibull_maximum_likelihood({1.0, 1.0, 1.0}), InvalidInput);
  EXPECT_THROW(weibull_least_squares({1.0, 2.0, std::nan("")}), InvalidInput);
  EXPECT_THROW(weibull_maximum_likelihood({1.0, 2.0, 0.0}), InvalidInput);
}

TEST(Weibull, BootstrapIntervalsCoverTheTrueValues) {
  // 30 particles a set (the paper's): about 90 % of the 90 % intervals hold the true σ0 and m.
  Rng rng(7);
  int sigma0_in = 0, modulus_in = 0;
  const int experiments = 200;
  double width = 0;
  for (int e = 0; e < experiments; ++e) {
    const std::vector<double> s = weibull_sample(10.5, 4.2, 30, rng);
    const WeibullEstimate w = weibull_bootstrap(s, WeibullMethod::least_squares, 400, rng);
    EXPECT_LE(w.sigma0_lo, w.sigma0_hi);
    sigma0_in += w.sigma0_lo <= 10.5 && 10.5 <= w.sigma0_hi;
    modulus_in += w.modulus_lo <= 4.2 && 4.2 <= w.modulus_hi;
    width += (w.sigma0_hi - w.sigma0_lo) / w.fit.sigma0 / experiments;
  }
  EXPECT_GE(sigma0_in, 0.8 * experiments);
  EXPECT_LE(sigma0_in, 0.97 * experiments);
  EXPECT_GE(modulus_in, 0.7 * experiments);  // the percentile interval of m runs a little short
  // 2·1.645·SD(σ0)/σ0 with SD/σ0 ≈ 1.053/(m·√30) = 4.6 % (the Fisher information): about 15 %.
  EXPECT_NEAR(width, 0.15, 0.05);
  std::printf("bootstrap, 200 sets of 30: σ0 covered %d, m covered %d, mean σ0 width %.3f\n",
              sigma0_in, modulus_in, width);
  // Same stream, same intervals.
  const std::vector<double> s = {9.0, 10.0, 11.0, 12.0, 8.5};
  Rng a(1), b(1);
  EXPECT_EQ(weibull_bootstrap(s, WeibullMethod::maximum_likelihood, 50, a).modulus_hi,
            weibull_bootstrap(s, WeibullMethod::maximum_likelihood, 50, b).modulus_hi);
  EXPECT_THROW(weibull_bootstrap(s, WeibullMethod::least_squares, 5, a), InvalidInput);
}

TEST(Weibull, SurvivorsEnterAsCensoredSamples) {
  // A survivor's strength is only known to lie above the stress it carried. Johnson's adjusted
  // ranks by hand: failures 1 and 3, a survivor at 2, N = 3: the first failure has reverse rank 3,
  // rank (3·0 + 4)/4 = 1 and Ps = 3/4; the second reverse rank 1, rank (1·1 + 4)/2 = 2.5 and Ps =
  // 1 − 2.5/4.
  const auto p = weibull_plotting_positions({3.0, 1.0}, {2.0});
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], std::make_pair(1.0, 0.75));
  EXPECT_EQ(p[1], std::make_pair(3.0, 0.375));
  // Without survivors the ranks are i exactly: Ps_i = 1 − i/(N + 1).
  const auto plain = weibull_plotting_positions({5.0, 2.0, 9.0, 4.0});
  for (std::size_t i = 0; i < plain.size(); ++i)
    EXPECT_EQ(plain[i].second, 1.0 - double(i + 1) / 5.0);

  // A known law censored at a fixed stress (every sample above 1.1·σ0 survives it, about 27 %)
  // and at a random one (each sample's test stops at a uniform stress in [0.5, 2]·σ0): both
  // fits recover σ0 and m; dropping the survivors, or taking them for failures, does not.
  Rng rng(11);
  const std::vector<double> s = weibull_sample(10.5e6, 4.2, 20000, rng);
  std::vector<double> fixed_f, fixed_s, random_f, random_s;
  for (double v : s) {
    (v <= 1.1 * 10.5e6 ? fixed_f : fixed_s).push_back(std::min(v, 1.1 * 10.5e6));
    const double stop = 10.5e6 * (0.5 + 1.5 * rng.uniform());
    (v <= stop ? random_f : random_s).push_back(std::min(v, stop));
  }
  EXPECT_NEAR(double(fixed_s.size()) / s.size(), std::exp(-std::pow(1.1, 4.2)), 0.01);
  for (const auto& [f, c] :
       {std::make_pair(fixed_f, fixed_s), std::make_pair(random_f, random_s)}) {
    for (const WeibullFit w : {weibull_least_squares(f, c), weibull_maximum_likelihood(f, c)}) {
      EXPECT_NEAR(w.sigma0 / 10.5e6, 1.0, 0.015);
      EXPECT_NEAR(w.modulus / 4.2, 1.0, 0.05);
    }
    EXPECT_LT(weibull_least_squares(f).sigma0, 0.96 * 10.5e6);  // survivors dropped
    std::vector<double> as_failures = f;
    as_failures.insert(as_failures.end(), c.begin(), c.end());
    EXPECT_LT(weibull_maximum_likelihood(as_failures).sigma0, 0.97 * 10.5e6);
  }
  // The censored likelihood ln L = Σ_f [ln m − m ln σ0 + (m − 1) ln x] − Σ_all (x/σ0)^m is
  // largest at the ML fit.
  const std::vector<double> f = {7.1, 8.4, 9.0, 9.9, 10.4}, c = {6.0, 11.8, 12.5};
  const WeibullFit ml = weibull_maximum_likelihood(f, c);
  auto log_l = [&](double sigma0, double m) {
    double l = 0;
    for (double x : f) l += std::log(m) - m * std::log(sigma0) + (m - 1) * std::log(x);
    for (const auto* v : {&f, &c})
      for (double x : *v) l -= std::pow(x / sigma0, m);
    return l;
  };
  for (const double ds : {-1e-3, 0.0, 1e-3})
    for (const double dm : {-1e-3, 0.0, 1e-3})
      if (ds != 0.0 || dm != 0.0) {
        EXPECT_LT(log_l(ml.sigma0 * (1 + ds), ml.modulus * (1 + dm)), log_l(ml.sigma0, ml.modulus));
      }
  // The bootstrap brackets the fit and repeats on the same stream; bad survivors are refused.
  Rng a(3), b(3);
  const WeibullEstimate e = weibull_bootstrap(f, c, WeibullMethod::least_squares, 50, a);
  EXPECT_LE(e.sigma0_lo, e.fit.sigma0);
  EXPECT_GE(e.sigma0_hi, e.fit.sigma0);
  EXPECT_EQ(weibull_bootstrap(f, c, WeibullMethod::least_squares, 50, b).sigma0_hi, e.sigma0_hi);
  EXPECT_THROW(weibull_least_squares({1.0, 2.0}, {3.0, 4.0}), InvalidInput);
  EXPECT_THROW(weibull_maximum_likelihood(f, {std::nan("")}), InvalidInput);
  EXPECT_THROW(weibull_least_squares(f, {-1.0}), InvalidInput);
}

TEST(Weibull, SpearmanRanks) {
  EXPECT_DOUBLE_EQ(spearman({1, 2, 3, 4}, {10, 20, 30, 40}), 1.0);
  EXPECT_DOUBLE_EQ(spearman({1, 2, 3, 4}, {4, 1, 0, -3}), -1.0);
  EXPECT_DOUBLE_EQ(spearman({27.5, 31.6, 35.7, 39.7, 43.9}, {10.5, 10.0, 8.71, 8.04, 7.92}), -1.0);
  // Ties share their mean rank: x ranks 1.5, 1.5, 3; y ranks 1, 2, 3.
  EXPECT_NEAR(spearman({1, 1, 2}, {1, 2, 3}), std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_THROW(spearman({1, 2}, {1}), InvalidInput);
}
