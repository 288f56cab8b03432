// specimen.vtp: the spheres of a specimen for ParaView (VTK XML PolyData).
#pragma once

#include "io/formats/specimen_csv.h"

#include <string>
#include <vector>

namespace clumpkit {

/// specimen.vtp: VTK XML PolyData, one point per sphere with point data radius, body (the id of
/// specimen.csv, from 1), kind (0 soil, 1 rock) and zone (the region of a zoned specimen); in
/// ParaView use a Glyph filter (sphere, scale
/// by radius, factor 2). Each of `labels` adds an Int32 point array: its value for each body on
/// every sphere of that body (one value per body, in the bodies' order).
struct BodyLabels {
  std::string name;
  std::vector<int> values;
};
void write_specimen_vtp(const std::string& path, const std::vector<SpecimenBody>& bodies,
                        const std::vector<BodyLabels>& labels = {});

}  // namespace clumpkit
