// CTGU 2017's Table 1 at CI size (issue 16 acceptance 3, its CI variant): 10 and 20 mm spheres
// in cubes of 12 diameters (~2,000 spheres; 8 gave porosity 0.42 with loose wall layers), the
// bundled recipes with their lengths and rates scaled, #2 prepared to #1's tested porosity as
// in the bench; in the `quick` label, outside the sanitizer pass. The full table (10/30/60 mm,
// 16 diameters) is tests/bench/table1.sh.
#include "../cli_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <regex>
#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

const fs::path kRecipes = fs::path(CLUMPKIT_SOURCE_DIR) / "assets" / "recipes";
constexpr double kSide = 12.0;  // cube edge in diameters: ~50 s for the whole test on 2 cores

std::string replace_line(const std::string& text, const std::string& key,
                         const std::string& value) {
  const std::regex line("^" + key + " = .*$", std::regex::multiline);
  EXPECT_TRUE(std::regex_search(text, line)) << key;
  return std::regex_replace(text, line, key + " = " + value);
}

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

// The bundled Table 1 specimen with diameter d (m) and seed, prepared at `porosity` (< 0: the
// recipe's).
void make_specimen(const fs::path& dir, const std::string& name, double d, int seed,
                   double porosity = -1) {
  std::string t = slurp(kRecipes / "elastic-scaling-specimen.toml");
  t = replace_line(t, "seed", std::to_string(seed));
  if (porosity > 0) t = replace_line(t, "porosity", num(porosity));
  const std::string side = num(kSide * d);
  t = replace_line(t, "size", "[" + side + ", " + side + ", " + side + "]");
  t = replace_line(t, "sieves", "[" + num(1.01 * d) + ", " + num(0.99 * d) + "]");
  write(dir / (name + ".toml"), t);
  const Result r =
      run_cli("specimen --quiet --threads 2 --recipe " + (dir / (name + ".toml")).string() +
                  " --out " + (dir / name).string(),
              dir);
  ASSERT_EQ(r.rc, 0) << r.err;
}

// The bundled Table 1 test of `specimen` under `law`, its rates divided by λ (same inertial
// number at every size); returns report.json.
nlohmann::json run_case(const fs::path& dir, const std::string& name, const std::string& specimen,
                        const std::string& law, double lambda) {
  std::string t = slurp(kRecipes / "elastic-scaling-table1.toml");
  t = replace_line(t, "stiffness_scaling", "\"" + law + "\"");
  t = replace_line(t, "strain_rate", num(0.1 / lambda));
  t = replace_line(t, "servo_strain_rate", num(2.7 / lambda));
  write(dir / (name + ".toml"), t);
  const Result r = run_cli(
      "test triaxial --quiet --threads 2 --specimen " + (dir / specimen).string() + " --recipe " +
          (dir / (name + ".toml")).string() + " --out " + (dir / name).string(),
      dir);
  EXPECT_EQ(r.rc, 0) << r.err;
  return nlohmann::json::parse(slurp(dir / name / "report.json"));
}

// CTGU 2017's specimens have the same void ratio when tested: a specimen of diameter d under
// `law` prepared at the porosity (secant search, as tests/bench/table1.sh) whose tested porosity
// is `target` within 3e-4; returns its report.json.
nlohmann::json matched_case(const fs::path& dir, const std::string& name, double d, int seed,
                            const std::string& law, double lambda, double target) {
  // The search starts where it ended when last measured (#2, seed 2, 12 diameters: prepared at
  // 0.4053 for #1's 0.4021), so it takes one or two tries instead of four (a try is a specimen,
  // 16 s); the secant still decides, and the tolerance is unchanged.
  double prepared = 0.405, slope = 0.8, last_prepared = 0, last_tested = 0;
  for (int attempt = 1;; ++attempt) {
    const std::string specimen = "s" + name;
    fs::remove_all(dir / specimen);
    fs::remove_all(dir / name);
    make_specimen(dir, specimen, d, seed, prepared);
    const nlohmann::json rep = run_case(dir, name, specimen, law, lambda);
    const double tested = rep["porosity"].get<double>();
    if (std::abs(tested - target) <= 3e-4 || attempt == 4) {
      EXPECT_NEAR(tested, target, 3e-4) << name << " prepared at " << prepared;
      return rep;
    }
    if (attempt > 1 && prepared != last_prepared) {
      const double s = (tested - last_tested) / (prepared - last_prepared);
      if (s > 0.2 && s < 2) slope = s;
    }
    last_prepared = prepared, last_tested = tested;
    prepared += (target - tested) / slope;
  }
}

}  // namespace

