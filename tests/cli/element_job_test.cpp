// `clumpkit test` on the tiny specimen (issue 16): a triaxial curve with a peak, the same bytes
// for 1 and 2 threads; isotropic and oedometer moduli; bad input refused cleanly.
#include "cli_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

// Loading fast enough for a test, slow enough to stay quasi-static (inertial number < 1e-3).
const char* kTriaxial = R"([test]
confining = 100e3
strain_rate = 0.5
max_axial_strain = 0.02
record_every = 400
)";

const char* kIsotropic = R"([test]
confining = 100e3
final_stress = 300e3
strain_rate = 0.5
stress_rate = 3e6
record_every = 400
)";

// The numeric rows of curve.csv (its header skipped), each with its 11 columns.
std::vector<std::vector<double>> curve_rows(const fs::path& path) {
  return csv_rows(path, 11);
}

}  // namespace

TEST(CliElementTest, TriaxialHasAPeakAndTheSameBytesForOneAndTwoThreads) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  write(d / "tri.toml", kTriaxial);
  const std::string base = "test triaxial --quiet --specimen " + (d / "spec").string() +
                           " --recipe " + (d / "tri.toml").string();
  const Result one = run_cli(base + " --threads 1 --out " + (d / "t1").string(), d);
  ASSERT_EQ(one.rc, 0) << one.err;
  const Result two = run_cli(base + " --threads 2 --json --out " + (d / "t2").string(), d);
  ASSERT_EQ(two.rc, 0) << two.err;
  for (const char* f : {"curve.csv", "report.json"})
    EXPECT_EQ(slurp(d / "t1" / f), slurp(d / "t2" / f)) << f << " differs between thread counts";
  EXPECT_GT(fs::file_size(d / "t1" / "curve.png"), 5000u);
  const auto rep = nlohmann::json::parse(two.out);
  EXPECT_EQ(rep, nlohmann::json::parse(slurp(d / "t1" / "report.json")));
  EXPECT_TRUE(rep["consolidated"].get<bool>());
  EXPECT_LT(rep["inertial_number"].get<double>(), 1e-3);
  EXPECT_GE(expect_units_everywhere(d / "t1"), 3);  // curve.csv, report.json, manifest.json
  EXPECT_EQ(rep["units"]["peak_friction_angle"], "degree");
  // Columns: step, ε_a, ε_v, σ_a, σ_r, p, q, n, Z, unbalanced.
  const auto rows = curve_rows(d / "t1" / "curve.csv");
  ASSERT_GT(rows.size(), 20u);
  EXPECT_NEAR(rows.front()[3], 100e3, 1e3);  // consolidated: σ_a = σ_r = 100 kPa
  EXPECT_NEAR(rows.front()[4], 100e3, 1e3);
  double q_max = 0;
  for (const auto& r : rows) {
    EXPECT_NEAR(r[4], 100e3, 1e3) << "the radial servo holds the confining stress";
    EXPECT_NEAR(r[5], (r[3] + 2 * r[4]) / 3, 1e-6 * r[3]);
    EXPECT_NEAR(r[6], r[3] - r[4], 1e-6 * r[3]);
    q_max = std::max(q_max, r[6]);
  }
  EXPECT_GT(q_max, 30e3);  // the specimen carries a deviator
  EXPECT_GE(rows.back()[1], 0.02);
  // The report's peak is the curve's, in degrees: sin φ = (σ_a − σ_r)/(σ_a + σ_r).
  const double phi = rep["peak_friction_angle"].get<double>();
  EXPECT_GT(phi, 10.0);
  EXPECT_LT(phi, 60.0);
  EXPECT_GT(rep["young_modulus"].get<double>(), 0.0);
  EXPECT_LE(rep["critical_friction_angle"].get<double>(), phi + 1e-9);
}

