// Tests of the refinement after the greedy fill, its coverage grid and ledger (which must take a
// sphere out again), and the resolution that follows the sphere count.
#include "geom/fill/fill_refine.h"
#include "geom/errors.h"
#include "geom/fill/coverage_grid.h"
#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/fill/overshoot.h"
#include "geom/mesh/mesh_index.h"
#include "geom/random.h"
#include "geom/shapes/primitives.h"
#include "geom/volume/union_of_balls.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

using namespace clumpkit;

namespace fill_refine_test {

// A coarse torus (ring 3, tube 1): its greedy fill leaves uneven gaps along the ring.
Mesh torus() {
  return make_torus(3.0, 1.0, 48, 24);
}

FillOptions options(int spheres, int sweeps) {
  FillOptions o;
  o.spheres = spheres;
  o.refine_iterations = sweeps;
  return o;
}

}  // namespace fill_refine_test

using namespace fill_refine_test;

TEST(CoverageGrid, CoverAndUncoverCountUnionsExactly) {
  FieldOptions fo;
  fo.voxel_size = 0.05;
  const Mesh cube = make_box(Vec3(1, 1, 1));
  const DistanceField field = make_distance_field(cube, fo);
  CoverageGrid grid(field);
  const std::int64_t interior = grid.interior();
  ASSERT_GT(interior, 7000);  // 20³ voxel centres in the unit cube
  const Sphere a{Vec3(-0.1, 0, 0), 0.3}, b{Vec3(0.15, 0.05, 0), 0.25};
  const std::int64_t only_a = grid.uncovered_in(a), only_b = grid.uncovered_in(b);
  grid.cover(a);
  const std::int64_t b_beyond_a = grid.uncovered_in(b);
  EXPECT_LT(b_beyond_a, only_b);  // they overlap
  grid.cover(b);
  EXPECT_EQ(grid.uncovered(), interior - only_a - b_beyond_a);
  grid.cover(b);  // twice: one uncover leaves it covered
  grid.uncover(b);
  EXPECT_EQ(grid.uncovered(), interior - only_a - b_beyond_a);
  grid.uncover(a);
  EXPECT_EQ(grid.uncovered(), interior - only_b);
  grid.uncover(b);
  EXPECT_EQ(grid.uncovered(), interior);
  EXPECT_EQ(grid.uncovered_in(a), only_a);
}

TEST(OvershootLedger, RemovingASphereLeavesWhatTheOthersPutOutside) {
  const Mesh box = make_box(Vec3(2.0, 2.0, 2.0));  // [−1, 1]³
  const MeshIndex index(box);
  const std::array<Vec3, 2> reach{Vec3::Constant(-2.0), Vec3::Constant(2.0)};
  const Sphere a{Vec3(0.75, 0, 0), 0.5}, b{Vec3(0.75, 0.2, 0), 0.5}, c{Vec3(0, 0, -0.7), 0.5};
  OvershootLedger ledger(index, reach, 0.01), only_b(index, reach, 0.01);
  only_b.add(b);
  ledger.add(a);
  ledger.add(b);
  ledger.add(c);
  const double cap_c = 0.2 * 0.2 * M_PI * (3 * 0.5 - 0.2) / 3;  // height 0.2 above z = −1
  ledger.remove(a);
  EXPECT_NEAR(ledger.volume(), only_b.volume() + cap_c, 0.01 * cap_c);
  ledger.remove(c);
  EXPECT_NEAR(ledger.volume(), only_b.volume(), 1e-12);
  ledger.remove(b);
  EXPECT_NEAR(ledger.volume(), 0.0, 1e-12);
  EXPECT_THROW(ledger.remove(b), std::logic_error);
}

// The refinement raises the torus's coverage (the greedy pass leaves gaps of unequal length
// along the ring), never lowers it, keeps the contract: each sphere at most the grown radius of
// its centre's exact distance, the outside volume under --max-overshoot by the report's measure.
TEST(FillRefine, RaisesCoverageWithinTheContract) {
  const Mesh mesh = torus();
  const FillOptions o = options(30, 8);
  const FillResult r = fill(mesh, o);
  ASSERT_EQ(r.clump.spheres.size(), 30u);
  EXPECT_GT(r.refine_moves, 0);
  const Fidelity before = assess_fidelity(mesh, r.greedy, r.voxel / 2);
  const Fidelity after = assess_fidelity(mesh, r.clump, r.voxel / 2);
  EXPECT_GT(after.covered_fraction, before.covered_fraction + 0.01);
  EXPECT_LE(after.overshoot_fraction, o.max_overshoot);
  const MeshIndex index(mesh);
  for (const Sphere& s : r.clump.spheres) {
    const double d = index.distance(s.center);
    EXPECT_LE(s.radius, d * (1.0 + o.tolerance_relative) + 1e-9);
  }
  // No refinement: the greedy clump itself.
  const FillResult g = fill(mesh, options(30, 0));
  EXPECT_EQ(g.refine_sweeps, 0);
  ASSERT_EQ(g.clump.spheres.size(), r.greedy.spheres.size());
  for (std::size_t i = 0; i < g.clump.spheres.size(); ++i)
    EXPECT_EQ(g.clump.spheres[i].center, r.greedy.spheres[i].center);
}

