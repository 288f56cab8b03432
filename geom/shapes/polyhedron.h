// Angular polyhedra from a sphere cut by random planes, stretched to target axis ratios
// (Hu et al. 2023 §3.1 and §3.4).
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/random.h"
#include "geom/range.h"

namespace clumpkit {

/// Hu et al. 2023: a sphere cut by `planes` random planes gives an angular parent particle; it is
/// then stretched to principal-axis ratios E = I/L and F = S/I and scaled to the volume-equivalent
/// diameter D.
/// Plane normals are uniform on the unit sphere; each plane's distance from the centre is
/// uniform in [offset_min, offset_max] times the sphere radius (defaults 0.6–0.95: every plane
/// cuts, none passes near the centre). The sphere itself is the intersection of the half-spaces
/// tangent to a level-`sphere_level` icosphere (642 planes at level 3), so the uncut parts stay
/// finely faceted. Corners come from the polar dual: the hull of the points n/h.
struct PolyhedronParams {
  double diameter = 1.0;  ///< D, volume-equivalent diameter of the result
  int planes = 30;
  double E = 1.0, F = 1.0;
  double offset_min = 0.6, offset_max = 0.95;
  int sphere_level = 3;
};

/// The values validate() takes and the recipes quote (besides offset_max in [offset_min, 1]).
inline constexpr Range kPolyhedronPlanes = integers(0, 10000);  ///< 0: the faceted sphere
inline constexpr Range kAxisRatio = open_closed(0, 1);          ///< E and F
inline constexpr Range kPlaneOffset = open_closed(0, 1);        ///< offsets, over the radius
inline constexpr Range kSphereLevel = integers(1, 5);

void validate(const PolyhedronParams& p);

/// Builds the polyhedron, centred on its centroid with its long, intermediate and short
/// principal axes along x, y and z. The stretch is iterated (at most 8 times) until the measured
/// E and F (inertia-aligned extents) match the targets within 1e-3.
Mesh make_polyhedron(const PolyhedronParams& params, Rng& rng);

}  // namespace clumpkit
