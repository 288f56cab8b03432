#include "dem/core/timestep.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

double body_critical_timestep(const Body& body, double kn, double ks) {
  double dt = critical_timestep(body.mass, kn);
  if (body.rotation_locked) return dt;
  const double k = std::max(kn, ks);
  for (int a = 0; a < 3; ++a) {
    double arm = 0.0;
    for (const Sphere& s : body.spheres) {
      Vec3 off = s.center;
      off[a] = 0.0;
      arm = std::max(arm, off.norm() + s.radius);
    }
    for (Vec3 off : body.vertices) {  // a polyhedral body's corners reach further
      off[a] = 0.0;
      arm = std::max(arm, off.norm());
    }
    dt = std::min(dt, critical_timestep(body.moments[a], k * arm * arm));
  }
  return dt;
}

double critical_timestep(const World& world) {
  const ContactParams& p = world.options().contact;
  double dt = std::numeric_limits<double>::infinity();
  // The stiffness of a body's contact with an equal body (kn, or kn·d/d_ref under linear
  // scaling). The fastest contact of either law then has ω² = 2·k/m: an equal pair (reduced mass
  // m/2) under both laws, and under linear scaling also a wall (2·k, the body alone on the spring)
  // or a much larger body (the same series limit). Using the wall's 2·k here would make the
  // linear law's step √2 shorter than the constant law's for the same fastest frequency.
  // A bonded body also carries the stiffness of its bonds (their springs act in parallel with
  // its contacts).
  std::vector<double> bonded(world.bodies().size(), 0.0);
  for (const Bond& bond : world.bonds()) {
    const double k = bond_stiffness(bond, world.options().cohesive);
    bonded[bond.a] += k;
    bonded[bond.b] += k;
  }
  for (std::size_t i = 0; i < world.bodies().size(); ++i) {
    const Body& b = world.bodies()[i];
    const double f = pair_stiffness_factor(p, b.diameter, b.diameter);
    // A polyhedral body on a platen: two corners' springs (an edge) at once.
    const double corners = b.vertices.empty() ? 0.0 : 2.0 * world.options().vertex_stiffness;
    dt = std::min(dt, body_critical_timestep(b, p.kn * f + bonded[i] + corners,
                                             p.ks * f + bonded[i] + corners));
  }
  return dt;
}

}  // namespace clumpkit::dem
