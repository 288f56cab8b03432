// ParaView/VTK export of a specimen: the sphere point cloud with its arrays and a script that
// glyphs it into true-size spheres (python3-vtk9 or ParaView's pvpython).
#pragma once

#include "io/formats/specimen_csv.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Writes into `dir` (which must exist):
///  - specimen.vtp: ASCII VTK XML PolyData, one vertex per sphere centre with point data radius
///    (m), body (the specimen.csv id) and kind (1 rock, 0 soil);
///  - glyph_clumpkit.py: reads specimen.vtp, glyphs it as ParaView's Glyph filter does (sphere of
///    radius 0.5 scaled by `radius` with factor 2, all points), writes spheres.vtp (a surface
///    to open in ParaView as is) and prints the number of points and the glyph bounds.
/// Returns the paths written.
std::vector<std::string> write_vtk_export(const std::vector<SpecimenBody>& bodies,
                                          const std::string& dir);

/// The command line that runs the script in the export directory.
inline std::string vtk_run_command() {
  return "python3 glyph_clumpkit.py";
}

}  // namespace clumpkit
