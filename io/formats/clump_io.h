// Clump files: CSV with header x,y,z,r, one sphere per line, '#' comment lines.
#pragma once

#include "geom/sphere.h"

#include <string>

namespace clumpkit {

/// Reads a clump CSV. Throws IoError for a missing file and InvalidInput (naming the file, line
/// and value) for an empty file, a bad header, a malformed number, NaN, or a radius ≤ 0.
Clump read_clump(const std::string& path);

/// Writes `# comment` lines (if any), the header and one line per sphere with round-trip
/// precision, atomically.
void write_clump(const std::string& path, const Clump& clump, const std::string& comment = "");

}  // namespace clumpkit
