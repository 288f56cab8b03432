// JSON and CSV renderings of shape descriptors, shared by `describe`, `shapes` and `library`.
#pragma once

#include "geom/descriptors/descriptors.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

/// JSON object with the keys of `clumpkit describe --json`: volume, area, sphericity,
/// equivalent_diameter, L, W, H, axes [S, I, L], E, F, AR, convexity, weighted_roundness,
/// view_roundness [3].
nlohmann::json to_json(const Descriptors& d);

/// CSV column names for descriptors, in the order of descriptor_csv_values.
const std::vector<std::string>& descriptor_csv_columns();
std::vector<double> descriptor_csv_values(const Descriptors& d);

}  // namespace clumpkit
