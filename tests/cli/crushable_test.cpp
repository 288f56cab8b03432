// A crushable specimen through the CLI: bonded cells written beside specimen.csv, an oedometer
// that breaks them with the breakage columns, the grading and the volume conserved, the same
// bytes for one and two threads, and bad crushable recipes refused with one line.
#include "cli_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace cli_test;

namespace {

// The Int32 point array `name` of a VTK XML PolyData file written in ascii.
std::vector<int> vtp_int_array(const fs::path& path, const std::string& name) {
  const std::string text = slurp(path);
  const std::size_t at = text.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const std::size_t from = text.find('>', at) + 1, to = text.find("</DataArray>", from);
  std::istringstream in(text.substr(from, to - from));
  std::vector<int> v;
  for (int x; in >> x;) v.push_back(x);
  return v;
}

// About 30 particles of 14–18 mm, 8 mm cells of four spheres, in a 55 mm cylinder at n = 0.45;
// `scale` sets the bonds' strength (0.15: weak enough that a 2 MPa oedometer breaks them).
std::string crushable_recipe(const std::string& scale, const std::string& extra = "") {
  return R"(seed = 4
soil_rock_threshold = 0.001
rock_mass_fraction = 1.0
[container]
diameter = 0.055
height = 0.055
[preparation]
method = "compression"
porosity = 0.45
[gradation]
sieves = [0.018, 0.014]
passing = [100, 0]
[density]
rock = 2650
[contact]
kn = 1e6
ks = 1e6
friction = 0.5
local_damping = 0.7
[rock]
crushable = true
spheres_per_cell = 4
cell_voxels = 12
[cells]
cell_size = 0.008
lloyd = 1
[bond]
scale = )" +
         scale + "\n" + extra;
}

constexpr const char* kOedometer =
    "[test]\nconfining = 50e3\nfinal_stress = 2e6\nstrain_rate = 0.5\nrecord_every = "
    "200\ndensity_scaling = 1000\n";

}  // namespace