TEST(CliQuickTable1, ConstantStiffnessHalvesTheModulusAtTwiceTheSizeAndScaledStiffnessKeepsIt) {
  const fs::path d = scratch();
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_NO_FATAL_FAILURE(make_specimen(d, "s10", 0.010, 1));
  const Result scaled = run_cli(
      "specimen-scale " + (d / "s10").string() + " --factor 2 --out " + (d / "s10x2").string(), d);
  ASSERT_EQ(scaled.rc, 0) << scaled.err;
  const auto e1 = run_case(d, "t1", "s10", "none", 1);
  const auto e1l = run_case(d, "t1l", "s10", "linear", 1);
  const auto e2 = matched_case(d, "t2", 0.020, 2, "none", 2, e1["porosity"].get<double>());
  // Under kn ∝ d the consolidation compacts every size alike, so #4 is the recipe's preparation
  // (at 16 diameters the bench's search never needs a second try for it; at 12 its tested
  // porosity scatters by a few 1e-4, and a re-prepared packing is another realisation).
  ASSERT_NO_FATAL_FAILURE(make_specimen(d, "s20", 0.020, 2));
  const auto e4 = run_case(d, "t4", "s20", "linear", 2);
  const auto e6 = run_case(d, "t6", "s10x2", "linear", 2);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto young = [](const nlohmann::json& r) { return r["young_modulus"].get<double>(); };
  std::printf(
      "bodies %d / %d, porosity %.4f / %.4f; E1 %.4g (linear %.4g), E2/E1 %.4f, E4/E1 %.4f, "
      "E6/E1 %.6f; %.1f s\n",
      e1["bodies"].get<int>(), e2["bodies"].get<int>(), e1["porosity"].get<double>(),
      e2["porosity"].get<double>(), young(e1), young(e1l), young(e2) / young(e1),
      young(e4) / young(e1l), young(e6) / young(e1l), seconds);
  for (const auto* r : {&e1, &e1l, &e2, &e4, &e6}) {
    EXPECT_TRUE((*r)["consolidated"].get<bool>());
    EXPECT_GT(young(*r), 0.0);
  }
  // At a fixed fabric the modulus goes as kn/d (affine estimate), so constant kn at twice the size
  // gives at least half the modulus; the packing is not a fixed fabric, though: at 5 MPa its
  // contacts are relatively twice as soft (κ = kn/(p·d) 800 against 1,600), so at the same
  // tested porosity it holds more contacts (and, prepared alike, it would be tested denser: 0.71
  // there). Measured 0.67-0.71 (seeds 1/2; the packing the search lands on) in these 12-diameter
  // cubes; in the bench's 16-diameter ones, mean of 7 replicates, 1.10 × 1/3 at 30 mm and 1.11 ×
  // 1/6 at 60 mm (tests/bench/RESULTS.md). Bounds: softer than #1 by 15 %, not softer than fixed
  // fabric.
  EXPECT_GT(young(e2) / young(e1), 0.5);
  EXPECT_LT(young(e2) / young(e1), 0.85);
  // kn ∝ d: the same modulus from an independent packing, within the scatter of one realisation
  // of these 12-diameter cubes. Measured: the same recipe and seed gave E1 (linear) 8.88e8 and
  // 7.97e8 Pa under two summation orders of the contact sums (rounding alone), and E4/E1 1.06 and
  // 1.34; Table 1's 7 % is the bench's claim (mean of 7 replicates at 16 diameters,
  // tests/bench/RESULTS.md). The band still fails a law off by a factor of two ...
  EXPECT_NEAR(young(e4) / young(e1l), 1.0, 0.4);
  // ... and exactly the same from #1's fabric scaled by two (a power of two: every length,
  // stiffness and time is exact, so the test repeats bit for bit).
  EXPECT_EQ(young(e6), young(e1l));
  EXPECT_EQ(e6["peak_deviator_stress"], e1l["peak_deviator_stress"]);
}