TEST(CliElementTest, IsotropicAndOedometerGiveModuliWithTheOedometerStiffer) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  write(d / "iso.toml", kIsotropic);
  const std::string spec =
      " --quiet --specimen " + (d / "spec").string() + " --recipe " + (d / "iso.toml").string();
  const Result iso = run_cli("test isotropic --json" + spec + " --out " + (d / "iso").string(), d);
  ASSERT_EQ(iso.rc, 0) << iso.err;
  const Result oed = run_cli("test oedometer --json" + spec + " --out " + (d / "oed").string(), d);
  ASSERT_EQ(oed.rc, 0) << oed.err;
  const auto ji = nlohmann::json::parse(iso.out), jo = nlohmann::json::parse(oed.out);
  const double k = ji["bulk_modulus"].get<double>(), m = jo["constrained_modulus"].get<double>();
  std::printf("bulk modulus %.4g Pa, constrained modulus %.4g Pa, K0 %.3f\n", k, m,
              jo["k0"].get<double>());
  EXPECT_GT(k, 0.0);
  // Elasticity: M = K + 4G/3 > K for any positive shear modulus.
  EXPECT_GT(m, k);
  EXPECT_GT(jo["k0"].get<double>(), 0.0);
  EXPECT_LT(jo["k0"].get<double>(), 1.0);
  // The modulus from the middle half's strain: the same material, so of the same order.
  const double m_in = jo["constrained_modulus_interior"].get<double>();
  EXPECT_GT(m_in, 0.5 * m);
  EXPECT_LT(m_in, 2.0 * m);
  std::printf("constrained modulus from the middle half %.4g Pa\n", m_in);
  // Under isotropic loading the stress is isotropic and p reaches the final stress.
  const auto rows = curve_rows(d / "iso" / "curve.csv");
  EXPECT_NEAR(rows.back()[5], 300e3, 3e3);
  for (const auto& r : rows) EXPECT_LT(std::abs(r[6]), 0.05 * r[5]);
}

