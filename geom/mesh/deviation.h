// How far one surface lies from another: the sampled one-sided distance.
#pragma once

#include "geom/mesh/mesh.h"

namespace clumpkit {

/// The one-sided distance from surface `from` to surface `to`, sampled at the vertices, edge
/// midpoints and face centroids of `from` (each distance exact to the nearest triangle of `to`,
/// MeshIndex). `at` is the sample of the largest distance.
struct SurfaceDeviation {
  double max = 0, mean = 0;
  Vec3 at = Vec3::Zero();
  int samples = 0;
};
SurfaceDeviation surface_deviation(const Mesh& from, const Mesh& to);

}  // namespace clumpkit
