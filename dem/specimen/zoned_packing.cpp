#include "dem/specimen/zoned_packing.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace clumpkit::dem {

namespace {

// Inward normal (x, y) of the segment's plane φ = angle (the plane φ = 0 has (0, 1)).
Eigen::Vector2d far_plane_normal(double angle) {
  return Eigen::Vector2d(std::sin(angle), -std::cos(angle));
}

std::string region_name(int k) {
  return "zones: region " + std::to_string(k + 1);
}

// Maximum of the small (or large) particles' acceptance weight over a mixed layer: the fraction
// is linear, so its extremes are at the bounds.
double largest_share(const ZoneRegion& r, bool small) {
  return small ? std::max(r.small_fraction, r.small_fraction_outer)
               : std::max(1.0 - r.small_fraction, 1.0 - r.small_fraction_outer);
}

}  // namespace

Prism Prism::scaled(double s) const {
  Prism p = *this;
  p.size *= s;
  return p;
}

bool Prism::holds(const Vec3& c, double r) const {
  if (c.z() - r < 0.0 || c.z() + r > size.z()) return false;
  if (shape == Shape::cuboid)
    return std::abs(c.x()) + r <= 0.5 * size.x() && std::abs(c.y()) + r <= 0.5 * size.y();
  if (std::hypot(c.x(), c.y()) + r > 0.5 * size.x()) return false;
  if (shape == Shape::cylinder) return true;
  return c.y() >= r && far_plane_normal(angle).dot(c.head<2>()) >= r;
}

double Prism::wall_distance(const Vec3& c) const {
  double d = std::min(c.z(), size.z() - c.z());
  if (shape == Shape::cuboid)
    return std::min({d, 0.5 * size.x() - std::abs(c.x()), 0.5 * size.y() - std::abs(c.y())});
  d = std::min(d, 0.5 * size.x() - std::hypot(c.x(), c.y()));
  if (shape == Shape::cylinder) return d;
  return std::min({d, c.y(), far_plane_normal(angle).dot(c.head<2>())});
}

void Prism::bounds(Vec3& lo, Vec3& hi) const {
  const double R = 0.5 * size.x();
  lo = Vec3(-0.5 * size.x(), -0.5 * size.y(), 0.0);
  hi = Vec3(0.5 * size.x(), 0.5 * size.y(), size.z());
  if (shape != Shape::segment) return;
  // The sector's corners (axis, φ = 0, φ = angle) and the axis directions it sweeps.
  lo.head<2>() = hi.head<2>() = Eigen::Vector2d::Zero();
  const auto take = [&](double x, double y) {
    lo.head<2>() = lo.head<2>().cwiseMin(Eigen::Vector2d(x, y));
    hi.head<2>() = hi.head<2>().cwiseMax(Eigen::Vector2d(x, y));
  };
  take(R, 0.0);
  take(R * std::cos(angle), R * std::sin(angle));
  if (angle >= 0.5 * M_PI) take(0.0, R);
  if (angle >= M_PI) take(-R, 0.0);
}

double Prism::volume() const {
  const double R = 0.5 * size.x();
  switch (shape) {
    case Shape::cuboid:
      return size.prod();
    case Shape::cylinder:
      return M_PI * R * R * size.z();
    case Shape::segment:
      return 0.5 * angle * R * R * size.z();
  }
  return 0.0;
}