TEST(FillRefine, SameSpheresForOneAndTwoThreads) {
  const Mesh mesh = make_octahedron(1.0);
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return fill(mesh, options(21, 8));
  };
  const FillResult one = run(1), two = run(2);
  ASSERT_EQ(one.clump.spheres.size(), two.clump.spheres.size());
  for (std::size_t i = 0; i < one.clump.spheres.size(); ++i) {
    EXPECT_EQ(one.clump.spheres[i].center, two.clump.spheres[i].center);
    EXPECT_EQ(one.clump.spheres[i].radius, two.clump.spheres[i].radius);
  }
}

// With every sphere inscribed (no tolerance), the covered volume is the union's, which the power
// diagram gives exactly: the report's measure (lengths exact along rows one voxel apart) agrees
// within 0.003 of the mesh volume.
TEST(FillRefine, ReportedCoverageAgreesWithTheExactUnion) {
  for (const Mesh& mesh : {torus(), make_ellipsoid(Vec3(2, 1, 1), 3)}) {
    FillOptions o = options(21, 8);
    o.max_overshoot = 0.0;
    o.tolerance = 0.0;
    o.tolerance_relative = 0.0;
    const FillResult r = fill(mesh, o);
    const Fidelity f = assess_fidelity(mesh, r.clump, r.voxel);
    EXPECT_LT(f.overshoot_fraction, 1e-9);
    const double exact = union_properties(r.clump).mass.volume / signed_volume(mesh);
    EXPECT_NEAR(f.covered_fraction, exact, 0.003);
  }
}

TEST(FillRefine, VoxelFollowsTheSphereCountWithinTheBudget) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  FillOptions o;
  o.spheres = 100;
  o.field.max_voxels = kDefaultMaxVoxels;
  const double expected =
      kSmallestSphereOverSpacing * std::cbrt(1.0 / 100) / kVoxelsPerSmallestRadius;
  EXPECT_NEAR(field_voxel_size(cube, fill_field_options(cube, o)), expected, 1e-12);
  o.spheres = 5;  // a few large spheres: the default 40 voxels across are fine enough
  EXPECT_NEAR(field_voxel_size(cube, fill_field_options(cube, o)), 1.0 / 40, 1e-12);
  o.spheres = 100000;  // at most kCountVoxelGrowth times the voxels of the resolution asked
  EXPECT_NEAR(field_voxel_size(cube, fill_field_options(cube, o)),
              1.0 / 40 / std::cbrt(kCountVoxelGrowth), 1e-12);
  o.field.max_voxels = 1e5;  // and never past the voxel budget
  EXPECT_LE(field_voxel_count(cube, fill_field_options(cube, o)), 1e5);
  o.spheres = 100;
  o.voxels_from_count = false;  // a resolution the user gave holds
  EXPECT_NEAR(field_voxel_size(cube, fill_field_options(cube, o)), 1.0 / 40, 1e-12);
}

TEST(FillRefine, RejectsBadSweeps) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  FillOptions o;
  o.refine_iterations = -1;
  EXPECT_THROW(fill(cube, o), InvalidInput);
  o.refine_iterations = 1001;
  EXPECT_THROW(fill(cube, o), InvalidInput);
}

// Large balls are counted block by block; every count must equal the row-by-row count of the
// voxel centres inside (the formula of the small balls), on a grid partly covered by balls.
TEST(CoverageGrid, LargeBallsCountExactlyAsVoxelByVoxel) {
  FieldOptions fo;
  fo.voxel_size = 0.02;
  const Mesh mesh = make_ellipsoid(Vec3(1.0, 0.7, 0.6), 3);
  const DistanceField field = make_distance_field(mesh, fo);
  CoverageGrid grid(field);
  Rng rng(5);
  std::vector<Sphere> covered;
  for (int n = 0; n < 12; ++n) {
    const Sphere s{Vec3(rng.uniform(-0.8, 0.8), rng.uniform(-0.5, 0.5), rng.uniform(-0.4, 0.4)),
                   rng.uniform(0.05, 0.45)};
    grid.cover(s);
    covered.push_back(s);
  }
  // Voxel (i, j, k) lies in ball s as the row formula says: its centre within the row's span.
  auto in_ball = [&](const Sphere& s, int i, int j, int k) {
    const Vec3 g = (s.center - field.origin) / field.h;
    const double rv = s.radius / field.h, dy = j - g.y(), dz = k - g.z();
    const double rem = rv * rv - dy * dy - dz * dz;
    if (rem < 0.0) return false;
    const double w = std::sqrt(rem);
    return std::ceil(g.x() - w) <= i && i <= std::floor(g.x() + w);
  };
  for (int probe = 0; probe < 40; ++probe) {
    const Sphere s{Vec3(rng.uniform(-0.8, 0.8), rng.uniform(-0.5, 0.5), rng.uniform(-0.4, 0.4)),
                   rng.uniform(0.2, 0.7)};
    std::int64_t expected = 0;
    for (int k = 0; k < field.dims[2]; ++k)
      for (int j = 0; j < field.dims[1]; ++j)
        for (int i = 0; i < field.dims[0]; ++i) {
          if (!(field.at(i, j, k) > 0.0f) || !in_ball(s, i, j, k)) continue;
          bool hit = false;
          for (const Sphere& c : covered) hit = hit || in_ball(c, i, j, k);
          expected += !hit;
        }
    EXPECT_EQ(grid.uncovered_in(s), expected) << "probe " << probe;
    // Every fourth probe takes one ball out again, so the counts after an uncover (the blocks'
    // row pieces set again) are checked too.
    if (probe % 4 == 3 && !covered.empty()) {
      grid.uncover(covered.back());
      covered.pop_back();
    }
  }
}
