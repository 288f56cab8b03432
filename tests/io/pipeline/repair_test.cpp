// `clumpkit repair` (io/pipeline/repair.h, geom/mesh/repair.h): a sphere with holes punched in it
// closes to within 1 % of its volume and then reads and fills as a watertight solid; what cannot
// be repaired is refused with nothing written.
#include "io/pipeline/repair.h"

#include "geom/errors.h"
#include "geom/shapes/primitives.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/fill.h"

#include <gtest/gtest.h>

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

}  // namespace

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
  FillJobOptions fill;
  fill.mesh = (d / "closed.stl").string();
  fill.out = (d / "clump.csv").string();
  fill.fill.spheres = 5;
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
