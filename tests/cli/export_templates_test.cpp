// `clumpkit export` of a clump library or one clump CSV: exact masses from --density and the
// union of the spheres, units, Jin et al. 2017's mass equivalence, LAMMPS molecule templates.
#include "cli_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

// The tiny rock library (6 block particles of 8 spheres, well under a second) in `d`/lib.
void build_tiny_library(const fs::path& d) {
  write(d / "rocks.toml", kTinyRocks);
  const Result r = run_cli(
      "library --quiet --recipe " + (d / "rocks.toml").string() + " --out " + (d / "lib").string(),
      d);
  ASSERT_EQ(r.rc, 0) << r.err;
}

// library.csv as rows of cells named by column (units dropped: "volume[m3]" is "volume").
std::vector<std::map<std::string, std::string>> csv_records(const fs::path& path) {
  std::istringstream in(slurp(path));
  std::string line;
  std::vector<std::string> head;
  std::vector<std::map<std::string, std::string>> rows;
  auto cells = [](const std::string& l) {
    std::vector<std::string> out;
    std::stringstream s(l);
    std::string c;
    while (std::getline(s, c, ',')) out.push_back(c);
    return out;
  };
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (head.empty()) {
      head = cells(line);
      continue;
    }
    const std::vector<std::string> c = cells(line);
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < head.size() && k < c.size(); ++k)
      row[clumpkit::column_name(head[k])] = c[k];
    rows.push_back(row);
  }
  return rows;
}

// The body rows of bodies.infile (id mass xcm ycm zcm ixx iyy izz ixy ixz iyz ...), after its
// count line.
std::vector<std::vector<double>> infile_rows(const fs::path& path) {
  std::vector<std::vector<double>> rows = number_table(path);
  if (!rows.empty()) rows.erase(rows.begin());
  return rows;
}

double rel(double a, double b) {
  return std::abs(a / b - 1);
}

}  // namespace

