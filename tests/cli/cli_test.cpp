// End-to-end tests of the clumpkit binary: outputs, determinism, exit codes and error lines.
#include "cli_helpers.h"

#include "geom/shapes/primitives.h"
#include "io/formats/clump_io.h"
#include "io/formats/mesh_io.h"
#include "io/formats/png.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

const char* kSmallRecipe = R"(seed = 5
[[fraction]]
name = "blocks"
method = "block"
count = 12
W = { uniform = [0.02, 0.04] }
L_over_H = { lognormal = { mu = 0.47, sigma = 0.25, min = 1.0, max = 3.5 } }
W_split = { uniform = [0.3, 0.7] }
nd = { integers = [1, 3] }

[[fraction]]
name = "grains"
method = "hull"
count = 6
diameter = 0.01
roundness = [1.2, 1.4]

[[fraction]]
name = "rockfill"
method = "polyhedron"
count = 3
diameter = 0.0275
E = 0.6667
)";

}  // namespace

TEST(Cli, HelpStatesUnitsAndDefaults) {
  const fs::path d = scratch();
  const Result r = run_cli("shape block --help", d);
  EXPECT_EQ(r.rc, 0);
  EXPECT_NE(r.out.find("--nd"), std::string::npos);
  EXPECT_NE(r.out.find("=2"), std::string::npos) << r.out;  // default shown
  EXPECT_NE(r.out.find("unit"), std::string::npos);
}

