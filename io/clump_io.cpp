#include "io/clump_io.h"

#include "geom/errors.h"
#include "io/atomic_file.h"
#include "io/report.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace clumpkit {

namespace {
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
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
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      std::string h;
      for (char ch : line)
        if (ch != ' ') h += ch;
      if (h != "x,y,z,r")
        throw InvalidInput(path + ": line " + std::to_string(lineno) +
                           ": expected header 'x,y,z,r', got '" + line.substr(0, 40) + "'");
      header = true;
      continue;
    }
    double v[4];
    std::stringstream ss(line);
    std::string cell;
    int k = 0;
    while (std::getline(ss, cell, ',')) {
      if (k >= 4)
        throw InvalidInput(path + ": line " + std::to_string(lineno) + ": more than 4 columns");
      cell = trim(cell);
      std::istringstream num(cell);
      num.imbue(std::locale::classic());
      if (!(num >> v[k]) || !(num >> std::ws).eof())
        throw InvalidInput(path + ": line " + std::to_string(lineno) + ": cannot parse '" +
                           cell.substr(0, 40) + "' as a number");
      ++k;
    }
    if (k != 4)
      throw InvalidInput(path + ": line " + std::to_string(lineno) +
                         ": expected 4 columns x,y,z,r");
    for (double x : v)
      if (!std::isfinite(x))
        throw InvalidInput(path + ": line " + std::to_string(lineno) + ": value is not finite");
    if (!(v[3] > 0))
      throw InvalidInput(path + ": line " + std::to_string(lineno) +
                         ": field r: radius must be positive, got " + format_number(v[3]));
    c.spheres.push_back(Sphere{Vec3(v[0], v[1], v[2]), v[3]});
  }
  if (!header) throw InvalidInput(path + ": empty clump file (no 'x,y,z,r' header)");
  if (c.spheres.empty()) throw InvalidInput(path + ": clump file lists no spheres");
  return c;
}

void write_clump(const std::string& path, const Clump& clump, const std::string& comment) {
  write_file_atomically(
      path,
      [&](std::ostream& o) {
        std::istringstream lines(comment);
        std::string l;
        while (std::getline(lines, l)) o << "# " << l << "\n";
        o << "x,y,z,r\n";
        for (const auto& s : clump.spheres)
          o << format_number(s.center.x()) << "," << format_number(s.center.y()) << ","
            << format_number(s.center.z()) << "," << format_number(s.radius) << "\n";
      },
      false);
}

}  // namespace clumpkit
