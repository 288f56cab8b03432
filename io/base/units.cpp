// Units of every number clumpkit writes (docs/units.md).
#include "io/base/units.h"

#include "geom/errors.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <utility>

namespace clumpkit {

namespace {

// Columns of folders written before units were, whose names carried an SI unit: today the unit
// is in brackets and the name is bare.
constexpr std::array<std::pair<std::string_view, std::string_view>, 19> kOldNames = {{
    {"axial_stress_pa", "axial_stress"},
    {"radial_stress_pa", "radial_stress"},
    {"p_pa", "p"},
    {"q_pa", "q"},
    {"work_pa", "work"},
    {"depth_m", "depth"},
    {"tip_force_n", "tip_force"},
    {"sleeve_force_n", "sleeve_force"},
    {"qc_pa", "qc"},
    {"fs_pa", "fs"},
    {"sieve_m", "sieve"},
    {"diameter_m", "diameter"},
    {"peak_force_n", "peak_force"},
    {"peak_travel_m", "peak_travel"},
    {"strength_pa", "strength"},
    {"max_force_n", "max_force"},
    {"travel_m", "travel"},
    {"force_n", "force"},
    {"stress_pa", "stress"},
}};

const std::map<std::string, std::string, std::less<>>& vocabulary() {
  static const std::map<std::string, std::string, std::less<>> map(unit_table().begin(),
                                                                   unit_table().end());
  return map;
}

// The unit `u` of the vocabulary (lengths in "L") with lengths in `length`.
std::string in_length(const std::string& u, const LengthUnit& length) {
  std::string out;
  for (char c : u) {
    if (c == 'L')
      out += length.symbol;
    else
      out += c;
  }
  return out;
}

// "broken_class_3" is found as "broken_class_*": a family of numbered columns.
std::string numbered_family(const std::string& name) {
  std::size_t end = name.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
  if (end == name.size() || end == 0 || name[end - 1] != '_') return {};
  return name.substr(0, end) + "*";
}

}  // namespace

std::string unit_of(const std::vector<std::string>& path, const LengthUnit& length) {
  const auto& v = vocabulary();
  for (std::size_t first = 0; first < path.size(); ++first) {
    std::string tail;
    for (std::size_t i = first; i < path.size(); ++i) tail += (i > first ? "." : "") + path[i];
    if (auto it = v.find(tail); it != v.end()) return in_length(it->second, length);
    if (first + 1 < path.size()) {  // "parent.*": any key under parent
      std::string parent;
      for (std::size_t i = first; i + 1 < path.size(); ++i)
        parent += (i > first ? "." : "") + path[i];
      if (auto it = v.find(parent + ".*"); it != v.end()) return in_length(it->second, length);
    }
  }
  const std::string family = numbered_family(path.empty() ? std::string() : path.back());
  if (!family.empty())
    if (auto it = v.find(family); it != v.end()) return in_length(it->second, length);
  return {};
}

std::string csv_header(std::string_view file, std::string_view names, const LengthUnit& length) {
  std::string out;
  std::size_t start = 0;
  while (start <= names.size()) {
    std::size_t end = names.find(',', start);
    if (end == std::string_view::npos) end = names.size();
    const std::string name(names.substr(start, end - start));
    if (!out.empty() || start > 0) out += ',';
    out += unit_cell(name, unit_of({std::string(file), name}, length));
    start = end + 1;
  }
  return out;
}

std::string dotted(const std::vector<std::string>& path) {
  std::string key;
  for (const std::string& p : path) key += (key.empty() ? "" : ".") + p;
  return key;
}

void add_units(nlohmann::ordered_json& doc, const LengthUnit& length) {
  nlohmann::ordered_json units = nlohmann::ordered_json::object();
  for_each_number(doc, [&](const std::vector<std::string>& path) {
    const std::string key = dotted(path);
    if (units.contains(key)) return;
    const std::string u = unit_of(path, length);
    if (!u.empty()) units[key] = u;
  });
  doc["units"] = std::move(units);
}

std::string LengthUnit::pow(int power) const {
  return power == 1 ? symbol : symbol + std::to_string(power);
}

LengthUnit length_unit(const std::string& symbol, const std::string& option) {
  bool ok = !symbol.empty() && symbol.size() <= 8;
  for (char c : symbol) ok = ok && std::isalpha(static_cast<unsigned char>(c));
  if (!ok)
    throw InvalidInput(option + ": a length unit is a name of 1 to 8 letters (mm, m, um), got '" +
                       symbol + "'");
  return {symbol};
}

std::string unit_cell(std::string_view name, std::string_view unit) {
  std::string cell(name);
  if (!unit.empty()) cell.append("[").append(unit).append("]");
  return cell;
}

std::string column_name(std::string_view cell) {
  const std::size_t open = cell.find('[');
  if (open != std::string_view::npos && cell.back() == ']')
    return std::string(cell.substr(0, open));
  for (const auto& [old_name, name] : kOldNames)
    if (cell == old_name) return std::string(name);
  return std::string(cell);
}

std::string column_unit(std::string_view cell) {
  const std::size_t open = cell.find('[');
  if (open == std::string_view::npos || cell.back() != ']') return {};
  return std::string(cell.substr(open + 1, cell.size() - open - 2));
}

std::vector<std::string> column_names(const std::vector<std::string>& cells) {
  std::vector<std::string> names;
  names.reserve(cells.size());
  for (const std::string& c : cells) names.push_back(column_name(c));
  return names;
}

std::string json_unit(const nlohmann::json& units, const std::vector<std::string>& path) {
  if (!units.is_object()) return {};
  for (std::size_t first = 0; first < path.size(); ++first) {
    std::string key;
    for (std::size_t i = first; i < path.size(); ++i) key += (i > first ? "." : "") + path[i];
    const auto it = units.find(key);
    if (it != units.end() && it->is_string()) return it->get<std::string>();
  }
  return {};
}

}  // namespace clumpkit
