// Two columns of a CSV table with a header line, as a curve y(x): clumpkit's curve.csv files and
// any table written like them (comma-separated numbers, '#' comment lines).
#pragma once

#include "dem/measure/curve_residual.h"

#include <string>

namespace clumpkit {

/// The units of the two columns read: a header cell's ("depth[m]" → "m"), else the vocabulary's
/// for a clumpkit curve column of that name (folders written before units, all SI); empty when
/// neither says.
struct CurveUnits {
  std::string x, y;
};

/// Columns `x` and `y` of the CSV file at `path`, by their header names compared through
/// column_name: "depth", "depth[m]" and "depth_m" (a file written before units) name the same
/// column. Sets `units` when given. Throws IoError for a missing or unreadable file and
/// InvalidInput ("PATH: line N: column C: …") for a missing column, a cell that is not a finite
/// number, an x that does not increase strictly, or fewer than two rows.
dem::Curve read_curve_columns(const std::string& path, const std::string& x, const std::string& y,
                              CurveUnits* units = nullptr);

}  // namespace clumpkit
