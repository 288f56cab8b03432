// Helpers of the end-to-end tests: run the clumpkit binary, scratch directories, the error
// contract, and the tiny specimen recipe several commands share.
#pragma once

#include "geom/hash.h"
#include "units_check.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
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

/// Runs `clumpkit ARGS` (in the test's working directory: give it absolute paths), its standard
/// output and error captured through files in `dir`.
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

/// The numeric rows of a CSV file with a one-line header (given back in `header`); with
/// `columns` > 0 each row is expected to hold that many numbers (a row that does not is reported
/// and left out).
inline std::vector<std::vector<double>> csv_rows(const fs::path& path, std::size_t columns = 0,
                                                 std::string* header = nullptr) {
  std::istringstream in(slurp(path));
  std::string line;
  std::getline(in, line);
  if (header) *header = line;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream s(line);
    std::vector<double> row;
    double v;
    while (s >> v) row.push_back(v);
    if (columns == 0) {
      rows.push_back(row);
      continue;
    }
    EXPECT_EQ(row.size(), columns) << path << ": " << line;
    if (row.size() == columns) rows.push_back(row);
  }
  return rows;
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

// A tiny specimen recipe (a 60 mm cylinder, about 600 bodies) with its rock-library recipe, from
// tests/cli/tiny/ (the Python suite builds the same specimen).
inline const std::string kTinyRocks = slurp(CLUMPKIT_SOURCE_DIR "/tests/cli/tiny/rocks.toml");
inline const std::string kTinySpecimen = slurp(CLUMPKIT_SOURCE_DIR "/tests/cli/tiny/tiny.toml");

inline fs::path tiny_specimen_recipe(const fs::path& d) {
  write(d / "rocks.toml", kTinyRocks);
  write(d / "tiny.toml", kTinySpecimen);
  return d / "tiny.toml";
}

// The tiny specimen is deterministic, so the tests that only read it share one build per binary:
// the first to ask builds it under a lock in the build tree (test-cache/), the others wait and
// copy it. (Under the sanitizers one build takes a minute; eight tests need it.)
inline fs::path shared_tiny_specimen() {
  const fs::path binary(CLUMPKIT_BINARY);
  // Keyed by the recipes and the binary's stamp, so a rebuilt binary builds afresh.
  const std::string stamp = std::string(kTinyRocks) + kTinySpecimen +
                            std::to_string(fs::file_size(binary)) +
                            std::to_string(fs::last_write_time(binary).time_since_epoch().count());
  const std::uint64_t key = clumpkit::fnv1a(stamp.data(), stamp.size());
  const fs::path cache = binary.parent_path() / "test-cache";
  fs::create_directories(cache);
  const fs::path dir = cache / ("tiny-" + std::to_string(key));
  const int lock = ::open((dir.string() + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
  EXPECT_GE(lock, 0);
  ::flock(lock, LOCK_EX);
  if (!fs::exists(dir / "spec" / "manifest.json")) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    const Result r = run_cli("specimen --quiet --recipe " + tiny_specimen_recipe(dir).string() +
                                 " --out " + (dir / "spec").string(),
                             dir);
    EXPECT_EQ(r.rc, 0) << r.err;
  }
  ::flock(lock, LOCK_UN);
  ::close(lock);
  return dir / "spec";
}

// The tiny specimen (about 600 bodies) and its recipes in `d` (spec/, tiny.toml, rocks.toml): a
// copy of the shared build; fails the test if it cannot be built.
inline void build_tiny_specimen(const fs::path& d) {
  const fs::path spec = shared_tiny_specimen();
  ASSERT_TRUE(fs::exists(spec / "manifest.json")) << "the tiny specimen was not built";
  tiny_specimen_recipe(d);
  fs::copy(spec, d / "spec", fs::copy_options::recursive);
}

/// `o` with every "seconds" member removed, at any depth (the wall-clock fields of reports).
inline nlohmann::json without_seconds(nlohmann::json o) {
  if (o.is_object()) {
    o.erase("seconds");
    for (auto& [key, value] : o.items()) value = without_seconds(value);
  } else if (o.is_array()) {
    for (auto& value : o) value = without_seconds(value);
  }
  return o;
}

/// Every file under `a` and `b` is the same, byte for byte, and both hold the same files; JSON
/// files are compared with their wall-clock "seconds" fields left out.
inline void expect_same_outputs(const fs::path& a, const fs::path& b) {
  auto files = [](const fs::path& root) {
    std::vector<fs::path> found;
    for (const auto& e : fs::recursive_directory_iterator(root))
      if (e.is_regular_file()) found.push_back(fs::relative(e.path(), root));
    std::sort(found.begin(), found.end());
    return found;
  };
  const std::vector<fs::path> in_a = files(a), in_b = files(b);
  ASSERT_EQ(in_a, in_b) << a << " and " << b << " hold different files";
  ASSERT_FALSE(in_a.empty()) << a;
  for (const fs::path& f : in_a) {
    if (f.extension() == ".json")
      EXPECT_EQ(without_seconds(nlohmann::json::parse(slurp(a / f))),
                without_seconds(nlohmann::json::parse(slurp(b / f))))
          << f;
    else
      EXPECT_TRUE(slurp(a / f) == slurp(b / f)) << f << " differs";
  }
}

/// Runs `clumpkit ARGS` with its standard error to `cwd`/stopped.err (and its working directory
/// there), sends it SIGTERM after `seconds` and waits for it; returns its exit code (130 when it
/// stopped at a safe point, 0 when it had already finished, 143 when the signal came before it
/// had installed its handler).
inline int run_cli_stopped_after(const std::string& args, const fs::path& cwd, double seconds) {
  char delay[32];
  std::snprintf(delay, sizeof delay, "%.3f", seconds);
  const std::string script = "cd " + cwd.string() + " && { " + CLUMPKIT_BINARY + " " + args +
                             " >/dev/null 2>stopped.err & pid=$!; sleep " + delay +
                             "; kill -TERM $pid 2>/dev/null; wait $pid; }";
  const int status = std::system(("bash -c '" + script + "'").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A time drawn uniformly in [lo, hi] from the machine's entropy, so every run of a fault test
/// stops its job somewhere else; the test prints it.
inline double random_seconds(double lo, double hi) {
  std::random_device entropy;
  return std::uniform_real_distribution<double>(lo, hi)(entropy);
}

/// Wall-clock seconds `run` takes.
template <class F>
double timed(F&& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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

// A library of 8 blocks and 4 grains at 20 spheres: small enough for an end-to-end run.
inline constexpr const char* kLibraryRecipe = R"(seed = 11
[[fraction]]
name = "blocks"
method = "block"
count = 8
W = { uniform = [0.02, 0.04] }
L_over_H = { lognormal = { mu = 0.47, sigma = 0.25, min = 1.0, max = 3.5 } }
W_split = { uniform = [0.3, 0.7] }

[[fraction]]
name = "grains"
method = "hull"
count = 4
diameter = 0.01
roundness = [1.1, 1.3]

[fill]
spheres = 20
voxels = 24
)";

// Every regular file under `a` is in `b` with the same bytes, and `b` has no others.
inline void expect_same_tree(const fs::path& a, const fs::path& b) {
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), a);
    ASSERT_TRUE(fs::exists(b / rel)) << rel;
    EXPECT_EQ(slurp(e.path()), slurp(b / rel)) << rel;
    ++files;
  }
  int other = 0;
  for (const auto& e : fs::recursive_directory_iterator(b)) other += e.is_regular_file();
  EXPECT_EQ(files, other);
}

}  // namespace cli_test
