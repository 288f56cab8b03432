#include "geom/fill/fidelity.h"

#include "geom/errors.h"
#include "geom/mesh/mesh_distance.h"
#include "geom/mesh/ray_inside.h"
#include "geom/volume/union_of_balls.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace clumpkit {

namespace {

using Interval = std::pair<double, double>;

// Merges overlapping intervals (sorted by start).
std::vector<Interval> merged(std::vector<Interval> v) {
  std::sort(v.begin(), v.end());
  std::vector<Interval> out;
  for (const auto& iv : v) {
    if (!out.empty() && iv.first <= out.back().second)
      out.back().second = std::max(out.back().second, iv.second);
    else
      out.push_back(iv);
  }
  return out;
}

double length(const std::vector<Interval>& v) {
  double s = 0.0;
  for (const auto& iv : v) s += iv.second - iv.first;
  return s;
}

double intersection_length(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  double s = 0.0;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const double lo = std::max(a[i].first, b[j].first), hi = std::min(a[i].second, b[j].second);
    if (hi > lo) s += hi - lo;
    (a[i].second < b[j].second) ? ++i : ++j;
  }
  return s;
}

}  // namespace

Fidelity assess_fidelity(const Mesh& mesh, const Clump& clump, double spacing) {
  validate(clump);
  Fidelity r;
  r.spheres = static_cast<int>(clump.spheres.size());
  const MeshCheck check = check_mesh(mesh);
  r.watertight = check.closed && check.manifold && check.oriented;
  r.mesh_volume = signed_volume(mesh);
  if (r.watertight && !(r.mesh_volume > 0.0))
    throw InvalidInput("fidelity: the mesh has no positive volume");
  auto bb = bounding_box(mesh);
  if (spacing <= 0.0) spacing = (bb[1] - bb[0]).maxCoeff() / 200.0;
  for (const auto& s : clump.spheres) {
    bb[0] = bb[0].cwiseMin(s.center - Vec3::Constant(s.radius));
    bb[1] = bb[1].cwiseMax(s.center + Vec3::Constant(s.radius));
  }
  // Row lattice in (y, z), offset by an irrational fraction so no row passes exactly through a
  // mesh edge or vertex (that would double-count a crossing).
  const double y0 = bb[0].y() + spacing * 0.5012345, z0 = bb[0].z() + spacing * 0.4987654;
  const int ny = static_cast<int>((bb[1].y() - y0) / spacing) + 1;
  const int nz = static_cast<int>((bb[1].z() - z0) / spacing) + 1;
  std::vector<std::vector<int>> tri_rows(std::size_t(ny) * nz), ball_rows(std::size_t(ny) * nz);
  auto bucket = [&](double ylo, double yhi, double zlo, double zhi,
                    std::vector<std::vector<int>>& rows, int id) {
    const int ja = std::max(0, int(std::ceil((ylo - y0) / spacing))),
              jb = std::min(ny - 1, int(std::floor((yhi - y0) / spacing)));
    const int ka = std::max(0, int(std::ceil((zlo - z0) / spacing))),
              kb = std::min(nz - 1, int(std::floor((zhi - z0) / spacing)));
    for (int k = ka; k <= kb; ++k)
      for (int j = ja; j <= jb; ++j) rows[std::size_t(k) * ny + j].push_back(id);
  };
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    bucket(std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}),
           std::min({a.z(), b.z(), c.z()}), std::max({a.z(), b.z(), c.z()}), tri_rows, t);
  }
  for (int s = 0; s < static_cast<int>(clump.spheres.size()); ++s) {
    const auto& sp = clump.spheres[s];
    bucket(sp.center.y() - sp.radius, sp.center.y() + sp.radius, sp.center.z() - sp.radius,
           sp.center.z() + sp.radius, ball_rows, s);
  }

  double ball = 0.0, both = 0.0;
  // Watertight meshes: exact intervals from crossing parity. Otherwise ray-parity voting.
  std::unique_ptr<RayInside> rays;
  if (!r.watertight) rays = std::make_unique<RayInside>(mesh);
  double mesh_len = 0.0;
  std::vector<double> crossings;
  std::vector<Interval> chords, solid;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      const double y = y0 + j * spacing, z = z0 + k * spacing;
      crossings.clear();
      for (int t : tri_rows[std::size_t(k) * ny + j]) {
        const auto& tri = mesh.triangles[t];
        const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]],
                   &c = mesh.vertices[tri[2]];
        // Barycentric coordinates of (y, z) in the triangle's (y, z) projection.
        const double det = (b.y() - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (b.z() - a.z());
        if (det == 0.0) continue;
        const double u = ((y - a.y()) * (c.z() - a.z()) - (c.y() - a.y()) * (z - a.z())) / det;
        const double v = ((b.y() - a.y()) * (z - a.z()) - (y - a.y()) * (b.z() - a.z())) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0) continue;
        crossings.push_back(a.x() + u * (b.x() - a.x()) + v * (c.x() - a.x()));
      }
      std::sort(crossings.begin(), crossings.end());
      solid.clear();
      if (!rays) {
        for (std::size_t q = 0; q + 1 < crossings.size(); q += 2)
          solid.emplace_back(crossings[q], crossings[q + 1]);
      } else {
        // Not watertight: crossing parity is unreliable; vote on samples along the row, each
        // standing for a segment of length `spacing`.
        for (double x = bb[0].x() + 0.5 * spacing; x < bb[1].x(); x += spacing)
          if (rays->inside(Vec3(x, y, z))) {
            if (!solid.empty() && solid.back().second >= x - 0.5 * spacing - 1e-12 * spacing)
              solid.back().second = x + 0.5 * spacing;
            else
              solid.emplace_back(x - 0.5 * spacing, x + 0.5 * spacing);
          }
        mesh_len += length(solid);
      }
      chords.clear();
      for (int s : ball_rows[std::size_t(k) * ny + j]) {
        const auto& sp = clump.spheres[s];
        const double w2 = sp.radius * sp.radius - (y - sp.center.y()) * (y - sp.center.y()) -
                          (z - sp.center.z()) * (z - sp.center.z());
        if (w2 > 0.0)
          chords.emplace_back(sp.center.x() - std::sqrt(w2), sp.center.x() + std::sqrt(w2));
      }
      const auto uni = merged(chords);
      const double lb = length(uni);
      ball += lb;
      both += intersection_length(solid, uni);
    }
  const double cell = spacing * spacing;
  if (rays) {
    r.mesh_volume = mesh_len * cell;
    if (!(r.mesh_volume > 0.0)) throw InvalidInput("fidelity: the mesh encloses no volume");
    r.mesh_volume_method = "ray-parity voting on the row lattice (mesh not watertight)";
  }
  // The clump's own volume, centroid and inertia are exact (power diagram); the rows only
  // estimate the part outside the mesh, which is small, so the covered fraction inherits little
  // of their error.
  const UnionProperties u = union_properties(clump);
  r.clump_volume = u.mass.volume;
  r.overshoot_fraction = std::max(0.0, (ball - both) * cell) / r.mesh_volume;
  r.covered_fraction = (r.clump_volume - (ball - both) * cell) / r.mesh_volume;
  r.centroid_offset = (u.mass.centroid - solid_centroid(mesh)).norm();
  const Vec3 lm = Eigen::SelfAdjointEigenSolver<Mat3>(solid_inertia(mesh)).eigenvalues();
  const Vec3 lc = Eigen::SelfAdjointEigenSolver<Mat3>(u.mass.inertia).eigenvalues();
  for (int q = 0; q < 3; ++q)
    r.inertia_error = std::max(r.inertia_error, std::abs(lc[q] - lm[q]) / lm[q]);

  // Surface points: a barycentric lattice on each triangle, fine enough for the spacing.
  double sum = 0.0;
  std::size_t count = 0;
  for (const auto& tri : mesh.triangles) {
    const Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]], &c = mesh.vertices[tri[2]];
    const double edge = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const int m = std::max(1, static_cast<int>(std::ceil(edge / spacing)));
    for (int p = 0; p <= m; ++p)
      for (int q = 0; p + q <= m; ++q) {
        const Vec3 x = a + (b - a) * (double(p) / m) + (c - a) * (double(q) / m);
        double dmin = 1e300;
        for (const auto& s : clump.spheres) dmin = std::min(dmin, (x - s.center).norm() - s.radius);
        const double d = std::abs(dmin);
        sum += d;
        ++count;
        r.surface_max_distance = std::max(r.surface_max_distance, d);
      }
  }
  r.surface_mean_distance = count ? sum / double(count) : 0.0;

  // How far each sphere pokes out: radius minus the distance from its centre to the surface
  // (meaningful for centres inside the mesh, as every fill's are).
  const MeshDistance dist(mesh);
  for (const auto& s : clump.spheres) {
    const double d = dist.distance(s.center);
    r.overshoot_depth_max = std::max(r.overshoot_depth_max, s.radius - d);
  }
  r.overshoot_depth_max = std::max(0.0, r.overshoot_depth_max);
  return r;
}

}  // namespace clumpkit
