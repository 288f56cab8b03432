#include "dem/core/body.h"

#include "geom/errors.h"
#include "geom/sphere.h"

#include <cmath>
#include <string>

namespace clumpkit::dem {

namespace {

void check_density(double density) {
  require(kDensity, density, "DEM body: density");
}

}  // namespace

std::string kind_name(BodyKind kind) {
  return kind == BodyKind::rock ? "rock" : "soil";
}

double Body::bounding_radius() const {
  double r = 0.0;
  for (const Sphere& s : spheres) r = std::max(r, s.center.norm() + s.radius);
  return r;
}

Vec3 angular_momentum(const Vec3& moments, const Eigen::Quaterniond& q, const Vec3& omega) {
  const Mat3 rot = q.toRotationMatrix();
  return rot * moments.cwiseProduct(rot.transpose() * omega);
}

Vec3 angular_velocity_for(const Vec3& moments, const Vec3& momentum, const Eigen::Quaterniond& q) {
  const Mat3 rot = q.toRotationMatrix();
  return rot * (rot.transpose() * momentum).cwiseQuotient(moments);
}

Vec3 Body::angular_momentum() const {
  return dem::angular_momentum(moments, orientation, angular_velocity);
}

Vec3 Body::angular_velocity_for(const Vec3& momentum, const Eigen::Quaterniond& q) const {
  return dem::angular_velocity_for(moments, momentum, q);
}

double Body::kinetic_energy() const {
  return 0.5 * mass * velocity.squaredNorm() + 0.5 * angular_velocity.dot(angular_momentum());
}

Body make_sphere_body(const Vec3& center, double radius, double density) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InvalidInput("DEM sphere body: radius must be positive, got " + std::to_string(radius));
  if (!center.allFinite()) throw InvalidInput("DEM sphere body: centre must be finite");
  check_density(density);
  Body body;
  body.spheres.push_back(Sphere{Vec3::Zero(), radius});
  body.volume = 4.0 / 3.0 * kPi * radius * radius * radius;
  body.mass = body.volume * density;
  body.moments = Vec3::Constant(0.4 * body.mass * radius * radius);
  body.position = center;
  return body;
}

Body make_clump_body(const ClumpTemplate& clump_template, double density, const Vec3& position,
                     const Eigen::Quaterniond& orientation, double scale, int template_id) {
  check_density(density);
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw InvalidInput("DEM clump body: scale must be positive, got " + std::to_string(scale));
  if (clump_template.spheres.empty()) throw InvalidInput("DEM clump body: template has no spheres");
  Body body;
  body.kind = BodyKind::rock;
  body.template_id = template_id;
  body.scale = scale;
  body.spheres.reserve(clump_template.spheres.size());
  for (const Sphere& s : clump_template.spheres)
    body.spheres.push_back(Sphere{s.center * scale, s.radius * scale});
  // V·s·s·s in this order: the layer's drawn volume sums (and so its particle counts) are the
  // ones computed before bodies carried their template.
  body.volume = clump_template.mass.volume * scale * scale * scale;
  body.mass = density * body.volume;
  body.moments =
      density * clump_template.principal_moments * (scale * scale * scale * scale * scale);
  if (!(body.moments.minCoeff() > 0.0))
    throw InvalidInput("DEM clump body: principal moments must be positive");
  body.position = position;
  body.orientation = orientation.normalized();
  return body;
}

Body make_clump_body(const Clump& clump, double density) {
  const ClumpTemplate t = make_clump_template(clump);
  return make_clump_body(t, density, t.position, t.orientation);
}

}  // namespace clumpkit::dem
