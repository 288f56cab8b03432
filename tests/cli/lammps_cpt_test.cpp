// The CPT deck of `clumpkit export lammps --test cpt` run in LAMMPS: one sphere pressed on the
// cone and one on the shaft, their forces against the closed forms (as ProbeWall.* checks our
// engine's probe), the tip/sleeve split, and bad exports refused.
#include "cli_helpers.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// Probe of 18 mm, 60° apex at z = 0.05 m; spheres of 3 mm pressed 10 µm into it, 1,000 kg each
// so that they barely move while the tangential spring of the shaft's contact saturates.
constexpr double kR = 0.009, kApex = 0.05, kBeta = kPi / 6, kRadius = 0.003, kDelta = 1e-5;
constexpr double kMass = 1e3, kKn = 1e6, kMu = 0.5;

std::string format(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

struct Ball {
  double x, z, r;
};

// A specimen directory of soil spheres (at y = 0) of kMass each; `contact` the report's law.
void write_specimen(const fs::path& dir, const std::vector<Ball>& balls, const std::string& contact,
                    const std::string& gravity = "0") {
  fs::create_directories(dir);
  std::string csv =
      "# clumpkit specimen format 4, SI units\n# bodies\n"
      "body,kind,template,x,y,z,qw,qx,qy,qz,mass,volume,scale,I1,I2,I3,zone\n";
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Ball& b = balls[i];
    const double volume = 4.0 / 3.0 * kPi * std::pow(b.r, 3), inertia = 0.4 * kMass * b.r * b.r;
    csv += std::to_string(i + 1) + ",soil,-1," + format(b.x) + ",0," + format(b.z) + ",1,0,0,0," +
           format(kMass) + "," + format(volume) + ",1," + format(inertia) + "," + format(inertia) +
           "," + format(inertia) + ",0\n";
  }
  csv += "# spheres\nsphere,body,x,y,z,r\n";
  for (std::size_t i = 0; i < balls.size(); ++i)
    csv += std::to_string(i + 1) + "," + std::to_string(i + 1) + "," + format(balls[i].x) + ",0," +
           format(balls[i].z) + "," + format(balls[i].r) + "\n";
  write(dir / "specimen.csv", csv);
  write(dir / "report.json",
        R"({"container": {"diameter": 0.06, "height": 0.1}, "density": {"rock": 2650, "soil": 2650},
            "gravity": )" +
            gravity + R"(, "contact": )" + contact + "}");
  write(dir / "manifest.json", R"({"recipe_path": "x.toml", "recipe": "", "seed": 1})");
}

// One sphere of radius r0 on the cone's face 8 mm above the apex and one of radius r1 on the
// shaft 10 mm above the shoulder, each overlapping the probe by kDelta.
std::vector<Ball> cone_and_shaft(double r0, double r1) {
  const double z_face = kApex + 0.008, rho_face = 0.008 * std::tan(kBeta);
  return {
      {rho_face + (r0 - kDelta) * std::cos(kBeta), z_face - (r0 - kDelta) * std::sin(kBeta), r0},
      {-(kR + r1 - kDelta), kApex + kR / std::tan(kBeta) + 0.01, r1}};
}

const char* kUniformLaw =
    R"({"kn": 1e6, "ks": 1e6, "friction": 0.5, "damping_ratio": 0, "local_damping": 0})";

void write_two_sphere_specimen(const fs::path& dir) {
  write_specimen(dir, cone_and_shaft(kRadius, kRadius), kUniformLaw);
}

// Runs the exported deck of `spec` for the 5,000-step push with the walls fixed; "" or the error.
std::string export_and_run(const fs::path& d, const fs::path& spec, const std::string& out) {
  const Result r = run_cli("export lammps " + spec.string() + " --test cpt --recipe " +
                               (d / "cpt.toml").string() + " --out " + (d / out).string(),
                           d);
  if (r.rc != 0) return "export: " + r.err;
  const int rc =
      std::system(("cd " + (d / out).string() +
                   " && lmp -in in.clumpkit -var servo 0 -var dt 1e-7 -var apex 0.05 -var every "
                   "1000 -log none > run.txt 2>&1")
                      .c_str());
  return rc == 0 ? "" : slurp(d / out / "run.txt");
}

