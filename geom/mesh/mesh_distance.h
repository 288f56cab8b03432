// Exact Euclidean distance from points to a triangle mesh (CGAL AABB tree).
#pragma once

#include "geom/mesh/mesh.h"

#include <memory>

namespace clumpkit {

/// Distance queries against one mesh. Build once (O(n log n)), query in O(log n).
/// The unsigned distance to the nearest triangle, exact up to double rounding.
class MeshDistance {
 public:
  explicit MeshDistance(const Mesh& mesh);
  ~MeshDistance();
  MeshDistance(const MeshDistance&) = delete;
  MeshDistance& operator=(const MeshDistance&) = delete;

  double distance(const Vec3& p) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clumpkit
