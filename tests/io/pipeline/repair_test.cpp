// `clumpkit repair` (io/pipeline/repair.h, geom/mesh/repair.h): a sphere with holes punched in it
// closes to within 1 % of its volume and then reads and fills as a watertight solid; what cannot
// be repaired is refused with nothing written.
#include "io/pipeline/repair.h"

#include "geom/errors.h"
#include "geom/shapes/primitives.h"
#include "io/base/json_file.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/fill.h"
#include "io/pipeline/library.h"
#include "io/recipes/recipe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

using namespace clumpkit;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("clumpkit_repair_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The fill job's options for `mesh` to `out` with a budget of `spheres`, the rest at defaults.
FillJobOptions fill_options(const fs::path& mesh, const fs::path& out, int spheres) {
  FillJobOptions fill;
  fill.mesh = mesh.string();
  fill.out = out.string();
  fill.fill.spheres = spheres;
  return fill;
}

// The icosphere of level 3 without the triangles around three of its vertices: three holes.
Mesh holed_sphere() {
  Mesh m = make_icosphere(3);
  const std::set<int> centres = {0, 5, 11};  // vertices of the icosahedron, far apart
  std::vector<std::array<int, 3>> kept;
  for (const auto& t : m.triangles)
    if (!centres.count(t[0]) && !centres.count(t[1]) && !centres.count(t[2])) kept.push_back(t);
  m.triangles = kept;
  return m;
}

// Triangles within k vertex steps of vertex v (k = 1: its fan).
std::set<int> k_ring(const Mesh& m, int v, int k) {
  std::set<int> near = {v}, tris;
  for (int step = 0; step < k; ++step) {
    tris.clear();
    for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
      for (int c : m.triangles[t])
        if (near.count(c)) tris.insert(t);
    if (step + 1 < k)
      for (int t : tris)
        for (int c : m.triangles[t]) near.insert(c);
  }
  return tris;
}

// A scan as public ones come: an icosphere of 20,480 triangles with 7 holes in its base (1- to
// 6-rings: 5 to 36 edges), 80 triangles present in both orientations (a double wall) and 5
// present twice in the same one.
Mesh scanned_sphere() {
  Mesh m = make_icosphere(5);
  std::vector<int> bases;
  for (int v = 0; v < static_cast<int>(m.vertices.size()) && bases.size() < 7; ++v) {
    if (m.vertices[v].z() > -0.3) continue;
    bool apart = true;
    for (int b : bases) apart = apart && (m.vertices[v] - m.vertices[b]).norm() > 0.5;
    if (apart) bases.push_back(v);
  }
  std::set<int> gone;
  const int rings[7] = {1, 1, 2, 3, 4, 5, 6};  // 5 or 6 edges a ring step
  for (std::size_t h = 0; h < bases.size(); ++h) {
    const std::set<int> r = k_ring(m, bases[h], rings[h]);
    gone.insert(r.begin(), r.end());
  }
  std::vector<std::array<int, 3>> kept;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    if (!gone.count(t)) kept.push_back(m.triangles[t]);
  const std::size_t n = kept.size();
  int walls = 0;
  for (std::size_t t = 0; t < n && walls < 80; t += 97)
    if (m.vertices[kept[t][0]].z() > 0.0)
      kept.push_back({kept[t][0], kept[t][2], kept[t][1]}), ++walls;
  for (std::size_t t = 50; t < n && t < 50 + 5 * 211; t += 211) kept.push_back(kept[t]);
  m.triangles = kept;
  return m;
}

}  // namespace

