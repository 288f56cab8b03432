// `clumpkit export` to Yade, PFC and ParaView/VTK: each engine's files read back (by the real
// engine where Debian has it, by a parser for PFC) against the specimen.
#include "cli_helpers.h"
#include "io/formats/specimen_csv.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace fs = std::filesystem;
using namespace cli_test;
using clumpkit::read_specimen_csv;
using clumpkit::SpecimenBody;
using clumpkit::Sphere;
using clumpkit::Vec3;
namespace dem = clumpkit::dem;

namespace {

/// Builds the tiny specimen in `d`/spec (rock clumps of 8 spheres with three distinct moments
/// and arbitrary orientations) and exports it in `format` to `d`/FORMAT; returns its bodies.
std::vector<SpecimenBody> tiny_export(const fs::path& d, const std::string& format) {
  build_tiny_specimen(d);
  const Result r = run_cli("export " + format + " " + (d / "spec").string() + " --out " +
                               (d / format).string() + " --json",
                           d);
  EXPECT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], format);
  for (const auto& f : j["files"]) EXPECT_TRUE(fs::exists(f.get<std::string>())) << f;
  std::vector<SpecimenBody> bodies = read_specimen_csv((d / "spec" / "specimen.csv").string());
  EXPECT_EQ(j["bodies"].get<std::size_t>(), bodies.size());
  for (const SpecimenBody& b : bodies)
    if (b.kind == dem::BodyKind::rock) {
      EXPECT_GT(b.moments.maxCoeff() / b.moments.minCoeff(), 1.05) << "need anisotropic clumps";
      EXPECT_LT(std::abs(b.orientation.w()), 0.9999) << "need rotated clumps";
    }
  return bodies;
}

double relative(double a, double b) {
  return std::abs(a / b - 1);
}

}  // namespace

// ParaView's reader (python3-vtk9) reads the arrays, and glyphs of radius·2·0.5 span exactly the
// spheres' extent.
TEST(CliEngines, VtkReadsTheSpheresAndGlyphsThemToTheirTrueSize) {
  if (std::system("/usr/bin/python3 -c 'import vtkmodules' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-vtk9 not installed: run scripts/deps";
  const fs::path d = scratch();
  const std::vector<SpecimenBody> bodies = tiny_export(d, "vtk");
  const fs::path out = d / "vtk" / "out.txt";
  ASSERT_EQ(std::system(("cd " + (d / "vtk").string() + " && /usr/bin/python3 glyph_clumpkit.py >" +
                         out.string() + " 2>&1")
                            .c_str()),
            0)
      << slurp(out);
  std::size_t spheres = 0;
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const SpecimenBody& b : bodies)
    for (const Sphere& s : b.spheres) {
      ++spheres;
      lo = lo.cwiseMin(s.center - Vec3::Constant(s.radius));
      hi = hi.cwiseMax(s.center + Vec3::Constant(s.radius));
    }
  const std::string text = slurp(out);
  EXPECT_NE(text.find("points " + std::to_string(spheres) + " arrays radius body kind"),
            std::string::npos)
      << text;
  std::istringstream s(text.substr(text.find("bounds ") + 7));
  double b[6];
  for (double& v : b) s >> v;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b[2 * k], lo[k], 1e-12) << "axis " << k;
    EXPECT_NEAR(b[2 * k + 1], hi[k], 1e-12) << "axis " << k;
  }
  EXPECT_TRUE(fs::exists(d / "vtk" / "spheres.vtp"));
}