TEST(Cli, ShapeBlockThenDescribe) {
  const fs::path d = scratch();
  Result r =
      run_cli("shape block --L 75.1 --W 58.0 --H 49.8 --nd 2 --sl 0.8 --su 1.2 --seed 7 -o " +
                  (d / "block.stl").string(),
              d);
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run_cli("describe --json " + (d / "block.stl").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k :
       {"volume", "area", "sphericity", "equivalent_diameter", "L", "W", "H", "axes", "E", "F",
        "AR", "convexity", "weighted_roundness", "view_roundness"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["axes"].size(), 3u);
  EXPECT_EQ(j["view_roundness"].size(), 3u);
  // Every number says its unit: the mesh's, L, unless named; naming it changes no number.
  EXPECT_EQ(json_numbers_without_unit(j), std::vector<std::string>{});
  EXPECT_EQ(j["units"]["volume"], "L3");
  EXPECT_EQ(j["units"]["sphericity"], "1");
  r = run_cli("describe --json --length-unit mm " + (d / "block.stl").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto mm = nlohmann::json::parse(r.out);
  EXPECT_EQ(mm["units"]["volume"], "mm3");
  EXPECT_EQ(mm["units"]["L"], "mm");
  EXPECT_EQ(mm["volume"], j["volume"]);
  // Radial factors in [0.8, 1.2] keep the volume within [0.8³, 1.2³] of the cuboid's.
  const double v0 = 75.1 * 58.0 * 49.8;
  EXPECT_GT(j["volume"].get<double>(), 0.512 * v0);
  EXPECT_LT(j["volume"].get<double>(), 1.728 * v0);
  EXPECT_GT(j["sphericity"].get<double>(), 0.5);
  EXPECT_LT(j["sphericity"].get<double>(), 1.0);
}

TEST(Cli, EveryShapeKindWritesAValidMesh) {
  const fs::path d = scratch();
  const std::string cmds[] = {
      "shape hull --diameter 10 --points 20 --roundness 1.2:1.4 --seed 7 -o " +
          (d / "grain.stl").string(),
      "shape polyhedron --diameter 27.5 --planes 30 --E 0.667 --F 1 --seed 7 -o " +
          (d / "rock.obj").string(),
      "shape ellipsoid --axes 2,1,1 -o " + (d / "e.ply").string(),
      "shape box --size 2,1,1 -o " + (d / "b.stl").string()};
  for (const auto& c : cmds) {
    const Result r = run_cli(c, d);
    EXPECT_EQ(r.rc, 0) << c << "\n" << r.err;
  }
  Result r = run_cli("describe --json " + (d / "b.stl").string(), d);
  ASSERT_EQ(r.rc, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["volume"].get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(j["weighted_roundness"].get<double>(), 1.400563499209, 0.005 * 1.400563499209);
  r = run_cli("describe --json " + (d / "grain.stl").string(), d);
  j = nlohmann::json::parse(r.out);
  EXPECT_GE(j["weighted_roundness"].get<double>(), 1.2 - 1e-6);  // STL stores float32
  EXPECT_LE(j["weighted_roundness"].get<double>(), 1.4 + 1e-6);
  r = run_cli("describe --json " + (d / "rock.obj").string(), d);
  j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["equivalent_diameter"].get<double>(), 27.5, 1e-9);
  EXPECT_NEAR(j["E"].get<double>(), 0.667, 0.01);
}

// Byte-identical outputs for --threads 1 and --threads 2.
TEST(Cli, ShapesIsByteIdenticalForAnyThreadCount) {
  const fs::path d = scratch();
  write(d / "r.toml", kSmallRecipe);
  Result r1 = run_cli("shapes --recipe " + (d / "r.toml").string() + " --out " +
                          (d / "t1").string() + " --threads 1",
                      d);
  ASSERT_EQ(r1.rc, 0) << r1.err;
  Result r2 = run_cli("shapes --recipe " + (d / "r.toml").string() + " --out " +
                          (d / "t2").string() + " --threads 2",
                      d);
  ASSERT_EQ(r2.rc, 0) << r2.err;
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(d / "t1")) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), d / "t1");
    ASSERT_TRUE(fs::exists(d / "t2" / rel)) << rel;
    EXPECT_EQ(slurp(e.path()), slurp(d / "t2" / rel)) << rel;
    ++files;
  }
  EXPECT_EQ(files, 21 + 2);
  EXPECT_EQ(expect_units_everywhere(d / "t1"), 2);  // shapes.csv, manifest.json
  // The table has one row per particle plus the header, and the manifest the counts.
  const std::string csv = slurp(d / "t1" / "shapes.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 22);
  const auto m = nlohmann::json::parse(slurp(d / "t1" / "manifest.json"));
  EXPECT_EQ(m["particles"], 21);
  EXPECT_EQ(m["seed"], 5);
  EXPECT_EQ(m["fractions"].size(), 3u);
  // A rerun with another seed differs.
  std::string other = kSmallRecipe;
  other.replace(0, 8, "seed = 6");
  write(d / "r6.toml", other);
  ASSERT_EQ(
      run_cli("shapes --recipe " + (d / "r6.toml").string() + " --out " + (d / "t6").string(), d)
          .rc,
      0);
  EXPECT_NE(slurp(d / "t1" / "shapes.csv"), slurp(d / "t6" / "shapes.csv"));
}

// Bad inputs give one line naming file, field and value, exit 2, and no partial output.
TEST(Cli, EmptyMeshFile) {
  const fs::path d = scratch();
  write(d / "empty.stl", "");
  expect_one_line_error(run_cli("describe " + (d / "empty.stl").string(), d), "empty.stl");
}

TEST(Cli, TruncatedBinaryStl) {
  const fs::path d = scratch();
  ASSERT_EQ(run_cli("shape box --size 1,1,1 -o " + (d / "b.stl").string(), d).rc, 0);
  std::string bytes = slurp(d / "b.stl");
  write(d / "cut.stl", bytes.substr(0, bytes.size() - 20));
  expect_one_line_error(run_cli("describe " + (d / "cut.stl").string(), d), "cut.stl");
}

TEST(Cli, MissingFile) {
  const fs::path d = scratch();
  expect_one_line_error(run_cli("describe " + (d / "nope.stl").string(), d), "nope.stl");
  expect_one_line_error(
      run_cli("shapes --recipe " + (d / "nope.toml").string() + " --out " + (d / "o").string(), d),
      "nope.toml");
  EXPECT_FALSE(fs::exists(d / "o"));
}

