#include "dem/core/wall.h"

#include "geom/errors.h"

#include <cmath>
#include <string>

namespace clumpkit::dem {

Wall Wall::plane(const Vec3& point, const Vec3& normal, const Vec3& velocity) {
  const double n = normal.norm();
  if (!(n > 0.0) || !std::isfinite(n) || !point.allFinite() || !velocity.allFinite())
    throw InvalidInput("plane wall: point, normal and velocity must be finite, normal non-zero");
  Wall w;
  w.kind = Kind::plane;
  w.point = point;
  w.normal = normal / n;
  w.velocity = velocity;
  return w;
}

Wall Wall::cylinder(double axis_x, double axis_y, double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InvalidInput("cylinder wall: radius must be positive, got " + std::to_string(radius));
  Wall w;
  w.kind = Kind::cylinder;
  w.point = Vec3(axis_x, axis_y, 0.0);
  w.radius = radius;
  return w;
}

WallHit wall_hit(const Wall& wall, const Vec3& c, double r) {
  WallHit hit;
  if (wall.kind == Wall::Kind::plane) {
    const double d = (c - wall.point).dot(wall.normal);
    hit.overlap = r - d;
    hit.normal = wall.normal;
  } else {
    const Vec3 radial(c.x() - wall.point.x(), c.y() - wall.point.y(), 0.0);
    const double rho = radial.norm();
    if (!(rho > 0.0)) return hit;
    hit.overlap = rho + r - wall.radius;
    hit.normal = -radial / rho;
  }
  hit.touching = hit.overlap > 0.0;
  hit.point = c - (r - 0.5 * hit.overlap) * hit.normal;
  return hit;
}

}  // namespace clumpkit::dem
