// The overshoot contract of `clumpkit fill` (io/pipeline/fill.h) over random generated meshes:
// whenever the fill job returns, its report's overshoot is at most max_overshoot — closed
// polyhedra, two disjoint shells, a solid with a void, and open meshes read by voting.
#include "io/pipeline/fill.h"

#include "geom/errors.h"
#include "geom/random.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"
#include "io/formats/mesh_io.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

using namespace clumpkit;
namespace fs = std::filesystem;

TEST(FillContract, EveryReportOfARandomMeshKeepsTheOvershootBudget) {
  const fs::path d = fs::path(::testing::TempDir()) / "clumpkit_fill_contract";
  fs::remove_all(d);
  fs::create_directories(d);
  Rng rng(20261126);
  int filled = 0, refused = 0;
  for (int k = 0; k < 8; ++k) {
    PolyhedronParams p;
    p.planes = 8 + static_cast<int>(rng.uniform(0, 20));
    p.E = rng.uniform(0.5, 1.0);
    p.F = rng.uniform(0.4, 1.0);
    p.sphere_level = 1;
    Mesh m = make_polyhedron(p, rng);
    bool open = false;
    switch (k % 4) {
      case 1: {  // two disjoint shells
        Mesh other = make_polyhedron(p, rng);
        transform(other, Mat3::Identity(), Vec3(3.0, 0, 0));
        append_mesh(m, other);
        break;
      }
      case 2: {  // a solid with a void: a small inward box at its centroid
        Mesh hole = make_box(Vec3::Constant(0.1));
        flip_orientation(hole);
        append_mesh(m, hole);
        break;
      }
      case 3:  // a scan with a hole: one triangle missing, read by voting
        m.triangles.erase(m.triangles.begin() + static_cast<long>(rng.uniform(0, 4)));
        open = true;
        break;
    }
    const std::string mesh = (d / ("m" + std::to_string(k) + ".obj")).string();
    write_mesh(mesh, m);
    FillJobOptions job;
    job.mesh = mesh;
    job.out = (d / ("c" + std::to_string(k) + ".csv")).string();
    job.allow_open = open;
    job.fill.spheres = 12;
    job.fill.max_overshoot = rng.uniform(0.0, 0.02);
    try {
      const FillJobResult r = run_fill_job(
          job, [](const std::string&) {}, [](const std::string&) {});
      EXPECT_LE(r.fidelity.overshoot_fraction, job.fill.max_overshoot) << mesh;
      EXPECT_LE(r.report["overshoot_fraction"].get<double>(),
                r.report["max_overshoot"].get<double>())
          << mesh;
      ++filled;
    } catch (const InvalidInput& e) {
      // Refused: the contract could not be met; nothing may be written then.
      EXPECT_NE(std::string(e.what()).find("over --max-overshoot"), std::string::npos) << e.what();
      EXPECT_FALSE(fs::exists(job.out)) << mesh;
      ++refused;
    }
  }
  EXPECT_GE(filled, 6);  // the closed ones, at least
  std::printf("%d filled, %d refused\n", filled, refused);
}

// The report says how fine the grid was: the smallest sphere in voxels, and with
// check_resolution the coverage of a fill on twice the voxels; the clump written is the first.
TEST(FillJob, CheckResolutionReportsTheCoverageOnTwiceTheVoxels) {
  const fs::path d = fs::path(::testing::TempDir()) / "clumpkit_fill_resolution";
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string mesh = (d / "torus.obj").string();
  write_mesh(mesh, make_torus(3.0, 1.0, 48, 24));
  FillJobOptions job;
  job.mesh = mesh;
  job.out = (d / "c.csv").string();
  job.fill.spheres = 20;
  // Three fills (the check's on twice the voxels), their time in the grid of 40 voxels across the
  // tube. The sanitizer pass fills on 25 across (voxel 0.08, under a third of the work; there the
  // smallest sphere spans 12 voxels and the coverage changes by 0.002); the Release pass on 40.
  if (kSanitized) job.fill.field.voxels = 25;
  job.check_resolution = true;
  auto quiet = [](const std::string&) {};
  const FillJobResult r = run_fill_job(job, quiet, quiet);
  const auto& res = r.report["resolution"];
  EXPECT_DOUBLE_EQ(res["voxel"].get<double>(), r.fill.voxel);
  EXPECT_NEAR(res["finer_voxel"].get<double>(), r.fill.voxel / std::cbrt(2.0), 1e-12);
  EXPECT_GT(res["smallest_sphere_voxels"].get<double>(), 10.0);  // tube radius 1, voxel ~0.05
  EXPECT_NEAR(res["covered_change"].get<double>(),
              res["covered_fraction_finer"].get<double>() - r.fidelity.covered_fraction, 1e-12);
  EXPECT_LT(std::abs(res["covered_change"].get<double>()), 0.01);  // converged on a torus
  job.check_resolution = false;
  job.out = (d / "plain.csv").string();
  const FillJobResult plain = run_fill_job(job, quiet, quiet);
  EXPECT_FALSE(plain.report["resolution"].contains("covered_change"));
  ASSERT_EQ(plain.fill.clump.spheres.size(), r.fill.clump.spheres.size());
  for (std::size_t i = 0; i < plain.fill.clump.spheres.size(); ++i)
    EXPECT_EQ(plain.fill.clump.spheres[i].center, r.fill.clump.spheres[i].center);
}
