// Subdivision of a mesh to at least a triangle count without changing its shape: scan-sized test
// meshes from generated or coarse ones.
#pragma once

#include "geom/mesh/mesh.h"

#include <cstdint>

namespace clumpkit {

/// Splits every triangle into four at its edge midpoints (a midpoint shared by the two
/// triangles of its edge) as many times as it takes to reach `min_triangles`: each round ×4.
/// The new vertices lie on the old triangles, so the surface (volume, area, every planar face)
/// is unchanged and the result stays closed and consistently oriented if the input was.
/// Deterministic. Throws InvalidInput for min_triangles above 5e7 or an empty mesh.
Mesh refine(const Mesh& mesh, std::int64_t min_triangles);

}  // namespace clumpkit
