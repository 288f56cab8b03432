// clumpkit page through the CLI, without a browser (tests/browser/ opens the pages): a library's
// page holds every particle and the same bytes twice; folders it does not know, damaged files and
// mixed comparisons are refused with one line and nothing written.
#include "cli_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

using namespace cli_test;

namespace {

// The JSON inside a page's data script (window.NAME = JSON;) or part script (f(JSON);).
nlohmann::json script_json(const fs::path& path, char open, char close) {
  const std::string t = slurp(path);
  return nlohmann::json::parse(t.substr(t.find(open) + 1, t.rfind(close) - t.find(open) - 1));
}

void expect_nothing_written(const fs::path& dir) {
  EXPECT_FALSE(fs::exists(dir / "index.html"));
  EXPECT_FALSE(fs::exists(dir / "page"));
  EXPECT_FALSE(fs::exists(dir / "page.partial"));
}

}  // namespace

TEST(CliPage, ALibraryPageHoldsEveryParticleAndItsSpheresTheSameBytesTwice) {
  const fs::path d = scratch();
  write(d / "rocks.toml", kTinyRocks);
  const std::string lib = (d / "lib").string();
  Result r = run_cli(
      "library --quiet --recipe " + (d / "rocks.toml").string() + " --out " + lib + " --page", d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_NE(r.out.find("page: " + lib + "/index.html"), std::string::npos) << r.out;
  const nlohmann::json data = script_json(d / "lib" / "page" / "data.js", '=', ';');
  EXPECT_EQ(data["kind"], "library");
  const std::string table = slurp(d / "lib" / "library.csv");
  const std::size_t particles = std::count(table.begin(), table.end(), '\n') - 1;
  ASSERT_EQ(data["table"]["rows"].size(), particles);
  for (std::size_t k = 0; k < particles; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "%05d", static_cast<int>(k));
    const nlohmann::json part =
        script_json(d / "lib" / "page" / "parts" / (std::string(name) + ".js"), '(', ')');
    // Every sphere of the clump, in the mesh's frame, radius to six digits.
    std::vector<std::vector<double>> spheres;
    for (auto& row : csv_rows(d / "lib" / "particles" / (std::string(name) + ".csv")))
      if (row.size() == 4) spheres.push_back(row);
    ASSERT_EQ(part["s"].size(), spheres.size()) << name;
    for (std::size_t s = 0; s < spheres.size(); ++s)
      EXPECT_NEAR(part["s"][s][3].get<double>(), spheres[s][3], 5e-6 * spheres[s][3]);
    EXPECT_EQ(part["f"].size() % 3, 0u);
  }
  for (const char* f : {"three.min.js", "three-LICENSE.txt", "page.js", "page.css"})
    EXPECT_TRUE(fs::exists(d / "lib" / "page" / f)) << f;
  const std::string first = slurp(d / "lib" / "page" / "data.js");
  r = run_cli("page " + lib, d);
  ASSERT_EQ(r.rc, 0) << r.err;
  EXPECT_EQ(slurp(d / "lib" / "page" / "data.js"), first);
  EXPECT_FALSE(fs::exists(d / "lib" / "page.partial"));
}

TEST(CliPage, UnknownFoldersDamagedFilesAndMixedComparisonsAreRefusedNothingWritten) {
  const fs::path d = scratch();
  const auto page = [&](const std::string& args) {
    std::string a = "page";
    std::istringstream words(args);
    for (std::string w; words >> w;) a += " " + (w == "--out" ? w : (d / w).string());
    return run_cli(a, d);
  };
  fs::create_directories(d / "plain");
  Result r = page("plain");
  expect_one_line_error(r, "plain/manifest.json: not found");
  expect_nothing_written(d / "plain");

  fs::create_directories(d / "broken");
  write(d / "broken" / "manifest.json", "{\"tool\": \"clumpkit\", \"command\": ");
  r = page("broken");
  expect_one_line_error(r, "broken/manifest.json");
  expect_nothing_written(d / "broken");

  fs::create_directories(d / "cells");
  write(d / "cells" / "manifest.json", R"({"tool": "clumpkit", "command": "cells"})");
  r = page("cells");
  expect_one_line_error(r, "command 'cells' has no page");
  expect_nothing_written(d / "cells");

  // A library whose table lost a field on one row.
  write(d / "rocks.toml", kTinyRocks);
  ASSERT_EQ(run_cli("library --quiet --recipe " + (d / "rocks.toml").string() + " --out " +
                        (d / "lib").string(),
                    d)
                .rc,
            0);
  std::string table = slurp(d / "lib" / "library.csv");
  table.erase(table.rfind(','));
  write(d / "lib" / "library.csv", table + "\n");
  r = page("lib");
  expect_one_line_error(r, "lib/library.csv:7:");
  expect_nothing_written(d / "lib");

  r = page("lib lib --out both");
  expect_one_line_error(r, "a page of several folders compares tests of one kind");
  EXPECT_FALSE(fs::exists(d / "both"));
}