// The atoms at the end: id mol x y z radius fx fy fz, one row each.
std::vector<std::vector<double>> final_atoms(const fs::path& run, std::size_t count) {
  std::istringstream in(slurp(run / "atoms.final.txt"));
  std::string line;
  for (int k = 0; k < 9; ++k) std::getline(in, line);
  std::vector<std::vector<double>> a(count, std::vector<double>(9));
  for (auto& row : a)
    for (double& v : row) in >> v;
  return in ? a : std::vector<std::vector<double>>{};
}

// A push of 5,000 steps of 0.1 µs at 20 mm/s: 10 µm.
const char* kProbeRecipe =
    "[test]\nconfining = 100e3\n\n[probe]\ndiameter = 0.018\n"
    "velocity = 0.02\ndepth = 1e-5\n";

}  // namespace

TEST(CliLammpsCpt, OneSphereOnTheConeAndOneOnTheShaftGiveTheClosedForms) {
  if (!have_program("lmp")) GTEST_SKIP() << "LAMMPS (lmp) not installed: run scripts/deps";
  const fs::path d = scratch();
  write_two_sphere_specimen(d / "spec");
  write(d / "cpt.toml", kProbeRecipe);
  const std::string error = export_and_run(d, d / "spec", "lmp");
  ASSERT_EQ(error, "");
  std::string header;
  const auto curve = csv_rows(d / "lmp" / "cpt.csv", 6, &header);
  EXPECT_EQ(header, "step[1],depth[m],tip_force[N],sleeve_force[N],qc[Pa],fs[Pa]");
  ASSERT_EQ(curve.size(), 6u);
  const auto a = final_atoms(d / "lmp", 2);
  ASSERT_EQ(a.size(), 2u) << "atoms.final.txt";
  // Cone: the force along the face's outward normal (cos β, −sin β) is kn·δ, δ from where the
  // sphere ended (its centre's distance to the face, less its radius).
  const double nx = std::cos(kBeta), nz = -std::sin(kBeta);
  const double distance = a[0][2] * nx + (a[0][4] - kApex) * nz;  // the face passes the apex
  const double delta = kRadius - distance;
  EXPECT_GT(delta, 0.5 * kDelta);
  EXPECT_NEAR(a[0][6] * nx + a[0][8] * nz, kKn * delta, 1e-6 * kKn * delta);
  // Shaft: N = kn·δ radially, and once the tangential spring saturates (kt·slip > μN after
  // 2,500 of the 5,000 steps) μ·N axially, downwards on the sphere that moves up past it.
  const double shaft_delta = kR + kRadius + a[1][2];  // x < 0: the sphere's gap is R + r − |x|
  EXPECT_NEAR(-a[1][6], kKn * shaft_delta, 1e-6 * kKn * shaft_delta);
  EXPECT_NEAR(-a[1][8], kMu * kKn * shaft_delta, 1e-6 * kMu * kKn * shaft_delta);
  // cpt.csv's last row: each contact on its own part, forces on the probe (upwards positive).
  const auto& last = curve.back();
  EXPECT_EQ(last[0], 5000);
  EXPECT_NEAR(last[1], 1e-5, 1e-12);
  EXPECT_NEAR(last[2], -a[0][8], 1e-9 * std::abs(a[0][8]));
  EXPECT_NEAR(last[3], -a[1][8], 1e-9 * std::abs(a[1][8]));
  EXPECT_NEAR(last[4], last[2] / (kPi * kR * kR), 1e-9 * last[4]);
  // fs over the shaft below the lid, which starts at the highest sphere surface (the shaft
  // sphere's top) and rises 10 µm.
  const double shaft_top = kApex + kR / std::tan(kBeta) + 0.01 + kRadius;
  const double embedded = shaft_top + 1e-5 - (kApex + kR / std::tan(kBeta));
  EXPECT_NEAR(last[5], last[3] / (2 * kPi * kR * embedded), 1e-6 * last[5]);
  // The first row, before any slip: the shaft's contact has no axial force yet.
  EXPECT_NEAR(curve.front()[3], 0.0, 1e-12);
  // The way back: the push read as `clumpkit test cpt` reports one.
  const Result im = run_cli("import lammps " + (d / "lmp").string() + " --specimen " +
                                (d / "spec").string() + " --out " + (d / "imp").string(),
                            d);
  ASSERT_EQ(im.rc, 0) << im.err;
  const nlohmann::json rep = nlohmann::json::parse(slurp(d / "imp" / "report.json"));
  double qc_max = 0;
  for (const auto& row : curve) qc_max = std::max(qc_max, row[4]);
  EXPECT_EQ(rep["test"], "cpt");
  EXPECT_EQ(rep["qc_max"].get<double>(), qc_max);
  EXPECT_EQ(rep["final_depth"].get<double>(), last[1]);
  EXPECT_EQ(rep["steps"].get<double>(), 5000);
  EXPECT_EQ(rep["bodies"], 2);
  EXPECT_EQ(csv_rows(d / "imp" / "curve.csv", 6), curve);
  EXPECT_TRUE(fs::exists(d / "imp" / "curve.png"));
}

