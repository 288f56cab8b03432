// A watertight, 2-manifold, self-intersection-free surface around any triangle soup (CGAL 3D Alpha
// Wrapping, Portaneri et al. 2022).
#pragma once

#include "geom/mesh/mesh.h"

namespace clumpkit {

/// The alpha wrap of the triangles of `soup` (CGAL alpha_wrap_3): a surface that is closed,
/// 2-manifold, orientable and free of self-intersections by construction, lying outside the soup
/// at distance `offset`, which does not enter cavities or gaps narrower than about `alpha`
/// (lengths in the soup's units, both > 0). Crossing faces, folds, double walls and holes
/// narrower than alpha do not matter to it. The result faces outward. Throws InvalidInput for
/// sizes that are not positive and finite, or a soup without triangles.
Mesh alpha_wrap(const Mesh& soup, double alpha, double offset);

}  // namespace clumpkit