TEST(RepairJob, AScannedSphereWithBaseHolesAndDoubleWallsClosesAndFillsWithinTheContract) {
  const fs::path d = scratch("scan");
  const Mesh whole = make_icosphere(5);
  write_mesh((d / "scan.ply").string(), scanned_sphere());
  const RepairJobResult r = run_repair_job((d / "scan.ply").string(), (d / "closed.ply").string());
  EXPECT_EQ(r.repair.double_wall_triangles, 160);
  EXPECT_EQ(r.repair.duplicate_triangles, 5);
  EXPECT_EQ(r.repair.boundary_edges_after, 0);
  int base = 0, largest = 0;  // the 7 base holes (the walls leave holes of 3 edges)
  for (const RepairHole& h : r.repair.closed_holes)
    if (h.edges > 4) ++base, largest = std::max(largest, h.edges);
  EXPECT_EQ(base, 7);
  EXPECT_GE(largest, 30);
  EXPECT_LE(largest, 40);
  EXPECT_NEAR(r.repair.volume_after / signed_volume(whole), 1.0, 0.01);
  const FillJobOptions fill = fill_options(d / "closed.ply", d / "clump.csv", 50);
  const FillJobResult f = run_fill_job(
      fill, [](const std::string&) {}, [](const std::string&) {});
  EXPECT_EQ(f.report["inside_outside"], "ray parity along the grid rows (watertight mesh)");
  EXPECT_LE(f.fidelity.overshoot_fraction, fill.fill.max_overshoot);
  // A ball is one sphere to the fill (budget 50): the repaired base holds nothing outside it.
  EXPECT_GE(f.fill.clump.spheres.size(), 1u);
  EXPECT_LE(f.fill.clump.spheres.size(), 50u);
  EXPECT_GT(f.fidelity.covered_fraction, 0.9);
}

TEST(RepairJob, CubesTouchingAlongAnEdgeAreTwoShellsForRepairReadAndFill) {
  const fs::path d = scratch("lobes");
  Mesh two = make_box(Vec3(1, 1, 1));
  Mesh other = make_box(Vec3(1, 1, 1));
  transform(other, Mat3::Identity(), Vec3(1, 1, 0));
  append_mesh(two, other);
  write_mesh((d / "lobes.obj").string(), two);  // read back welded: 4 triangles at one edge
  MeshReadReport report;
  EXPECT_NEAR(signed_volume(read_mesh((d / "lobes.obj").string(), &report)), 2.0, 1e-12);
  EXPECT_EQ(report.shells, 2u);
  EXPECT_EQ(report.split_vertices, 2u);
  const RepairJobResult r = run_repair_job((d / "lobes.obj").string(), (d / "out.obj").string());
  EXPECT_EQ(r.repair.nonmanifold_edges, 1);
  EXPECT_NEAR(signed_volume(read_mesh((d / "out.obj").string())), 2.0, 1e-12);
  const FillJobOptions fill = fill_options(d / "lobes.obj", d / "clump.csv", 20);
  const FillJobResult f = run_fill_job(
      fill, [](const std::string&) {}, [](const std::string&) {});
  EXPECT_LE(f.fidelity.overshoot_fraction, fill.fill.max_overshoot);
  EXPECT_NEAR(f.fidelity.mesh_volume, 2.0, 1e-9);
  EXPECT_GT(f.fidelity.covered_fraction, 0.5);
}

TEST(RepairJob, ASphereWithThreeHolesClosesWithinOnePercentAndFillsAsAWatertightSolid) {
  const fs::path d = scratch("sphere");
  const Mesh whole = make_icosphere(3);
  const Mesh holed = holed_sphere();
  ASSERT_LT(holed.triangles.size(), whole.triangles.size());
  write_mesh((d / "holed.ply").string(), holed);
  try {
    read_mesh((d / "holed.ply").string());
    FAIL() << "an open mesh was read as a solid";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("clumpkit repair"), std::string::npos) << e.what();
  }
  const RepairJobResult r = run_repair_job((d / "holed.ply").string(), (d / "closed.stl").string());
  EXPECT_EQ(r.repair.holes, 3);
  EXPECT_EQ(r.repair.boundary_edges_after, 0);
  EXPECT_GT(r.repair.boundary_edges_before, 0);
  EXPECT_NEAR(r.repair.volume_after / signed_volume(whole), 1.0, 0.01);
  EXPECT_EQ(r.report["holes"], 3);
  // The written file is a solid for every command: the watertight path of fill.
  const Mesh closed = read_mesh((d / "closed.stl").string());
  EXPECT_NEAR(signed_volume(closed) / signed_volume(whole), 1.0, 0.01);
  const FillJobOptions fill = fill_options(d / "closed.stl", d / "clump.csv", 5);
  const FillJobResult f = run_fill_job(
      fill, [](const std::string&) {}, [](const std::string&) {});
  EXPECT_EQ(f.report["inside_outside"], "ray parity along the grid rows (watertight mesh)");
  EXPECT_LE(f.fidelity.overshoot_fraction, fill.fill.max_overshoot);
}

