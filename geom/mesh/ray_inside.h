// Inside/outside of points against meshes that need not be watertight: Embree ray-parity voting.
#pragma once

#include "geom/mesh/mesh.h"

#include <memory>

namespace clumpkit {

/// Ray-parity classifier. Each query casts 7 rays in fixed, irrational directions and counts the
/// surface crossings along each; a point is inside when most rays cross an odd number of times.
/// A hole or a flipped triangle spoils only the rays that pass through it, so the vote stays
/// right where a single parity or a winding-number sign would not.
class RayInside {
 public:
  explicit RayInside(const Mesh& mesh);
  ~RayInside();
  RayInside(const RayInside&) = delete;
  RayInside& operator=(const RayInside&) = delete;

  /// Fraction of the rays that say "inside", in [0, 1].
  double vote(const Vec3& p) const;
  bool inside(const Vec3& p) const { return vote(p) > 0.5; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clumpkit
