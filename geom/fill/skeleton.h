// Medial candidates of a distance field: interior voxels on a ridge of the distance, each the
// centre of a maximal inscribed ball (Zhang & Zhou 2015 §2.2).
#pragma once

#include "geom/fill/distance_field.h"

#include <vector>

namespace clumpkit {

/// A skeleton point: voxel index, centre and maximal inscribed radius (the distance there).
struct MedialCandidate {
  int i = 0, j = 0, k = 0;
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
};

/// Interior voxels where the distance field has a ridge: the largest slope to any of the 26
/// neighbours, (d(q) − d(p)) / |q − p|, is below `ridge` (1 = a ball contained in a neighbour's
/// ball; smaller is stricter). Such a voxel's ball is not contained in a neighbour's ball, so it
/// approximates a maximal inscribed ball. Candidates with radius < min_radius are dropped.
/// Order: by voxel index (deterministic).
std::vector<MedialCandidate> medial_candidates(const DistanceField& field, double ridge = 0.95,
                                               double min_radius = 0.0);

}  // namespace clumpkit
