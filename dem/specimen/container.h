// The one check of a specimen container's lengths (diameter, height, edges), for the specs of
// dem/specimen and the recipes that fill them.
#pragma once

namespace clumpkit::dem {

/// Throws InvalidInput "must be positive and finite, got V" for a container length that is not.
void check_container_length(double length);

}  // namespace clumpkit::dem
