#include "dem/core/wall.h"

#include "geom/errors.h"
#include "geom/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

Wall Wall::probe(const Vec3& apex, double diameter, double apex_deg, const Vec3& velocity) {
  if (!(diameter > 0.0) || !std::isfinite(diameter))
    throw InvalidInput("probe wall: diameter must be positive, got " + std::to_string(diameter));
  if (!(apex_deg > 0.0 && apex_deg < 180.0))
    throw InvalidInput("probe wall: apex angle must be in (0, 180) degrees, got " +
                       std::to_string(apex_deg));
  if (!apex.allFinite() || !velocity.allFinite())
    throw InvalidInput("probe wall: apex and velocity must be finite");
  const double radius = 0.5 * diameter;
  Wall w;
  w.kind = Kind::probe;
  w.point = apex;
  w.radius = radius;
  w.velocity = velocity;
  // Apex, then the shoulder where the cone meets the shaft: height R / tan(apex / 2).
  w.profile = {Eigen::Vector2d(0.0, 0.0),
               Eigen::Vector2d(radius, radius / std::tan(0.5 * apex_deg * kPi / 180.0))};
  w.sleeve_from = 1;
  return w;
}

void validate_probe_profile(const Wall& w) {
  const std::vector<Eigen::Vector2d>& p = w.profile;
  if (p.empty()) throw InvalidInput("probe wall: the profile has no point");
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (!p[k].allFinite() || p[k].x() < 0.0)
      throw InvalidInput("probe wall: profile point " + std::to_string(k) +
                         " must be finite with a radius >= 0");
    if (k > 0 && p[k].y() < p[k - 1].y())
      throw InvalidInput("probe wall: profile heights must not decrease (point " +
                         std::to_string(k) + ")");
  }
  if (w.sleeve_from < 0 || w.sleeve_from >= static_cast<int>(p.size()))
    throw InvalidInput("probe wall: the sleeve must start at a profile point, got " +
                       std::to_string(w.sleeve_from));
  if (!w.point.allFinite() || !w.velocity.allFinite())
    throw InvalidInput("probe wall: apex and velocity must be finite");
}

namespace {

// Probe: the closest point of the meridian profile to the centre, in the half-plane of the
// centre (unit e_ρ, horizontal). Segments in order, then the vertical ray above the last point;
// a tie keeps the lower one.
WallHit probe_hit(const Wall& wall, const Vec3& c, double r) {
  WallHit hit;
  const Vec3 radial(c.x() - wall.point.x(), c.y() - wall.point.y(), 0.0);
  const double rho = radial.norm();
  const Vec3 e_rho = rho > 0.0 ? Vec3(radial / rho) : Vec3(Vec3::UnitX());
  const Eigen::Vector2d p(rho, c.z() - wall.point.z());
  const std::vector<Eigen::Vector2d>& prof = wall.profile;
  const std::size_t m = prof.size();
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector2d q = prof[0];
  Eigen::Vector2d outward(0.0, -1.0);  // outward normal of the segment holding q
  std::size_t seg = 0;
  for (std::size_t k = 0; k + 1 < m; ++k) {
    const Eigen::Vector2d a = prof[k], d = prof[k + 1] - prof[k];
    const double l2 = d.squaredNorm();
    const double t = l2 > 0.0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
    const Eigen::Vector2d x = a + t * d;
    const double d2 = (p - x).squaredNorm();
    if (d2 < best) {
      best = d2, q = x, seg = k;
      outward = l2 > 0.0 ? Eigen::Vector2d(d.y(), -d.x()) / std::sqrt(l2) : outward;
    }
  }
  {  // the ray ρ = ρ_last, z ≥ z_last
    const Eigen::Vector2d x(prof[m - 1].x(), std::max(p.y(), prof[m - 1].y()));
    const double d2 = (p - x).squaredNorm();
    if (d2 < best) best = d2, q = x, seg = m - 1, outward = Eigen::Vector2d(1.0, 0.0);
  }
  // Inside the solid: above the apex and nearer the axis than the profile at that height.
  bool inside = false;
  if (p.y() >= prof[0].y()) {
    double bound = prof[m - 1].x();
    for (std::size_t k = 0; k + 1 < m; ++k)
      if (p.y() < prof[k + 1].y()) {
        const double h = prof[k + 1].y() - prof[k].y();
        const double t = h > 0.0 ? (p.y() - prof[k].y()) / h : 1.0;
        bound = prof[k].x() + t * (prof[k + 1].x() - prof[k].x());
        break;
      }
    inside = p.x() < bound;
  }
  const double dist = std::sqrt(best);
  Eigen::Vector2d n2 = dist > 0.0 ? Eigen::Vector2d((p - q) / dist) : outward;
  if (inside && dist > 0.0) n2 = -n2;
  hit.overlap = inside ? r + dist : r - dist;
  hit.normal = n2.x() * e_rho + n2.y() * Vec3::UnitZ();
  hit.part = static_cast<int>(seg) >= wall.sleeve_from ? ProbePart::sleeve : ProbePart::tip;
  hit.touching = hit.overlap > 0.0;
  hit.point = c - (r - 0.5 * hit.overlap) * hit.normal;
  return hit;
}

}  // namespace

WallHit wall_hit(const Wall& wall, const Vec3& c, double r) {
  if (wall.kind == Wall::Kind::probe) return probe_hit(wall, c, r);
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
