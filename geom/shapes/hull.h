// Random convex-hull grains with a target weighted roundness (Zhang & Zhou 2015 §2.1).
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/random.h"

namespace clumpkit {

/// Zhang & Zhou 2015 §2.1: N random points on a sphere of diameter d, their convex hull, redrawn
/// until the weighted roundness R (Zhang & Zhou 2015 eq. 2) lies in [roundness_min, roundness_max].
/// Points uniform on a sphere give R ≈ 1.05–1.15 only, so each attempt also draws a flattening
/// of the point cloud: y is scaled by b ~ U(aspect_min, 1) and z by c ~ U(aspect_min, b), which
/// reaches the flatter bands (1.2–1.6) of the paper's Figs. 9–11. `aspect_min = 1` is the plain
/// method of the paper. The long axis keeps the diameter d.
struct HullParams {
  double diameter = 1.0;
  int points = 20;
  double roundness_min = 1.0;
  double roundness_max = 10.0;
  double aspect_min = 0.3;
  int max_attempts = 2000;
};

struct HullResult {
  Mesh mesh;
  int attempts = 0;        ///< hulls drawn, including the accepted one
  double roundness = 0.0;  ///< weighted roundness of the accepted hull
};

/// Throws InvalidInput naming the field and value for bad parameters.
void validate(const HullParams& p);

/// Draws hulls until one meets the band. Throws InvalidInput after max_attempts, naming the band
/// (the band is unreachable with these parameters).
HullResult make_hull(const HullParams& params, Rng& rng);

}  // namespace clumpkit
