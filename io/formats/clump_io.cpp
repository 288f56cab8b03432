#include "io/formats/clump_io.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/limits.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace clumpkit {

namespace {
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

// The length unit of a clump header: the cells x,y,z,r, each with the same unit in brackets or
// none ("" then); spaces ignored. Throws InvalidInput naming the file and line otherwise.
std::string header_unit(const std::string& path, int lineno, const std::string& line) {
  std::string h;
  for (char ch : line)
    if (ch != ' ') h += ch;
  const std::vector<std::string> cells = split_csv(h);
  const char* names[4] = {"x", "y", "z", "r"};
  bool ok = cells.size() == 4 && !h.empty() && h.back() != ',';
  for (std::size_t q = 0; ok && q < 4; ++q) ok = column_name(cells[q]) == names[q];
  if (!ok)
    throw InvalidInput(path + ": line " + std::to_string(lineno) +
                       ": expected header 'x,y,z,r' (or with a length unit, x[m],y[m],z[m],r[m]), "
                       "got '" +
                       line.substr(0, 40) + "'");
  const std::string unit = column_unit(cells[0]);
  for (std::size_t q = 1; q < 4; ++q)
    if (column_unit(cells[q]) != unit)
      throw InvalidInput(path + ": line " + std::to_string(lineno) +
                         ": the columns x,y,z,r must share one length unit, got '" +
                         line.substr(0, 60) + "'");
  return unit;
}

// The first line that is neither blank nor a '#' comment, trimmed; its number in `lineno`.
bool first_content_line(std::istream& in, std::string& line, int& lineno) {
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && (line.front() == ' ' || line.front() == '\t' || line.back() == ' ' ||
                          line.back() == '\t' || line.back() == '\r'))
      line = trim(line);
    if (!line.empty() && line[0] != '#') return true;
  }
  return false;
}
}  // namespace

Clump read_clump(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open clump file");
  Clump c;
  std::string line;
  int lineno = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && (line.front() == ' ' || line.front() == '\t' || line.back() == ' ' ||
                          line.back() == '\t' || line.back() == '\r'))
      line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header_unit(path, lineno, line);
      header = true;
      continue;
    }
    // Four cells between commas, each a number that fills it (spaces and tabs around it
    // allowed): io/base/text.h, locale independent and fast (specimen files hold 1e5+ spheres).
    double v[4];
    int k = 0;
    std::string_view rest(line);
    while (true) {
      if (k >= 4)
        throw InvalidInput(path + ": line " + std::to_string(lineno) + ": more than 4 columns");
      const std::size_t comma = rest.find(',');
      std::string_view cell = rest.substr(0, comma);
      while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
      while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t')) cell.remove_suffix(1);
      const std::optional<double> x = to_number(cell);
      if (!x)
        throw InvalidInput(path + ": line " + std::to_string(lineno) + ": cannot parse '" +
                           std::string(cell.substr(0, 40)) + "' as a number");
      v[k++] = *x;
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    if (k != 4)
      throw InvalidInput(path + ": line " + std::to_string(lineno) +
                         ": expected 4 columns x,y,z,r");
    const char* names[4] = {"x", "y", "z", "r"};
    for (int q = 0; q < 4; ++q)
      if (!std::isfinite(v[q]))
        throw InvalidInput(path + ": line " + std::to_string(lineno) + ": field " + names[q] +
                           ": value is not finite, got " + format_number(v[q]));
    if (!(v[3] > 0))
      throw InvalidInput(path + ": line " + std::to_string(lineno) +
                         ": field r: radius must be positive, got " + format_number(v[3]));
    // The message's prefix only when a value fails (built per line it cost a third of the read).
    auto at = [&](int q) {
      return path + ": line " + std::to_string(lineno) + ": field " + names[q];
    };
    for (int q = 0; q < 3; ++q)
      if (!(std::abs(v[q]) <= kMaxLength)) check_coordinate(v[q], at(q));
    if (!(v[3] >= kMinLength && v[3] <= kMaxLength)) check_size(v[3], at(3));
    c.spheres.push_back(Sphere{Vec3(v[0], v[1], v[2]), v[3]});
  }
  if (!header) throw InvalidInput(path + ": empty clump file (no 'x,y,z,r' header)");
  if (c.spheres.empty()) throw InvalidInput(path + ": clump file lists no spheres");
  return c;
}

std::string read_clump_length_unit(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open clump file");
  std::string line;
  int lineno = 0;
  if (!first_content_line(in, line, lineno))
    throw InvalidInput(path + ": empty clump file (no 'x,y,z,r' header)");
  return header_unit(path, lineno, line);
}

void write_clump(const std::string& path, const Clump& clump, const std::string& comment,
                 const std::string& length_unit) {
  write_file_atomically(
      path,
      [&](std::ostream& o) {
        std::istringstream lines(comment);
        std::string l;
        while (std::getline(lines, l)) o << "# " << l << "\n";
        o << csv_header("clump", "x,y,z,r", LengthUnit{length_unit}) << "\n";
        for (const auto& s : clump.spheres)
          o << format_number(s.center.x()) << "," << format_number(s.center.y()) << ","
            << format_number(s.center.z()) << "," << format_number(s.radius) << "\n";
      },
      false);
}

}  // namespace clumpkit