ZoneVolumes zone_volumes(const ZoneLayout& layout, const Prism& prism) {
  const int n = static_cast<int>(layout.regions.size());
  ZoneVolumes v;
  v.volume.assign(n, 0.0);
  v.small_volume.assign(n, 0.0);
  v.wall_area.assign(n, 0.0);
  Vec3 lo, hi;
  prism.bounds(lo, hi);
  const double h = prism.size.z();
  // Adds the volume dv at coordinate c; returns its region.
  const auto add = [&](double c, double dv) {
    const int k = region_of(layout, c);
    v.volume[k] += dv;
    if (layout.regions[k].mixed) v.small_volume[k] += small_fraction_at(layout, k, c) * dv;
    return k;
  };
  const auto region_at = [&](const Vec3& p) {
    return region_of(layout, zone_coordinate(layout, p));
  };
  // Calls f(x, y, dA) at the midpoints of an m × m grid of the cross-section inside the prism.
  const auto cross_section = [&](int m, const auto& f) {
    const double dx = (hi.x() - lo.x()) / m, dy = (hi.y() - lo.y()) / m;
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const Vec3 p(lo.x() + (i + 0.5) * dx, lo.y() + (j + 0.5) * dy, 0.5 * h);
        if (prism.holds(p)) f(p, dx * dy);
      }
  };
  switch (layout.coordinate) {
    case ZoneCoordinate::radial:
      cross_section(2048, [&](const Vec3& p, double da) {
        v.wall_area[add(zone_coordinate(layout, p), da * h)] += 2.0 * da;  // floor, top
      });
      break;
    case ZoneCoordinate::depth: {
      double area = 0;
      cross_section(1024, [&](const Vec3&, double da) { area += da; });
      const int m = 100000;
      for (int k = 0; k < m; ++k) {
        const Vec3 p(0.0, 0.0, (k + 0.5) * h / m);
        add(zone_coordinate(layout, p), area * h / m);
      }
      v.wall_area[region_at(Vec3(0, 0, 0))] += area;
      v.wall_area[region_at(Vec3(0, 0, h))] += area;
      break;
    }
    case ZoneCoordinate::spherical: {
      const int m = 256;
      cross_section(m, [&](const Vec3& p, double da) {
        for (int k = 0; k < m; ++k)
          add(zone_coordinate(layout, Vec3(p.x(), p.y(), (k + 0.5) * h / m)), da * h / m);
        for (const double z : {0.0, h}) v.wall_area[region_at(Vec3(p.x(), p.y(), z))] += da;
      });
      break;
    }
  }
  // The sides: points along each edge of the cross-section's boundary, at heights through the
  // prism (one height suffices for radial zones, which do not change along z).
  const int heights = layout.coordinate == ZoneCoordinate::radial ? 1 : 256;
  const auto side = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, bool arc) {
    const int m = 4096;
    const double R = 0.5 * prism.size.x();
    const double a0 = std::atan2(a.y(), a.x()), a1 = std::atan2(b.y(), b.x());
    const double span = arc ? (a1 > a0 ? a1 - a0 : a1 - a0 + 2 * M_PI) : 0.0;
    const double length = arc ? R * span : (b - a).norm();
    for (int i = 0; i < m; ++i) {
      const double t = (i + 0.5) / m;
      const Eigen::Vector2d q =
          arc ? Eigen::Vector2d(R * std::cos(a0 + t * span), R * std::sin(a0 + t * span))
              : Eigen::Vector2d(a + t * (b - a));
      for (int k = 0; k < heights; ++k) {
        const Vec3 p(q.x(), q.y(), (k + 0.5) * h / heights);
        v.wall_area[region_at(p)] += length / m * h / heights;
      }
    }
  };
  const double R = 0.5 * prism.size.x();
  switch (prism.shape) {
    case Prism::Shape::cuboid: {
      const double x = 0.5 * prism.size.x(), y = 0.5 * prism.size.y();
      side({-x, -y}, {x, -y}, false);
      side({x, -y}, {x, y}, false);
      side({x, y}, {-x, y}, false);
      side({-x, y}, {-x, -y}, false);
      break;
    }
    case Prism::Shape::cylinder:  // two half circles
      side({R, 0}, {-R, 0}, true);
      side({-R, 0}, {R, 0}, true);
      break;
    case Prism::Shape::segment: {
      const Eigen::Vector2d end(R * std::cos(prism.angle), R * std::sin(prism.angle));
      side({0, 0}, {R, 0}, false);
      side({R, 0}, end, true);
      side(end, {0, 0}, false);
      break;
    }
  }
  return v;
}