// Contact stiffness ∝ diameter (CTGU 2017's groups D–E): d_ref = 6 mm, a 6 mm sphere on the cone
// (against a wall 2·d/d_ref = 2 × kn), a 9 mm one on the shaft (3 × kn, and μ·N axially), and a
// 6 mm and a 9 mm sphere pressed together away from the probe (2·d_i·d_j/((d_i + d_j)·d_ref) =
// 1.2 × kn): the closed forms of dem::wall_stiffness_factor and pair_stiffness_factor.
TEST(CliLammpsCpt, LinearStiffnessScalingGivesEachSizeItsOwnSprings) {
  if (!have_program("lmp")) GTEST_SKIP() << "LAMMPS (lmp) not installed: run scripts/deps";
  const fs::path d = scratch();
  std::vector<Ball> balls = cone_and_shaft(0.003, 0.0045);
  const double px = 0.015, pz = kApex + 0.03;  // 3 mm clear of the shaft
  balls.push_back({px, pz, 0.003});
  balls.push_back({px + 0.0075 - kDelta, pz, 0.0045});
  write_specimen(d / "spec", balls,
                 R"({"kn": 1e6, "ks": 1e6, "friction": 0.5, "damping_ratio": 0,
                     "local_damping": 0, "stiffness_scaling": "linear", "d_ref": 0.006})",
                 "false");  // a compression specimen's report: prepared without gravity
  write(d / "cpt.toml", kProbeRecipe);
  const std::string error = export_and_run(d, d / "spec", "lmp");
  ASSERT_EQ(error, "");
  EXPECT_EQ(slurp(d / "lmp" / "in.clumpkit").find("gravity"), std::string::npos);
  const nlohmann::json m = nlohmann::json::parse(slurp(d / "lmp" / "manifest.json"));
  ASSERT_EQ(m["stiffness_classes"].size(), 2u);
  EXPECT_EQ(m["stiffness_classes"][1]["diameter"].get<double>(), 0.009);
  EXPECT_EQ(m["stiffness_class_error"].get<double>(), 0.0);
  const auto a = final_atoms(d / "lmp", 4);
  ASSERT_EQ(a.size(), 4u) << "atoms.final.txt";
  const double nx = std::cos(kBeta), nz = -std::sin(kBeta);
  const double delta = 0.003 - (a[0][2] * nx + (a[0][4] - kApex) * nz);
  EXPECT_GT(delta, 0.5 * kDelta);
  EXPECT_NEAR(a[0][6] * nx + a[0][8] * nz, 2 * kKn * delta, 1e-6 * 2 * kKn * delta);
  const double shaft_delta = kR + 0.0045 + a[1][2];
  EXPECT_NEAR(-a[1][6], 3 * kKn * shaft_delta, 1e-6 * 3 * kKn * shaft_delta);
  EXPECT_NEAR(-a[1][8], kMu * 3 * kKn * shaft_delta, 1e-6 * kMu * 3 * kKn * shaft_delta);
  const double pair_delta = 0.0075 - (a[3][2] - a[2][2]);
  EXPECT_GT(pair_delta, 0.5 * kDelta);
  EXPECT_NEAR(-a[2][6], 1.2 * kKn * pair_delta, 1e-6 * 1.2 * kKn * pair_delta);
  EXPECT_NEAR(a[3][6], 1.2 * kKn * pair_delta, 1e-6 * 1.2 * kKn * pair_delta);
  // The tip and the sleeve read every class's fix: the last row holds both spheres' forces.
  const auto curve = csv_rows(d / "lmp" / "cpt.csv", 6);
  ASSERT_FALSE(curve.empty());
  EXPECT_NEAR(curve.back()[2], -a[0][8], 1e-9 * std::abs(a[0][8]));
  EXPECT_NEAR(curve.back()[3], -a[1][8], 1e-9 * std::abs(a[1][8]));
  // A clump under linear scaling, and linear scaling in any other deck, are refused.
  const Result other =
      run_cli("export lammps " + (d / "spec").string() + " --out " + (d / "settle").string(), d);
  expect_one_line_error(other, "contact.stiffness_scaling");
  EXPECT_FALSE(fs::exists(d / "settle"));
}

