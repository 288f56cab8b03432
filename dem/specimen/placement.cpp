// Non-overlapping random placement of spheres and clumps in a vertical cylinder or a box.
#include "dem/specimen/placement.h"

#include "geom/errors.h"
#include "geom/sphere.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {
namespace {

/// Uniform grid over a rectangular footprint [x0, x0 + wx] × [y0, y0 + wy], growing upwards in z
/// from z0 as spheres are added. Holds indices of placed spheres.
class SphereGrid {
 public:
  SphereGrid(const Vec3& origin, double width_x, double width_y, double cell,
             double max_sphere_radius)
      : origin_(origin), cell_(cell), reach_(max_sphere_radius) {
    nx_ = static_cast<int>(std::floor(width_x / cell)) + 1;
    ny_ = static_cast<int>(std::floor(width_y / cell)) + 1;
  }

  void add(const Vec3& center, double r) {
    const int ix = std::clamp(index(center.x() - origin_.x()), 0, nx_ - 1);
    const int iy = std::clamp(index(center.y() - origin_.y()), 0, ny_ - 1);
    const int iz = std::max(0, index(center.z() - origin_.z()));
    if (iz >= layers_) {
      layers_ = iz + 1;
      cells_.resize(static_cast<std::size_t>(layers_) * nx_ * ny_);
    }
    cells_[cell_index(ix, iy, iz)].push_back(static_cast<int>(centers_.size()));
    centers_.push_back(center);
    radii_.push_back(r);
  }

  /// True if a sphere at `center` of radius `r` overlaps (strictly) any stored sphere.
  bool overlaps(const Vec3& center, double r) const {
    if (layers_ == 0) return false;
    const double d = r + reach_;
    const Vec3 c = center - origin_;
    const int x0 = std::clamp(index(c.x() - d), 0, nx_ - 1);
    const int x1 = std::clamp(index(c.x() + d), 0, nx_ - 1);
    const int y0 = std::clamp(index(c.y() - d), 0, ny_ - 1);
    const int y1 = std::clamp(index(c.y() + d), 0, ny_ - 1);
    const int z0 = std::max(0, index(c.z() - d));
    const int z1 = std::min(layers_ - 1, index(c.z() + d));
    for (int iz = z0; iz <= z1; ++iz)
      for (int iy = y0; iy <= y1; ++iy)
        for (int ix = x0; ix <= x1; ++ix)
          for (int s : cells_[cell_index(ix, iy, iz)]) {
            const double sum = r + radii_[s];
            if ((centers_[s] - center).squaredNorm() < sum * sum) return true;
          }
    return false;
  }

 private:
  int index(double offset) const {
    const double i = std::floor(offset / cell_);
    // Clamp before converting so far-away queries cannot overflow.
    return static_cast<int>(std::clamp(i, -1.0, 1e9));
  }
  std::size_t cell_index(int ix, int iy, int iz) const {
    return (static_cast<std::size_t>(iz) * ny_ + iy) * nx_ + ix;
  }

  Vec3 origin_;
  double cell_;
  double reach_;
  int nx_ = 1, ny_ = 1;
  int layers_ = 0;
  std::vector<std::vector<int>> cells_;
  std::vector<Vec3> centers_;
  std::vector<double> radii_;
};

/// Checks the items (every sphere finite with a positive radius) and returns each item's
/// effective bounding radius (never below what its spheres need, with a rounding margin); sets
/// the largest sphere radius and bounding radius. `who` names the caller in errors.
std::vector<double> bounding_radii(const std::vector<PlacementItem>& items, const char* who,
                                   double& max_sphere, double& max_bound) {
  std::vector<double> bound(items.size());
  max_sphere = 0.0;
  max_bound = 0.0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const PlacementItem& item = items[i];
    if (item.spheres.empty())
      throw InvalidInput(std::string(who) + ": item " + std::to_string(i) + " has no spheres");
    double need = 0.0;
    for (std::size_t s = 0; s < item.spheres.size(); ++s) {
      const Sphere& sphere = item.spheres[s];
      if (!(sphere.radius > 0.0) || !std::isfinite(sphere.radius) || !sphere.center.allFinite())
        throw InvalidInput(std::string(who) + ": item " + std::to_string(i) + " sphere " +
                           std::to_string(s) + " has a bad centre or radius " +
                           std::to_string(sphere.radius));
      need = std::max(need, sphere.center.norm() + sphere.radius);
      max_sphere = std::max(max_sphere, sphere.radius);
    }
    const double given = std::isfinite(item.bounding_radius) ? item.bounding_radius : 0.0;
    bound[i] = std::max(given, need) * (1.0 + 1e-12);  // margin for rotation rounding
    max_bound = std::max(max_bound, bound[i]);
  }
  return bound;
}

/// Tries `item` at `position` and `orientation`: when none of its spheres overlaps a placed one,
/// adds them to the grid (and `world` holds their centres) and returns true.
bool try_place(const PlacementItem& item, const Vec3& position,
               const Eigen::Quaterniond& orientation, SphereGrid& grid, std::vector<Vec3>& world) {
  world.resize(item.spheres.size());
  for (std::size_t s = 0; s < item.spheres.size(); ++s) {
    world[s] = orientation * item.spheres[s].center + position;
    if (grid.overlaps(world[s], item.spheres[s].radius)) return false;
  }
  for (std::size_t s = 0; s < item.spheres.size(); ++s) grid.add(world[s], item.spheres[s].radius);
  return true;
}

}  // namespace

Eigen::Quaterniond uniform_orientation(Rng& rng) {
  const double u1 = rng.uniform();
  const double u2 = rng.uniform();
  const double u3 = rng.uniform();
  const double a = std::sqrt(1.0 - u1);
  const double b = std::sqrt(u1);
  Eigen::Quaterniond q(b * std::cos(2.0 * kPi * u3), a * std::sin(2.0 * kPi * u2),
                       a * std::cos(2.0 * kPi * u2), b * std::sin(2.0 * kPi * u3));
  q.normalize();
  return q;
}

