#include "io/formats/curve_csv.h"

#include "geom/errors.h"
#include "io/base/text.h"
#include "io/base/units.h"

#include <cmath>
#include <sstream>

namespace clumpkit {

namespace {

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// A header cell's unit, else the vocabulary's for a curve column of its name (SI).
std::string cell_unit(const std::string& cell) {
  const std::string u = column_unit(cell);
  return u.empty() ? unit_of({"curve", column_name(cell)}, si_length()) : u;
}

}  // namespace

dem::Curve read_curve_columns(const std::string& path, const std::string& x, const std::string& y,
                              CurveUnits* units) {
  std::istringstream in(read_file(path, "curve"));
  std::string line;
  int lineno = 0;
  std::vector<std::string> header;
  int ix = -1, iy = -1;
  const std::string x_name = column_name(x), y_name = column_name(y);
  dem::Curve c;
  while (std::getline(in, line)) {
    ++lineno;
    line = trimmed(line);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = split_csv(line);
    for (std::string& cell : cells) cell = trimmed(cell);
    if (header.empty()) {
      header = cells;
      for (int k = 0; k < static_cast<int>(header.size()); ++k) {
        if (column_name(header[k]) == x_name && ix < 0) ix = k;
        if (column_name(header[k]) == y_name && iy < 0) iy = k;
      }
      std::string names;
      for (const std::string& h : header) names += (names.empty() ? "" : ", ") + h;
      if (ix < 0) throw InvalidInput(path + ": no column '" + x + "' (columns: " + names + ")");
      if (iy < 0) throw InvalidInput(path + ": no column '" + y + "' (columns: " + names + ")");
      if (units) *units = {cell_unit(header[ix]), cell_unit(header[iy])};
      continue;
    }
    const std::string at = path + ": line " + std::to_string(lineno) + ": column '";
    auto cell = [&](int k, const std::string& name) {
      if (k >= static_cast<int>(cells.size()))
        throw InvalidInput(at + name + "': the row has only " + std::to_string(cells.size()) +
                           " cells");
      const std::optional<double> v = to_number(cells[k]);
      if (!v || !std::isfinite(*v))
        throw InvalidInput(at + name + "': expected a finite number, got '" +
                           cells[k].substr(0, 40) + "'");
      return *v;
    };
    const double vx = cell(ix, x), vy = cell(iy, y);
    if (!c.x.empty() && !(vx > c.x.back()))
      throw InvalidInput(at + x + "': x must increase strictly, got " + cells[ix] + " after " +
                         std::to_string(c.x.back()));
    c.x.push_back(vx);
    c.y.push_back(vy);
  }
  if (header.empty()) throw InvalidInput(path + ": empty curve file (no header line)");
  if (c.x.size() < 2)
    throw InvalidInput(path + ": a curve needs at least 2 rows, got " + std::to_string(c.x.size()));
  return c;
}

}  // namespace clumpkit