TEST(CliLammpsCpt, BadCptExportsAreRefusedWithOneLine) {
  const fs::path d = scratch();
  write_two_sphere_specimen(d / "spec");
  write(d / "cpt.toml", kProbeRecipe);
  write(d / "noprobe.toml", "[test]\nconfining = 100e3\n");
  write(d / "wide.toml", "[test]\nconfining = 100e3\n\n[probe]\ndiameter = 0.04\ndepth = 0.01\n");
  write(d / "unknown.toml", "[test]\nconfining = 100e3\n\n[probe]\ndepth = 0.01\nspeed = 1\n");
  // The probe against the specimen: a radially zoned one whose core of small particles (30 mm)
  // is under 4 probe diameters, and a 10° segment whose walls keep the 6 mm spheres 31 mm from
  // the axis, out of the 18 mm probe's reach.
  fs::copy(d / "spec", d / "zoned", fs::copy_options::recursive);
  fs::copy(d / "spec", d / "narrow", fs::copy_options::recursive);
  nlohmann::json zoned = nlohmann::json::parse(slurp(d / "spec" / "report.json"));
  zoned["zones"] = {{"coordinate", "radial"},
                    {"regions", {{{"outer", 0.03}, {"scale", 1}}, {{"outer", 1}, {"scale", 2}}}}};
  write(d / "zoned" / "report.json", zoned.dump());
  nlohmann::json narrow = nlohmann::json::parse(slurp(d / "spec" / "report.json"));
  narrow["container"]["shape"] = "segment";
  narrow["container"]["angle_deg"] = 10;
  write(d / "narrow" / "report.json", narrow.dump());
  // A run whose cpt.csv was cut in the middle of a row.
  fs::create_directories(d / "run");
  write(d / "run" / "cpt.csv",
        "step,depth_m,tip_force_n,sleeve_force_n,qc_pa,fs_pa\n0,0,0,0,0,0\n100,2e-06,1.5\n");
  const std::string out = (d / "o").string(), spec = (d / "spec").string();
  const auto recipe = [&](const char* name) { return " --recipe " + (d / name).string(); };
  struct Case {
    std::string args, needle;
  };
  // `export lammps SOURCE --test cpt --recipe RECIPE` into `out`, both in the scratch directory.
  const auto cpt = [&](const fs::path& source, const char* name) {
    return "export lammps " + source.string() + " --test cpt" + recipe(name) + " --out " + out;
  };
  const Case cases[] = {
      {"export lammps " + spec + " --test cpt --out " + out, "--test cpt needs --recipe"},
      {"export lammps " + spec + recipe("cpt.toml") + " --out " + out,
       "--recipe is for --test cpt"},
      {"export yade " + spec + " --test cpt" + recipe("cpt.toml") + " --out " + out,
       "only available for lammps"},
      {cpt(spec, "noprobe.toml"), "[probe]"},
      {cpt(spec, "wide.toml"), "wider than half the cell"},
      {cpt(spec, "unknown.toml"), "probe.speed"},
      {cpt(spec, "missing.toml"), "missing.toml"},
      {cpt(spec, "cpt.toml") + " --tile 2x2", "--tile and --test cpt"},
      {cpt(d / "zoned", "cpt.toml"), "smaller than 4 probe diameters"},
      {cpt(d / "narrow", "cpt.toml"), "the segment's walls keep particles"},
      {"export yade " + (d / "narrow").string() + " --out " + out,
       "exported only as a CPT chamber"},
      {"import lammps " + (d / "run").string() + " --specimen " + spec + " --out " + out,
       "cpt.csv:3: not six finite numbers"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    expect_one_line_error(run_cli(c.args, d), c.needle);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".partial"));
  }
}