namespace {

// `dir` as clumpkit wrote it before units were recorded: CSV headers without units (and the
// names that carried an SI unit, axial_stress_pa, qc_pa, ...), manifests and reports without
// "units".
void as_written_before_units(const fs::path& dir) {
  const std::vector<std::pair<std::string, std::string>> old_names = {
      {"axial_stress", "axial_stress_pa"},
      {"radial_stress", "radial_stress_pa"},
      {"p", "p_pa"},
      {"q", "q_pa"},
      {"work", "work_pa"},
      {"depth", "depth_m"},
      {"qc", "qc_pa"},
      {"fs", "fs_pa"},
      {"sieve", "sieve_m"}};
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    if (name == "manifest.json" || name == "report.json") {  // records keep theirs: checksummed
      nlohmann::ordered_json j = nlohmann::ordered_json::parse(slurp(e.path()));
      j.erase("units");
      write(e.path(), j.dump(1));
    } else if (e.path().extension() == ".csv") {
      std::istringstream in(slurp(e.path()));
      std::string out;
      for (std::string line; std::getline(in, line);) {
        if (line.find('[') != std::string::npos && line[0] != '#') {
          std::string bare;
          for (const std::string& cell : clumpkit::split_csv(line)) {
            std::string name = clumpkit::column_name(cell);
            for (const auto& [now, then] : old_names)
              if (name == now) name = then;
            bare += (bare.empty() ? "" : ",") + name;
          }
          line = bare;
        }
        out += line + "\n";
      }
      write(e.path(), out);
    }
  }
}

}  // namespace

// Folders written before units still open: the page (with a note that their units are not
// recorded) and compare-curves (by today's column names or the old ones).
TEST(CliPage, FoldersWrittenBeforeUnitsStillOpenWithANote) {
  const fs::path d = scratch();
  build_tiny_specimen(d);
  fs::copy(d / "spec", d / "old", fs::copy_options::recursive);
  as_written_before_units(d / "old");
  ASSERT_EQ(slurp(d / "old" / "specimen.csv").find('['), std::string::npos);
  for (const char* dir : {"spec", "old"}) {
    const Result r = run_cli("page " + (d / dir).string(), d);
    ASSERT_EQ(r.rc, 0) << dir << ": " << r.err;
  }
  const nlohmann::json now = script_json(d / "spec" / "page" / "data.js", '=', ';');
  const nlohmann::json then = script_json(d / "old" / "page" / "data.js", '=', ';');
  EXPECT_TRUE(now["units_recorded"].get<bool>());
  EXPECT_FALSE(then["units_recorded"].get<bool>());
  // The same specimen either way: the page's own data differs only in what says units.
  EXPECT_EQ(now["folders"].size(), then["folders"].size());

  // Curves: today's header and the old one give the same curve under either name.
  write(d / "now.csv", "step[1],depth[m],qc[Pa]\n0,0,1e5\n1,0.01,2e5\n2,0.02,4e5\n");
  write(d / "then.csv", "step,depth_m,qc_pa\n0,0,1e5\n1,0.01,2e5\n2,0.02,4e5\n");
  for (const char* columns : {"--x depth --y qc", "--x depth_m --y qc_pa"}) {
    const Result r = run_cli("compare-curves " + (d / "now.csv").string() + " " +
                                 (d / "then.csv").string() + " " + columns + " --json",
                             d);
    ASSERT_EQ(r.rc, 0) << columns << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["residual_abs"].get<double>(), 0.0) << columns;
  }
}
