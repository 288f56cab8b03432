// Clump files: CSV with header x,y,z,r (each cell may carry its length unit, x[m],y[m],z[m],r[m]),
// one sphere per line, '#' comment lines.
#pragma once

#include "geom/sphere.h"

#include <string>

namespace clumpkit {

/// Reads a clump CSV (header x,y,z,r, with or without one length unit on every cell). Throws
/// IoError for a missing file and InvalidInput (naming the file, line and value) for an empty
/// file, a bad header, a malformed number, NaN, or a radius ≤ 0.
Clump read_clump(const std::string& path);

/// The length unit a clump CSV's header names ("m" for x[m],y[m],z[m],r[m]), "" for a header
/// without units. Throws as read_clump does for a missing file or a bad header.
std::string read_clump_length_unit(const std::string& path);

/// Writes `# comment` lines (if any), the header x[U],y[U],z[U],r[U] with U = `length_unit` (the
/// unit of the coordinates: "m", "mm"; "L" where it is the input mesh's, unnamed) and one line
/// per sphere with round-trip precision, atomically.
void write_clump(const std::string& path, const Clump& clump, const std::string& comment = "",
                 const std::string& length_unit = "L");

}  // namespace clumpkit