TEST(CliCrushable, OedometerBreaksTheCellsConservingVolumeSameBytesForAnyThreadsAndResume) {
  const fs::path d = scratch();
  write(d / "weak.toml", crushable_recipe("0.15"));
  Result r = run_cli(
      "specimen --quiet --recipe " + (d / "weak.toml").string() + " --out " + (d / "spec").string(),
      d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto spec = nlohmann::json::parse(slurp(d / "spec" / "report.json"));
  ASSERT_TRUE(fs::exists(d / "spec" / "bonds.csv"));
  EXPECT_GE(spec["crushable"]["particles"].get<int>(), 20);
  EXPECT_GT(spec["crushable"]["bonds"].get<int>(), spec["crushable"]["cells"].get<int>());
  write(d / "oed.toml", kOedometer);
  const std::string base = "test oedometer --quiet --allow-dynamic --specimen " +
                           (d / "spec").string() + " --recipe " + (d / "oed.toml").string();
  const double whole =
      timed([&] { r = run_cli(base + " --threads 1 --out " + (d / "one").string(), d); });
  ASSERT_EQ(r.rc, 0) << r.err;
  // Run on two threads, stopped by SIGTERM at a random time (its bonds' damage saved with the
  // checkpoint) and resumed: the same bytes as the one-thread run never stopped, which checks
  // the thread count and the resume in one run (a separate two-thread run checked nothing more).
  const std::string stopped = base + " --threads 2 --out " + (d / "stopped").string();
  const double when = random_seconds(0.3 * whole, 0.8 * whole);
  const int rc = run_cli_stopped_after(stopped, d, when);
  std::printf("crushable oedometer of %.1f s stopped after %.2f s: exit %d\n", whole, when, rc);
  EXPECT_TRUE(rc == 130 || rc == 0 || rc == 143) << slurp(d / "stopped.err");
  r = run_cli(stopped + " --resume", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(slurp(d / "one" / "curve.csv"), slurp(d / "stopped" / "curve.csv"));
  EXPECT_EQ(slurp(d / "one" / "grading.csv"), slurp(d / "stopped" / "grading.csv"));
  const auto rep = nlohmann::json::parse(slurp(d / "one" / "report.json"));
  // The specimen's bodies and bonds, report and manifest; the test's curve (with breakage),
  // grading, report and manifest.
  EXPECT_EQ(expect_units_everywhere(d / "spec"), 4);
  EXPECT_GE(expect_units_everywhere(d / "one"), 4);
  const auto& b = rep["breakage"];
  // Broken: bonds failed, particles split into more fragments, the grading moved finer.
  EXPECT_GT(b["bonds_broken"].get<double>(), 0);
  EXPECT_GT(b["particles_broken"].get<double>(), 0);
  EXPECT_GT(b["fragments"].get<double>(), b["particles"].get<double>());
  EXPECT_GT(b["hardin_br"].get<double>(), 0);
  EXPECT_LT(b["hardin_br"].get<double>(), 1);
  EXPECT_GT(b["einav_b"].get<double>(), 0);
  EXPECT_GT(b["marsal_bg"].get<double>(), 0);
  EXPECT_GT(b["work"].get<double>(), 0);
  // Conservation: the fragments hold the particles' solid volume.
  EXPECT_NEAR(b["solid_volume_final"].get<double>() / b["solid_volume_initial"].get<double>(), 1,
              1e-12);
  const auto& modes = b["bonds_broken_by_mode"];
  EXPECT_EQ(
      modes["mode_i"].get<double>() + modes["mode_ii"].get<double>() + modes["mixed"].get<double>(),
      b["bonds_broken"].get<double>());
  std::string header;
  const std::vector<std::vector<double>> rows = csv_rows(d / "one" / "curve.csv", 25, &header);
  ASSERT_GT(rows.size(), 3u);
  EXPECT_NE(header.find(",bonds_broken[1],bonds_mode_i[1],bonds_mode_ii[1],bonds_mixed[1],"
                        "fragments[1],"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find(",work[J/m3],broken_class_1[1],"), std::string::npos) << header;
  EXPECT_EQ(rows[0][16], 0);  // no particle broken at the consolidated state
  EXPECT_EQ(rows[0][20], 0);  // nor any work done
  for (const auto& row : rows) {
    EXPECT_EQ(row[12] + row[13] + row[14], row[11]);  // every broken bond in one mode
    // The broken fraction of each size class: a fraction.
    for (int c = 21; c < 25; ++c) {
      EXPECT_GE(row[c], 0.0);
      EXPECT_LE(row[c], 1.0);
    }
  }
  for (const char* f : {"grading.png", "breakage.png", "breakage_work.png", "fragments.vtp"})
    EXPECT_TRUE(fs::exists(d / "one" / f)) << f;
  // fragments.vtp: every sphere labelled by its particle and its fragment, numbered from 1 up to
  // the report's counts.
  const std::vector<int> particle = vtp_int_array(d / "one" / "fragments.vtp", "particle"),
                         fragment = vtp_int_array(d / "one" / "fragments.vtp", "fragment");
  ASSERT_EQ(particle.size(), fragment.size());
  ASSERT_FALSE(particle.empty());
  EXPECT_EQ(*std::min_element(fragment.begin(), fragment.end()), 1);
  EXPECT_EQ(*std::max_element(fragment.begin(), fragment.end()), b["fragments"].get<double>());
  EXPECT_EQ(*std::max_element(particle.begin(), particle.end()), b["particles"].get<double>());
  EXPECT_EQ(slurp(d / "one" / "fragments.vtp"), slurp(d / "stopped" / "fragments.vtp"));
}

TEST(CliCrushable, TheUnbreakableControlKeepsItsGrading) {
  // The weak specimen's control (the same particles, cells and bonds, which cannot fail) under
  // the same oedometer: no bond fails, no index moves, and the grading after is the grading
  // before (every fragment sized from its cells as built).
  const fs::path d = scratch();
  std::string recipe = crushable_recipe("0.15");
  recipe.replace(recipe.find("crushable = true"), 16, "crushable = true\nunbreakable = true");
  write(d / "control.toml", recipe);
  Result r = run_cli("specimen --quiet --recipe " + (d / "control.toml").string() + " --out " +
                         (d / "spec").string(),
                     d);
  ASSERT_EQ(r.rc, 0) << r.err;
  write(d / "oed.toml", kOedometer);
  r = run_cli("test oedometer --quiet --allow-dynamic --specimen " + (d / "spec").string() +
                  " --recipe " + (d / "oed.toml").string() + " --out " + (d / "oed").string(),
              d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto b = nlohmann::json::parse(slurp(d / "oed" / "report.json"))["breakage"];
  EXPECT_EQ(b["bonds_broken"].get<double>(), 0);
  EXPECT_EQ(b["hardin_br"].get<double>(), 0);
  EXPECT_EQ(b["einav_b"].get<double>(), 0);
  EXPECT_EQ(b["marsal_bg"].get<double>(), 0);
  for (const auto& row : csv_rows(d / "oed" / "grading.csv", 3)) EXPECT_EQ(row[1], row[2]);
}

TEST(CliCrushable, BadCrushableRecipesAreRefusedWithOneLine) {
  const fs::path d = scratch();
  struct Case {
    std::string recipe, needle;
  };
  const std::vector<Case> cases = {
      {crushable_recipe("0"), "bond.scale"},
      {crushable_recipe("1.85", "[zz]\n"), "zz: unknown key"},
      {[] {
         std::string s = crushable_recipe("1.85");
         return s.replace(s.find("cell_size = 0.008"), 17, "cell_size = 0.030");
       }(),
       "cells.cell_size"},
      {[] {
         std::string s = crushable_recipe("1.85");
         return s.replace(s.find("method = \"compression\""), 22, "method = \"deposition\"");
       }(),
       "rock.crushable"},
  };
  for (const Case& c : cases) {
    write(d / "bad.toml", c.recipe);
    SCOPED_TRACE(c.needle);
    expect_one_line_error(run_cli("specimen --quiet --recipe " + (d / "bad.toml").string() +
                                      " --out " + (d / "out").string(),
                                  d),
                          c.needle);
    EXPECT_FALSE(fs::exists(d / "out"));
    EXPECT_FALSE(fs::exists(d / "out.partial"));
  }
}
