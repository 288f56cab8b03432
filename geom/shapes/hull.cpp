#include "geom/shapes/hull.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/limits.h"
#include "geom/mesh/cgal_mesh.h"

#include <cmath>
#include <string>

namespace clumpkit {

void validate(const HullParams& p) {
  check_size(p.diameter, "hull: diameter");
  if (p.points < 4 || p.points > 100000)
    throw InvalidInput("hull: points must be in [4, 100000], got " + std::to_string(p.points));
  if (!(p.roundness_min >= 1.0) || !(p.roundness_max >= p.roundness_min) ||
      !std::isfinite(p.roundness_max))
    throw InvalidInput("hull: roundness band must satisfy 1 <= min <= max, got " +
                       std::to_string(p.roundness_min) + ":" + std::to_string(p.roundness_max));
  if (!(p.aspect_min > 0.0 && p.aspect_min <= 1.0))
    throw InvalidInput("hull: aspect_min must be in (0, 1], got " + std::to_string(p.aspect_min));
  if (p.max_attempts < 1)
    throw InvalidInput("hull: max_attempts must be at least 1, got " +
                       std::to_string(p.max_attempts));
}

HullResult make_hull(const HullParams& p, Rng& rng) {
  validate(p);
  HullResult r;
  std::vector<Vec3> pts(p.points);
  for (r.attempts = 1; r.attempts <= p.max_attempts; ++r.attempts) {
    const double b = rng.uniform(p.aspect_min, 1.0);
    const double c = rng.uniform(p.aspect_min, b);
    for (auto& x : pts) x = 0.5 * p.diameter * rng.unit_vector().cwiseProduct(Vec3(1.0, b, c));
    Mesh hull;
    try {
      hull = convex_hull(pts);
    } catch (const InvalidInput&) {
      continue;  // coplanar draw (only possible for tiny N): draw again
    }
    const PrincipalFrame frame = principal_frame(hull);
    const Roundness rd = weighted_roundness(hull, frame, /*convex=*/true);
    if (rd.weighted >= p.roundness_min && rd.weighted <= p.roundness_max) {
      // Centre the grain on its centroid, as every generator does.
      transform(hull, Mat3::Identity(), -frame.centroid);
      r.mesh = std::move(hull);
      r.roundness = rd.weighted;
      return r;
    }
  }
  throw InvalidInput("hull: no grain with weighted roundness in [" +
                     std::to_string(p.roundness_min) + ", " + std::to_string(p.roundness_max) +
                     "] after " + std::to_string(p.max_attempts) +
                     " attempts (points=" + std::to_string(p.points) +
                     ", aspect_min=" + std::to_string(p.aspect_min) + ")");
}

}  // namespace clumpkit
