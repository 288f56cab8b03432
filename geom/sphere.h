// Spheres, clumps of overlapping spheres, and mass properties: the types every fill, volume
// and DEM routine shares.
#pragma once

#include "geom/mesh/mesh.h"

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

/// Indices of the spheres left after exact deduplication: of spheres sharing a centre exactly,
/// only the largest is kept (the others are nested in it). Sorted ascending. Both sphere-union
/// engines use it, so they agree on what a duplicate is.
std::vector<int> distinct_balls(const std::vector<Sphere>& spheres);

}  // namespace clumpkit
