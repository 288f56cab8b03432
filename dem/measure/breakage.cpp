#include "dem/measure/breakage.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {

namespace {

void check_pieces(const std::vector<SievedPiece>& pieces, const char* which) {
  if (pieces.empty()) throw InvalidInput(std::string("breakage: no ") + which + " pieces");
  for (const SievedPiece& p : pieces)
    if (!(p.volume > 0 && std::isfinite(p.volume) && p.size >= 0 && std::isfinite(p.size)))
      throw InvalidInput(std::string("breakage: a ") + which + " piece of volume " +
                         format_number(p.volume) + " and size " + format_number(p.size) +
                         " (volume must be positive, size ≥ 0)");
}

double total_volume(const std::vector<SievedPiece>& pieces) {
  double v = 0;
  for (const SievedPiece& p : pieces) v += p.volume;
  return v;
}

// Hardin's breakage potential: ∫ log10(d/silt) dF above the silt limit.
double potential(const std::vector<SievedPiece>& pieces, double silt) {
  double b = 0;
  for (const SievedPiece& p : pieces)
    if (p.size > silt) b += p.volume * std::log10(p.size / silt);
  return b / total_volume(pieces);
}

// ∫ F d(log10 d) over [d_m, d_M] for the step curve of the pieces: a piece of size s adds its
// fraction over log10(d_M) − log10(clamp(s)).
double area_under(const std::vector<SievedPiece>& pieces, double dm, double dM) {
  double a = 0;
  for (const SievedPiece& p : pieces)
    a += p.volume * (std::log10(dM) - std::log10(std::clamp(p.size, dm, dM)));
  return a / total_volume(pieces);
}

void check_limits(const BreakageLimits& l) {
  if (!(l.silt > 0 && std::isfinite(l.silt)))
    throw InvalidInput("breakage: the silt limit must be positive, got " + format_number(l.silt));
  if (!(l.fractal_dimension > 0 && l.fractal_dimension < 3))
    throw InvalidInput("breakage: the fractal dimension must be in (0, 3), got " +
                       format_number(l.fractal_dimension));
}

}  // namespace

std::vector<double> sieve_series(double smallest, double largest, double ratio) {
  if (!(smallest > 0 && largest > smallest && std::isfinite(largest) && ratio > 1 &&
        std::isfinite(ratio)))
    throw InvalidInput("sieve series: need 0 < smallest < largest and ratio > 1, got " +
                       format_number(smallest) + ", " + format_number(largest) + ", " +
                       format_number(ratio));
  std::vector<double> s;
  for (double d = largest; d > smallest; d /= ratio) s.push_back(d);
  std::reverse(s.begin(), s.end());
  return s;
}

std::vector<double> passing(const std::vector<SievedPiece>& pieces,
                            const std::vector<double>& sieves) {
  check_pieces(pieces, "sieved");
  const double total = total_volume(pieces);
  std::vector<double> f;
  f.reserve(sieves.size());
  for (std::size_t k = 0; k < sieves.size(); ++k) {
    if (!(sieves[k] > 0 && std::isfinite(sieves[k])) || (k > 0 && !(sieves[k] > sieves[k - 1])))
      throw InvalidInput("breakage: sieve openings must be positive and ascending, got " +
                         format_number(sieves[k]));
    double v = 0;
    for (const SievedPiece& p : pieces)
      if (p.size < sieves[k]) v += p.volume;
    f.push_back(v / total);
  }
  return f;
}

double hardin_breakage(const std::vector<SievedPiece>& initial,
                       const std::vector<SievedPiece>& current, const BreakageLimits& limits) {
  check_limits(limits);
  check_pieces(initial, "initial");
  check_pieces(current, "current");
  const double bp0 = potential(initial, limits.silt);
  if (!(bp0 > 0)) throw InvalidInput("breakage: the initial grading is all below the silt limit");
  return (bp0 - potential(current, limits.silt)) / bp0;
}

double einav_breakage(const std::vector<SievedPiece>& initial,
                      const std::vector<SievedPiece>& current, const BreakageLimits& limits) {
  check_limits(limits);
  check_pieces(initial, "initial");
  check_pieces(current, "current");
  double dM = 0;
  for (const SievedPiece& p : initial) dM = std::max(dM, p.size);
  const double dm = limits.silt;
  if (!(dM > dm)) throw InvalidInput("breakage: the initial grading is all below the silt limit");
  // ∫ (d/d_M)^a d(log10 d) from d_m to d_M = (1 − (d_m/d_M)^a) / (a·ln 10), a = 3 − D.
  const double a = 3.0 - limits.fractal_dimension;
  const double ultimate = (1.0 - std::pow(dm / dM, a)) / (a * std::log(10.0));
  const double a0 = area_under(initial, dm, dM);
  return (area_under(current, dm, dM) - a0) / (ultimate - a0);
}

double marsal_breakage(const std::vector<SievedPiece>& initial,
                       const std::vector<SievedPiece>& current, const std::vector<double>& sieves) {
  const std::vector<double> f0 = passing(initial, sieves), f = passing(current, sieves);
  // Retained between consecutive sieves, with the pan (below the smallest) and the part above
  // the largest: differences of the passing fractions with 0 and 1 at the ends.
  double bg = 0, below0 = 0, below = 0;
  for (std::size_t k = 0; k <= sieves.size(); ++k) {
    const double p0 = k < sieves.size() ? f0[k] : 1.0, p = k < sieves.size() ? f[k] : 1.0;
    bg += std::max(0.0, (p0 - below0) - (p - below));
    below0 = p0;
    below = p;
  }
  return bg;
}

}  // namespace clumpkit::dem
