#include "geom/shapes/distribution.h"

#include "geom/errors.h"

#include <cmath>
#include <sstream>

namespace clumpkit {

namespace {
std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}
}  // namespace

Distribution constant(double value) {
  Distribution d;
  d.a = value;
  return d;
}

void validate(const Distribution& d, const std::string& field) {
  auto fail = [&](const std::string& why) { throw InvalidInput(field + ": " + why); };
  for (double v : {d.a, d.b})
    if (!std::isfinite(v)) fail("must be finite, got " + describe(d));
  if (std::isnan(d.min) || std::isnan(d.max))
    fail("truncation must not be NaN, got " + describe(d));
  switch (d.kind) {
    case Distribution::Kind::Constant:
      break;
    case Distribution::Kind::Uniform:
    case Distribution::Kind::Integers:
      if (d.a > d.b) fail("lower bound exceeds upper bound, got " + describe(d));
      if (d.kind == Distribution::Kind::Integers &&
          (d.a != std::floor(d.a) || d.b != std::floor(d.b)))
        fail("integer bounds must be whole numbers, got " + describe(d));
      break;
    case Distribution::Kind::Normal:
    case Distribution::Kind::Lognormal:
      if (d.b < 0) fail("sigma must not be negative, got " + describe(d));
      if (d.min > d.max) fail("min exceeds max, got " + describe(d));
      if (d.kind == Distribution::Kind::Lognormal && d.max <= 0)
        fail("lognormal max must be positive, got " + describe(d));
      break;
  }
}

double sample(const Distribution& d, Rng& rng) {
  switch (d.kind) {
    case Distribution::Kind::Constant:
      return d.a;
    case Distribution::Kind::Uniform:
      return rng.uniform(d.a, d.b);
    case Distribution::Kind::Integers:
      return d.a + static_cast<double>(rng.below(static_cast<std::uint64_t>(d.b - d.a) + 1));
    case Distribution::Kind::Normal:
    case Distribution::Kind::Lognormal:
      for (int i = 0; i < 10000; ++i) {
        double x = d.a + d.b * rng.normal();
        if (d.kind == Distribution::Kind::Lognormal) x = std::exp(x);
        if (x >= d.min && x <= d.max) return x;
      }
      throw NumericError("truncated " + describe(d) + " rejected 10000 draws in a row");
  }
  return d.a;
}

double lower_bound(const Distribution& d) {
  switch (d.kind) {
    case Distribution::Kind::Constant:
    case Distribution::Kind::Uniform:
    case Distribution::Kind::Integers:
      return d.a;
    case Distribution::Kind::Normal:
      return d.min;
    case Distribution::Kind::Lognormal:
      return std::max(0.0, d.min);
  }
  return d.a;
}

double upper_bound(const Distribution& d) {
  switch (d.kind) {
    case Distribution::Kind::Constant:
      return d.a;
    case Distribution::Kind::Uniform:
    case Distribution::Kind::Integers:
      return d.b;
    case Distribution::Kind::Normal:
    case Distribution::Kind::Lognormal:
      return d.max;
  }
  return d.a;
}

std::string describe(const Distribution& d) {
  auto trunc = [&]() {
    std::string s;
    if (d.min > -1e300) s += ", min=" + num(d.min);
    if (d.max < 1e300) s += ", max=" + num(d.max);
    return s;
  };
  switch (d.kind) {
    case Distribution::Kind::Constant:
      return num(d.a);
    case Distribution::Kind::Uniform:
      return "uniform(" + num(d.a) + ", " + num(d.b) + ")";
    case Distribution::Kind::Integers:
      return "integers(" + num(d.a) + ", " + num(d.b) + ")";
    case Distribution::Kind::Normal:
      return "normal(mu=" + num(d.a) + ", sigma=" + num(d.b) + trunc() + ")";
    case Distribution::Kind::Lognormal:
      return "lognormal(mu=" + num(d.a) + ", sigma=" + num(d.b) + trunc() + ")";
  }
  return "?";
}

}  // namespace clumpkit
