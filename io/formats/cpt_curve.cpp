#include "io/formats/cpt_curve.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace clumpkit {

std::string cpt_curve_header() {
  return csv_header("cpt", kCptCurveColumns, si_length());
}

void write_cpt_curve(const std::string& path, const std::vector<dem::CptRow>& rows) {
  write_file_atomically(path, [&](std::ostream& f) {
    f << cpt_curve_header() << "\n";
    for (const dem::CptRow& c : rows)
      f << c.step << "," << format_number(c.depth) << "," << format_number(c.tip_force) << ","
        << format_number(c.sleeve_force) << "," << format_number(c.qc) << "," << format_number(c.fs)
        << "\n";
  });
}

std::vector<dem::CptRow> read_cpt_curve(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open the CPT curve");
  std::string line;
  bool header = static_cast<bool>(std::getline(in, line));
  if (header) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string names;
    for (const std::string& n : column_names(split_csv(line)))
      names += (names.empty() ? "" : ",") + n;
    header = names == kCptCurveColumns;
  }
  if (!header)
    throw InvalidInput(path + ":1: not a CPT curve (its header must be '" + cpt_curve_header() +
                       "')");
  std::vector<dem::CptRow> rows;
  for (long line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty()) continue;
    std::istringstream s(line);
    double v[6];
    int n = 0;
    for (std::string cell; n < 6 && std::getline(s, cell, ',');)
      v[n++] = to_number(cell).value_or(NAN);
    std::string rest;
    if (n != 6 || std::getline(s, rest) ||
        !std::all_of(v, v + 6, [](double x) { return std::isfinite(x); }))
      throw InvalidInput(path + ":" + std::to_string(line_no) + ": not six finite numbers '" +
                         line + "'");
    dem::CptRow r;
    r.step = static_cast<long long>(v[0]);
    r.depth = v[1], r.tip_force = v[2], r.sleeve_force = v[3], r.qc = v[4], r.fs = v[5];
    rows.push_back(r);
  }
  if (rows.empty()) throw InvalidInput(path + ": a CPT curve without rows");
  return rows;
}

}  // namespace clumpkit