namespace {

// The time step the deck runs with (its `variable dt index T` line).
double consolidated_dt(const fs::path& deck) {
  const std::string text = slurp(deck), key = "variable    dt     index ";
  const std::size_t at = text.find(key);
  return at == std::string::npos ? 0.0 : std::stod(text.substr(at + key.size()));
}

// `clumpkit test cpt --save-consolidated` on the specimen in d/spec, then its chamber in LAMMPS:
// the deck starts at the state clumpkit's push starts from (apex and lid at the top platen, both
// stresses at the confining stress) and its servo holds them during a short push.
void push_saved_chamber_in_lammps(const fs::path& d, const std::string& diameter) {
  write(d / "cpt.toml", "[test]\nconfining = 100e3\nrecord_every = 200\n\n[probe]\ndiameter = " +
                            diameter + "\nvelocity = 0.08\ndepth = 0.001\n");
  const Result t =
      run_cli("test cpt --quiet --save-consolidated --specimen " + (d / "spec").string() +
                  " --recipe " + (d / "cpt.toml").string() + " --out " + (d / "c").string(),
              d);
  ASSERT_EQ(t.rc, 0) << t.err;
  const nlohmann::json consolidated =
      nlohmann::json::parse(slurp(d / "c" / "consolidated" / "report.json"));
  EXPECT_EQ(consolidated["gravity"], 0.0);
  EXPECT_EQ(consolidated["confining_stress"], 100e3);
  const Result e =
      run_cli("export lammps " + (d / "c" / "consolidated").string() + " --test cpt --recipe " +
                  (d / "cpt.toml").string() + " --out " + (d / "lmp").string(),
              d);
  ASSERT_EQ(e.rc, 0) << e.err;
  const int rc = std::system(
      ("cd " + (d / "lmp").string() + " && lmp -in in.clumpkit -log log.txt > run.txt 2>&1")
          .c_str());
  ASSERT_EQ(rc, 0) << slurp(d / "lmp" / "run.txt");
  // The push's thermo rows: step rise qc axial_stress lateral_stress cpu.
  std::istringstream log(slurp(d / "lmp" / "log.txt"));
  std::string line;
  std::vector<std::vector<double>> rows;
  bool in_push = false;
  while (std::getline(log, line)) {
    if (line.find("Step v_rise v_qc v_saxial v_slateral") != std::string::npos)
      in_push = true;
    else if (in_push && line.rfind("Loop time", 0) == 0)
      break;
    else if (in_push) {
      std::istringstream s(line);
      std::vector<double> row;
      for (double v; s >> v;) row.push_back(v);
      if (row.size() == 6) rows.push_back(row);
    }
  }
  ASSERT_GE(rows.size(), 2u);
  // Consolidated by clumpkit to 1 % (its tolerance), loaded as such: within 1 % at step 0, and
  // held within 5 % while the cone goes in.
  EXPECT_NEAR(rows.front()[3], 100e3, 1e3);
  EXPECT_NEAR(rows.front()[4], 100e3, 1e3);
  for (const auto& r : rows) {
    EXPECT_NEAR(r[3], 100e3, 5e3) << "step " << r[0];
    EXPECT_NEAR(r[4], 100e3, 5e3) << "step " << r[0];
  }
  const auto curve = csv_rows(d / "lmp" / "cpt.csv", 6);
  ASSERT_FALSE(curve.empty());
  // Whole rows of the recipe's record_every (200 steps), the last at or just past the depth
  // (one row: 200 v dt).
  const double dt = consolidated_dt(d / "lmp" / "in.clumpkit");
  EXPECT_GE(curve.back()[1], 0.001 - 1e-12);
  EXPECT_LT(curve.back()[1], 0.001 + 200 * 0.08 * dt);
  EXPECT_EQ(curve.back()[0] - curve[curve.size() - 2][0], 200);
}

}  // namespace

