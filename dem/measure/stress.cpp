#include "dem/measure/stress.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit::dem {

namespace {

void check_wall(const World& world, int wall) {
  if (wall < 0 || wall >= static_cast<int>(world.walls().size()))
    throw InvalidInput("DEM stress: no wall " + std::to_string(wall));
}

}  // namespace

Vec3 wall_force(const World& world, int wall) {
  check_wall(world, wall);
  Vec3 f = Vec3::Zero();
  for (const WallContact& c : world.wall_contacts())
    if (c.wall == wall) f -= c.state.force();
  for (const VertexContact& c : world.vertex_contacts())
    if (c.wall == wall) f -= c.state.force();
  return f;
}

ProbeForces probe_forces(const World& world, int wall) {
  check_wall(world, wall);
  const Wall& probe = world.walls()[wall];
  if (probe.kind != Wall::Kind::probe)
    throw InvalidInput("DEM stress: wall " + std::to_string(wall) + " is not a probe");
  ProbeForces f;
  for (const WallContact& c : world.wall_contacts()) {
    if (c.wall != wall) continue;
    const WallHit hit =
        wall_hit(probe, world.sphere_center(c.sphere), world.sphere_radius(c.sphere));
    (hit.part == ProbePart::tip ? f.tip : f.sleeve) -= c.state.force();
  }
  return f;
}

double wall_stress(const World& world, int wall, double area) {
  check_wall(world, wall);
  if (!(area > 0.0)) throw InvalidInput("DEM stress: wall area must be positive");
  double push = 0.0;
  for (const WallContact& c : world.wall_contacts())
    if (c.wall == wall) push += c.state.force().dot(c.state.normal);
  return push / area;
}

double wall_contact_stiffness(const World& world, int wall) {
  check_wall(world, wall);
  const ContactParams& p = world.options().contact;
  const double dt = world.options().timestep;
  double k = 0.0;
  for (const WallContact& c : world.wall_contacts())
    if (c.wall == wall && c.state.overlap > 0.0) {
      const Body& b = world.bodies()[world.sphere_body(c.sphere)];
      const ContactParams q = scaled_stiffness(p, wall_stiffness_factor(p, b.diameter));
      k += q.kn + normal_dashpot(b.mass, q) / dt;
    }
  return k;
}

Mat3 love_weber_stress(const World& world, const std::function<bool(const Vec3&)>& inside,
                       double volume) {
  if (!(volume > 0.0)) throw InvalidInput("DEM stress: region volume must be positive");
  const auto& bodies = world.bodies();
  std::vector<char> in(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) in[b] = inside(bodies[b].position) ? 1 : 0;
  Mat3 sum = Mat3::Zero();
  // Pair contact: body of j receives +f at the point, body of i receives −f.
  for (const PairContact& c : world.contacts()) {
    const Vec3 f = c.state.force();
    const int bi = world.sphere_body(c.i), bj = world.sphere_body(c.j);
    if (in[bj]) sum += (c.state.point - bodies[bj].position) * f.transpose();
    if (in[bi]) sum -= (c.state.point - bodies[bi].position) * f.transpose();
  }
  for (const WallContact& c : world.wall_contacts()) {
    const int b = world.sphere_body(c.sphere);
    if (in[b]) sum += (c.state.point - bodies[b].position) * c.state.force().transpose();
  }
  return -0.5 * (sum + sum.transpose()) / volume;
}

double mean_stress(const Mat3& s) {
  return s.trace() / 3.0;
}

double deviator_stress(const Mat3& s) {
  const Mat3 d = s - mean_stress(s) * Mat3::Identity();
  return std::sqrt(1.5 * d.cwiseProduct(d).sum());
}

double coordination_number(const World& world) {
  if (world.bodies().empty()) return 0.0;
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(world.contacts().size());
  for (const PairContact& c : world.contacts()) {
    if (!(c.state.overlap > 0.0)) continue;
    const int a = world.sphere_body(c.i), b = world.sphere_body(c.j);
    pairs.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(pairs.begin(), pairs.end());
  const auto distinct = std::unique(pairs.begin(), pairs.end()) - pairs.begin();
  return 2.0 * static_cast<double>(distinct) / static_cast<double>(world.bodies().size());
}

}  // namespace clumpkit::dem
