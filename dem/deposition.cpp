#include "dem/deposition.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {

World make_deposition_world(const std::vector<PlacementItem>& items,
                            const std::vector<Placement>& placements, const DepositionSpec& spec) {
  if (items.size() != placements.size())
    throw InvalidInput("make_deposition_world: " + std::to_string(items.size()) + " items but " +
                       std::to_string(placements.size()) + " placements");
  if (!(spec.radius > 0) || !std::isfinite(spec.radius))
    throw InvalidInput("make_deposition_world: radius must be positive and finite");
  if (!(spec.timestep_safety > 0) || !std::isfinite(spec.timestep_safety))
    throw InvalidInput("make_deposition_world: timestep_safety must be positive and finite");

  WorldOptions options;
  options.contact = spec.contact;
  World world(options);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const PlacementItem& item = items[k];
    const Placement& place = placements[k];
    if (item.spheres.empty())
      throw InvalidInput("make_deposition_world: item " + std::to_string(k) + " has no spheres");
    Clump clump;
    for (const Sphere& s : item.spheres)
      clump.spheres.push_back({place.orientation * s.center + place.position, s.radius});
    if (clump.spheres.size() == 1) {
      world.add_body(
          make_sphere_body(clump.spheres[0].center, clump.spheres[0].radius, spec.soil_density));
    } else {
      world.add_body(make_clump_body(clump, spec.rock_density));
    }
  }
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  world.add_wall(Wall::cylinder(0.0, 0.0, spec.radius));
  if (!world.bodies().empty())
    world.options().timestep = spec.timestep_safety * critical_timestep(world);
  return world;
}

RunOutcome deposit(World& world, const DepositionSpec& spec) {
  RunLimits limits;
  limits.max_steps = spec.max_steps;
  limits.unbalanced_ratio_below = spec.unbalanced_ratio;
  return run_until(world, limits);
}

double lattice_porosity(const World& world, double radius, double z_lo, double z_hi,
                        double spacing) {
  if (!(radius > 0) || !(spacing > 0) || !(z_hi > z_lo) || !std::isfinite(radius) ||
      !std::isfinite(z_lo) || !std::isfinite(z_hi))
    throw InvalidInput("lattice_porosity: need radius > 0, spacing > 0 and z_hi > z_lo");
  const long nxy = static_cast<long>(std::ceil(2.0 * radius / spacing));
  const long nz = static_cast<long>(std::ceil((z_hi - z_lo) / spacing));
  const auto coord = [&](long i, double lo) {
    return lo + (static_cast<double>(i) + 0.5) * spacing;
  };
  // Point (i, j, k) is in the region when its centre is inside the disc and below z_hi.
  const auto in_region = [&](long i, long j, long k) {
    const double x = coord(i, -radius), y = coord(j, -radius), z = coord(k, z_lo);
    return x * x + y * y < radius * radius && z <= z_hi;
  };
  std::vector<char> solid(static_cast<std::size_t>(nxy * nxy * nz), 0);
  const auto clamp_index = [&](double v, double lo, long n) {
    return std::clamp(static_cast<long>(std::floor((v - lo) / spacing - 0.5)), 0L, n - 1);
  };
  for (const Body& body : world.bodies()) {
    for (const Sphere& s : body.spheres) {
      const Vec3 c = body.orientation * s.center + body.position;
      const double r = s.radius;
      if (c.z() + r < z_lo || c.z() - r > z_hi || std::hypot(c.x(), c.y()) - r > radius) continue;
      const long i0 = clamp_index(c.x() - r, -radius, nxy),
                 i1 = clamp_index(c.x() + r, -radius, nxy) + 1;
      const long j0 = clamp_index(c.y() - r, -radius, nxy),
                 j1 = clamp_index(c.y() + r, -radius, nxy) + 1;
      const long k0 = clamp_index(c.z() - r, z_lo, nz), k1 = clamp_index(c.z() + r, z_lo, nz) + 1;
      for (long k = k0; k <= std::min(k1, nz - 1); ++k)
        for (long j = j0; j <= std::min(j1, nxy - 1); ++j)
          for (long i = i0; i <= std::min(i1, nxy - 1); ++i) {
            const Vec3 p(coord(i, -radius), coord(j, -radius), coord(k, z_lo));
            if ((p - c).squaredNorm() <= r * r)
              solid[static_cast<std::size_t>((k * nxy + j) * nxy + i)] = 1;
          }
    }
  }
  long total = 0, filled = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < nxy; ++j)
      for (long i = 0; i < nxy; ++i)
        if (in_region(i, j, k)) {
          ++total;
          filled += solid[static_cast<std::size_t>((k * nxy + j) * nxy + i)];
        }
  if (total == 0) throw InvalidInput("lattice_porosity: the region holds no lattice point");
  return 1.0 - static_cast<double>(filled) / static_cast<double>(total);
}

}  // namespace clumpkit::dem
