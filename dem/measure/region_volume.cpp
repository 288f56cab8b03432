#include "dem/measure/region_volume.h"

#include "geom/errors.h"
#include "geom/volume/slicing.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace clumpkit::dem {

double CylinderRegion::volume() const {
  return M_PI * radius * radius * (z_hi - z_lo);
}

namespace {

template <class F>
double simpson(const F& f, double a, double b, double fa, double fm, double fb, double whole,
               double tol, int depth) {
  const double m = 0.5 * (a + b);
  const double lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double delta = left + right - whole;
  if (depth <= 0 || std::abs(delta) <= 15.0 * tol) return left + right + delta / 15.0;
  return simpson(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1) +
         simpson(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1);
}

/// ∫_a^b f by adaptive Simpson on `pieces` equal panels (the first split avoids a symmetric
/// integrand fooling the error estimate).
template <class F>
double integrate(const F& f, double a, double b, double tol, int pieces = 8) {
  double sum = 0.0;
  const double h = (b - a) / pieces;
  double x0 = a, f0 = f(a);
  for (int k = 0; k < pieces; ++k) {
    const double x1 = k + 1 == pieces ? b : a + (k + 1) * h;
    const double f1 = f(x1), fm = f(0.5 * (x0 + x1));
    const double whole = (x1 - x0) / 6.0 * (f0 + 4.0 * fm + f1);
    sum += simpson(f, x0, x1, f0, fm, f1, whole, tol / pieces, 40);
    x0 = x1;
    f0 = f1;
  }
  return sum;
}

// Area of the disk of radius a whose centre lies d from the centre of the disk of radius R, inside
// the latter: the lens of the two circles in closed form.
double lens_area(double a, double R, double d) {
  if (d >= a + R) return 0.0;
  if (d <= R - a) return M_PI * a * a;
  if (d <= a - R) return M_PI * R * R;
  const double ca = std::clamp((d * d + a * a - R * R) / (2.0 * d * a), -1.0, 1.0);
  const double cR = std::clamp((d * d + R * R - a * a) / (2.0 * d * R), -1.0, 1.0);
  const double k = (-d + a + R) * (d + a - R) * (d - a + R) * (d + a + R);
  return a * a * std::acos(ca) + R * R * std::acos(cR) - 0.5 * std::sqrt(std::max(0.0, k));
}

}  // namespace

std::vector<double> body_volumes(const World& world) {
  std::vector<double> out;
  out.reserve(world.bodies().size());
  for (const Body& b : world.bodies()) {
    if (!(b.volume > 0.0))
      throw InvalidInput("body_volumes: body " + std::to_string(out.size()) +
                         " has no volume (bodies come from make_sphere_body or make_clump_body)");
    out.push_back(b.volume);
  }
  return out;
}

double column_height(const World& world) {
  const std::vector<double> volumes = body_volumes(world);
  double v = 0.0, vz = 0.0;
  for (std::size_t k = 0; k < volumes.size(); ++k) {
    v += volumes[k];
    vz += volumes[k] * world.bodies()[k].position.z();
  }
  return v > 0 ? 2.0 * vz / v : 0.0;
}

