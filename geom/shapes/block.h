// Rock-block generator of Jin et al. 2017 (§2.1): a meshed cuboid with randomly
// scaled node radii.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/random.h"

namespace clumpkit {

/// Parameters of Jin et al. 2017 §2.1: a cuboid L×W×H (along x, y, z) whose six faces are meshed
/// with every edge split into `nd` segments; each node's distance from the centre is multiplied by
/// a uniform random factor in [sl, su] (Jin et al. 2017 eq. 1: γ = r·RAND(Sl, Su)).
struct BlockParams {
  double L = 1.0, W = 1.0, H = 1.0;
  int nd = 2;
  double sl = 0.8, su = 1.2;
};

/// Throws InvalidInput naming the field and value for non-positive or non-finite sizes, nd < 1
/// or > 64, non-positive sl, or sl > su.
void validate(const BlockParams& p);

/// Builds the block. Nodes are shared across faces, so the mesh is closed and 2-manifold. Each
/// triangle keeps a positive determinant against the centre under radial scaling (the
/// determinant is multilinear), so the surface stays a radial graph over the sphere: outward
/// oriented and free of self-intersections for any factors in (0, ∞).
Mesh make_block(const BlockParams& params, Rng& rng);

}  // namespace clumpkit
