#include "dem/lab/weibull.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace clumpkit::dem {

namespace {

void check_values(const std::vector<double>& s, const char* what) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!(s[i] > 0.0) || !std::isfinite(s[i]))
      throw InvalidInput(std::string("Weibull fit: ") + what + " " + std::to_string(i) +
                         " must be positive and finite, got " + format_number(s[i]));
}

void check_strengths(const std::vector<double>& failed, const std::vector<double>& survived) {
  if (failed.size() < 3)
    throw InvalidInput("Weibull fit: needs at least 3 failures, got " +
                       std::to_string(failed.size()));
  check_values(failed, "strength");
  check_values(survived, "survivor's stress");
  if (*std::min_element(failed.begin(), failed.end()) ==
      *std::max_element(failed.begin(), failed.end()))
    throw InvalidInput("Weibull fit: the strengths are all equal (" + format_number(failed[0]) +
                       ")");
}

// Slope and intercept of the least-squares line y = a·x + b.
std::pair<double, double> line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  const double a = sxy / sxx;
  return {a, my - a * mx};
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double at = q * (v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(std::floor(at));
  const double f = at - i;
  return i + 1 < v.size() ? (1 - f) * v[i] + f * v[i + 1] : v[i];
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = 0.5 * (i + j) + 1.0;
    i = j + 1;
  }
  return r;
}

}  // namespace

std::vector<std::pair<double, double>> weibull_plotting_positions(
    const std::vector<double>& failed, const std::vector<double>& survived) {
  // Ascending, a failure before a survivor of the same stress (false sorts first).
  std::vector<std::pair<double, bool>> all;
  for (double v : failed) all.push_back({v, false});
  for (double v : survived) all.push_back({v, true});
  std::sort(all.begin(), all.end());
  const double n = static_cast<double>(all.size());
  std::vector<std::pair<double, double>> out;
  double rank = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].second) continue;
    const double reverse = n - static_cast<double>(i);
    rank = (reverse * rank + n + 1.0) / (reverse + 1.0);
    out.push_back({all[i].first, 1.0 - rank / (n + 1.0)});
  }
  return out;
}

WeibullFit weibull_least_squares(const std::vector<double>& failed,
                                 const std::vector<double>& survived) {
  check_strengths(failed, survived);
  std::vector<double> x, y;
  for (const auto& [sigma, ps] : weibull_plotting_positions(failed, survived)) {
    x.push_back(std::log(sigma));
    y.push_back(std::log(std::log(1.0 / ps)));
  }
  const auto [m, b] = line(x, y);
  return {std::exp(-b / m), m};
}

WeibullFit weibull_maximum_likelihood(const std::vector<double>& failed,
                                      const std::vector<double>& survived) {
  check_strengths(failed, survived);
  // Scaled by the largest value, so that x^m stays finite for any m.
  const double top =
      std::max(*std::max_element(failed.begin(), failed.end()),
               survived.empty() ? 0.0 : *std::max_element(survived.begin(), survived.end()));
  std::vector<double> l;
  double mean = 0.0;  // of the failures' logarithms
  for (double v : failed) {
    l.push_back(std::log(v / top));
    mean += l.back();
  }
  mean /= static_cast<double>(failed.size());
  for (double v : survived) l.push_back(std::log(v / top));
  auto f = [&](double m) {  // increasing in m, from −∞ to −mean > 0
    double a = 0, b = 0;
    for (double x : l) {
      const double w = std::exp(m * x);
      a += w * x;
      b += w;
    }
    return a / b - 1.0 / m - mean;
  };
  double lo = 1.0, hi = 1.0;
  while (f(lo) > 0.0) lo *= 0.5;
  while (f(hi) < 0.0) hi *= 2.0;
  while (hi - lo > 1e-12 * hi) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  const double m = 0.5 * (lo + hi);
  double sum = 0;
  for (double x : l) sum += std::exp(m * x);
  return {top * std::pow(sum / static_cast<double>(failed.size()), 1.0 / m), m};
}

std::pair<std::vector<double>, std::vector<double>> weibull_resample(
    const std::vector<double>& failed, const std::vector<double>& survived, Rng& rng) {
  const std::size_t n = failed.size() + survived.size();
  for (;;) {
    std::pair<std::vector<double>, std::vector<double>> draw;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = rng.below(n);
      if (i < failed.size())
        draw.first.push_back(failed[i]);
      else
        draw.second.push_back(survived[i - failed.size()]);
    }
    const auto& f = draw.first;
    if (f.size() >= 3 &&
        *std::min_element(f.begin(), f.end()) < *std::max_element(f.begin(), f.end()))
      return draw;
  }
}

WeibullEstimate weibull_bootstrap(const std::vector<double>& failed,
                                  const std::vector<double>& survived, WeibullMethod method,
                                  int resamples, Rng& rng, double level) {
  auto fit = [&](const std::vector<double>& f, const std::vector<double>& s) {
    return method == WeibullMethod::least_squares ? weibull_least_squares(f, s)
                                                  : weibull_maximum_likelihood(f, s);
  };
  require(kBootstrapResamples, resamples, "Weibull bootstrap: resamples");
  if (!(level > 0.0 && level < 1.0))
    throw InvalidInput("Weibull bootstrap: level must be in (0, 1), got " + format_number(level));
  WeibullEstimate e;
  e.fit = fit(failed, survived);
  std::vector<double> s0, m;
  for (int r = 0; r < resamples; ++r) {
    const auto [f, s] = weibull_resample(failed, survived, rng);
    const WeibullFit w = fit(f, s);
    s0.push_back(w.sigma0);
    m.push_back(w.modulus);
  }
  const double tail = 0.5 * (1.0 - level);
  e.sigma0_lo = percentile(s0, tail);
  e.sigma0_hi = percentile(s0, 1.0 - tail);
  e.modulus_lo = percentile(m, tail);
  e.modulus_hi = percentile(m, 1.0 - tail);
  return e;
}

SizeLaw size_law(const std::vector<double>& d, const std::vector<double>& s) {
  if (d.size() != s.size() || d.size() < 2)
    throw InvalidInput("size law: needs at least 2 sizes with one strength each, got " +
                       std::to_string(d.size()) + " sizes and " + std::to_string(s.size()) +
                       " strengths");
  std::vector<double> x, y;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (!(d[i] > 0.0) || !std::isfinite(d[i]) || !(s[i] > 0.0) || !std::isfinite(s[i]))
      throw InvalidInput("size law: size " + format_number(d[i]) + " and strength " +
                         format_number(s[i]) + " must be positive and finite");
    x.push_back(std::log(d[i]));
    y.push_back(std::log(s[i]));
  }
  if (*std::min_element(d.begin(), d.end()) == *std::max_element(d.begin(), d.end()))
    throw InvalidInput("size law: the sizes are all equal (" + format_number(d[0]) + ")");
  const auto [a, b] = line(x, y);
  return {std::exp(b), -a};
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 2)
    throw InvalidInput("Spearman correlation: needs two series of one length ≥ 2, got " +
                       std::to_string(x.size()) + " and " + std::to_string(y.size()));
  const std::vector<double> rx = ranks(x), ry = ranks(y);
  const double n = static_cast<double>(x.size()), mean = 0.5 * (n + 1);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (rx[i] - mean) * (ry[i] - mean);
    sxx += (rx[i] - mean) * (rx[i] - mean);
    syy += (ry[i] - mean) * (ry[i] - mean);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

}  // namespace clumpkit::dem
