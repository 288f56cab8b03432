// The units rule (docs/units.md) checked on a command's output folder: every numeric CSV column
// has a unit in its header cell, every number in a JSON file a unit in its "units" map.
#pragma once

#include "io/base/text.h"
#include "io/base/units.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cli_test {

/// The numbers of one JSON document without a unit in its "units" map: their key paths.
inline std::vector<std::string> json_numbers_without_unit(const nlohmann::json& doc) {
  std::vector<std::string> missing;
  const nlohmann::json units =
      doc.is_object() && doc.contains("units") ? doc["units"] : nlohmann::json();
  clumpkit::for_each_number(doc, [&](const std::vector<std::string>& path) {
    if (!clumpkit::json_unit(units, path).empty()) return;
    const std::string key = clumpkit::dotted(path);
    if (missing.empty() || missing.back() != key) missing.push_back(key);
  });
  return missing;
}

/// The numeric columns of one CSV text ('#' comment lines skipped) whose header cell has no
/// unit: their header cells. A line without a number is a header (specimen.csv and bonds.csv
/// hold several sections, each under its own); a column is numeric when any of its cells is a
/// number.
inline std::vector<std::string> csv_columns_without_unit(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header, missing;
  std::vector<bool> numeric;
  auto close_section = [&] {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (numeric[i] && clumpkit::column_unit(header[i]).empty()) missing.push_back(header[i]);
  };
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> cells = clumpkit::split_csv(line);
    bool any_number = false;
    for (const std::string& c : cells) any_number = any_number || clumpkit::to_number(c);
    if (!any_number) {
      close_section();
      header = cells;
      numeric.assign(header.size(), false);
      continue;
    }
    for (std::size_t i = 0; i < cells.size() && i < header.size(); ++i)
      if (clumpkit::to_number(cells[i])) numeric[i] = true;
  }
  close_section();
  return missing;
}

/// Every CSV and JSON file under `dir` (a command's output folder) follows the units rule; the
/// failure names the file and the columns or keys without a unit. Returns the number of files
/// read, for the caller to check that the folder held what it expects.
inline int expect_units_everywhere(const std::filesystem::path& dir) {
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string ext = e.path().extension().string();
    if (ext != ".csv" && ext != ".json") continue;
    std::ifstream f(e.path());
    std::stringstream s;
    s << f.rdbuf();
    ++files;
    std::vector<std::string> missing;
    if (ext == ".csv") {
      missing = csv_columns_without_unit(s.str());
    } else {
      const nlohmann::json doc = nlohmann::json::parse(s.str(), nullptr, false);
      EXPECT_FALSE(doc.is_discarded()) << e.path() << ": not JSON";
      if (!doc.is_discarded()) missing = json_numbers_without_unit(doc);
    }
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    EXPECT_TRUE(missing.empty()) << e.path() << ": no unit for " << list;
  }
  return files;
}

}  // namespace cli_test
