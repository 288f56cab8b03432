// `clumpkit crush` on the bundled quick recipe: the same bytes for one and two threads and after
// a killed run is resumed, damaged records redone, the report's keys and values consistent with
// the per-particle results. In the `quick` label (outside the sanitizer pass): three runs.
#include "../cli_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

const std::string kRecipe = std::string(CLUMPKIT_SOURCE_DIR) + "/assets/recipes/crush-quick.toml";

std::string run_dir(const fs::path& d, const std::string& name, int threads) {
  const Result r = run_cli("crush --quiet --threads " + std::to_string(threads) + " --recipe " +
                               kRecipe + " --out " + (d / name).string(),
                           d);
  EXPECT_EQ(r.rc, 0) << r.err;
  return (d / name).string();
}

}  // namespace

TEST(CliQuickCrush, SameBytesForAnyThreadCountAndAfterAResume) {
  const fs::path d = scratch();
  const fs::path one = run_dir(d, "one", 1), two = run_dir(d, "two", 2);
  for (const char* f : {"results.csv", "report.json", "particles/00000.csv", "particles/00005.json",
                        "particles/00003.cells.json"})
    EXPECT_EQ(slurp(one / f), slurp(two / f)) << f;
  // results.csv, report.json, manifest.json and each particle's curve, record and cells.
  EXPECT_GE(expect_units_everywhere(one), 3 + 3 * 6);

  // A run killed after four particles: its DIR.partial holds their records and no report. The
  // rerun keeps them, redoes a damaged one and ends with the same bytes.
  fs::rename(two, d / "three.partial");
  for (const char* f : {"results.csv", "report.json", "manifest.json", "particles/00004.json",
                        "particles/00005.json", "particles/00005.csv"})
    fs::remove(d / "three.partial" / f);
  std::string rec = slurp(d / "three.partial/particles/00002.json");
  rec[rec.find("\"steps\"") + 9] ^= 1;  // one changed digit: the checksum no longer matches
  write(d / "three.partial/particles/00002.json", rec);
  const Result r =
      run_cli("crush --quiet --json --recipe " + kRecipe + " --out " + (d / "three").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.err.find("00002.json was damaged"), std::string::npos) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["resumed"].get<int>(), 3);
  for (const char* f : {"results.csv", "report.json", "particles/00002.json"})
    EXPECT_EQ(slurp(one / f), slurp(d / "three" / f)) << f;
  EXPECT_FALSE(fs::exists(d / "three.partial"));
}

TEST(CliQuickCrush, ReportHoldsEachSetsWeibullFitAndTheSizeLaw) {
  const fs::path d = scratch();
  const fs::path out = run_dir(d, "r", 2);
  const nlohmann::json rep = nlohmann::json::parse(slurp(out / "report.json"));
  ASSERT_EQ(rep["sets"].size(), 2u);
  std::vector<double> d_set, s0;
  for (const auto& s : rep["sets"]) {
    SCOPED_TRACE(s["name"].get<std::string>());
    ASSERT_EQ(s["samples"].get<int>(), 3);
    ASSERT_EQ(s["failed"].get<int>(), 3);  // every particle breaks within 30 % of the gap
    ASSERT_EQ(s["survived"].get<int>(), 0);
    const double sigma0 = s["sigma0"].get<double>();
    // σ0 in Pa, inside its own bootstrap interval; strengths of the order of the bonds' 9 MPa.
    EXPECT_GE(sigma0, s["sigma0_ci90"][0].get<double>());
    EXPECT_LE(sigma0, s["sigma0_ci90"][1].get<double>());
    EXPECT_GT(sigma0, 1e5);
    EXPECT_LT(sigma0, 1e8);
    EXPECT_GT(s["weibull_modulus"].get<double>(), 0.0);
    EXPECT_NEAR(s["diameter"].get<double>(), s["name"] == "d16" ? 0.016 : 0.020, 1e-9);
    d_set.push_back(s["diameter"].get<double>());
    s0.push_back(sigma0);
  }
  // Two sizes: the size law passes through both σ0 exactly.
  const double k = rep["size_coefficient"].get<double>(), a = rep["size_exponent"].get<double>();
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(k * std::pow(d_set[i], -a) / s0[i], 1.0, 1e-9);
  // The mean strength of a set is the mean of its rows in results.csv (σ = Fp/D²).
  std::istringstream csv(slurp(out / "results.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("id[1],set,sample[1],diameter[m],", 0), 0u);
  double sum = 0;
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> c;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) c.push_back(x);
    ASSERT_EQ(c.size(), 16u);
    const double dm = std::stod(c[3]), fp = std::stod(c[8]), st = std::stod(c[10]);
    EXPECT_NEAR(st, fp / (dm * dm), 1e-9 * st);
    // max_force: the largest force of the particle's curve (a survivor's censoring stress × D²).
    std::istringstream curve(
        slurp(out / "particles" / (std::string(5 - c[0].size(), '0') + c[0] + ".csv")));
    double largest = 0;
    std::getline(curve, line);
    for (std::string row; std::getline(curve, row);)
      largest = std::max(largest, std::stod(row.substr(row.find(',') + 1)));
    EXPECT_EQ(std::stod(c[15]), largest);
    EXPECT_GE(largest, fp);
    if (c[1] == "d16") sum += st, ++rows;
  }
  EXPECT_EQ(rows, 3);
  EXPECT_NEAR(rep["sets"][0]["mean_strength"].get<double>(), sum / 3, 1e-9 * sum);
  for (const char* f : {"weibull.png", "size.png", "curves_d16.png", "curves_d20.png",
                        "manifest.json", "recipe.toml", "particles/00000.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  // The cells before and after (the page draws them): one entry per cell, each moved rigidly
  // (a unit rotation), labelled by its fragment at the end as the record counts them.
  for (int k = 0; k < 6; ++k) {
    const std::string stem = "particles/0000" + std::to_string(k);
    const nlohmann::json rec = nlohmann::json::parse(slurp(out / (stem + ".json")));
    const nlohmann::json cells =
        nlohmann::json::parse(slurp(out / (stem + ".cells.json")))["cells"];
    ASSERT_EQ(cells.size(), rec["cells"].get<std::size_t>()) << stem;
    int fragments = 0;
    for (const auto& c : cells) {
      fragments = std::max(fragments, c["fragment"].get<int>());
      const auto& q = c["q"];
      EXPECT_NEAR(std::hypot(std::hypot(q[0].get<double>(), q[1].get<double>()),
                             std::hypot(q[2].get<double>(), q[3].get<double>())),
                  1.0, 1e-12);
      EXPECT_EQ(c["v"].size() % 3, 0u);
      EXPECT_GE(c["f"].size(), 4u);  // a convex cell has four faces at least
    }
    EXPECT_EQ(fragments, rec["fragments"].get<int>()) << stem;
  }
}