TEST(CliElementTest, SpecimenScaledByTwoTestsTheSameBitForBit) {
  // CTGU 2017 eqs. 1–3 through the CLI (issue 16 acceptance 1): `specimen-scale --factor 2`, then
  // the same triaxial at half the strain rate (ε̇/λ): every strain and stress of the curve is the
  // same bits — no absolute length hides in the reader, the cell, the servo, the time step or
  // the skin.
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  Result r = run_cli(
      "specimen-scale " + (d / "spec").string() + " --factor 2 --out " + (d / "spec2").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto src = nlohmann::json::parse(slurp(d / "spec" / "report.json"));
  const auto big = nlohmann::json::parse(slurp(d / "spec2" / "report.json"));
  EXPECT_EQ(big["container"]["diameter"].get<double>(),
            2 * src["container"]["diameter"].get<double>());
  EXPECT_EQ(big["contact"]["kn"].get<double>(), 2 * src["contact"]["kn"].get<double>());
  EXPECT_EQ(big["porosity"], src["porosity"]);
  EXPECT_EQ(big["scale_factor"].get<double>(), 2.0);
  const char* recipe =
      "[test]\nconfining = 100e3\nstrain_rate = %s\nmax_axial_strain = 0.01\n"
      "record_every = 400\n";
  char text[256];
  std::snprintf(text, sizeof text, recipe, "0.5");
  write(d / "a.toml", text);
  std::snprintf(text, sizeof text, recipe, "0.25");
  write(d / "b.toml", text);
  for (const char* c : {"a", "b"}) {
    const std::string spec = std::string(c) == "a" ? "spec" : "spec2";
    r = run_cli("test triaxial --quiet --specimen " + (d / spec).string() + " --recipe " +
                    (d / (std::string(c) + ".toml")).string() + " --out " + (d / c).string(),
                d);
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  const std::string a = slurp(d / "a" / "curve.csv"), b = slurp(d / "b" / "curve.csv");
  EXPECT_GT(a.size(), 500u);
  EXPECT_EQ(a, b) << "the λ = 2 copy's curve differs";
  // Its specimen.csv: every length doubled, exactly.
  const auto one = nlohmann::json::parse(slurp(d / "a" / "report.json"));
  const auto two = nlohmann::json::parse(slurp(d / "b" / "report.json"));
  EXPECT_EQ(two["timestep"].get<double>(), 2 * one["timestep"].get<double>());
  EXPECT_EQ(two["peak_friction_angle"], one["peak_friction_angle"]);
}

TEST(CliElementTest, BundledTestRecipeParses) {
  // The bundled recipe against the tiny specimen, cut short by the recipe's own keys: it parses
  // and runs (its full length is for the quick specimen), and saves its consolidated state.
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  std::string text =
      slurp(fs::path(CLUMPKIT_SOURCE_DIR) / "assets/recipes/test-triaxial-quick.toml");
  ASSERT_NE(text.find("max_axial_strain = 0.2"), std::string::npos);
  text.replace(text.find("max_axial_strain = 0.2"), 22, "max_axial_strain = 0.002");
  write(d / "quick.toml", text);
  const Result r =
      run_cli("test triaxial --quiet --save-consolidated --specimen " + (d / "spec").string() +
                  " --recipe " + (d / "quick.toml").string() + " --out " + (d / "tri").string(),
              d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(fs::exists(d / "tri" / "manifest.json"));
  // The consolidated state, as a specimen the exports read (the sanitizer pass's check of
  // --save-consolidated; CliImport.LammpsOedometerFromTheSavedConsolidatedState... runs it in
  // LAMMPS, label long).
  for (const char* f : {"specimen.csv", "report.json", "manifest.json"})
    EXPECT_TRUE(fs::exists(d / "tri" / "consolidated" / f)) << f;
}

TEST(CliElementTest, ShortTriaxialOfASmallCompressedCylinderSavesItsConsolidatedState) {
  // The job end to end in seconds under the sanitizers (the sibling of BundledTestRecipeParses,
  // label long): a gravity-free cylinder of about 130 spheres of 10 mm (5 d across and high,
  // n = 0.42), tested to 0.05 % axial strain with --save-consolidated (stopped and resumed:
  // StageFiles.ElementTest... on the same drive, CliQuickElementTest through the CLI).
  const fs::path d = scratch();
  write(d / "cyl.toml", R"(seed = 5
soil_rock_threshold = 1.0
rock_mass_fraction = 0.0
[container]
shape = "cylinder"
diameter = 0.05
height = 0.05
[preparation]
method = "compression"
porosity = 0.42
[gradation]
sieves = [0.0101, 0.0099]
passing = [100, 0]
[density]
soil = 2650
[contact]
kn = 8e7
ks = 8e5
friction = 0.5
local_damping = 0.7
)");
  Result r = run_cli(
      "specimen --quiet --recipe " + (d / "cyl.toml").string() + " --out " + (d / "cyl").string(),
      d);
  ASSERT_EQ(r.rc, 0) << r.err;
  write(d / "t.toml",
        "[test]\nconfining = 2e5\nstrain_rate = 0.5\nmax_axial_strain = 5e-4\nrecord_every = "
        "100\nconsolidation_tolerance = 0.05\n");
  const std::string base = "test triaxial --quiet --allow-dynamic --specimen " +
                           (d / "cyl").string() + " --recipe " + (d / "t.toml").string();
  r = run_cli(base + " --save-consolidated --out " + (d / "tri").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto rep = nlohmann::json::parse(slurp(d / "tri" / "report.json"));
  EXPECT_GT(rep["steps"].get<long long>(), 0);
  for (const char* f : {"specimen.csv", "report.json", "manifest.json"})
    EXPECT_TRUE(fs::exists(d / "tri" / "consolidated" / f)) << f;
}

TEST(CliElementTest, CompressedCuboidAndItsScaledCopyTestTheSameBitForBit) {
  // A gravity-free cuboid specimen (preparation.method = "compression", ~570 spheres of 10 mm in
  // an 8 d cube at n = 0.40, kn ∝ d) tested in a cuboid cell at CTGU 2017's 5 MPa, and its copy
  // at λ = 2 (specimen-scale: the recorded linear law keeps kn_ref, the diameters double the
  // stiffness) tested at half the strain rate: the same curve, bit for bit.
  const fs::path d = scratch();
  write(d / "cube.toml", R"(seed = 3
soil_rock_threshold = 1.0
rock_mass_fraction = 0.0
[container]
shape = "cuboid"
size = [0.08, 0.08, 0.08]
[preparation]
method = "compression"
porosity = 0.40
[gradation]
sieves = [0.0101, 0.0099]
passing = [100, 0]
[density]
soil = 2650
[contact]
kn = 8e7
ks = 8e5
friction = 0.8
stiffness_scaling = "linear"
d_ref = 0.01
)");
  Result r = run_cli(
      "specimen --quiet --recipe " + (d / "cube.toml").string() + " --out " + (d / "cube").string(),
      d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto spec = nlohmann::json::parse(slurp(d / "cube" / "report.json"));
  EXPECT_EQ(spec["container"]["shape"], "cuboid");
  EXPECT_NEAR(spec["porosity"].get<double>(), 0.40, 1e-12);
  EXPECT_EQ(spec["contact"]["stiffness_scaling"], "linear");
  EXPECT_EQ(spec["contact"]["d_ref"].get<double>(), 0.01);
  EXPECT_GT(spec["bodies"].get<int>(), 500);
  // Not exportable yet: refused with one line rather than exported as a cylinder with one kn.
  expect_one_line_error(
      run_cli("export lammps " + (d / "cube").string() + " --out " + (d / "lmp").string(), d),
      "container.shape");
  EXPECT_FALSE(fs::exists(d / "lmp"));
  r = run_cli(
      "specimen-scale " + (d / "cube").string() + " --factor 2 --out " + (d / "cube2").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto big = nlohmann::json::parse(slurp(d / "cube2" / "report.json"));
  EXPECT_EQ(big["contact"]["kn"], spec["contact"]["kn"]);  // kn_ref at d_ref: unchanged
  EXPECT_EQ(big["container"]["hi"][2].get<double>(), 2 * spec["container"]["hi"][2].get<double>());
  const char* recipe =
      "[test]\nconfining = 5e6\nstrain_rate = %s\nmax_axial_strain = 2e-4\nrecord_every = 100\n";
  char text[256];
  std::snprintf(text, sizeof text, recipe, "0.1");
  write(d / "a.toml", text);
  std::snprintf(text, sizeof text, recipe, "0.05");
  write(d / "b.toml", text);
  // Its consolidated state cannot be saved for the exports either (they model cylinders).
  expect_one_line_error(
      run_cli("test triaxial --quiet --save-consolidated --specimen " + (d / "cube").string() +
                  " --recipe " + (d / "a.toml").string() + " --out " + (d / "c").string(),
              d),
      "--save-consolidated");
  EXPECT_FALSE(fs::exists(d / "c.partial"));
  for (const char* c : {"a", "b"}) {
    const std::string s = std::string(c) == "a" ? "cube" : "cube2";
    r = run_cli("test triaxial --quiet --specimen " + (d / s).string() + " --recipe " +
                    (d / (std::string(c) + ".toml")).string() + " --out " + (d / c).string(),
                d);
    ASSERT_EQ(r.rc, 0) << r.err;
  }
  EXPECT_EQ(slurp(d / "a" / "curve.csv"), slurp(d / "b" / "curve.csv"));
  const auto rep = nlohmann::json::parse(slurp(d / "a" / "report.json"));
  EXPECT_TRUE(rep["consolidated"].get<bool>());
  EXPECT_EQ(rep["contact"]["stiffness_scaling"], "linear");
  // The cuboid cell holds σ3 = 5 MPa on its four lateral walls; Young's modulus is of the order
  // of the affine estimate (K_V ≈ 0.33·kn/d = 2.6 GPa, E of order 1 GPa).
  const auto rows = curve_rows(d / "a" / "curve.csv");
  ASSERT_GT(rows.size(), 10u);
  for (const auto& row : rows) EXPECT_NEAR(row[4], 5e6, 0.01 * 5e6);
  const double e = rep["young_modulus"].get<double>();
  EXPECT_GT(e, 0.3e9);
  EXPECT_LT(e, 3e9);
}

TEST(CliElementTest, BadInputIsRefusedWithOneLine) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  write(d / "tri.toml", kTriaxial);
  write(d / "unknown.toml", "[test]\nconfinning = 1e5\n");
  write(d / "negative.toml", "[test]\nconfining = -1\n");
  write(d / "linear.toml", "[contact]\nstiffness_scaling = \"linear\"\n");
  // Inertial number ε̇·d·sqrt(ρ/p) ≈ 1e4 · 0.01 · 0.16 ≫ 1e-2 on the tiny specimen.
  write(d / "dynamic.toml", "[test]\nconfining = 1e5\nstrain_rate = 1e4\n");
  fs::create_directories(d / "notspec");
  const std::string spec = " --specimen " + (d / "spec").string();
  const std::string out = (d / "out").string();
  struct Case {
    std::string args, needle;
  };
  const Case cases[] = {
      {"test shear" + spec + " --recipe " + (d / "tri.toml").string() + " --out " + out, "shear"},
      {"test triaxial" + spec + " --recipe " + (d / "unknown.toml").string() + " --out " + out,
       "test.confinning"},
      {"test triaxial" + spec + " --recipe " + (d / "negative.toml").string() + " --out " + out,
       "test.confining"},
      {"test triaxial" + spec + " --recipe " + (d / "linear.toml").string() + " --out " + out,
       "contact.d_ref"},
      {"test triaxial" + spec + " --recipe " + (d / "dynamic.toml").string() + " --out " + out,
       "--allow-dynamic"},
      {"test oedometer --specimen " + (d / "notspec").string() + " --recipe " +
           (d / "tri.toml").string() + " --out " + out,
       "notspec"},
      {"test triaxial --specimen " + (d / "missing").string() + " --recipe " +
           (d / "tri.toml").string() + " --out " + out,
       "missing"},
      {"test triaxial" + spec + " --recipe " + (d / "tri.toml").string() + " --out " +
           (d / "spec").string(),
       "spec"},
      {"specimen-scale " + (d / "spec").string() + " --factor 0 --out " + out, "--factor"},
      {"specimen-scale " + (d / "spec").string() + " --factor -2 --out " + out, "--factor"},
      {"specimen-scale " + (d / "spec").string() + " --factor nan --out " + out, "--factor"},
      {"specimen-scale " + (d / "spec").string() + " --factor 1e40 --out " + out, "1e30"},
      {"specimen-scale " + (d / "missing").string() + " --factor 2 --out " + out, "missing"},
      {"specimen-scale " + (d / "spec").string() + " --factor 2 --out " + (d / "spec").string(),
       "spec"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    expect_one_line_error(run_cli(c.args, d), c.needle);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".partial"));
  }
  EXPECT_TRUE(fs::exists(d / "spec" / "specimen.csv"));  // the specimen is untouched
}