TEST(RepairJob, AClosedMeshIsKeptAndWhatCannotBeRepairedIsRefusedWithNothingWritten) {
  const fs::path d = scratch("refused");
  write_mesh((d / "ball.obj").string(), make_icosphere(2));
  const RepairJobResult r = run_repair_job((d / "ball.obj").string(), (d / "out.obj").string());
  EXPECT_EQ(r.repair.holes, 0);
  EXPECT_NEAR(r.repair.volume_after, r.repair.volume_before, 1e-12);
  // Two spheres through each other: closed, the surface crossing itself, mended by their union
  // and reported so.
  Mesh two = make_icosphere(2);
  Mesh other = make_icosphere(2);
  transform(other, Mat3::Identity(), Vec3(0.5, 0, 0));
  append_mesh(two, other);
  write_mesh((d / "two.ply").string(), two);
  const RepairJobResult u = run_repair_job((d / "two.ply").string(), (d / "two-out.ply").string());
  EXPECT_EQ(u.report["mended_by"], "union");
  EXPECT_EQ(u.report["self_intersections"]["united_shells"], 1);
  EXPECT_GT(u.report["self_intersections"]["crossings_between_shells"].get<int>(), 0);
  EXPECT_EQ(u.report["wrap"]["applied"], false);
  EXPECT_TRUE(u.report["changed"].get<bool>());
  EXPECT_LT(u.report["distance"]["max_fraction"].get<double>(), 0.01);
  EXPECT_LT(u.repair.volume_after, u.repair.volume_capped);
  // A flat sheet encloses nothing: refused with one line naming the file, nothing written.
  Mesh sheet;
  sheet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  write_mesh((d / "sheet.obj").string(), sheet);
  try {
    run_repair_job((d / "sheet.obj").string(), (d / "sheet-out.obj").string());
    FAIL() << "a sheet was repaired";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find((d / "sheet.obj").string()), std::string::npos) << m;
    EXPECT_NE(m.find("encloses no volume"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(d / "sheet-out.obj"));
  EXPECT_THROW(run_repair_job((d / "ball.obj").string(), (d / "ball.obj").string()), InvalidInput);
  EXPECT_THROW(run_repair_job((d / "ball.obj").string(), (d / "out.off").string()), InvalidInput);
}

TEST(RepairJob, FillWithRepairFillsARawScanInOneCommandAndRecordsTheRepair) {
  const fs::path d = scratch("fill");
  write_mesh((d / "holed.ply").string(), holed_sphere());
  FillJobOptions fill = fill_options(d / "holed.ply", d / "clump.csv", 5);
  // Without --repair the open mesh is refused; with it, it is closed, filled and reported.
  EXPECT_THROW(run_fill_job(
                   fill, [](const std::string&) {}, [](const std::string&) {}),
               InvalidInput);
  fill.repair = true;
  std::vector<std::string> notes;
  const FillJobResult f = run_fill_job(
      fill, [&](const std::string& n) { notes.push_back(n); }, [](const std::string&) {});
  ASSERT_TRUE(f.report.contains("repair"));
  EXPECT_EQ(f.report["repair"]["holes"], 3);
  EXPECT_EQ(f.report["repair"]["boundary_edges_after"], 0);
  EXPECT_EQ(f.report["inside_outside"], "ray parity along the grid rows (watertight mesh)");
  EXPECT_LE(f.fidelity.overshoot_fraction, fill.fill.max_overshoot);
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find("repaired") != std::string::npos;
  }));
  EXPECT_TRUE(fs::exists(d / "clump.csv"));
}