TEST(CliLammpsCpt, TheSavedConsolidatedChamberStartsAtTheConfiningStressInLammps) {
  if (!have_program("lmp")) GTEST_SKIP() << "LAMMPS (lmp) not installed: run scripts/deps";
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  // A 12 mm probe pushed 1 mm at 80 mm/s into the 60 mm cylinder at 100 kPa.
  ASSERT_NO_FATAL_FAILURE(push_saved_chamber_in_lammps(d, "0.012"));
}

TEST(CliLammpsCpt, TheSavedSegmentChamberStartsAtTheConfiningStressInLammps) {
  if (!have_program("lmp")) GTEST_SKIP() << "LAMMPS (lmp) not installed: run scripts/deps";
  const fs::path d = scratch();
  // A 90° segment of 120 mm, 60 mm tall, of 6 mm spheres compressed to porosity 0.36 (960
  // spheres); an 18 mm probe, as CTGU 2017's segment on a small scale.
  write(d / "seg.toml",
        "name = \"seg\"\nseed = 1\nsoil_rock_threshold = 1.0\nrock_mass_fraction = 0.0\n"
        "[container]\nshape = \"segment\"\nangle = 90\ndiameter = 0.12\nheight = 0.06\n"
        "[preparation]\nmethod = \"compression\"\nporosity = 0.36\nfriction = 0.0\n"
        "[gradation]\nsieves = [0.00601, 0.00599]\npassing = [100, 0]\n[density]\nsoil = 2650\n"
        "[contact]\nkn = 5e5\nks = 5e5\nfriction = 0.5\n");
  const Result s = run_cli(
      "specimen --quiet --recipe " + (d / "seg.toml").string() + " --out " + (d / "spec").string(),
      d);
  ASSERT_EQ(s.rc, 0) << s.err;
  ASSERT_NO_FATAL_FAILURE(push_saved_chamber_in_lammps(d, "0.018"));
  // The radial planes are in the deck; the settle deck refuses the segment.
  const std::string deck = slurp(d / "lmp" / "in.clumpkit");
  EXPECT_NE(deck.find("region      side1 plane 0 0 0 1 -6.123233995736766e-17 0 side in"),
            std::string::npos);
  expect_one_line_error(run_cli("export lammps " + (d / "c" / "consolidated").string() + " --out " +
                                    (d / "settle").string(),
                                d),
                        "exported only as a CPT chamber");
  EXPECT_FALSE(fs::exists(d / "settle"));
}
