#include "dem/core/contact.h"

#include "geom/errors.h"
#include "geom/sphere.h"

#include <cmath>
#include <string>

namespace clumpkit::dem {

double damping_ratio_from_restitution(double e) {
  if (!(e > 0.0 && e <= 1.0))
    throw InvalidInput("contact: restitution must be in (0, 1], got " + std::to_string(e));
  const double l = std::log(e);
  return -l / std::sqrt(kPi * kPi + l * l);
}

double restitution_from_damping_ratio(double beta) {
  require(kDampingRatio, beta, "contact: damping ratio");
  return std::exp(-beta * kPi / std::sqrt(1.0 - beta * beta));
}

void validate(const ContactParams& p) {
  require(kNormalStiffness, p.kn, "contact: kn");
  require(kShearStiffness, p.ks, "contact: ks");
  if (p.scaling == StiffnessScaling::linear)
    require(kReferenceDiameter, p.d_ref, "contact: d_ref (linear stiffness scaling)");
  require(kFriction, p.friction, "contact: friction");
  require(kDampingRatio, p.damping_ratio, "contact: damping ratio");
  require(kLocalDamping, p.local_damping, "contact: local damping");
}

void update_contact(ContactState& s, const Vec3& normal, double overlap, const Vec3& point,
                    const Vec3& v, double effective_mass, const ContactParams& p, double dt) {
  update_contact_force(s.shear, s.normal_force, normal, overlap, v,
                       normal_dashpot(effective_mass, p), p, dt);
  s.normal = normal;
  s.point = point;
  s.overlap = overlap;
}

void rescale_friction(ContactState& s, double new_friction) {
  const double limit = new_friction * std::max(s.normal_force, 0.0);
  const double magnitude = s.shear.norm();
  if (magnitude > limit) s.shear *= (magnitude > 0.0 ? limit / magnitude : 0.0);
}

Vec3 local_damping(const Vec3& force, const Vec3& velocity, double alpha) {
  if (alpha == 0.0) return force;
  Vec3 out = force;
  for (int k = 0; k < 3; ++k) {
    const double sign = velocity[k] > 0.0 ? 1.0 : (velocity[k] < 0.0 ? -1.0 : 0.0);
    out[k] -= alpha * std::abs(force[k]) * sign;
  }
  return out;
}

}  // namespace clumpkit::dem