TEST(Cli, OpenMesh) {
  const fs::path d = scratch();
  write(d / "open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  expect_one_line_error(run_cli("describe " + (d / "open.obj").string(), d), "open.obj");
}

TEST(Cli, NanInRecipe) {
  const fs::path d = scratch();
  write(d / "nan.toml",
        "[[fraction]]\nmethod = \"block\"\ncount = 2\nW = 0.03\nL = 0.05\nH = 0.02\nsl = nan\n");
  const Result r =
      run_cli("shapes --recipe " + (d / "nan.toml").string() + " --out " + (d / "o").string(), d);
  expect_one_line_error(r, "nan.toml");
  EXPECT_NE(r.err.find("fraction[0].sl"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nan"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "o"));
  EXPECT_FALSE(fs::exists(d / "o.partial"));
}

TEST(Cli, SlGreaterThanSu) {
  const fs::path d = scratch();
  write(d / "slsu.toml",
        "[[fraction]]\nmethod = \"block\"\ncount = 2\nW = 0.03\nL = 0.05\nH = 0.02\nsl = 1.3\nsu = "
        "1.1\n");
  const Result r =
      run_cli("shapes --recipe " + (d / "slsu.toml").string() + " --out " + (d / "o").string(), d);
  expect_one_line_error(r, "slsu.toml");
  EXPECT_NE(r.err.find("fraction[0].sl"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1.3"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "o"));
  // Same rule on the single-shape command.
  const Result s =
      run_cli("shape block --L 1 --W 1 --H 1 --sl 1.3 --su 1.1 -o " + (d / "x.stl").string(), d);
  expect_one_line_error(s, "sl");
  EXPECT_FALSE(fs::exists(d / "x.stl"));
}

TEST(Cli, UnknownRecipeKey) {
  const fs::path d = scratch();
  write(d / "key.toml",
        "[[fraction]]\nmethod = \"block\"\ncount = 2\nW = 0.03\nL = 0.05\nH = 0.02\nsigma = 3\n");
  const Result r =
      run_cli("shapes --recipe " + (d / "key.toml").string() + " --out " + (d / "o").string(), d);
  expect_one_line_error(r, "key.toml");
  EXPECT_NE(r.err.find("fraction[0].sigma"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "o"));
  write(d / "top.toml",
        "sead = 3\n[[fraction]]\nmethod = \"block\"\ncount = 2\nW = 0.03\nL = 0.05\nH = 0.02\n");
  expect_one_line_error(
      run_cli("shapes --recipe " + (d / "top.toml").string() + " --out " + (d / "o").string(), d),
      "sead");
}

TEST(Cli, BadCommandLineValues) {
  const fs::path d = scratch();
  expect_one_line_error(run_cli("shape box --size 1,-1,1 -o " + (d / "b.stl").string(), d), "-1");
  expect_one_line_error(
      run_cli("shape hull --diameter 1 --roundness 1.4 -o " + (d / "h.stl").string(), d),
      "--roundness");
  expect_one_line_error(run_cli("shape box --size 1,1,1 -o " + (d / "b.xyz").string(), d), "b.xyz");
  EXPECT_FALSE(fs::exists(d / "b.stl"));
  EXPECT_FALSE(fs::exists(d / "h.stl"));
}

TEST(Cli, BundledRecipesParse) {
  const fs::path d = scratch();
  for (const char* name : {"srm-rock-blocks", "sand-roundness", "rockfill-shapes"}) {
    // Parse-only check of the bundled files: generate into a scratch dir with a tiny copy.
    const std::string text =
        slurp(fs::path(CLUMPKIT_SOURCE_DIR) / "assets" / "recipes" / (std::string(name) + ".toml"));
    ASSERT_FALSE(text.empty()) << name;
  }
  const Result r =
      run_cli("shapes --quiet --recipe " +
                  (fs::path(CLUMPKIT_SOURCE_DIR) / "assets/recipes/rockfill-shapes.toml").string() +
                  " --out " + (d / "rf").string(),
              d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_TRUE(fs::exists(d / "rf" / "meshes" / "00059.stl"));
}

// `clumpkit fill` output, JSON report and bad input.
TEST(Cli, FillWritesClumpAndReport) {
  const fs::path d = scratch();
  ASSERT_EQ(
      run_cli("shape block --L 75.1 --W 58.0 --H 49.8 --seed 1 -o " + (d / "b.stl").string(), d).rc,
      0);
  const Result r = run_cli("fill " + (d / "b.stl").string() + " -o " + (d / "c.csv").string() +
                               " --spheres 47 --json --png " + (d / "c.png").string() + " --vtp " +
                               (d / "c.vtp").string(),
                           d);
  ASSERT_EQ(r.rc, 0) << r.err;
  // The picture: 900 × 962, something drawn in the middle of each of its four views.
  const auto im = clumpkit::read_png((d / "c.png").string());
  ASSERT_EQ(im.width, 900);
  ASSERT_EQ(im.height, 962);
  for (int v = 0; v < 4; ++v) {
    long drawn = 0;
    const int x0 = (v % 2) * 450, y0 = 62 + (v / 2) * 450;
    for (int y = y0 + 175; y < y0 + 275; ++y)
      for (int x = x0 + 175; x < x0 + 275; ++x) drawn += im.at(x, y)[0] != 255;
    EXPECT_GT(drawn, 5000) << "view " << v;
  }
  const std::string vtp = slurp(d / "c.vtp");
  EXPECT_NE(vtp.find("NumberOfVerts=\"47\" NumberOfPolys=\"48\""), std::string::npos);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k :
       {"spheres", "mesh_volume", "clump_volume", "covered_fraction", "overshoot_fraction",
        "surface_mean_distance", "surface_max_distance", "seconds"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["spheres"], 47);
  EXPECT_GT(j["covered_fraction"].get<double>(), 0.85);
  EXPECT_LT(j["overshoot_fraction"].get<double>(), 0.01);
  const std::string csv = slurp(d / "c.csv");
  EXPECT_NE(csv.find("x[L],y[L],z[L],r[L]\n"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 47 + 1 + 2);  // header, 2 comment lines
  EXPECT_EQ(expect_units_everywhere(d), 1);                         // the clump
  EXPECT_EQ(json_numbers_without_unit(j), std::vector<std::string>{});
}

TEST(Cli, FillBadInput) {
  const fs::path d = scratch();
  ASSERT_EQ(run_cli("shape box --size 1,1,1 -o " + (d / "b.stl").string(), d).rc, 0);
  const std::string out = " -o " + (d / "c.csv").string();
  expect_one_line_error(run_cli("fill " + (d / "b.stl").string() + out + " --spheres 0", d),
                        "--spheres");
  expect_one_line_error(run_cli("fill " + (d / "b.stl").string() + out + " --min-radius -1", d),
                        "--min-radius");
  expect_one_line_error(run_cli("fill " + (d / "b.stl").string() + out + " --min-radius 5", d),
                        "min-radius");
  write(d / "open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  expect_one_line_error(run_cli("fill " + (d / "open.obj").string() + out, d), "open.obj");
  write(d / "empty.stl", "");
  expect_one_line_error(run_cli("fill " + (d / "empty.stl").string() + out, d), "empty.stl");
  // Pictures and ParaView files: their folder must exist, and no output may name another.
  expect_one_line_error(
      run_cli("fill " + (d / "b.stl").string() + out + " --png " + (d / "no" / "c.png").string(),
              d),
      "--png");
  expect_one_line_error(
      run_cli("fill " + (d / "b.stl").string() + out + " --vtp " + (d / "c.csv").string(), d),
      "--vtp");
  expect_one_line_error(
      run_cli("fill " + (d / "b.stl").string() + out + " --png " + (d / "b.stl").string(), d),
      "--png");
  EXPECT_FALSE(fs::exists(d / "c.csv"));
  EXPECT_FALSE(fs::exists(d / "no"));
}

// `clumpkit library` is byte-identical for 1 and 2 threads, and a killed run resumes to
// the same bytes.

TEST(Cli, LibraryDeterministicAndResumable) {
  const fs::path d = scratch();
  write(d / "r.toml", kLibraryRecipe);
  const std::string base = "library --quiet --recipe " + (d / "r.toml").string() + " --out ";
  Result r = run_cli(base + (d / "t1").string() + " --threads 1", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run_cli(base + (d / "t2").string() + " --threads 2", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  expect_same_tree(d / "t1", d / "t2");
  EXPECT_TRUE(fs::exists(d / "t1" / "particles" / "00011.csv"));
  const std::string table = slurp(d / "t1" / "library.csv");
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 13);
  EXPECT_NE(table.find("covered_fraction"), std::string::npos);

  // Killed half-way (a real SIGKILL at an arbitrary moment), then resumed.
  const std::string kill = "timeout -s KILL 0.6 " + std::string(CLUMPKIT_BINARY) + " " + base +
                           (d / "k").string() + " --threads 2 >/dev/null 2>&1";
  (void)std::system(kill.c_str());
  r = run_cli(base + (d / "k").string() + " --threads 2 --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  expect_same_tree(d / "t1", d / "k");

  EXPECT_FALSE(fs::exists(d / "k.partial"));

  // Stopped by SIGINT (Ctrl-C) a moment after the start (the whole run takes ~0.3 s on one
  // thread): exit 130 with one line saying so and the finished particles kept in i.partial,
  // then resumed. (A signal before the handler is installed kills at once, also status 130.)
  const std::string stop = "timeout --preserve-status -s INT 0.12 " + std::string(CLUMPKIT_BINARY) +
                           " " + base + (d / "i").string() + " --threads 1 >/dev/null 2>" +
                           (d / "i.err").string();
  const int status = std::system(stop.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 130) {
    EXPECT_FALSE(fs::exists(d / "i"));
    if (fs::exists(d / "i.partial")) {
      EXPECT_NE(slurp(d / "i.err").find("clumpkit: stopped: "), std::string::npos)
          << slurp(d / "i.err");
      EXPECT_NE(slurp(d / "i.err").find("library stopped on request after"), std::string::npos);
    }
  } else {
    EXPECT_EQ(WEXITSTATUS(status), 0) << slurp(d / "i.err");
  }
  r = run_cli(base + (d / "i").string() + " --threads 2 --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  expect_same_tree(d / "t1", d / "i");

  // Simulated crash after half the particles: the work directory t3.partial holds every other
  // particle record and no tables.
  fs::copy(d / "t2", d / "t3.partial", fs::copy_options::recursive);
  for (int i = 0; i < 12; i += 2) {
    char name[32];
    std::snprintf(name, sizeof name, "%05d.json", i);
    ASSERT_TRUE(fs::remove(d / "t3.partial" / "particles" / name));
  }
  fs::remove(d / "t3.partial" / "library.csv");
  fs::remove(d / "t3.partial" / "manifest.json");
  r = run_cli(base + (d / "t3").string() + " --threads 2 --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["resumed"], 6);
  expect_same_tree(d / "t1", d / "t3");
  EXPECT_FALSE(fs::exists(d / "t3.partial"));

  // A work directory of another recipe is stale: discarded, nothing of it is kept.
  fs::copy(d / "t2", d / "t4.partial", fs::copy_options::recursive);
  {
    std::ofstream stale(d / "t4.partial" / "recipe.toml");
    stale << "seed = 1\n";
  }
  r = run_cli(base + (d / "t4").string() + " --threads 2 --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["resumed"], 0);
  expect_same_tree(d / "t1", d / "t4");
}

TEST(Cli, LibraryBadInput) {
  const fs::path d = scratch();
  std::string bad = kLibraryRecipe;
  bad.replace(bad.find("spheres = 20"), 12, "spheres = 0");
  write(d / "bad.toml", bad);
  const Result r =
      run_cli("library --recipe " + (d / "bad.toml").string() + " --out " + (d / "o").string(), d);
  expect_one_line_error(r, "fill.spheres");
  EXPECT_FALSE(fs::exists(d / "o"));
  // A directory that is not a clumpkit output is refused and left alone.
  write(d / "r.toml", kLibraryRecipe);
  fs::create_directories(d / "x");
  write(d / "x" / "notes.txt", "mine\n");
  expect_one_line_error(
      run_cli("library --recipe " + (d / "r.toml").string() + " --out " + (d / "x").string(), d),
      "not a clumpkit output");
  EXPECT_TRUE(fs::exists(d / "x" / "notes.txt"));
  EXPECT_FALSE(fs::exists(d / "x.partial"));
}

// `clumpkit volume`, every method on oracle C2, and bad or degenerate input.
TEST(Cli, VolumeAllMethodsOnOracleC2) {
  const fs::path d = scratch();
  write(d / "c2.csv", "# two unit balls 1 apart\nx,y,z,r\n0,0,0,1\n0,0,1,1\n");
  const Result r = run_cli("volume " + (d / "c2.csv").string() + " --method all --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double v = 9 * M_PI / 4;
  for (const char* m : {"exact", "inclusion_exclusion", "analytic_slice", "pixel_slice", "voxel"}) {
    ASSERT_TRUE(j.contains(m)) << m;
    EXPECT_TRUE(j[m].contains("seconds")) << m;
  }
  EXPECT_NEAR(j["exact"]["volume"].get<double>(), v, 1e-12 * v);
  EXPECT_NEAR(j["exact"]["centroid"][2].get<double>(), 0.5, 1e-12);
  EXPECT_NEAR(j["exact"]["inertia"][2][2].get<double>(), 3.004147974995, 1e-10 * 3.0);
  EXPECT_NEAR(j["exact"]["inertia"][0][0].get<double>(), 5.213080309551, 1e-10 * 5.2);
  EXPECT_NEAR(j["inclusion_exclusion"]["volume"].get<double>(), v, 1e-9 * v);
  EXPECT_NEAR(j["analytic_slice"]["volume"].get<double>(), v, 1e-9 * v);
  EXPECT_NEAR(j["pixel_slice"]["volume"].get<double>(), v, 0.05 * v);  // touch rule: biased high
  EXPECT_GT(j["pixel_slice"]["volume"].get<double>(), v);
  EXPECT_NEAR(j["voxel"]["volume"].get<double>(), v, 0.01 * v);
}

TEST(Cli, VolumeBadAndDegenerateInput) {
  const fs::path d = scratch();
  write(d / "zero.csv", "x,y,z,r\n0,0,0,1\n1,0,0,0\n");
  expect_one_line_error(run_cli("volume " + (d / "zero.csv").string(), d), "field r");
  write(d / "neg.csv", "x,y,z,r\n0,0,0,-1\n");
  expect_one_line_error(run_cli("volume " + (d / "neg.csv").string(), d), "-1");
  write(d / "nan.csv", "x,y,z,r\n0,nan,0,1\n");
  expect_one_line_error(run_cli("volume " + (d / "nan.csv").string(), d), "field y");
  write(d / "empty.csv", "");
  expect_one_line_error(run_cli("volume " + (d / "empty.csv").string(), d), "empty.csv");
  expect_one_line_error(run_cli("volume " + (d / "empty.csv").string() + " --method magic", d),
                        "--method");
  // 1e6 identical spheres: the answer of one sphere, no crash.
  {
    std::ofstream o(d / "same.csv");
    o << "x,y,z,r\n";
    for (int i = 0; i < 1000000; ++i) o << "1,2,3,1\n";
  }
  const Result r = run_cli("volume " + (d / "same.csv").string() + " --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["exact"]["volume"].get<double>(), 4 * M_PI / 3, 1e-12);
  EXPECT_EQ(j["exact"]["hidden_spheres"], 999999);
}

TEST(Cli, FillAllowOpenSaysItVotedAndKeepsTheOvershootContract) {
  // A sphere with one triangle missing, as a scan arrives: filled by voting within the contract.
  const fs::path d = scratch();
  clumpkit::Mesh scan = clumpkit::make_icosphere(3);
  scan.triangles.pop_back();
  clumpkit::write_mesh((d / "open.obj").string(), scan);
  Result r = run_cli("fill " + (d / "open.obj").string() + " -o " + (d / "c.csv").string() +
                         " --spheres 5 --allow-open --json",
                     d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["inside_outside"].get<std::string>().find("ray-parity"), std::string::npos);
  EXPECT_NE(r.err.find("ray-parity voting"), std::string::npos);
  EXPECT_NE(r.err.find("clumpkit repair"), std::string::npos);  // the other way out
  EXPECT_LE(j["overshoot_fraction"].get<double>(), j["max_overshoot"].get<double>());
  EXPECT_TRUE(fs::exists(d / "c.csv"));
  // A tetrahedron without a face has no inside the votes agree on: the contract cannot be met,
  // so the fill is refused rather than reported above it.
  write(d / "lid.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n");
  r = run_cli("fill " + (d / "lid.obj").string() + " -o " + (d / "l.csv").string() +
                  " --spheres 5 --allow-open",
              d);
  EXPECT_EQ(r.rc, 2) << r.err;
  EXPECT_NE(r.err.find("over --max-overshoot 0.01"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(d / "l.csv"));
}

TEST(Cli, SpecimenSameForAnyThreadCountAndAfterAKill) {
  const fs::path d = scratch();
  const std::string base = "specimen --quiet --checkpoint-seconds 0.5 --recipe " +
                           tiny_specimen_recipe(d).string() + " --out ";
  Result r = run_cli(base + (d / "t1").string() + " --threads 1", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  r = run_cli(base + (d / "t2").string() + " --threads 2 --json", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_EQ(json_numbers_without_unit(report), std::vector<std::string>{});
  // specimen.csv, calibration.csv, report.json, manifest.json, and the library's files.
  EXPECT_GE(expect_units_everywhere(d / "t1"), 4);
  for (const char* f : {"specimen.csv", "calibration.csv", "specimen.vtp"})
    EXPECT_EQ(slurp(d / "t1" / f), slurp(d / "t2" / f)) << f;
  EXPECT_FALSE(fs::exists(d / "t2" / "checkpoints"));
  EXPECT_FALSE(fs::exists(d / "t2.partial"));

  // A real SIGKILL part-way (the run takes several seconds), then --resume: same bytes, and
  // nothing at --out until the run has finished.
  const std::string kill = "timeout -s KILL 3 " + std::string(CLUMPKIT_BINARY) + " " + base +
                           (d / "k").string() + " --threads 2 >/dev/null 2>&1";
  (void)std::system(kill.c_str());
  EXPECT_FALSE(fs::exists(d / "k"));
  ASSERT_TRUE(fs::exists(d / "k.partial"));
  r = run_cli(base + (d / "k").string() + " --threads 2 --resume", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(slurp(d / "t1" / "specimen.csv"), slurp(d / "k" / "specimen.csv"));
  EXPECT_EQ(slurp(d / "t1" / "calibration.csv"), slurp(d / "k" / "calibration.csv"));

  // Ctrl-C (SIGINT) part-way: the running stages save a checkpoint, exit 130 with one line
  // naming what is kept, then --resume: same bytes.
  const std::string stop = "timeout --preserve-status -s INT 2 " + std::string(CLUMPKIT_BINARY) +
                           " " + base + (d / "i").string() + " --threads 2 >/dev/null 2>" +
                           (d / "i.err").string();
  const int status = std::system(stop.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(d / "i.err");
  const std::string said = slurp(d / "i.err");
  EXPECT_NE(said.find("clumpkit: stopped: "), std::string::npos) << said;
  EXPECT_NE(said.find("continue with --resume"), std::string::npos) << said;
  EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
  EXPECT_FALSE(fs::exists(d / "i"));
  r = run_cli(base + (d / "i").string() + " --threads 2 --resume", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(slurp(d / "t1" / "specimen.csv"), slurp(d / "i" / "specimen.csv"));

  // The report: bodies and spheres match specimen.csv, porosities in range, Dr consistent.
  const std::string csv = slurp(d / "t2" / "specimen.csv");
  const auto bodies_at = csv.find("body[1],kind,"), spheres_at = csv.find("# spheres");
  ASSERT_NE(spheres_at, std::string::npos);
  const long body_lines = std::count(csv.begin() + bodies_at, csv.begin() + spheres_at, '\n') - 1;
  const long sphere_lines = std::count(csv.begin() + spheres_at, csv.end(), '\n') - 2;
  EXPECT_EQ(report["bodies"].get<long>(), body_lines);
  EXPECT_EQ(report["spheres"].get<long>(), sphere_lines);
  EXPECT_GT(report["rocks"].get<long>(), 0);
  const double n = report["porosity"], n_max = report["porosity_max"],
               n_min = report["porosity_min"];
  EXPECT_GT(n_max, n_min);
  EXPECT_GT(n, 0.3);
  EXPECT_LT(n, 0.5);
  const double e = n / (1 - n), e_max = n_max / (1 - n_max), e_min = n_min / (1 - n_min);
  EXPECT_NEAR(report["relative_density"].get<double>(), (e_max - e) / (e_max - e_min), 1e-12);
  EXPECT_EQ(report["layer_porosity"].size(), 2u);
  EXPECT_EQ(report["calibration"].size(), 6u);
  EXPECT_TRUE(fs::exists(d / "t2" / "calibration.png"));
  EXPECT_TRUE(fs::exists(d / "t2" / "manifest.json"));
  int slices = 0;
  for (const auto& e2 : fs::directory_iterator(d / "t2" / "slices"))
    slices += e2.path().extension() == ".png";
  EXPECT_EQ(slices, 5);
  const std::string vtp = slurp(d / "t2" / "specimen.vtp");
  EXPECT_NE(vtp.find("NumberOfPoints=\"" + std::to_string(sphere_lines) + "\""), std::string::npos);
}

TEST(Cli, SpecimenBadRecipesFailBeforeSimulation) {
  const fs::path d = scratch();
  tiny_specimen_recipe(d);
  const std::string good = kTinySpecimen;
  auto run = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    write(d / "bad.toml", text);
    return run_cli(
        "specimen --recipe " + (d / "bad.toml").string() + " --out " + (d / "o").string(), d);
  };
  expect_one_line_error(run("target_relative_density = 0.5", "target_relative_density = 1.5"),
                        "target_relative_density: must be in [0, 1], got 1.5");
  expect_one_line_error(run("passing = [100, 70, 0]", "passing = [90, 70, 0]"),
                        "gradation.passing[0]");
  expect_one_line_error(run("diameter = 0.060", "diameter = 0.020"), "container.diameter");
  expect_one_line_error(run("recipe = \"rocks.toml\"", "library = \"no-such-dir\""),
                        "rock.library: no clump library");
  // Gravity-free specimens: a cuboid needs the compression method, which has no layers.
  expect_one_line_error(
      run("diameter = 0.060\nheight = 0.100", "shape = \"cuboid\"\nsize = [0.1, 0.1, 0.1]"),
      "container.shape: a cuboid needs preparation.method");
  expect_one_line_error(run("[container]", "[preparation]\nmethod = \"compression\"\n[container]"),
                        "layers: applies to preparation.method");
  expect_one_line_error(run("[container]", "[preparation]\nmethod = \"squeeze\"\n[container]"),
                        "preparation.method: expected");
  expect_one_line_error(
      run("[container]", "[contact]\nstiffness_scaling = \"linear\"\n[container]"),
      "contact.d_ref");
  EXPECT_FALSE(fs::exists(d / "o"));
  EXPECT_FALSE(fs::exists(d / "o.partial"));
}
