// Spheres, clumps of overlapping spheres, and mass properties: the types every fill, volume
// and DEM routine shares.
#pragma once

#include "geom/vec.h"

#include <vector>

namespace clumpkit {

/// π to double precision (C++17 has no std::numbers), shared so that no file keeps its own copy.
inline constexpr double kPi = 3.14159265358979323846;

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
};

/// A rigid clump: overlapping spheres in one frame (the units of the source).
struct Clump {
  std::vector<Sphere> spheres;
};

/// Mass properties at unit density: volume, centroid, and the inertia tensor about the centroid
/// I = ∫(r²δ - r rᵀ) dV.
struct MassProperties {
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};

/// Throws InvalidInput naming the sphere index and value for a non-finite centre or a radius
/// that is not positive and finite.
void validate(const Clump& clump);

/// Centres closer than this times the larger radius count as one (distinct_balls).
inline constexpr double kCoincidentCentres = 1e-8;

/// Indices of the spheres left after deduplication: of spheres whose centres lie within
/// kCoincidentCentres times the larger radius of each other, only the largest (then the lowest
/// index) is kept; the others lie inside it but for a sliver at most that thick. Sorted
/// ascending. Both sphere-union engines use it, so they agree on what a duplicate is.
std::vector<int> distinct_balls(const std::vector<Sphere>& spheres);

}  // namespace clumpkit
