#include "dem/timestep.h"

#include "geom/errors.h"

#include <cmath>
#include <string>

namespace clumpkit::dem {

double critical_timestep(double mass, double stiffness) {
  if (!(mass > 0.0) || !std::isfinite(mass))
    throw InvalidInput("critical time step: mass must be positive, got " + std::to_string(mass));
  if (!(stiffness > 0.0) || !std::isfinite(stiffness))
    throw InvalidInput("critical time step: stiffness must be positive, got " +
                       std::to_string(stiffness));
  return std::sqrt(mass / stiffness);
}

}  // namespace clumpkit::dem