// A clump CSV: mass = density × the exact union volume, against the lens formula for two
// overlapping spheres, V = 2·(4/3)πr³ − π(4r + d)(2r − d)²/12; a sphere's moments 2/5·M·r²;
// --length-unit mm scales V by 1e-9 and I by 1e-15 against the same numbers read as metres.
TEST(CliExportTemplates, ClumpCsvMassIsDensityTimesTheExactUnion) {
  const fs::path d = scratch();
  write(d / "two.csv", "x,y,z,r\n-0.5,0,0,1\n0.5,0,0,1\n");
  write(d / "one.csv", "x,y,z,r\n3,-2,7,1.5\n");
  const double rho = 2650;
  Result r = run_cli("export lammps " + (d / "two.csv").string() + " --out " +
                         (d / "two").string() + " --density 2650 --length-unit mm",
                     d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto two = infile_rows(d / "two" / "bodies.infile");
  ASSERT_EQ(two.size(), 1u);
  const double v_two = 2 * 4.0 / 3.0 * M_PI - M_PI * 5.0 * 1.0 / 12.0;  // mm³, r = 1, d = 1
  EXPECT_LT(rel(two[0][1], rho * v_two * 1e-9), 1e-9) << two[0][1];

  for (const char* unit : {"m", "mm"}) {
    r = run_cli("export lammps " + (d / "one.csv").string() + " --out " +
                    (d / (std::string("one_") + unit)).string() + " --density 2650 --length-unit " +
                    unit,
                d);
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  const auto m = infile_rows(d / "one_m" / "bodies.infile");
  const auto mm = infile_rows(d / "one_mm" / "bodies.infile");
  ASSERT_EQ(m.size(), 1u);
  ASSERT_EQ(mm.size(), 1u);
  const double mass = rho * 4.0 / 3.0 * M_PI * std::pow(1.5, 3);
  EXPECT_LT(rel(m[0][1], mass), 1e-9);
  for (int k = 5; k < 8; ++k) EXPECT_LT(rel(m[0][k], 0.4 * mass * 1.5 * 1.5), 1e-9) << k;
  for (int k = 8; k < 11; ++k) EXPECT_LT(std::abs(m[0][k]), 1e-9 * m[0][5]) << k;
  EXPECT_LT(rel(mm[0][1], 1e-9 * m[0][1]), 1e-12);
  for (int k = 5; k < 8; ++k) EXPECT_LT(rel(mm[0][k], 1e-15 * m[0][k]), 1e-12) << k;
}

// A library: every body's mass and moments are density × the library's exact clump volume and
// unit-density moments; --mass mesh makes the mass density × V_mesh (Jin et al. 2017 §2.2), for
// the library and for one of its template CSVs (its mesh lies beside it).
TEST(CliExportTemplates, LibraryAndTemplateMassesAndMeshEquivalence) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_library(d));
  const auto lib = csv_records(d / "lib" / "library.csv");
  ASSERT_EQ(lib.size(), 6u);
  const double rho = 2650;
  for (const char* mass : {"clump", "mesh"}) {
    const fs::path out = d / (std::string("lib_") + mass);
    const Result r = run_cli("export lammps " + (d / "lib").string() + " --out " + out.string() +
                                 " --density 2650 --mass " + mass,
                             d);
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto rows = infile_rows(out / "bodies.infile");
    ASSERT_EQ(rows.size(), lib.size());
    for (std::size_t i = 0; i < lib.size(); ++i) {
      const double v =
          std::stod(lib[i].at(std::string(mass) == "mesh" ? "volume" : "clump_volume"));
      const double factor = v / std::stod(lib[i].at("clump_volume"));
      EXPECT_LT(rel(rows[i][1], rho * v), 1e-9) << mass << " body " << i;
      // Unrotated bodies: the box-frame tensor is diag(I1, I2, I3).
      for (int a = 0; a < 3; ++a)
        EXPECT_LT(
            rel(rows[i][5 + a], rho * factor * std::stod(lib[i].at("I" + std::to_string(a + 1)))),
            1e-9)
            << mass << " body " << i << " axis " << a;
    }
  }
  // One template CSV of the library with --mass mesh: its mesh 00002.stl lies beside it.
  const Result r =
      run_cli("export lammps " + (d / "lib" / "particles" / "00002.template.csv").string() +
                  " --out " + (d / "tpl").string() + " --density 2650 --mass mesh",
              d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto tpl = infile_rows(d / "tpl" / "bodies.infile");
  ASSERT_EQ(tpl.size(), 1u);
  // The mesh read back from STL has single-precision vertices: 1e-6, not 1e-9.
  EXPECT_LT(rel(tpl[0][1], rho * std::stod(lib[2].at("volume"))), 1e-6);
}

// LAMMPS molecule templates of a library (fix deposit ... mol): every deposited body, two of
// each template, has our mass and sorted principal moments to 1e-9, on 1 and 2 ranks; the
// atoms' types name the templates (molecules.csv).
TEST(CliExportTemplates, LammpsMoleculeTemplatesDepositWithOurMassProperties) {
  if (!have_program("lmp")) GTEST_SKIP() << "LAMMPS (lmp) not installed: run scripts/deps";
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_library(d));
  const Result r = run_cli(
      "export lammps " + (d / "lib").string() + " --out " + (d / "ex").string() + " --density 2650",
      d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto lib = csv_records(d / "lib" / "library.csv");
  const auto types = csv_records(d / "ex" / "molecules.csv");
  ASSERT_EQ(types.size(), lib.size());
  std::vector<std::string> commands = {"lmp"};
  if (have_program("mpirun")) commands.push_back("mpirun --allow-run-as-root -np 2 lmp");
  std::vector<std::vector<double>> first;
  for (std::size_t c = 0; c < commands.size(); ++c) {
    const fs::path run = d / ("run" + std::to_string(c));
    fs::copy(d / "ex", run, fs::copy_options::recursive);
    const std::string cmd = "cd " + run.string() + " && " + commands[c] +
                            " -in in.deposit -var count 2 -var nsteps 300 -log none >out.txt 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(run / "out.txt");
    const auto bodies = dump_rows(run / "deposit_bodies.300.txt");
    const auto atoms = dump_rows(run / "deposit_atoms.300.txt");  // id mol type x y z radius
    ASSERT_EQ(bodies.size(), 2 * lib.size()) << slurp(run / "out.txt");
    std::map<long, int> type_of_mol;
    for (const auto& a : atoms) type_of_mol[static_cast<long>(a.at(1))] = static_cast<int>(a.at(2));
    std::map<int, int> deposited;
    for (const auto& b : bodies) {
      const int type = type_of_mol.at(static_cast<long>(b.at(1)));
      ++deposited[type];
      const auto& t = types.at(type - 1);
      const auto& row = lib.at(std::stoul(t.at("template")));
      const double rho = 2650;
      EXPECT_LT(rel(b.at(2), rho * std::stod(row.at("clump_volume"))), 1e-9) << "type " << type;
      std::vector<double> ours = {std::stod(row.at("I1")), std::stod(row.at("I2")),
                                  std::stod(row.at("I3"))};
      std::vector<double> theirs = {b.at(6), b.at(7), b.at(8)};
      std::sort(ours.begin(), ours.end());
      std::sort(theirs.begin(), theirs.end());
      for (int k = 0; k < 3; ++k) EXPECT_LT(rel(theirs[k], rho * ours[k]), 1e-9) << "type " << type;
    }
    for (std::size_t k = 1; k <= lib.size(); ++k) EXPECT_EQ(deposited[static_cast<int>(k)], 2) << k;
    if (c == 0)
      first = bodies;
    else
      EXPECT_EQ(bodies, first) << "1 and 2 ranks deposit differently";
  }
}

// Bad template sources: one line, exit 2, nothing at --out.
TEST(CliExportTemplates, BadInputFailsWithOneLineAndWritesNothing) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_library(d));
  write(d / "two.csv", "x,y,z,r\n-0.5,0,0,1\n0.5,0,0,1\n");
  write(d / "nan.csv", "x,y,z,r\n-0.5,0,nan,1\n");
  const std::string out = " --out " + (d / "o").string();
  expect_one_line_error(run_cli("export lammps " + (d / "two.csv").string() + out, d),
                        "needs --density");
  expect_one_line_error(run_cli("export lammps " + (d / "lib").string() + out, d),
                        "needs --density");
  expect_one_line_error(
      run_cli("export yade " + (d / "nan.csv").string() + out + " --density 2650", d), "nan.csv");
  expect_one_line_error(
      run_cli("export lammps " + (d / "two.csv").string() + out + " --density -3", d),
      "--density must be a positive");
  expect_one_line_error(run_cli("export lammps " + (d / "two.csv").string() + out +
                                    " --density 2650 --length-unit ft",
                                d),
                        "--length-unit must be m or mm, got 'ft'");
  expect_one_line_error(
      run_cli("export lammps " + (d / "two.csv").string() + out + " --density 2650 --mass mesh", d),
      "no two.stl");
  expect_one_line_error(
      run_cli("export lammps " + (d / "two.csv").string() + out + " --density 2650 --tile 2x2", d),
      "--tile copies a specimen");
  // A template whose sphere file is gone: the file is named.
  fs::remove(d / "lib" / "particles" / "00003.template.csv");
  expect_one_line_error(run_cli("export pfc " + (d / "lib").string() + out + " --density 2650", d),
                        "00003.template.csv");
  EXPECT_FALSE(fs::exists(d / "o"));
  EXPECT_FALSE(fs::exists(d / "o.partial"));
}
