#include "geom/range.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <cmath>

namespace clumpkit {

bool Range::contains(double x) const {
  if (std::isnan(x)) return false;
  if (integer && x != std::floor(x)) return false;
  const bool above_lo = lo_open ? x > lo : x >= lo;
  const bool below_hi = hi_open ? x < hi : x <= hi;
  return above_lo && below_hi;
}

std::string Range::text() const {
  const std::string kind = integer ? "integer " : "";
  const bool no_lo = std::isinf(lo), no_hi = std::isinf(hi);
  if (no_lo && no_hi) return integer ? "integer" : "any";
  if (no_hi) return kind + (lo_open ? "> " : ">= ") + format_number(lo);
  if (no_lo) return kind + (hi_open ? "< " : "<= ") + format_number(hi);
  return kind + (integer ? "in " : "") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
         format_number(hi) + (hi_open ? ")" : "]");
}

std::string outside(const Range& r, double x) {
  if (r.contains(x)) return "";
  const std::string t = r.text();
  // "must be >= 0" reads; "must be in [0, 1]" and "must be an integer in [1, 100]" need a word.
  const bool bare = t.front() == '[' || t.front() == '(';
  const std::string what = r.integer ? "an " + t : (bare ? "in " + t : t);
  return "must be " + what;
}

void require(const Range& r, double x, const std::string& name) {
  const std::string why = outside(r, x);
  if (!why.empty()) throw InvalidInput(name + ": " + why + ", got " + format_number(x));
}

}  // namespace clumpkit