// Yade builds each clump from its spheres (its own centroid and axes); after 1,000 steps every
// clump still has our exact mass and principal moments, and Yade's centroid is within a bound.
TEST(CliEngines, YadeKeepsOurMassAndPrincipalMoments) {
  if (!have_program("yade")) GTEST_SKIP() << "Yade not installed: run scripts/deps";
  const fs::path d = scratch();
  const std::vector<SpecimenBody> bodies = tiny_export(d, "yade");
  const fs::path dir = d / "yade";
  ASSERT_EQ(
      std::system(
          ("cd " + dir.string() + " && yade -n -x run_clumpkit.py 1000 >out.txt 2>&1").c_str()),
      0)
      << slurp(dir / "out.txt");
  std::map<long, const SpecimenBody*> by_id;
  for (const SpecimenBody& b : bodies) by_id[b.id] = &b;
  for (const char* step : {"0", "1000"}) {
    const auto rows = number_table(dir / ("bodies." + std::string(step) + ".txt"));
    std::size_t rocks = 0;
    double worst = 0;
    for (const auto& row : rows) {
      const SpecimenBody& b = *by_id.at(static_cast<long>(row.at(0)));
      ASSERT_EQ(b.kind, dem::BodyKind::rock);
      std::vector<double> ours = {b.moments.x(), b.moments.y(), b.moments.z()};
      std::vector<double> theirs = {row.at(3), row.at(4), row.at(5)};
      std::sort(ours.begin(), ours.end());
      std::sort(theirs.begin(), theirs.end());
      worst = std::max(worst, relative(row.at(2), b.mass));
      for (int k = 0; k < 3; ++k) worst = std::max(worst, relative(theirs[k], ours[k]));
      ++rocks;
    }
    EXPECT_EQ(rocks, static_cast<std::size_t>(std::count_if(
                         bodies.begin(), bodies.end(),
                         [](const SpecimenBody& b) { return b.kind == dem::BodyKind::rock; })));
    EXPECT_LT(worst, 1e-9) << "step " << step;
  }
  // Yade's clump centroid comes from its grid (DISCRETIZATION 30), not from the exact union:
  // measured at most 1.0e-5 m here, 0.3 % of the smallest rock's equivalent radius.
  double worst_offset = 0, worst_share = 0;
  for (const auto& row : number_table(dir / "yade_residuals.txt")) {
    const SpecimenBody& b = *by_id.at(static_cast<long>(row.at(0)));
    const double equivalent_radius = std::cbrt(3 * b.volume / (4 * M_PI));
    worst_offset = std::max(worst_offset, row.at(2));
    worst_share = std::max(worst_share, row.at(2) / equivalent_radius);
  }
  std::cout << "Yade centroid residual: " << worst_offset << " m, " << worst_share
            << " of the equivalent radius\n";
  EXPECT_LT(worst_share, 0.01);
}

namespace {

/// The logical lines of a PFC data file (continuations '&' joined), without comments.
std::vector<std::vector<std::string>> pfc_commands(const fs::path& path) {
  std::ifstream in(path);
  std::string line, joined;
  std::vector<std::vector<std::string>> commands;
  while (std::getline(in, line)) {
    const std::size_t semicolon = line.find(';');
    if (semicolon != std::string::npos) line.erase(semicolon);
    joined += " " + line;
    const std::size_t last = joined.find_last_not_of(' ');
    if (last != std::string::npos && joined[last] == '&') {
      joined.erase(last);
      continue;
    }
    std::istringstream s(joined);
    std::vector<std::string> words;
    std::string w;
    while (s >> w) words.push_back(w);
    if (!words.empty()) commands.push_back(words);
    joined.clear();
  }
  return commands;
}

/// The value after `key` in a command, as a number.
double after(const std::vector<std::string>& c, const std::string& key, int offset = 1) {
  const auto it = std::find(c.begin(), c.end(), key);
  if (it == c.end() || it + offset >= c.end()) throw std::runtime_error("no " + key);
  return std::stod(*(it + offset));
}

}  // namespace

