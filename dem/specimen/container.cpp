#include "dem/specimen/container.h"

#include "geom/errors.h"
#include "geom/format.h"

namespace clumpkit::dem {

void check_container_length(double length) {
  const std::string why = outside(kContainerLength, length);
  if (!why.empty()) throw InvalidInput(why + ", got " + format_number(length));
}

}  // namespace clumpkit::dem
