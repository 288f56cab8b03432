#include "geom/shapes/polyhedron.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/limits.h"
#include "geom/mesh/cgal_mesh.h"
#include "geom/shapes/primitives.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace clumpkit {

namespace {

void check(bool ok, const char* field, double value, const char* rule) {
  if (!ok)
    throw InvalidInput(std::string("polyhedron: ") + field + " " + rule + ", got " +
                       std::to_string(value));
}

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
  check(p.planes >= 0 && p.planes <= 10000, "planes", p.planes, "must be in [0, 10000]");
  check(p.E > 0.0 && p.E <= 1.0, "E", p.E, "must be in (0, 1]");
  check(p.F > 0.0 && p.F <= 1.0, "F", p.F, "must be in (0, 1]");
  check(p.offset_min > 0.0 && p.offset_min <= 1.0, "offset_min", p.offset_min, "must be in (0, 1]");
  check(p.offset_max >= p.offset_min && p.offset_max <= 1.0, "offset_max", p.offset_max,
        "must be in [offset_min, 1]");
  check(p.sphere_level >= 1 && p.sphere_level <= 5, "sphere_level", p.sphere_level,
        "must be in [1, 5]");
}

Mesh make_polyhedron(const PolyhedronParams& p, Rng& rng) {
  validate(p);
  // Half-spaces n·x <= h: tangent planes of the sphere, then the random cuts.
  std::vector<std::pair<Vec3, double>> halfspaces;
  const Mesh sphere = make_icosphere(p.sphere_level);
  for (const auto& n : sphere.vertices) halfspaces.emplace_back(n, 1.0);
  for (int i = 0; i < p.planes; ++i) {
    const Vec3 n = rng.unit_vector();
    const double h = rng.uniform(p.offset_min, p.offset_max);
    halfspaces.emplace_back(n, h);
  }
  // Polar duality (the origin is strictly inside, all h > 0): plane i maps to the point n_i/h_i,
  // and each facet of the hull of those points is a corner of the polyhedron where its three
  // planes meet. Solving each corner from its planes in index order makes the result independent
  // of how the hull code orders its work.
  std::vector<Vec3> dual;
  std::map<std::array<double, 3>, int> plane_of;
  for (std::size_t i = 0; i < halfspaces.size(); ++i) {
    dual.push_back(halfspaces[i].first / halfspaces[i].second);
    plane_of.emplace(std::array<double, 3>{dual.back().x(), dual.back().y(), dual.back().z()},
                     static_cast<int>(i));
  }
  const Mesh dual_hull = convex_hull(dual);
  std::vector<int> plane(dual_hull.vertices.size());
  for (std::size_t i = 0; i < plane.size(); ++i) {
    const Vec3& d = dual_hull.vertices[i];
    plane[i] = plane_of.at({d.x(), d.y(), d.z()});
  }
  std::vector<Vec3> corners;
  corners.reserve(dual_hull.triangles.size());
  for (const auto& t : dual_hull.triangles) {
    std::array<int, 3> ids{plane[t[0]], plane[t[1]], plane[t[2]]};
    std::sort(ids.begin(), ids.end());
    Mat3 a;
    Vec3 b;
    for (int k = 0; k < 3; ++k) {
      a.row(k) = halfspaces[ids[k]].first.transpose();
      b[k] = halfspaces[ids[k]].second;
    }
    corners.push_back(a.fullPivLu().solve(b));
  }
  Mesh m = convex_hull(corners);  // deduplicates corners shared by 4+ planes

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