// PFC: no engine here. The data file is parsed back: each template's unit-density volume and
// inertia, each replicate's axis–angle against the quaternion, every pebble and ball.
TEST(CliEngines, PfcDataFileParsesBackToTheSpecimen) {
  const fs::path d = scratch();
  const std::vector<SpecimenBody> bodies = tiny_export(d, "pfc");
  const auto commands = pfc_commands(d / "pfc" / "clumpkit.p3dat");
  EXPECT_NE(slurp(d / "pfc" / "clumpkit.p3dat").find("syntax of PFC 7.0"), std::string::npos);
  struct Template {
    double volume;
    Vec3 inertia;
    std::vector<Sphere> pebbles;
  };
  std::map<std::string, Template> templates;
  std::size_t replicated = 0, balls = 0;
  double worst_pebble = 0, worst_rotation = 0;
  for (const auto& c : commands) {
    if (c.size() > 3 && c[0] == "clump" && c[1] == "template" && c[2] == "create") {
      Template t;
      const auto p = std::find(c.begin(), c.end(), "pebbles");
      ASSERT_NE(p, c.end());
      const int n = std::stoi(*(p + 1));
      for (int k = 0; k < n; ++k) {
        const auto at = p + 2 + 4 * k;
        t.pebbles.push_back(
            {Vec3(std::stod(at[1]), std::stod(at[2]), std::stod(at[3])), std::stod(at[0])});
      }
      t.volume = after(c, "volume");
      t.inertia = Vec3(after(c, "inertia"), after(c, "inertia", 2), after(c, "inertia", 3));
      for (int k = 4; k <= 6; ++k) EXPECT_EQ(after(c, "inertia", k), 0.0);
      EXPECT_EQ(after(c, "position"), 0.0);
      templates[c[4]] = t;
    } else if (c.size() > 3 && c[0] == "clump" && c[1] == "replicate") {
      const SpecimenBody& b = bodies.at(static_cast<std::size_t>(after(c, "id")) - 1);
      ASSERT_EQ(b.kind, dem::BodyKind::rock);
      const Template& t = templates.at(c[5]);
      // Unit density: volume and I/ρ; replicate's density gives back the mass and moments.
      const double density = after(c, "density");
      EXPECT_LT(relative(t.volume, b.volume), 1e-15);
      EXPECT_LT(relative(density * t.volume, b.mass), 1e-14);
      for (int k = 0; k < 3; ++k) EXPECT_LT(relative(density * t.inertia[k], b.moments[k]), 1e-14);
      const Vec3 position(after(c, "position"), after(c, "position", 2), after(c, "position", 3));
      const Vec3 axis(after(c, "axis"), after(c, "axis", 2), after(c, "axis", 3));
      const double angle = after(c, "angle") * M_PI / 180;
      EXPECT_LT(std::abs(axis.norm() - 1), 1e-14);
      const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, axis));
      worst_rotation = std::max(worst_rotation, q.angularDistance(b.orientation));
      ASSERT_EQ(t.pebbles.size(), b.spheres.size());
      for (std::size_t k = 0; k < b.spheres.size(); ++k) {
        worst_pebble = std::max(worst_pebble,
                                (q * t.pebbles[k].center + position - b.spheres[k].center).norm());
        EXPECT_EQ(t.pebbles[k].radius, b.spheres[k].radius);
      }
      ++replicated;
    } else if (c.size() > 3 && c[0] == "ball" && c[1] == "create") {
      const SpecimenBody& b = bodies.at(static_cast<std::size_t>(after(c, "id")) - 1);
      ASSERT_EQ(b.kind, dem::BodyKind::soil);
      EXPECT_EQ(Vec3(after(c, "position"), after(c, "position", 2), after(c, "position", 3)),
                b.spheres.front().center);
      EXPECT_EQ(after(c, "radius"), b.spheres.front().radius);
      ++balls;
    }
  }
  EXPECT_EQ(replicated + balls, bodies.size());
  EXPECT_GT(replicated, 20u);
  EXPECT_LT(worst_rotation, 1e-12);
  EXPECT_LT(worst_pebble, 1e-15);
}

namespace {

/// The last thermo row of a LIGGGHTS screen output whose header starts with "Step".
std::vector<double> last_thermo(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<double> last;
  bool in_table = false;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string first;
    s >> first;
    if (first == "Step") {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    std::vector<double> row;
    try {
      row.push_back(std::stod(first));
      double v;
      while (s >> v) row.push_back(v);
      last = row;
    } catch (const std::exception&) {
      in_table = first != "Loop";  // INFO lines of insertions sit inside the table
    }
  }
  return last;
}

}  // namespace

