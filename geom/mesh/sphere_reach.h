// How far a sphere reaches through a mesh's surface, for centres on either side of it.
#pragma once

#include "geom/mesh/mesh_index.h"
#include "geom/mesh/ray_inside.h"
#include "geom/sphere.h"

namespace clumpkit {

/// The depth by which `s` pokes through the surface of the mesh that `index` and `inside` were
/// built on: radius − the centre's distance to the surface for a centre inside (ray-parity vote),
/// radius + that distance for one outside; negative when the sphere lies wholly inside, clear of
/// the surface by that much. Unlike Fidelity::overshoot_depth_max (geom/fill/fidelity.h), which
/// assumes a fill's centres inside, this also judges a clump that is not the mesh's own fill.
inline double sphere_reach(const MeshIndex& index, const RayInside& inside, const Sphere& s) {
  const double d = index.distance(s.center);
  return inside.inside(s.center) ? s.radius - d : s.radius + d;
}

}  // namespace clumpkit
