#include "geom/sphere.h"

#include "geom/errors.h"

#include <cmath>
#include <string>

namespace clumpkit {

void validate(const Clump& clump) {
  if (clump.spheres.empty()) throw InvalidInput("clump has no spheres");
  for (std::size_t i = 0; i < clump.spheres.size(); ++i) {
    const Sphere& s = clump.spheres[i];
    if (!s.center.allFinite())
      throw InvalidInput("sphere " + std::to_string(i) + ": centre is not finite");
    if (!(s.radius > 0.0) || !std::isfinite(s.radius))
      throw InvalidInput("sphere " + std::to_string(i) +
                         ": radius must be positive and finite, got " + std::to_string(s.radius));
  }
}

}  // namespace clumpkit
