// Test fixture: a small deposition world (spheres and clumps falling in a cylinder) shared by the
// run and checkpoint tests.
#pragma once

#include "dem/core/body.h"
#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "geom/random.h"

#include <cmath>

namespace clumpkit::dem::test {

constexpr double kDensity = 2650.0;  // kg/m³

// Spheres (radius 4–6 mm) on a loose lattice in a cylinder of radius 5 cm with random
// velocities, four three-sphere clumps above them, a floor and (optionally) a top platen moving
// down.
// Gravity, friction, viscous damping: contacts with shear history form within a few hundred
// steps.
// `scaled`: kn ∝ d (d_ref 1 cm), a frictionless floor and a cylinder closing in at 1 cm/s — every
// field a servo-driven element test adds to the world.
inline World make_deposition(int spheres, bool platen = true, bool scaled = false) {
  WorldOptions o;
  o.contact.kn = 1e5;
  o.contact.ks = 1e5;
  if (scaled) {
    o.contact.scaling = StiffnessScaling::linear;
    o.contact.d_ref = 0.01;
  }
  o.contact.friction = 0.5;
  o.contact.damping_ratio = 0.3;
  World world(o);
  const double R = 0.05, spacing = 0.0125;
  Rng rng(42);
  int placed = 0;
  for (int layer = 0; placed < spheres; ++layer)
    for (int ix = -4; ix <= 4 && placed < spheres; ++ix)
      for (int iy = -4; iy <= 4 && placed < spheres; ++iy) {
        const double x = ix * spacing, y = iy * spacing;
        if (std::hypot(x, y) > R - 0.008) continue;
        const double r = rng.uniform(0.004, 0.006);
        Body b = make_sphere_body(Vec3(x, y, 0.007 + layer * spacing), r, kDensity);
        b.velocity = rng.uniform(Vec3::Constant(-0.3), Vec3::Constant(0.3));
        world.add_body(std::move(b));
        ++placed;
      }
  const double top = 0.007 + (placed / 30 + 2) * spacing;
  const Clump clump{{Sphere{Vec3(-0.006, 0.0, 0.0), 0.005}, Sphere{Vec3(0.004, 0.001, 0.0), 0.006},
                     Sphere{Vec3(0.0, 0.004, 0.003), 0.004}}};
  for (int k = 0; k < 4; ++k) {
    Body c = make_clump_body(clump, kDensity);
    c.position = Vec3(k % 2 ? 0.02 : -0.02, k / 2 ? 0.02 : -0.02, top);
    c.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7 * k + 0.3, rng.unit_vector()));
    c.velocity = Vec3(0.0, 0.0, -0.5);
    c.angular_velocity = rng.uniform(Vec3::Constant(-5), Vec3::Constant(5));
    world.add_body(std::move(c));
  }
  Wall floor = Wall::plane(Vec3::Zero(), Vec3::UnitZ()), side = Wall::cylinder(0.0, 0.0, R);
  if (scaled) {
    floor.friction = 0.0;
    side.radial_velocity = -0.01;
  }
  world.add_wall(floor);
  world.add_wall(side);
  if (platen) world.add_wall(Wall::plane(Vec3(0, 0, top + 0.03), -Vec3::UnitZ(), Vec3(0, 0, -0.2)));
  world.options().timestep = 0.2 * critical_timestep(world);
  return world;
}

}  // namespace clumpkit::dem::test
