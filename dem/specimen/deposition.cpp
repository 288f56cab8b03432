#include "dem/specimen/deposition.h"

#include "dem/core/timestep.h"
#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {

World make_deposition_world(const std::vector<Body>& bodies,
                            const std::vector<Placement>& placements, const DepositionSpec& spec) {
  if (bodies.size() != placements.size())
    throw InvalidInput("make_deposition_world: " + std::to_string(bodies.size()) + " bodies but " +
                       std::to_string(placements.size()) + " placements");
  if (!(spec.radius > 0) || !std::isfinite(spec.radius))
    throw InvalidInput("make_deposition_world: radius must be positive and finite");
  require(kTimestepSafety, spec.timestep_safety, "make_deposition_world: timestep_safety");
  WorldOptions options;
  options.contact = spec.contact;
  options.sort_every = 1000;  // placement order is random: sort for locality (as LAMMPS)
  World world(options);
  world.reserve(bodies);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (bodies[k].spheres.empty())
      throw InvalidInput("make_deposition_world: body " + std::to_string(k) + " has no spheres");
    Body b = bodies[k];
    b.position = placements[k].position;
    // A plain sphere keeps the identity: its placement orientation would change nothing.
    if (b.kind == BodyKind::rock) b.orientation = placements[k].orientation;
    world.add_body(std::move(b));
  }
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  world.add_wall(Wall::cylinder(0.0, 0.0, spec.radius));
  if (!world.bodies().empty())
    world.options().timestep = spec.timestep_safety * critical_timestep(world);
  return world;
}

}  // namespace clumpkit::dem
