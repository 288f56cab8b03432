// `clumpkit cells`: a random-plane particle cut into Voronoi cells through the binary — the
// cells tile the parent, the files agree with the report, the same command gives the same bytes.
#include "cli_helpers.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace cli_test;

TEST(CliCells, CutsAParticleIntoBondedCellsReproducibly) {
  const fs::path d = scratch();
  // OBJ keeps the corners' doubles exactly (an STL rounds them to floats).
  const std::string parent = (d / "parent.obj").string();
  ASSERT_EQ(run_cli("shape polyhedron --planes 30 --diameter 0.0275 --seed 7 -o " + parent, d).rc,
            0);
  const Result r = run_cli(
      "cells " + parent + " --cell-size 0.0065 --seed 3 --out " + (d / "a").string() + " --json",
      d);
  ASSERT_EQ(r.rc, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["cells"], 76);  // round((27.5 / 6.5)³) = round(75.7)
  EXPECT_EQ(json_numbers_without_unit(j), std::vector<std::string>{});
  EXPECT_GE(expect_units_everywhere(d / "a"), 5);  // cells, bonds, bond points, report, manifest
  EXPECT_LT(std::abs(j["volume_error"].get<double>()), 1e-12);
  EXPECT_NEAR(j["cells_volume"].get<double>() / j["parent_volume"].get<double>(), 1.0, 1e-12);
  // The parent's volume is describe's.
  const Result describe = run_cli("describe " + parent + " --json", d);
  ASSERT_EQ(describe.rc, 0);
  EXPECT_NEAR(nlohmann::json::parse(describe.out)["volume"].get<double>() /
                  j["parent_volume"].get<double>(),
              1.0, 1e-12);
  // The files hold what the report counts: one cells.csv row per cell, one bonds.csv row per
  // bond, the points of bond_points.csv, and cells.vtp's polygons are the cells' faces.
  const auto cells = csv_rows(d / "a" / "cells.csv");
  const auto bonds = csv_rows(d / "a" / "bonds.csv");
  const auto points = csv_rows(d / "a" / "bond_points.csv");
  ASSERT_EQ(cells.size(), 76u);
  ASSERT_EQ(static_cast<int>(bonds.size()), j["bonds"].get<int>());
  ASSERT_EQ(static_cast<int>(points.size()), j["bond_points"].get<int>());
  double volume = 0, faces = 0, area = 0, point_area = 0;
  for (const auto& c : cells) volume += c[1], faces += c[11];
  for (const auto& b : bonds) {
    area += b[3];
    EXPECT_GE(b[10], 0.75);
    EXPECT_LE(b[10], 1.25);
  }
  for (const auto& p : points) point_area += p[4];
  EXPECT_NEAR(volume / j["parent_volume"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(point_area / area, 1.0, 1e-12);
  EXPECT_NE(slurp(d / "a" / "cells.vtp")
                .find("NumberOfPolys=\"" + std::to_string(static_cast<int>(faces)) + "\""),
            std::string::npos);
  const nlohmann::json manifest = nlohmann::json::parse(slurp(d / "a" / "manifest.json"));
  EXPECT_EQ(manifest["command"], "cells");
  EXPECT_EQ(manifest["seed"], 3);
  // The same command, the same bytes; another seed, other cells; --count and no strength spread.
  ASSERT_EQ(
      run_cli("cells " + parent + " --cell-size 0.0065 --seed 3 --out " + (d / "b").string(), d).rc,
      0);
  expect_same_tree(d / "a", d / "b");
  ASSERT_EQ(
      run_cli(
          "cells " + parent + " --count 20 --seed 4 --strength-sd 0 --out " + (d / "c").string(), d)
          .rc,
      0);
  const auto c_bonds = csv_rows(d / "c" / "bonds.csv");
  EXPECT_EQ(csv_rows(d / "c" / "cells.csv").size(), 20u);
  for (const auto& b : c_bonds) EXPECT_EQ(b[10], 1.0);
}