TEST(RepairJob, LibraryWithRepairMakesALibraryOfAFolderOfRawScans) {
  const fs::path d = scratch("library");
  fs::create_directories(d / "scans");
  // A holed sphere of radius 10 (mm) and a closed box of 20 × 10 × 10 mm: the raw scans.
  Mesh ball = holed_sphere();
  for (Vec3& v : ball.vertices) v *= 10.0;
  write_mesh((d / "scans" / "a-ball.ply").string(), ball);
  write_mesh((d / "scans" / "b-box.obj").string(), make_box(Vec3(20, 10, 10)));
  const std::string text =
      "seed = 3\n[[fraction]]\nname = \"scans\"\nmethod = \"mesh\"\nfolder = \"scans\"\n"
      "scale = 0.001\n[fill]\nspheres = 5\n";
  const ShapeRecipe recipe = parse_shape_recipe(text, (d / "scans.toml").string());
  ASSERT_EQ(recipe.fractions.size(), 1u);
  EXPECT_EQ(recipe.fractions[0].count, 2);
  // Without --repair the open scan is refused, naming it, and nothing is published.
  try {
    run_library(recipe, (d / "plain").string(), {});
    FAIL() << "an open scan went into a library";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("a-ball.ply"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(d / "plain"));
  LibraryOptions options;
  options.repair = true;
  const LibraryResult r = run_library(recipe, (d / "lib").string(), options);
  EXPECT_EQ(r.particles, 2u);
  nlohmann::ordered_json ball_rec, box_rec;
  ASSERT_TRUE(read_sealed_record((d / "lib" / "particles" / "00000.json").string(), ball_rec));
  ASSERT_TRUE(read_sealed_record((d / "lib" / "particles" / "00001.json").string(), box_rec));
  EXPECT_EQ(ball_rec["method"], "mesh");
  EXPECT_NE(ball_rec["source"].get<std::string>().find("a-ball.ply"), std::string::npos);
  EXPECT_EQ(ball_rec["repair"]["holes"], 3);
  EXPECT_EQ(box_rec["repair"]["holes"], 0);
  // Scaled to metres: the ball's volume within 1 % of the closed sphere's, the box's exact.
  const double ball_volume = signed_volume(make_icosphere(3)) * 1e-6;
  EXPECT_NEAR(ball_rec["descriptors"]["volume"].get<double>() / ball_volume, 1.0, 0.01);
  EXPECT_NEAR(box_rec["descriptors"]["volume"].get<double>(), 2e-6, 1e-15);
  // A recipe's mesh fraction errors name the field.
  const auto error_of = [&](const std::string& t) {
    try {
      parse_shape_recipe(t, (d / "scans.toml").string());
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("[[fraction]]\nmethod = \"mesh\"\n").find("fraction[0].folder: missing"),
            std::string::npos);
  EXPECT_NE(error_of("[[fraction]]\nmethod = \"mesh\"\nfolder = \"none\"\n").find("no such folder"),
            std::string::npos);
  EXPECT_NE(error_of("[[fraction]]\nmethod = \"mesh\"\nfolder = \"scans\"\ncount = 3\n")
                .find("fraction[0].count: 3 particles but 2 mesh files"),
            std::string::npos);
  EXPECT_NE(error_of("[[fraction]]\nmethod = \"mesh\"\nfolder = \"scans\"\nscale = -1\n")
                .find("fraction[0].scale"),
            std::string::npos);
  EXPECT_NE(error_of("[[fraction]]\nmethod = \"block\"\ncount = 1\nW = 0.02\nscale = 2\n")
                .find("fraction[0].scale: only for method mesh"),
            std::string::npos);
}
