// The job of `clumpkit compare-curves`: the residual of one test curve against another (CTGU
// 2017, eq. 4) over their common range.
#pragma once

#include <nlohmann/json.hpp>

#include <limits>
#include <string>

namespace clumpkit {

/// What the job compares: curve b against the reference a, columns `x` and `y` of each CSV (by
/// column_name: with or without a unit, or a name of a file written before units, "qc_pa").
struct CompareCurvesOptions {
  std::string a, b;
  std::string x = "depth", y = "qc";
  int points = 200;
  /// Window on x: only the overlap within [from, to] is compared (unbounded by default).
  double from = -std::numeric_limits<double>::infinity();
  double to = std::numeric_limits<double>::infinity();
  /// Also draw both curves (whole, A blue, B red, each labelled with its file) into this PNG.
  std::string png;
};

/// Reads both curves and returns {a, b, x, y, from, to (the range compared), points,
/// residual_abs, residual_rel, relative_points, units (from and to in x's unit, residual_abs in
/// y's squared, where the files say them)}, after writing `png` when asked. Throws IoError /
/// InvalidInput naming the file for bad input, and for columns whose units differ between the
/// two files.
nlohmann::ordered_json compare_curves(const CompareCurvesOptions& o);

}  // namespace clumpkit
