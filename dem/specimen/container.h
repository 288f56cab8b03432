// The one check of a specimen container's lengths (diameter, height, edges), for the specs of
// dem/specimen and the recipes that fill them.
#pragma once

#include "geom/range.h"

namespace clumpkit::dem {

/// A container's length: a diameter, a height or an edge (m; finite).
inline constexpr Range kContainerLength = above(0);

/// Throws InvalidInput "must be > 0, got V" (kContainerLength's words, for the caller to prefix
/// with the field) for a container length outside kContainerLength.
void check_container_length(double length);

}  // namespace clumpkit::dem
