#include "dem/cuboid_cell.h"

#include "dem/stress.h"
#include "geom/errors.h"

#include <cmath>

namespace clumpkit::dem {

CuboidCell add_cuboid_walls(World& world, const Vec3& lo, const Vec3& hi) {
  if (!((hi - lo).minCoeff() > 0.0) || !(hi - lo).allFinite())
    throw InvalidInput("cuboid cell: the box must have positive, finite edges");
  CuboidCell cell;
  for (int a = 0; a < 3; ++a) {
    Wall low = Wall::plane(lo, Vec3::Unit(a)), high = Wall::plane(hi, -Vec3::Unit(a));
    low.friction = high.friction = 0.0;
    cell.walls[2 * a] = world.add_wall(low);
    cell.walls[2 * a + 1] = world.add_wall(high);
  }
  return cell;
}

Vec3 cell_lengths(const World& world, const CuboidCell& cell) {
  Vec3 l;
  for (int a = 0; a < 3; ++a)
    l[a] =
        world.walls()[cell.walls[2 * a + 1]].point[a] - world.walls()[cell.walls[2 * a]].point[a];
  return l;
}

namespace {

double face_area(const Vec3& l, int axis) {
  return l[(axis + 1) % 3] * l[(axis + 2) % 3];
}

}  // namespace

Vec3 cell_wall_stress(const World& world, const CuboidCell& cell) {
  const Vec3 l = cell_lengths(world, cell);
  Vec3 s;
  for (int a = 0; a < 3; ++a) {
    const double area = face_area(l, a);
    s[a] = 0.5 * (wall_stress(world, cell.walls[2 * a], area) +
                  wall_stress(world, cell.walls[2 * a + 1], area));
  }
  return s;
}

Mat3 cell_love_weber_stress(const World& world, const CuboidCell& cell) {
  Vec3 lo, hi;
  for (int a = 0; a < 3; ++a) {
    lo[a] = world.walls()[cell.walls[2 * a]].point[a];
    hi[a] = world.walls()[cell.walls[2 * a + 1]].point[a];
  }
  const Vec3 l = hi - lo;
  return love_weber_stress(
      world,
      [&](const Vec3& x) {
        return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
      },
      l.prod());
}

void servo_step(World& world, const CuboidCell& cell, const Vec3& target, const ServoGain& gain) {
  const Vec3 l = cell_lengths(world, cell);
  const double dt = world.options().timestep;
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const int w = cell.walls[2 * a + side];
      const double area = face_area(l, a);
      set_wall_speed(world, w,
                     servo_speed(wall_stress(world, w, area), target[a], area,
                                 wall_contact_stiffness(world, w), dt, gain));
    }
  world.step(1);
}

ConsolidationResult servo_consolidate(World& world, const CuboidCell& cell,
                                      const ConsolidationSettings& s,
                                      const std::function<bool()>& stop) {
  if (!(s.target.minCoeff() > 0.0) || !s.target.allFinite())
    throw InvalidInput("consolidation: target stresses must be positive");
  if (s.check_every < 1) throw InvalidInput("consolidation: check_every must be at least 1");
  ConsolidationResult r;
  auto settled = [&] {
    r.stress = cell_wall_stress(world, cell);
    r.unbalanced = mean_unbalanced_force_ratio(world);
    const Vec3 err = (r.stress - s.target).cwiseAbs().cwiseQuotient(s.target);
    return err.maxCoeff() <= s.tolerance && r.unbalanced <= s.unbalanced;
  };
  while (r.steps < s.max_steps) {
    for (int k = 0; k < s.check_every; ++k) servo_step(world, cell, s.target, s.gain);
    r.steps += s.check_every;
    if (settled()) {
      r.reached = true;
      break;
    }
    if (stop && stop()) break;
  }
  for (int w : cell.walls) set_wall_speed(world, w, 0.0);
  r.stress = cell_wall_stress(world, cell);
  r.unbalanced = mean_unbalanced_force_ratio(world);
  return r;
}

}  // namespace clumpkit::dem
