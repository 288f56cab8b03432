// Clump templates: spheres in the principal frame with exact mass properties and the pose back
// to the source mesh, ready for a DEM code.
#pragma once

#include "geom/sphere.h"

#include <Eigen/Geometry>

namespace clumpkit {

/// A clump in its own principal frame: centroid at the origin, inertia axes along x, y, z
/// (moments ascending). Unit density; multiply mass and inertia by the material density.
struct ClumpTemplate {
  std::vector<Sphere> spheres;  ///< in the principal frame
  MassProperties mass;          ///< exact; centroid = 0, inertia diagonal in this frame
  Vec3 principal_moments = Vec3::Zero();
  /// Pose back to the source frame: x_source = orientation · x_template + position (Hamilton,
  /// template frame -> source frame).
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Vec3 position = Vec3::Zero();
  /// Mass equivalence (Jin et al. 2017 §2.2): V_mesh / V_clump, the factor by which a DEM code
  /// scales the clump density so the clump weighs what the rock weighs (1 without a mesh volume).
  double density_factor = 1.0;
};

/// Principal axes of an inertia tensor: the eigenvectors as columns (ascending moments), each
/// with its largest component positive, the third flipped if needed for a right-handed frame, so
/// that the frame does not depend on the eigen-solver's signs; `moments` gets the eigenvalues.
Mat3 principal_axes(const Mat3& inertia, Vec3& moments);

/// Builds the template from a clump with exact union mass properties (union_properties).
/// Axes: eigenvectors of the inertia tensor, ascending moments, each with its largest component
/// positive, the third flipped if needed for a right-handed frame. mesh_volume ≤ 0 means unknown.
ClumpTemplate make_clump_template(const Clump& clump, double mesh_volume = 0.0);

}  // namespace clumpkit
