// Helpers of the end-to-end tests: run the clumpkit binary, scratch directories, the error
// contract, and the tiny specimen recipe several commands share.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

struct Result {
  int rc = -1;
  std::string out, err;
};

inline fs::path scratch() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  fs::path p = fs::temp_directory_path() / "clumpkit_cli_tests" /
               (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write(const fs::path& p, const std::string& text) {
  std::ofstream o(p, std::ios::binary);
  o << text;
}

inline Result run_cli(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd =
      std::string(CLUMPKIT_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  Result r;
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// Whether a program is on the PATH (the DEM engines the export tests run).
inline bool have_program(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

// The error contract: exit code 2 and exactly one line "clumpkit: error: ..." containing `needle`.
inline void expect_one_line_error(const Result& r, const std::string& needle) {
  EXPECT_EQ(r.rc, 2) << r.err;
  EXPECT_EQ(r.err.rfind("clumpkit: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << "missing '" << needle << "' in: " << r.err;
}

// A tiny specimen recipe (a 60 mm cylinder, about 600 bodies) with its rock-library recipe.

inline const char* kTinyRocks = R"(name = "tiny-rocks"
seed = 3

[[fraction]]
name = "rock 10-15 mm"
method = "block"
count = 6
W = { uniform = [0.010, 0.015] }
L_over_H = { uniform = [1.2, 2.0] }
W_split = { uniform = [0.3, 0.7] }

[fill]
spheres = 8
voxels = 16
)";

inline const char* kTinySpecimen = R"(name = "tiny-specimen"
seed = 5
soil_rock_threshold = 0.010
rock_mass_fraction = 0.30
target_relative_density = 0.5
layers = 2

[container]
diameter = 0.060
height = 0.100

[gradation]
sieves = [0.015, 0.010, 0.006]
passing = [100, 70, 0]

[fines]
below = 0.005
replace_with = [0.005, 0.010]

[rock]
recipe = "rocks.toml"
)";

inline fs::path tiny_specimen_recipe(const fs::path& d) {
  write(d / "rocks.toml", kTinyRocks);
  write(d / "tiny.toml", kTinySpecimen);
  return d / "tiny.toml";
}

// Builds the tiny specimen into `d`/spec (about 600 bodies, 6 s); fails the test if it cannot.
inline void build_tiny_specimen(const fs::path& d) {
  const Result r = run_cli("specimen --quiet --recipe " + tiny_specimen_recipe(d).string() +
                               " --out " + (d / "spec").string(),
                           d);
  ASSERT_EQ(r.rc, 0) << r.err;
}

/// Whitespace-separated numbers of every line of `path` not starting with '#'.
inline std::vector<std::vector<double>> number_table(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::vector<double> row;
    double v;
    while (s >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

/// Rows of a LAMMPS dump (custom or local) after its ITEM: ATOMS / ITEM: ENTRIES line.
inline std::vector<std::vector<double>> dump_rows(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> rows;
  bool data = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: ATOMS", 0) == 0 || line.rfind("ITEM: ENTRIES", 0) == 0) {
      data = true;
      continue;
    }
    if (!data) continue;
    std::istringstream s(line);
    std::vector<double> row;
    double v;
    while (s >> v) row.push_back(v);
    rows.push_back(row);
  }
  std::sort(rows.begin(), rows.end());  // by id (atoms) or by the owning atom id (bodies)
  return rows;
}

}  // namespace cli_test
