// `clumpkit test cpt` on the tiny specimen: a cone pushed 9 mm into it gives a cone resistance
// well above the confining stress, the same bytes for 1 and 2 threads; bad probes are refused
// before anything is written.
#include "cli_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

// A 12 mm probe in the 60 mm cylinder at 80 mm/s: inertial number (v / D_c)·d·sqrt(ρ/p) ≈ 0.009.
const char* kCpt = R"([test]
confining = 100e3
record_every = 2000

[probe]
diameter = 0.012
velocity = 0.08
depth = 0.009
)";

// The numeric rows of curve.csv, its header checked.
std::vector<std::vector<double>> cpt_rows(const fs::path& path) {
  std::string header;
  auto rows = csv_rows(path, 6, &header);
  EXPECT_EQ(header, "step[1],depth[m],tip_force[N],sleeve_force[N],qc[Pa],fs[Pa]");
  return rows;
}

}  // namespace

TEST(CliCpt, PushIntoTheTinySpecimenSameBytesForOneAndTwoThreads) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  write(d / "cpt.toml", kCpt);
  const std::string base = "test cpt --quiet --specimen " + (d / "spec").string() + " --recipe " +
                           (d / "cpt.toml").string();
  const Result one = run_cli(base + " --threads 1 --out " + (d / "c1").string(), d);
  ASSERT_EQ(one.rc, 0) << one.err;
  const Result two = run_cli(base + " --threads 2 --json --out " + (d / "c2").string(), d);
  ASSERT_EQ(two.rc, 0) << two.err;
  for (const char* f : {"curve.csv", "report.json"})
    EXPECT_EQ(slurp(d / "c1" / f), slurp(d / "c2" / f)) << f << " differs between thread counts";
  EXPECT_GT(fs::file_size(d / "c1" / "curve.png"), 5000u);
  const auto rep = nlohmann::json::parse(two.out);
  EXPECT_EQ(rep["test"], "cpt");
  EXPECT_TRUE(rep["consolidated"].get<bool>());
  EXPECT_FALSE(rep["reached_bottom"].get<bool>());
  EXPECT_LT(rep["inertial_number"].get<double>(), 1e-2);
  EXPECT_EQ(rep["probe"]["apex_deg"], 60.0);
  EXPECT_GE(expect_units_everywhere(d / "c1"), 3);  // curve.csv, report.json, manifest.json
  // Columns: step, depth, tip force, sleeve force, qc, fs.
  const auto rows = cpt_rows(d / "c1" / "curve.csv");
  ASSERT_GT(rows.size(), 10u);
  EXPECT_EQ(rows.front()[1], 0.0);
  EXPECT_GE(rows.back()[1], 0.009);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    EXPECT_GT(rows[k][1], rows[k - 1][1]);
    EXPECT_NEAR(rows[k][4], rows[k][2] / (3.14159265358979323846 * 0.006 * 0.006),
                1e-9 * std::abs(rows[k][4]) + 1e-9);
  }
  // With most of the 10.4 mm cone buried, qc is far above the confining stress (13 times at the
  // end of this push, measured; about 20 times once buried on a 40 mm push).
  EXPECT_GT(rep["qc_max"].get<double>(), 5.0 * 100e3);
  EXPECT_GT(rows.back()[4], 2.0 * 100e3);
}

TEST(CliCpt, BadProbesAreRefusedBeforeAnythingIsWritten) {
  const fs::path d = scratch();
  ASSERT_NO_FATAL_FAILURE(build_tiny_specimen(d));
  const std::string test = "[test]\nconfining = 100e3\n";
  write(d / "noprobe.toml", test);
  write(d / "wide.toml", test + "[probe]\ndiameter = 0.04\ndepth = 0.01\n");
  write(d / "apex.toml", test + "[probe]\napex_deg = 180\ndepth = 0.01\n");
  write(d / "nodepth.toml", test + "[probe]\ndiameter = 0.01\n");
  write(d / "unknown.toml", test + "[probe]\ndepth = 0.01\nspeed = 1\n");
  write(d / "fast.toml", test + "[probe]\ndiameter = 0.01\ndepth = 0.01\nvelocity = 10\n");
  write(d / "probe.toml", std::string(kCpt));
  // The tiny specimen as if zoned radially, with a core of 30 mm (under 4 probe diameters of
  // 12 mm) and of 5 mm (narrower than the probe): the guard reads the specimen's report.
  for (const auto& [name, core] :
       {std::pair<const char*, double>{"core30", 0.03}, {"core5", 0.005}}) {
    fs::copy(d / "spec", d / name, fs::copy_options::recursive);
    nlohmann::json report = nlohmann::json::parse(slurp(d / name / "report.json"));
    report["zones"] = {
        {"coordinate", "radial"},
        {"regions", {{{"outer", core}, {"scale", 1}}, {{"outer", 1}, {"scale", 2}}}}};
    write(d / name / "report.json", report.dump(2));
  }
  const std::string out = (d / "out").string();
  // `clumpkit test KIND` of specimen `spec` with recipe `recipe`, both in the scratch directory.
  const auto command = [&](const char* kind, const char* spec, const char* recipe) {
    return std::string("test ") + kind + " --specimen " + (d / spec).string() + " --recipe " +
           (d / recipe).string() + " --out " + out;
  };
  struct Case {
    std::string args, needle;
  };
  const Case cases[] = {
      {command("cpt", "spec", "noprobe.toml"), "[probe]"},
      {command("cpt", "spec", "wide.toml"), "half the cell"},
      {command("cpt", "spec", "apex.toml"), "probe.apex_deg"},
      {command("cpt", "spec", "nodepth.toml"), "probe.depth"},
      {command("cpt", "spec", "unknown.toml"), "probe.speed"},
      {command("cpt", "spec", "fast.toml"), "probe.velocity"},
      {command("triaxial", "spec", "wide.toml"), "test cpt"},
      {command("cpt", "core30", "probe.toml"), "smaller than 4 probe diameters"},
      {command("cpt", "core5", "probe.toml"), "wider than the specimen's core"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    expect_one_line_error(run_cli(c.args, d), c.needle);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".partial"));
  }
}
