// Picture of a clump against its mesh: three orthogonal views in one PNG.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/sphere.h"

#include <string>

namespace clumpkit {

/// Writes a PNG with three panels, views along x, y and z: the mesh silhouette filled grey and
/// each sphere's outline in red (an orthographic projection keeps spheres circles). `pixels` is
/// the panel size. Atomic write; throws IoError naming the path.
void write_views_png(const std::string& path, const Mesh& mesh, const Clump& clump,
                     int pixels = 300);

}  // namespace clumpkit
