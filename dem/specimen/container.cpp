#include "dem/specimen/container.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <cmath>

namespace clumpkit::dem {

void check_container_length(double length) {
  if (!(length > 0.0) || !std::isfinite(length))
    throw InvalidInput("must be positive and finite, got " + format_number(length));
}

}  // namespace clumpkit::dem
