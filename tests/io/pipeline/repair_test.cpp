// `clumpkit repair` (io/pipeline/repair.h, geom/mesh/repair.h): a sphere with holes punched in it
// closes to within 1 % of its volume and then reads and fills as a watertight solid; what cannot
// be repaired is refused with nothing written.
#include "io/pipeline/repair.h"

#include "geom/errors.h"
#include "geom/shapes/primitives.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/fill.h"

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
  // Two spheres through each other: closed, but the surface crosses itself.
  Mesh two = make_icosphere(2);
  Mesh other = make_icosphere(2);
  transform(other, Mat3::Identity(), Vec3(0.5, 0, 0));
  append_mesh(two, other);
  write_mesh((d / "two.ply").string(), two);
  try {
    run_repair_job((d / "two.ply").string(), (d / "two-out.ply").string());
    FAIL() << "a self-intersecting result was written";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find((d / "two.ply").string()), std::string::npos) << m;
    EXPECT_NE(m.find("intersects itself"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(d / "two-out.ply"));
  EXPECT_THROW(run_repair_job((d / "ball.obj").string(), (d / "ball.obj").string()), InvalidInput);
  EXPECT_THROW(run_repair_job((d / "ball.obj").string(), (d / "out.off").string()), InvalidInput);
}
