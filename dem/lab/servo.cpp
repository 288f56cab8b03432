#include "dem/lab/servo.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {

double servo_speed(double stress, double target, double area, double stiffness, double dt,
                   const ServoGain& gain) {
  if (!(area > 0.0) || !(dt > 0.0) || !(gain.max_speed > 0.0) || !std::isfinite(gain.max_speed))
    throw InvalidInput("servo: area, time step and max_speed must be positive");
  if (!(gain.relaxation > 0.0 && gain.relaxation <= 1.0))
    throw InvalidInput("servo: relaxation must be in (0, 1], got " +
                       std::to_string(gain.relaxation));
  const double error = target - stress;
  if (!(stiffness > 0.0)) return error > 0.0 ? gain.max_speed : -gain.max_speed;
  const double v = gain.relaxation * area * error / (stiffness * dt);
  return std::clamp(v, -gain.max_speed, gain.max_speed);
}

void set_wall_speed(World& world, int wall, double speed) {
  if (wall < 0 || wall >= static_cast<int>(world.walls().size()))
    throw InvalidInput("servo: no wall " + std::to_string(wall));
  Wall& w = world.walls()[wall];
  if (w.kind == Wall::Kind::probe)
    throw InvalidInput("servo: wall " + std::to_string(wall) +
                       " is a probe (it moves at its own velocity)");
  if (w.kind == Wall::Kind::plane)
    w.velocity = speed * w.normal;
  else
    w.radial_velocity = -speed;
}

}  // namespace clumpkit::dem