ZonedParticles zoned_particles(const ZoneLayout& layout, const ZoneVolumes& volumes,
                               const std::vector<ParticleClass>& classes,
                               const std::vector<RockTemplate>& templates, double porosity,
                               double mixed_porosity, double wall_excess, double soil_density,
                               double rock_density, std::uint64_t seed) {
  const int n = static_cast<int>(layout.regions.size());
  struct Drawn {
    Body body;
    char small;
    double bound;
  };
  std::vector<Drawn> drawn;
  ZonedParticles out;
  out.goal.assign(n, 0.0);
  // Draws the classes × scale for `solid` m³ into region k from stream `stream`.
  const auto draw = [&](int k, double scale, double solid, std::uint64_t stream, char small) {
    if (!(solid > 0.0)) return;
    std::vector<ParticleClass> scaled = classes;
    for (ParticleClass& c : scaled) c.min_size *= scale, c.max_size *= scale;
    Rng rng = Rng::stream(seed, stream);
    LayerParticles p = layer_particles(scaled, templates, solid, soil_density, rock_density, rng);
    for (Body& b : p.bodies) {
      b.zone = k;
      const double bound = b.bounding_radius();
      drawn.push_back({std::move(b), small, bound});
    }
  };
  // The classes' mean diameter by volume (the mass fractions of spheres of one density).
  double mean_d = 0, percent = 0;
  for (const ParticleClass& c : classes)
    mean_d += c.mass_percent * 0.5 * (c.min_size + c.max_size), percent += c.mass_percent;
  mean_d /= percent;
  for (int k = 0; k < n; ++k) {
    const ZoneRegion& r = layout.regions[k];
    if (!(volumes.volume.at(k) > 0.0))
      throw InvalidInput(region_name(k) + ": holds no volume inside the container (bounds " +
                         format_number(inner_bound(layout, k)) + " to " + format_number(r.outer) +
                         " m)");
    // Streams 1000 + 2k and 1001 + 2k: apart from the compression's own streams.
    const std::uint64_t stream = 1000 + 2 * static_cast<std::uint64_t>(k);
    const double V = volumes.volume[k];
    if (!r.mixed) {
      const double effective =
          std::max(0.0, V - wall_excess * mean_d * r.scale * volumes.wall_area[k]);
      out.goal[k] = (1.0 - porosity) * effective;
      draw(k, r.scale, out.goal[k], stream, 0);
    } else {
      const double small = volumes.small_volume[k], large = V - small;
      const double d =
          mean_d * (small * small_scale(layout, k) + large * large_scale(layout, k)) / V;
      const double share = std::max(0.0, 1.0 - wall_excess * d * volumes.wall_area[k] / V);
      out.goal[k] = (1.0 - mixed_porosity) * V * share;
      draw(k, small_scale(layout, k), (1.0 - mixed_porosity) * small * share, stream, 1);
      draw(k, large_scale(layout, k), (1.0 - mixed_porosity) * large * share, stream + 1, 0);
    }
  }
  std::stable_sort(drawn.begin(), drawn.end(),
                   [](const Drawn& a, const Drawn& b) { return a.bound > b.bound; });
  for (Drawn& d : drawn) {
    out.bodies.push_back(std::move(d.body));
    out.small.push_back(d.small);
  }
  return out;
}

std::vector<Placement> place_zoned(const ZonedParticles& particles, const ZoneLayout& layout,
                                   const Prism& prism, double factor, Rng& rng) {
  const Prism loose = prism.scaled(factor);
  Vec3 lo, hi;
  loose.bounds(lo, hi);
  // Each region's box: the loose prism's, cut to the image of the region's outer bound.
  const int n = static_cast<int>(layout.regions.size());
  std::vector<Vec3> region_lo(n, lo), region_hi(n, hi);
  const Vec3 o = factor * layout.origin;
  for (int k = 0; k < n; ++k) {
    const double reach = factor * layout.regions[k].outer;
    Vec3& a = region_lo[k];
    Vec3& b = region_hi[k];
    if (k == n - 1) continue;  // the last region takes everything beyond
    if (layout.coordinate == ZoneCoordinate::radial) {
      const Eigen::Vector2d r2 = Eigen::Vector2d::Constant(reach);
      a.head<2>() = a.head<2>().cwiseMax(o.head<2>() - r2);
      b.head<2>() = b.head<2>().cwiseMin(o.head<2>() + r2);
    } else if (layout.coordinate == ZoneCoordinate::depth) {
      a.z() = std::max(a.z(), o.z() - reach);
    } else {
      a = a.cwiseMax(o - Vec3::Constant(reach));
      b = b.cwiseMin(o + Vec3::Constant(reach));
    }
  }
  const CandidateCentre candidate = [&](std::size_t i, double bound,
                                        Rng& r) -> std::optional<Vec3> {
    const int k = particles.bodies[i].zone;
    const ZoneRegion& region = layout.regions[k];
    const Vec3 a = region_lo[k] + Vec3::Constant(bound), b = region_hi[k] - Vec3::Constant(bound);
    if (!((b - a).minCoeff() > 0.0)) return std::nullopt;
    const bool small = particles.small[i] != 0;
    const double top = region.mixed ? largest_share(region, small) : 1.0;
    for (int t = 0; t < 200; ++t) {
      const Vec3 p = r.uniform(a, b);
      if (!loose.holds(p, bound)) continue;
      const double c = zone_coordinate(layout, p / factor);
      if (region_of(layout, c) != k) continue;
      if (region.mixed) {
        const double f = small_fraction_at(layout, k, c);
        if (r.uniform() * top >= (small ? f : 1.0 - f)) continue;
      }
      return p;
    }
    return std::nullopt;
  };
  return place_by_candidates(placement_items(particles.bodies), lo, hi, candidate, rng);
}

}  // namespace clumpkit::dem
