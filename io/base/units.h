// Units of every number clumpkit writes (docs/units.md): a CSV column's unit in its header cell
// ("volume[m3]", "porosity[1]"), a JSON file's "units" map, and readers that take headers with
// or without units (folders written before units were).
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace clumpkit {

/// The unit of a dimensionless number.
inline constexpr const char* kDimensionless = "1";

/// The length unit of a geometry command's numbers: the input mesh's, which no mesh format
/// states. "L" (the mesh's length unit) unless the user names it (--length-unit mm); the numbers
/// are the same either way. Recipes and everything made from them are SI: "m".
struct LengthUnit {
  std::string symbol = "L";
  /// "L", "L2", "L3", ... ("m3", "mm3" for a named unit): the unit of a length to `power`.
  std::string pow(int power) const;
};

/// SI lengths, the unit of every command that reads a recipe.
inline LengthUnit si_length() {
  return {"m"};
}

/// Throws InvalidInput naming `option` unless `symbol` is a plain unit name (letters, 1 to 8:
/// "mm", "m", "um", "in").
LengthUnit length_unit(const std::string& symbol, const std::string& option = "--length-unit");

/// "volume[m3]": a numeric column's header cell. An empty unit gives the bare name (a text
/// column: names, paths, kinds).
std::string unit_cell(std::string_view name, std::string_view unit);

/// The column a header cell names, without its unit ("volume[m3]" → "volume"); a name of the
/// folders written before units were ("axial_stress_pa") is read as today's ("axial_stress").
std::string column_name(std::string_view cell);

/// The unit in a header cell ("volume[m3]" → "m3"); empty when it has none.
std::string column_unit(std::string_view cell);

/// column_name of each cell of a header.
std::vector<std::string> column_names(const std::vector<std::string>& cells);

/// clumpkit's vocabulary (io/base/unit_table.cpp): a name, a tail of a JSON key path
/// ("fidelity.spheres", "seconds.*") or a CSV file kind and column ("curve.q"), and its unit with
/// lengths in "L"; "" for a text column.
const std::vector<std::pair<std::string, std::string>>& unit_table();

/// The unit of the number at `path` by the vocabulary, lengths in `length`: the most specific
/// entry (the longest tail of the path, a "parent.*" entry before the bare name); empty when the
/// vocabulary has none (the units test then fails for that output).
std::string unit_of(const std::vector<std::string>& path, const LengthUnit& length);

/// The header line (no newline) of a CSV of kind `file` ("library", "curve") with the columns
/// `names` ("id,fraction,volume"): each cell with its unit from the vocabulary ("id[1]",
/// "fraction", "volume[m3]").
std::string csv_header(std::string_view file, std::string_view names, const LengthUnit& length);

/// Sets `doc["units"]` to the unit of every number in `doc` (keyed by its path, array levels
/// left out: "descriptors.volume"), by the vocabulary; a number it has no entry for is left out.
void add_units(nlohmann::ordered_json& doc, const LengthUnit& length);

/// Calls `f(path)` for every number in the JSON document `doc` (nlohmann::json or ordered_json),
/// `path` its object keys from the root with array levels left out; the top-level "units" map is
/// not visited. add_units and the tests that check a file's units walk documents with it.
template <class Json, class F>
void for_each_number(const Json& doc, F&& f, std::vector<std::string>& path) {
  if (doc.is_object()) {
    for (auto it = doc.begin(); it != doc.end(); ++it) {
      if (path.empty() && it.key() == "units") continue;
      path.push_back(it.key());
      for_each_number(it.value(), f, path);
      path.pop_back();
    }
  } else if (doc.is_array()) {
    for (const auto& e : doc) for_each_number(e, f, path);
  } else if (doc.is_number() && !path.empty()) {
    f(static_cast<const std::vector<std::string>&>(path));
  }
}

template <class Json, class F>
void for_each_number(const Json& doc, F&& f) {
  std::vector<std::string> path;
  for_each_number(doc, f, path);
}

/// The dotted key of a path ("descriptors.volume").
std::string dotted(const std::vector<std::string>& path);

/// The unit of the number at `path` (object keys from the root, array levels left out) in a
/// JSON file whose "units" map is `units`: the entry for the longest tail of the path
/// ("descriptors.volume", else "volume"); empty when none matches.
std::string json_unit(const nlohmann::json& units, const std::vector<std::string>& path);

}  // namespace clumpkit
