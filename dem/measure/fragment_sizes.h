// The pieces of a bonded assembly for sieving: each fragment (bodies joined by intact bonds) with
// its solid volume and its intermediate dimension.
#pragma once

#include "dem/core/body.h"
#include "dem/core/bond.h"
#include "dem/measure/breakage.h"

#include <vector>

namespace clumpkit::dem {

/// A fragment's extents L ≥ I ≥ S (m) along the principal axes of inertia of its bodies
/// together (each body's principal moments turned into the world and shifted to the fragment's
/// centroid), over its spheres' surfaces.
Vec3 fragment_extents(const std::vector<Body>& bodies, const std::vector<int>& members);

/// One piece per fragment of `bodies` under the bonds that hold (dem::fragments; an unbonded
/// body is a fragment of its own), in order of the fragments' labels: the sum of its bodies'
/// Body::volume and its intermediate extent I (fragment_extents). Throws InvalidInput for a
/// body without a positive volume.
std::vector<SievedPiece> fragment_pieces(const std::vector<Body>& bodies,
                                         const std::vector<Bond>& bonds);

}  // namespace clumpkit::dem
