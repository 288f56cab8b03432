// What every kind of page's data share: CSV tables of an output folder, curves, images, names.
#include "io/pipeline/page_data.h"

#include "geom/errors.h"
#include "io/base/text.h"
#include "io/base/units.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>

namespace clumpkit::page_data {

int CsvTable::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), column_name(name));
  return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

double CsvTable::number(std::size_t row, int col) const {
  const ordered_json& v = rows[row][static_cast<std::size_t>(col)];
  return v.is_number() ? v.get<double>() : NAN;
}

CsvTable read_table(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path.string() + ": cannot open (the folder's manifest lists it)");
  CsvTable t;
  LineReader at{path.string()};
  std::string line;
  while (std::getline(in, line)) {
    ++at.line;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = split_csv(line);
    if (t.columns.empty()) {
      for (const std::string& c : cells) t.units.push_back(column_unit(c));
      t.columns = column_names(cells);
      continue;
    }
    if (cells.size() != t.columns.size())
      at.fail(std::to_string(cells.size()) + " fields, the header has " +
              std::to_string(t.columns.size()));
    std::vector<ordered_json> row;
    // A cell that is not all a finite number (a name, a path, an empty cell) stays text: the
    // table shows it as written.
    for (const std::string& c : cells) {
      const std::optional<double> v = to_number(c);
      if (v && std::isfinite(*v))
        row.emplace_back(sig(*v));
      else
        row.emplace_back(c);
    }
    t.rows.push_back(std::move(row));
  }
  if (t.columns.empty()) throw InvalidInput(path.string() + ": empty table");
  return t;
}

ordered_json table_json(const CsvTable& t, const std::vector<std::string>& keep) {
  std::vector<int> cols;
  ordered_json columns = ordered_json::array(), units = ordered_json::array(),
               rows = ordered_json::array();
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (keep.empty() || std::find(keep.begin(), keep.end(), t.columns[c]) != keep.end()) {
      cols.push_back(static_cast<int>(c));
      columns.push_back(t.columns[c]);
      units.push_back(c < t.units.size() ? t.units[c] : std::string());
    }
  for (const auto& r : t.rows) {
    ordered_json row = ordered_json::array();
    for (int c : cols) row.push_back(r[static_cast<std::size_t>(c)]);
    rows.push_back(std::move(row));
  }
  return {{"columns", columns}, {"units", units}, {"rows", rows}};
}

ordered_json series(const CsvTable& t, const std::string& label, const std::string& x, double fx,
                    const std::string& y, double fy, bool log_x) {
  const int cx = t.column(x), cy = t.column(y);
  ordered_json xs = ordered_json::array(), ys = ordered_json::array();
  if (cx < 0 || cy < 0) return {{"label", label}, {"x", xs}, {"y", ys}};
  // A plot 560 pixels wide shows no more than 2000 points apart.
  const std::size_t stride = std::max<std::size_t>(1, t.rows.size() / 2000);
  for (std::size_t k = 0; k < t.rows.size(); k += stride) {
    double a = t.number(k, cx) * fx;
    const double b = t.number(k, cy) * fy;
    if (log_x) a = a > 0 ? std::log10(a) : NAN;
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    xs.push_back(sig(a)), ys.push_back(sig(b));
  }
  return {{"label", label}, {"x", xs}, {"y", ys}};
}

std::string display_name(const fs::path& dir) {
  const fs::path p = dir.has_filename() ? dir : dir.parent_path();
  return fs::absolute(p).lexically_normal().filename().string();
}

std::string id_stem(const ordered_json& id, const fs::path& table) {
  // The cell went through sig(): a whole number stays whole, and the cast below needs one ≥ 0.
  const double v = id.is_number() ? id.get<double>() : -1;
  if (!(v >= 0) || v != std::floor(v) || v > 1e15)
    throw InvalidInput(table.string() + ": particle id '" +
                       (id.is_string() ? id.get<std::string>() : id.dump()) +
                       "' is not a whole number >= 0");
  return id_name(static_cast<std::size_t>(v));
}

void Images::add(const fs::path& file, const std::string& caption) {
  if (!fs::exists(file)) return;
  std::string src = fs::relative(file, out).generic_string();
  if (src.rfind("..", 0) == 0 || fs::path(src).is_absolute()) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string name = "img/" + std::to_string(list.size()) + "-" + file.filename().string();
    copies->push_back({name, bytes});
    src = "page/" + name;
  }
  list.push_back({{"src", src}, {"caption", caption}});
}

}  // namespace clumpkit::page_data
