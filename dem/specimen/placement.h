// Non-overlapping random placement of spheres and clumps in a vertical cylinder or a box.
#pragma once

#include "geom/random.h"
#include "geom/sphere.h"

#include <Eigen/Geometry>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace clumpkit::dem {

/// One body to place: spheres in the body frame (centroid at the origin; a soil sphere is one
/// sphere at the origin) and the radius of a centroid-centred ball holding every sphere (m).
/// A bounding radius smaller than the spheres need is raised to the true value.
struct PlacementItem {
  std::vector<Sphere> spheres;
  double bounding_radius = 0.0;
};

/// Where an item went: centroid in the world and orientation (body -> world, Hamilton unit
/// quaternion, x_world = orientation · x_body + position), as in Body.
struct Placement {
  Vec3 position = Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// Uniformly random rotation (Shoemake's method from three uniforms), normalised.
Eigen::Quaterniond uniform_orientation(Rng& rng);

/// Places items in the given order (callers pass largest first) at random positions and
/// uniformly random orientations inside the vertical cylinder of `radius` around the z-axis,
/// standing on z = 0: every sphere fully inside (horizontal distance + r <= radius, z - r >= 0)
/// and no sphere overlapping any sphere of an earlier item (spheres of one item may overlap).
/// Sequential random trials from the bottom up: each trial draws a centroid uniformly in the
/// disc of radius (radius − bounding radius) and in height in the band [z_lo, z_lo + band]
/// (band = diameter of the largest item; never below the bounding radius), then an orientation.
/// After `max_trials` failed trials z_lo rises by the item's bounding radius (it never falls),
/// so every item is placed. Collision checks use a uniform grid of the placed spheres.
/// Deterministic for a given Rng state. If `height` is given it receives the top of the highest
/// sphere (0 for no items). Throws InvalidInput for a non-positive or non-finite radius,
/// max_trials < 1, an item without spheres, a bad sphere, or an item wider than the cylinder.
std::vector<Placement> place_in_cylinder(const std::vector<PlacementItem>& items, double radius,
                                         Rng& rng, int max_trials = 200, double* height = nullptr);

/// Places items in the given order (largest first) at uniformly random positions and orientations
/// inside the box [lo, hi] (every item's bounding ball inside it), no sphere overlapping any
/// sphere of an earlier item: up to `max_trials` random trials per item. Returns an empty vector
/// when some item found no room (the box is too crowded: enlarge it and try again). Deterministic
/// for a given Rng state. Throws InvalidInput for an empty or non-finite box, max_trials < 1, a
/// bad item, or an item wider than the box.
std::vector<Placement> place_in_box(const std::vector<PlacementItem>& items, const Vec3& lo,
                                    const Vec3& hi, Rng& rng, int max_trials = 1000);

/// A candidate centroid for item `item` of bounding radius `bound`, drawn from `rng`, or nothing
/// when the region it belongs to yielded none; the item's bounding ball must lie in [lo, hi] of
/// place_by_candidates.
using CandidateCentre =
    std::function<std::optional<Vec3>(std::size_t item, double bound, Rng& rng)>;

/// place_in_box with the centroids drawn by `candidate` (then an orientation from `rng`), so that
/// each item can be kept to its own region (a zone of the container): up to `max_trials` trials
/// per item, an empty result when some item found no room. [lo, hi] bounds the collision grid.
/// Deterministic for a given Rng state.
std::vector<Placement> place_by_candidates(const std::vector<PlacementItem>& items, const Vec3& lo,
                                           const Vec3& hi, const CandidateCentre& candidate,
                                           Rng& rng, int max_trials = 1000);

}  // namespace clumpkit::dem