std::vector<Placement> place_in_cylinder(const std::vector<PlacementItem>& items, double radius,
                                         Rng& rng, int max_trials, double* height) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InvalidInput("place_in_cylinder: cylinder radius must be positive and finite, got " +
                       std::to_string(radius));
  if (max_trials < 1)
    throw InvalidInput("place_in_cylinder: max_trials must be at least 1, got " +
                       std::to_string(max_trials));

  double max_sphere = 0.0, max_bound = 0.0;
  std::vector<double> bound = bounding_radii(items, "place_in_cylinder", max_sphere, max_bound);
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (bound[i] > radius * (1.0 + 1e-12))
      throw InvalidInput("place_in_cylinder: item " + std::to_string(i) + " (bounding radius " +
                         std::to_string(bound[i]) + ") does not fit in a cylinder of radius " +
                         std::to_string(radius));
    bound[i] = std::min(bound[i], radius);
  }
  max_bound = std::min(max_bound, radius);

  std::vector<Placement> placements;
  placements.reserve(items.size());
  double top = 0.0;
  if (items.empty()) {
    if (height) *height = top;
    return placements;
  }

  const double band = 2.0 * max_bound;
  SphereGrid grid(Vec3(-radius, -radius, 0.0), 2.0 * radius, 2.0 * radius, 2.0 * max_sphere,
                  max_sphere);
  double z_lo = 0.0;
  std::vector<Vec3> world;  // candidate sphere centres

  for (std::size_t i = 0; i < items.size(); ++i) {
    const PlacementItem& item = items[i];
    const double b = bound[i];
    const double disc = radius - b;
    bool placed = false;
    while (!placed) {
      const double z_min = std::max(z_lo, b);
      const double z_max = std::max(z_lo + band, z_min);
      for (int t = 0; t < max_trials && !placed; ++t) {
        const double rho = disc * std::sqrt(rng.uniform());
        const double phi = 2.0 * kPi * rng.uniform();
        const Vec3 position(rho * std::cos(phi), rho * std::sin(phi), rng.uniform(z_min, z_max));
        const Eigen::Quaterniond orientation = uniform_orientation(rng);
        if (!try_place(item, position, orientation, grid, world)) continue;
        for (std::size_t s = 0; s < item.spheres.size(); ++s)
          top = std::max(top, world[s].z() + item.spheres[s].radius);
        placements.push_back({position, orientation});
        placed = true;
      }
      // Band crowded for this item: move it up. Once z_lo clears every placed sphere by the
      // bounding radius any trial succeeds, so the loop ends.
      if (!placed) z_lo += b;
    }
  }
  if (height) *height = top;
  return placements;
}

std::vector<Placement> place_in_box(const std::vector<PlacementItem>& items, const Vec3& lo,
                                    const Vec3& hi, Rng& rng, int max_trials) {
  if (!lo.allFinite() || !hi.allFinite() || !((hi - lo).minCoeff() > 0.0))
    throw InvalidInput("place_in_box: the box must have positive, finite edges");
  if (max_trials < 1)
    throw InvalidInput("place_in_box: max_trials must be at least 1, got " +
                       std::to_string(max_trials));
  double max_sphere = 0.0, max_bound = 0.0;
  const std::vector<double> bound = bounding_radii(items, "place_in_box", max_sphere, max_bound);
  const Vec3 size = hi - lo;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (2.0 * bound[i] >= size.minCoeff())
      throw InvalidInput("place_in_box: item " + std::to_string(i) + " (bounding radius " +
                         std::to_string(bound[i]) + ") does not fit in the box");
  const CandidateCentre uniform = [&](std::size_t, double b, Rng& r) -> std::optional<Vec3> {
    return r.uniform(lo + Vec3::Constant(b), hi - Vec3::Constant(b));
  };
  return place_by_candidates(items, lo, hi, uniform, rng, max_trials);
}

std::vector<Placement> place_by_candidates(const std::vector<PlacementItem>& items, const Vec3& lo,
                                           const Vec3& hi, const CandidateCentre& candidate,
                                           Rng& rng, int max_trials) {
  if (!lo.allFinite() || !hi.allFinite() || !((hi - lo).minCoeff() > 0.0))
    throw InvalidInput("place_by_candidates: the box must have positive, finite edges");
  if (max_trials < 1)
    throw InvalidInput("place_by_candidates: max_trials must be at least 1, got " +
                       std::to_string(max_trials));
  double max_sphere = 0.0, max_bound = 0.0;
  const std::vector<double> bound =
      bounding_radii(items, "place_by_candidates", max_sphere, max_bound);
  const Vec3 size = hi - lo;
  std::vector<Placement> placements;
  placements.reserve(items.size());
  if (items.empty()) return placements;
  SphereGrid grid(lo, size.x(), size.y(), 2.0 * max_sphere, max_sphere);
  std::vector<Vec3> world;  // candidate sphere centres
  for (std::size_t i = 0; i < items.size(); ++i) {
    const PlacementItem& item = items[i];
    bool placed = false;
    for (int t = 0; t < max_trials && !placed; ++t) {
      const std::optional<Vec3> position = candidate(i, bound[i], rng);
      if (!position) continue;
      const Eigen::Quaterniond orientation = uniform_orientation(rng);
      if (!try_place(item, *position, orientation, grid, world)) continue;
      placements.push_back({*position, orientation});
      placed = true;
    }
    if (!placed) return {};  // too crowded: the caller enlarges the box
  }
  return placements;
}

}  // namespace clumpkit::dem
