#include "dem/measure/compressibility.h"

#include <cmath>
#include <limits>

namespace clumpkit::dem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Least-squares line y = a + b·x through points [first, last) and its squared error.
struct Line {
  double a = kNaN, b = kNaN, sse = kNaN;
};

Line fit(const std::vector<double>& x, const std::vector<double>& y, std::size_t first,
         std::size_t last) {
  const double n = double(last - first);
  double sx = 0, sy = 0;
  for (std::size_t k = first; k < last; ++k) sx += x[k], sy += y[k];
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0;
  for (std::size_t k = first; k < last; ++k) {
    sxx += (x[k] - mx) * (x[k] - mx);
    sxy += (x[k] - mx) * (y[k] - my);
  }
  Line l;
  if (!(sxx > 0)) return l;
  l.b = sxy / sxx;
  l.a = my - l.b * mx;
  l.sse = 0;
  for (std::size_t k = first; k < last; ++k) {
    const double r = y[k] - (l.a + l.b * x[k]);
    l.sse += r * r;
  }
  return l;
}

}  // namespace

double compression_index(const std::vector<double>& e, const std::vector<double>& sigma, double lo,
                         double hi) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < e.size() && k < sigma.size(); ++k)
    if (sigma[k] > 0 && sigma[k] >= lo && sigma[k] <= hi)
      x.push_back(std::log10(sigma[k])), y.push_back(e[k]);
  if (x.size() < 3) return kNaN;
  return -fit(x, y, 0, x.size()).b;
}

double yield_stress(const std::vector<double>& e, const std::vector<double>& sigma) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < e.size() && k < sigma.size(); ++k)
    if (sigma[k] > 0) x.push_back(std::log10(sigma[k])), y.push_back(e[k]);
  if (x.size() < 6) return kNaN;
  double best = std::numeric_limits<double>::infinity();
  Line first, second;
  for (std::size_t brk = 3; brk + 3 <= x.size(); ++brk) {
    const Line a = fit(x, y, 0, brk), b = fit(x, y, brk, x.size());
    if (!(a.sse + b.sse < best)) continue;
    best = a.sse + b.sse;
    first = a;
    second = b;
  }
  if (!(std::abs(first.b - second.b) > 0)) return kNaN;
  return std::pow(10.0, (second.a - first.a) / (first.b - second.b));
}

}  // namespace clumpkit::dem
