#include "io/formats/bonds_csv.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"

#include <cmath>
#include <fstream>
#include <optional>

namespace clumpkit {

namespace {

std::string vec(const Vec3& v) {
  return format_number(v.x()) + "," + format_number(v.y()) + "," + format_number(v.z());
}

}  // namespace

void write_bonds_csv(const std::string& path, const SpecimenBonds& s) {
  write_file_atomically(path, [&](std::ostream& o) {
    const dem::CohesiveParams& l = s.law;
    o << "# clumpkit bonds format " << kBondsCsvFormat
      << ", SI units. The cohesive law (Hu et al. 2023 eqs. 5-11), the bonds between bodies of "
         "specimen.csv (ids from 1; normal in a's body frame), their integration points (in a's "
         "and in b's body frame)\n# law\n"
      << csv_header("bonds", "kn,kt,sigma_n,sigma_t,g_n,g_t,friction", si_length()) << "\n"
      << format_number(l.kn) << "," << format_number(l.kt) << "," << format_number(l.sigma_n) << ","
      << format_number(l.sigma_t) << "," << format_number(l.g_n) << "," << format_number(l.g_t)
      << "," << format_number(l.friction) << "\n# bonds\n"
      << csv_header("bonds", "bond,a,b,nx,ny,nz,factor", si_length()) << "\n";
    for (std::size_t k = 0; k < s.bonds.size(); ++k) {
      const dem::Bond& b = s.bonds[k];
      o << k + 1 << "," << b.a + 1 << "," << b.b + 1 << "," << vec(b.normal_in_a) << ","
        << format_number(b.factor) << "\n";
    }
    o << "# points\n"
      << csv_header("bonds", "bond,ax,ay,az,bx,by,bz,area,damage,sx,sy,sz,mix", si_length())
      << "\n";
    for (std::size_t k = 0; k < s.bonds.size(); ++k)
      for (const dem::BondPoint& p : s.bonds[k].points)
        o << k + 1 << "," << vec(p.in_a) << "," << vec(p.in_b) << "," << format_number(p.area)
          << "," << format_number(p.state.damage) << "," << vec(p.state.slip) << ","
          << format_number(p.state.failure_mix) << "\n";
  });
}

SpecimenBonds read_bonds_csv(const std::string& path, std::size_t bodies) {
  std::ifstream in(path);
  if (!in) throw IoError(path + ": cannot open bonds file");
  SpecimenBonds s;
  std::string line;
  LineReader at{path};
  long& line_no = at.line;
  auto bad = [&](const std::string& why) { at.fail(why); };
  auto number = [&](const std::string& cell, const char* field) { return at.number(cell, field); };
  auto id = [&](const std::string& cell, const char* field, std::size_t count) {
    const double v = number(cell, field);
    if (v != std::floor(v) || v < 1 || v > static_cast<double>(count))
      bad("field " + std::string(field) + ": no " + field + " '" + cell + "' (1.." +
          std::to_string(count) + ")");
    return static_cast<int>(v) - 1;
  };
  auto vec3 = [&](const std::vector<std::string>& c, std::size_t i, const char* field) {
    return Vec3(number(c[i], field), number(c[i + 1], field), number(c[i + 2], field));
  };
  enum class Section { head, law, bonds, points } section = Section::head;
  bool have_law = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1 &&
        line.rfind("# clumpkit bonds format " + std::to_string(kBondsCsvFormat) + ",", 0) != 0)
      bad("not a clumpkit bonds.csv of format " + std::to_string(kBondsCsvFormat));
    if (line.empty()) continue;
    if (line == "# law" || line == "# bonds" || line == "# points") {
      section = line == "# law"     ? Section::law
                : line == "# bonds" ? Section::bonds
                                    : Section::points;
      continue;
    }
    if (line[0] == '#') continue;
    const std::vector<std::string> c = split_csv(line);
    // A section's header, with units ("kn[N/m3],...") or without (files written before units).
    const std::string first = column_name(c.front());
    if (first == "kn" || first == "bond") continue;
    if (section == Section::law) {
      if (c.size() != 7) bad("the law row has 7 fields, found " + std::to_string(c.size()));
      s.law = {number(c[0], "kn"),      number(c[1], "kt"),  number(c[2], "sigma_n"),
               number(c[3], "sigma_t"), number(c[4], "g_n"), number(c[5], "g_t"),
               number(c[6], "friction")};
      try {
        dem::validate_values(s.law);
      } catch (const InvalidInput& e) {
        bad(e.what());
      }
      have_law = true;
    } else if (section == Section::bonds) {
      if (c.size() != 7) bad("a bond row has 7 fields, found " + std::to_string(c.size()));
      if (number(c[0], "bond") != static_cast<double>(s.bonds.size() + 1))
        bad("field bond: expected id " + std::to_string(s.bonds.size() + 1) + ", found " + c[0]);
      dem::Bond b;
      b.a = id(c[1], "a", bodies);
      b.b = id(c[2], "b", bodies);
      if (b.a == b.b)
        bad("fields a, b: a bond joins two different bodies, found " + c[1] + " twice");
      b.normal_in_a = vec3(c, 3, "nx..nz");
      if (std::abs(b.normal_in_a.norm() - 1.0) > 1e-9) bad("fields nx..nz: not a unit normal");
      b.factor = number(c[6], "factor");
      if (!(b.factor > 0)) bad("field factor: must be positive, found " + c[6]);
      s.bonds.push_back(std::move(b));
    } else if (section == Section::points) {
      if (c.size() != 13) bad("a point row has 13 fields, found " + std::to_string(c.size()));
      dem::BondPoint p;
      const int bond = id(c[0], "bond", s.bonds.size());
      p.in_a = vec3(c, 1, "ax..az");
      p.in_b = vec3(c, 4, "bx..bz");
      p.area = number(c[7], "area");
      if (!(p.area >= 0)) bad("field area: must not be negative, found " + c[7]);
      p.state.damage = number(c[8], "damage");
      if (!(p.state.damage >= 0 && p.state.damage <= 1))
        bad("field damage: must be in [0, 1], found " + c[8]);
      p.state.slip = vec3(c, 9, "sx..sz");
      p.state.failure_mix = number(c[12], "mix");
      if (!(p.state.failure_mix >= 0 && p.state.failure_mix <= 1))
        bad("field mix: must be in [0, 1], found " + c[12]);
      s.bonds[static_cast<std::size_t>(bond)].points.push_back(p);
    } else {
      bad("a data row before the '# law' section");
    }
  }
  if (line_no == 0) throw InvalidInput(path + ": empty bonds file");
  if (!have_law) throw InvalidInput(path + ": no '# law' row");
  for (std::size_t k = 0; k < s.bonds.size(); ++k)
    if (s.bonds[k].points.empty())
      throw InvalidInput(path + ": bond " + std::to_string(k + 1) + " has no points");
  return s;
}

}  // namespace clumpkit
