#include "geom/shapes/polyhedron.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/limits.h"
#include "geom/shapes/halfspaces.h"
#include "geom/shapes/primitives.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit {

namespace {

// Rotates into the principal frame: x = long, y = intermediate, z = short axis.
void to_principal_frame(Mesh& m, PrincipalFrame& f) {
  f = principal_frame(m);
  Mat3 r;
  r.row(0) = f.axes.col(2).transpose();
  r.row(1) = f.axes.col(1).transpose();
  r.row(2) = f.axes.col(0).transpose();
  if (r.determinant() < 0) r.row(2) *= -1.0;
  for (auto& p : m.vertices) p = r * (p - f.centroid);
}
}  // namespace

void validate(const PolyhedronParams& p) {
  check_size(p.diameter, "polyhedron: diameter");
  require(kPolyhedronPlanes, p.planes, "polyhedron: planes");
  require(kAxisRatio, p.E, "polyhedron: E");
  require(kAxisRatio, p.F, "polyhedron: F");
  require(kPlaneOffset, p.offset_min, "polyhedron: offset_min");
  require(closed(p.offset_min, 1), p.offset_max, "polyhedron: offset_max");
  require(kSphereLevel, p.sphere_level, "polyhedron: sphere_level");
}

Mesh make_polyhedron(const PolyhedronParams& p, Rng& rng) {
  validate(p);
  // Half-spaces n·x <= h: tangent planes of the sphere, then the random cuts.
  std::vector<Halfspace> halfspaces;
  const Mesh sphere = make_icosphere(p.sphere_level);
  for (const auto& n : sphere.vertices) halfspaces.push_back({n, 1.0});
  for (int i = 0; i < p.planes; ++i) {
    const Vec3 n = rng.unit_vector();
    const double h = rng.uniform(p.offset_min, p.offset_max);
    halfspaces.push_back({n, h});
  }
  Mesh m = intersect_halfspaces(halfspaces, Vec3::Zero());  // the origin is inside: all h > 0

  // Stretch along the principal axes to E and F (Hu et al. 2023: E = I/L, F = S/I).
  PrincipalFrame f;
  to_principal_frame(m, f);
  for (int iter = 0; iter < 8; ++iter) {
    const double L = f.extents[2];
    const Vec3 target(L, p.E * L, p.E * p.F * L);
    const Vec3 current(f.extents[2], f.extents[1], f.extents[0]);
    const Vec3 s = target.cwiseQuotient(current);
    for (auto& x : m.vertices) x = x.cwiseProduct(s);
    to_principal_frame(m, f);
    const double E = f.extents[1] / f.extents[2], F = f.extents[0] / f.extents[1];
    if (std::abs(E - p.E) < 1e-3 && std::abs(F - p.F) < 1e-3) break;
  }
  // Scale to the volume-equivalent diameter.
  const double d_eq = std::cbrt(6.0 * signed_volume(m) / M_PI);
  for (auto& x : m.vertices) x *= p.diameter / d_eq;
  return m;
}

}  // namespace clumpkit
