// The lengths clumpkit accepts: beyond them volumes (∝ L³) and moments (∝ L⁵) overflow or sink
// into denormals, so inputs outside are refused up front with the value named.
#pragma once

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/range.h"

#include <cmath>
#include <string>

namespace clumpkit {

/// Largest length magnitude (coordinate, size, radius) in any unit: (1e30)⁵ = 1e150 stays far
/// from overflow in a moment of inertia, and squares and cubes of coordinate differences stay
/// exact enough for CGAL's filtered predicates.
inline constexpr double kMaxLength = 1e30;
/// Smallest size or radius: (1e-30)⁵ = 1e-150 stays a normal double.
inline constexpr double kMinLength = 1e-30;

/// A size or radius, in any unit: [kMinLength, kMaxLength].
inline constexpr Range kSize = closed(kMinLength, kMaxLength);

/// Throws InvalidInput "`what`: must be between 1e-30 and 1e30, got V" unless `v` is a positive
/// size within kSize (NaN and infinities included).
inline void check_size(double v, const std::string& what) {
  if (!kSize.contains(v))
    throw InvalidInput(what + ": must be a size between 1e-30 and 1e30, got " + format_number(v));
}

/// Throws InvalidInput "`what`: must be finite with magnitude at most 1e30, got V" unless `v` is
/// a coordinate within [−kMaxLength, kMaxLength].
inline void check_coordinate(double v, const std::string& what) {
  if (!(std::abs(v) <= kMaxLength))
    throw InvalidInput(what + ": must be finite with magnitude at most 1e30, got " +
                       format_number(v));
}

}  // namespace clumpkit
