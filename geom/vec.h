// The small vector and matrix types every part of clumpkit uses (Eigen's 3-vectors and 3×3).
#pragma once

#include <Eigen/Dense>

namespace clumpkit {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

}  // namespace clumpkit
