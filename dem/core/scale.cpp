#include "dem/core/scale.h"

#include "geom/errors.h"

#include <cmath>
#include <string>
#include <utility>

namespace clumpkit::dem {

World scaled_world(const World& world, double lambda) {
  if (!(lambda > 0.0) || !std::isfinite(lambda))
    throw InvalidInput("scale: the factor must be positive and finite, got " +
                       std::to_string(lambda));
  const double l2 = lambda * lambda, l3 = l2 * lambda;
  WorldOptions o = world.options();
  o.timestep *= lambda;
  o.skin *= lambda;
  o.gravity /= lambda;
  if (o.contact.scaling == StiffnessScaling::none) {
    o.contact.kn *= lambda;
    o.contact.ks *= lambda;
  }
  o.vertex_stiffness *= lambda;  // a corner's spring, like a constant kn
  if (!world.bonds().empty())
    throw InvalidInput(
        "scaled copy: a world with bonds has no similar copy (the cohesive law's "
        "strengths and energies do not scale with lengths)");
  World out(o);
  for (Body b : world.bodies()) {
    for (Vec3& v : b.vertices) v *= lambda;
    for (Sphere& s : b.spheres) {
      s.center *= lambda;
      s.radius *= lambda;
    }
    b.mass *= l3;
    b.volume *= l3;
    b.moments *= l3 * l2;
    b.diameter *= lambda;
    b.scale *= lambda;
    b.position *= lambda;
    b.angular_velocity /= lambda;
    b.force *= l2;
    b.torque *= l3;
    const Eigen::Quaterniond q = b.orientation;
    out.add_body(std::move(b));
    out.bodies().back().orientation = q;  // exact bits, not re-normalised
  }
  for (Wall w : world.walls()) {
    w.point *= lambda;
    w.radius *= lambda;
    out.add_wall(w);
  }
  auto scale_state = [&](ContactState& s) {
    s.point *= lambda;
    s.overlap *= lambda;
    s.excused *= lambda;
    s.normal_force *= l2;
    s.shear *= l2;
  };
  std::vector<PairContact> contacts = world.contacts();
  for (PairContact& c : contacts) scale_state(c.state);
  std::vector<WallContact> wall_contacts = world.wall_contacts();
  for (WallContact& c : wall_contacts) scale_state(c.state);
  World::ListState lists = world.list_state();
  lists.time *= lambda;
  for (Vec3& x : lists.build_positions) x *= lambda;
  for (Vec3& x : lists.filter_positions) x *= lambda;
  lists.near_limit *= l2;
  out.restore(std::move(lists), std::move(contacts), std::move(wall_contacts));
  std::vector<VertexContact> corners = world.vertex_contacts();
  for (VertexContact& c : corners) scale_state(c.state);
  out.restore_vertex_contacts(std::move(corners));
  return out;
}

}  // namespace clumpkit::dem