// LIGGGHTS: every template as the engine prints it (7 digits) has our mass and principal
// moments; a body of a template given v and ω has ke/multisphere = ½Mv² and erotate/multisphere
// = ½ω·Iω; after the insertion step every sphere of the pre-placed specimen is where we put it.
TEST(CliEngines, LiggghtsTakesOurTemplatesAndPlacesTheSpecimen) {
  if (!have_program("liggghts")) GTEST_SKIP() << "LIGGGHTS not installed: run scripts/deps";
  const fs::path d = scratch();
  const std::vector<SpecimenBody> bodies = tiny_export(d, "liggghts");
  const fs::path dir = d / "liggghts";
  ASSERT_EQ(
      std::system(("cd " + dir.string() + " && liggghts -in in.clumpkit >out.txt 2>&1").c_str()), 0)
      << slurp(dir / "out.txt");

  // Templates are numbered in the order of the first rock body of each (template, scale).
  std::vector<const SpecimenBody*> first_of_template;
  {
    std::map<std::pair<int, double>, bool> seen;
    for (const SpecimenBody& b : bodies)
      if (b.kind == dem::BodyKind::rock && !seen[{b.template_id, b.scale}]) {
        seen[{b.template_id, b.scale}] = true;
        first_of_template.push_back(&b);
      }
  }
  std::istringstream log(slurp(dir / "log.liggghts"));
  std::string line;
  std::size_t k = 0;
  double worst = 0;
  while (std::getline(log, line)) {
    if (line.find("   mass = ") == 0) {
      const double mass = std::stod(line.substr(10));
      worst = std::max(worst, relative(mass, first_of_template.at(k)->mass));
    } else if (line.find("Principal moments of inertia_:") != std::string::npos) {
      std::string rest = line.substr(line.find(':') + 1);
      std::replace(rest.begin(), rest.end(), ',', ' ');
      std::istringstream s(rest);
      std::vector<double> theirs(3);
      for (double& v : theirs) s >> v;
      const Vec3& m = first_of_template.at(k)->moments;
      std::vector<double> ours = {m.x(), m.y(), m.z()};
      std::sort(ours.begin(), ours.end());
      std::sort(theirs.begin(), theirs.end());
      for (int i = 0; i < 3; ++i) worst = std::max(worst, relative(theirs[i], ours[i]));
      ++k;
    }
  }
  EXPECT_EQ(k, first_of_template.size());
  EXPECT_LT(worst, 5e-7) << "LIGGGHTS prints 7 significant digits";

  // Every sphere after step 1 (soil atoms 1.., then each body's atoms, bodies_map.csv).
  std::map<long, std::vector<double>> atoms;
  for (const auto& row : dump_rows(dir / "atoms.1.txt")) atoms[static_cast<long>(row.at(0))] = row;
  std::map<long, long> first_atom;
  {
    std::ifstream map(dir / "bodies_map.csv");
    while (std::getline(map, line))
      if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream s(line);
        long body = 0, id = 0, first = 0;
        std::string kind;
        s >> body >> kind >> id >> first;
        first_atom[body] = first;
      }
  }
  double r_min = INFINITY, worst_position = 0;
  std::size_t spheres = 0;
  for (const SpecimenBody& b : bodies)
    for (std::size_t i = 0; i < b.spheres.size(); ++i) {
      const auto& a = atoms.at(first_atom.at(b.id) + static_cast<long>(i));
      worst_position =
          std::max(worst_position, (Vec3(a[2], a[3], a[4]) - b.spheres[i].center).norm());
      EXPECT_NEAR(a[5], b.spheres[i].radius, 1e-15);
      r_min = std::min(r_min, b.spheres[i].radius);
      ++spheres;
    }
  EXPECT_EQ(atoms.size(), spheres);
  EXPECT_LT(worst_position, 1e-6 * r_min);

  // One body of template 1 with v and ω (no gravity, no contacts, a tiny step): the engine's
  // kinetic energies are ours.
  const SpecimenBody& b = *first_of_template.front();
  const Vec3 v(0.3, -0.2, -1.0), w(30, -50, 100);
  write(
      dir / "in.check",
      "atom_style sphere\natom_modify map array\nboundary f f f\nnewton off\n"
      "communicate single vel yes\nunits si\nregion domain block -1 1 -1 1 -1 1 units box\n"
      "create_box 2 domain\nneighbor 0.001 bin\n"
      "fix m1 all property/global kn peratomtypepair 2 1e6 1e6 1e6 1e6\n"
      "fix m2 all property/global kt peratomtypepair 2 1e6 1e6 1e6 1e6\n"
      "fix m3 all property/global gamman peratomtypepair 2 0 0 0 0\n"
      "fix m4 all property/global gammat peratomtypepair 2 0 0 0 0\n"
      "fix m5 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\n"
      "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
      "timestep 1e-12\ninclude templates.liggghts\nfix ms all multisphere\n"
      "region p block -1e-12 1e-12 -1e-12 1e-12 -1e-12 1e-12 units box volume_limit 1e-300\n"
      "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 vel constant 0.3 -0.2 -1.0 "
      "omega constant 30 -50 100 insert_every once overlapcheck no all_in no orientation "
      "template region p particles_in_region 1\n"
      "compute ke all ke/multisphere\ncompute rke all erotate/multisphere\n"
      "thermo_style custom step atoms c_ke c_rke\nthermo_modify format float %.17g\n"
      "run 1\n");
  ASSERT_EQ(
      std::system(
          ("cd " + dir.string() + " && liggghts -in in.check -log none >check.txt 2>&1").c_str()),
      0)
      << slurp(dir / "check.txt");
  const std::vector<double> row = last_thermo(slurp(dir / "check.txt"));
  ASSERT_EQ(row.size(), 4u) << slurp(dir / "check.txt");
  const double ke = 0.5 * b.mass * v.squaredNorm();
  const double erotate = 0.5 * w.dot(b.moments.asDiagonal() * w);
  EXPECT_LT(relative(row[2], ke), 1e-8) << row[2] << " vs " << ke;
  EXPECT_LT(relative(row[3], erotate), 1e-8) << row[3] << " vs " << erotate;
}