void body_region_volumes(const Body& body, double body_volume, double radius,
                         const std::vector<std::array<double, 2>>& z_ranges,
                         std::vector<double>& out) {
  out.assign(z_ranges.size(), 0.0);
  std::vector<Sphere> world_spheres;
  double z0 = INFINITY, z1 = -INFINITY, rho_min = INFINITY, rho_max = 0.0;
  for (const Sphere& s : body.spheres) {
    const Vec3 c = body.orientation * s.center + body.position;
    world_spheres.push_back({c, s.radius});
    z0 = std::min(z0, c.z() - s.radius);
    z1 = std::max(z1, c.z() + s.radius);
    const double rho = std::hypot(c.x(), c.y());
    rho_min = std::min(rho_min, rho - s.radius);
    rho_max = std::max(rho_max, rho + s.radius);
  }
  if (rho_min >= radius) return;
  const bool radially_inside = rho_max <= radius;
  // The body's height cut at the planes of the ranges that cut it: each piece is integrated
  // once, whatever number of ranges holds it (a clump cut by the side wall lies in a layer and
  // a band of a specimen's profile).
  std::vector<double> cuts;
  for (std::size_t k = 0; k < z_ranges.size(); ++k) {
    const double lo = z_ranges[k][0], hi = z_ranges[k][1];
    if (z1 <= lo || z0 >= hi) continue;
    if (radially_inside && z0 >= lo && z1 <= hi) {
      out[k] = body_volume;
      continue;
    }
    cuts.push_back(std::max(z0, lo));
    cuts.push_back(std::min(z1, hi));
  }
  if (cuts.empty()) return;
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  const double region_disk = M_PI * radius * radius;
  std::vector<Disk> disks;
  auto slice_area = [&](double z) {
    disks.clear();
    for (const Sphere& s : world_spheres) {
      const double dz = z - s.center.z();
      const double r2 = s.radius * s.radius - dz * dz;
      if (r2 > 0.0) disks.push_back({s.center.x(), s.center.y(), std::sqrt(r2)});
    }
    if (disks.empty()) return 0.0;
    const double a = union_of_disks(disks).area;
    if (radially_inside) return a;
    disks.push_back({0.0, 0.0, radius});
    return std::max(0.0, a + region_disk - union_of_disks(disks).area);
  };
  // One sphere (a soil grain: most bodies of a specimen): between the planes the cap integral in
  // closed form, π∫(r² − t²)dt; cut by the side wall, the same quadrature over the lens of its
  // slice disk and the region's disk instead of a union of disks.
  const bool one = world_spheres.size() == 1;
  const Vec3 c = world_spheres.front().center;
  const double r = world_spheres.front().radius, d = std::hypot(c.x(), c.y());
  auto piece = [&](double a, double b) {
    if (one && radially_inside) {
      const auto primitive = [&](double z) {
        const double t = z - c.z();
        return r * r * t - t * t * t / 3.0;
      };
      return M_PI * (primitive(b) - primitive(a));
    }
    if (one)
      return integrate(
          [&](double z) {
            const double t = z - c.z(), r2 = r * r - t * t;
            return r2 > 0.0 ? lens_area(std::sqrt(r2), radius, d) : 0.0;
          },
          a, b, 1e-9 * body_volume);
    return integrate(slice_area, a, b, 1e-9 * body_volume);
  };
  std::vector<double> pieces(cuts.size() - 1, -1.0);  // −1: not needed yet
  for (std::size_t k = 0; k < z_ranges.size(); ++k) {
    const double lo = std::max(z0, z_ranges[k][0]), hi = std::min(z1, z_ranges[k][1]);
    if (!(hi > lo) || out[k] > 0.0) continue;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
      if (cuts[i] >= lo && cuts[i + 1] <= hi) {
        if (pieces[i] < 0.0) pieces[i] = piece(cuts[i], cuts[i + 1]);
        out[k] += pieces[i];
      }
  }
}

double body_region_volume(const Body& body, double body_volume, const CylinderRegion& region) {
  std::vector<double> out;
  body_region_volumes(body, body_volume, region.radius, {{region.z_lo, region.z_hi}}, out);
  return out[0];
}

std::vector<double> region_porosities(const World& world, const std::vector<double>& volumes,
                                      const std::vector<CylinderRegion>& regions) {
  std::vector<std::array<double, 2>> ranges;
  for (const CylinderRegion& region : regions) {
    if (!(region.radius > 0) || !(region.z_hi > region.z_lo))
      throw InvalidInput("region porosity: empty region (radius " + std::to_string(region.radius) +
                         ", z " + std::to_string(region.z_lo) + " to " +
                         std::to_string(region.z_hi) + ")");
    if (region.radius != regions.front().radius)
      throw InvalidInput("region porosities: the regions differ in radius");
    ranges.push_back({region.z_lo, region.z_hi});
  }
  const auto& bodies = world.bodies();
  if (volumes.size() != bodies.size())
    throw InvalidInput("region porosity: body volumes do not match the bodies");
  if (regions.empty()) return {};
  const std::size_t m = regions.size();
  std::vector<double> part(bodies.size() * m, 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bodies.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::vector<double> out;
                      for (std::size_t k = r.begin(); k != r.end(); ++k) {
                        body_region_volumes(bodies[k], volumes[k], regions.front().radius, ranges,
                                            out);
                        std::copy(out.begin(), out.end(), part.begin() + k * m);
                      }
                    });
  std::vector<double> porosity(m);
  for (std::size_t j = 0; j < m; ++j) {
    double solid = 0.0;
    for (std::size_t k = 0; k < bodies.size(); ++k)
      solid += part[k * m + j];  // fixed order: same sum for any thread count
    porosity[j] = 1.0 - solid / regions[j].volume();
  }
  return porosity;
}

double region_porosity(const World& world, const std::vector<double>& volumes,
                       const CylinderRegion& region) {
  return region_porosities(world, volumes, {region})[0];
}

double coordination_number(const World& world, const CylinderRegion& region) {
  const auto& bodies = world.bodies();
  std::vector<std::pair<int, int>> pairs;
  for (const PairContact& c : world.contacts()) {
    if (!(c.state.normal_force > 0.0)) continue;
    int a = world.sphere_body(c.i), b = world.sphere_body(c.j);
    if (a > b) std::swap(a, b);
    pairs.emplace_back(a, b);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<int> count(bodies.size(), 0);
  for (const auto& [a, b] : pairs) ++count[a], ++count[b];
  long inside = 0, total = 0;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const Vec3& p = bodies[k].position;
    if (std::hypot(p.x(), p.y()) < region.radius && p.z() >= region.z_lo && p.z() <= region.z_hi) {
      ++inside;
      total += count[k];
    }
  }
  return inside == 0 ? 0.0 : static_cast<double>(total) / static_cast<double>(inside);
}

}  // namespace clumpkit::dem
