// A clump and its mesh in one VTK XML PolyData file (.vtp) for ParaView.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/sphere.h"

#include <string>

namespace clumpkit {

/// Writes the mesh's triangles as polygons and each sphere's centre as a vertex cell, in one
/// point list (mesh vertices first). Point data: "radius" and "diameter" (0 on mesh vertices),
/// "sphere" (the sphere's row in the clump CSV, −1 on mesh vertices). In ParaView: the mesh
/// shows as it is (set Opacity for a veil); Glyph → Sphere, Scale Array "diameter", Scale
/// Factor 1 (ParaView's sphere glyph has radius 0.5) draws the spheres to size. Atomic write;
/// throws IoError naming the path.
void write_clump_vtp(const std::string& path, const Mesh& mesh, const Clump& clump);

}  // namespace clumpkit
