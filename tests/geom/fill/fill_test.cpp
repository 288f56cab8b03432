// Tests of the greedy maximal-inscribed-sphere fill and its fidelity report.
#include "geom/fill/fill.h"
#include "geom/errors.h"
#include "geom/fill/fidelity.h"
#include "geom/mesh/cgal_mesh.h"
#include "geom/mesh/mesh_index.h"
#include "geom/shapes/block.h"
#include "geom/shapes/primitives.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

namespace {
// Capsule: convex hull of two icospheres of radius R whose centres are ±a on x.
Mesh capsule(double a, double R) {
  const Mesh s = make_icosphere(4);
  std::vector<Vec3> pts;
  for (const auto& p : s.vertices) {
    pts.push_back(R * p + Vec3(a, 0, 0));
    pts.push_back(R * p - Vec3(a, 0, 0));
  }
  return convex_hull(pts);
}
}  // namespace

TEST(Fill, SphereGivesOneSphereOfTheTrueRadius) {
  Mesh s = make_icosphere(5);
  for (auto& p : s.vertices) p = 10.0 * p + Vec3(3, -2, 1);
  FillOptions o;
  o.spheres = 1;
  o.tolerance_relative = 0.0;  // the pure inscribed radius
  const FillResult r = fill(s, o);
  ASSERT_EQ(r.clump.spheres.size(), 1u);
  // Half a voxel, the acceptance tolerance; the icosphere's inradius is 9.994.
  EXPECT_NEAR(r.clump.spheres[0].radius, 10.0, 0.5 * r.voxel);
  EXPECT_LT((r.clump.spheres[0].center - Vec3(3, -2, 1)).norm(), 0.5 * r.voxel);
  const Fidelity f = assess_fidelity(s, r.clump, r.voxel / 2);
  EXPECT_GT(f.covered_fraction, 0.99);
  EXPECT_LT(f.overshoot_fraction, 1e-3);
}

TEST(Fill, EllipsoidTwoOneOne) {
  const Mesh e = make_ellipsoid(Vec3(2, 1, 1), 4);
  FillOptions o;
  o.spheres = 20;
  const FillResult r = fill(e, o);
  // Medial balls of an ellipsoid stop short of the tips: the fill may end early when no
  // candidate adds volume.
  ASSERT_GE(r.clump.spheres.size(), 8u);
  ASSERT_LE(r.clump.spheres.size(), 20u);
  // The largest inscribed sphere of a 2:1:1 ellipsoid has the short semi-axis as radius
  // (curvature radius at the tip of the long axis is b²/a = 0.5 < 1, so it sits at the centre).
  EXPECT_NEAR(r.greedy.spheres[0].radius, 1.0 * 1.03, 0.05);
  EXPECT_LT(r.greedy.spheres[0].center.norm(), 2 * r.voxel);  // its local search may shift it
  // The refinement may slide it along the long axis, where it stays about as large.
  EXPECT_NEAR(r.clump.spheres[0].radius, 1.0 * 1.03, 0.05);
  EXPECT_LT(r.clump.spheres[0].center.tail<2>().norm(), 2 * r.voxel);
  const Fidelity f = assess_fidelity(e, r.clump, r.voxel / 2);
  EXPECT_GT(f.covered_fraction, 0.93);
  EXPECT_LT(f.overshoot_fraction, 0.01);
  // The clump is elongated like the ellipsoid: centres spread along x much more than y, z.
  double sx = 0, sy = 0;
  for (const auto& s : r.clump.spheres) {
    sx = std::max(sx, std::abs(s.center.x()));
    sy = std::max(sy, std::abs(s.center.y()));
  }
  EXPECT_GT(sx, 3 * sy);
}

// A sphere inside another covers nothing. The greedy search reckoned with grown radii the
// contract then refused, so on this ellipsoid 5 of 50 spheres sat inside others (229 of 460 at
// the finer voxel); and where the medial candidates run out, looser ridges keep the budget buying
// spheres that cover something.
TEST(Fill, NoSphereLiesInsideAnother) {
  const Mesh e = make_ellipsoid(Vec3(2, 1, 1), 4);
  FillOptions o;
  o.spheres = 50;
  const FillResult r = fill(e, o);
  ASSERT_EQ(r.clump.spheres.size(), 50u);
  // The greedy clump; the refinement may still move a sphere over a neighbour (1 of 50 here).
  for (const Sphere& a : r.greedy.spheres)
    for (const Sphere& b : r.greedy.spheres) {
      if (&a == &b) continue;
      EXPECT_GT((a.center - b.center).norm() + a.radius, b.radius * (1 + 1e-9));
    }
  for (std::size_t i = 1; i < r.coverage_curve.size(); ++i)
    EXPECT_GT(r.coverage_curve[i], r.coverage_curve[i - 1]);
}

TEST(Fill, CapsuleSpheresRunAlongTheAxis) {
  const Mesh c = capsule(2.0, 1.0);
  FillOptions o;
  o.spheres = 10;
  o.tolerance_relative = 0.0;
  o.spend_budget = false;  // no sphere grown past the surface
  const FillResult r = fill(c, o);
  const Fidelity f = assess_fidelity(c, r.clump, r.voxel / 2);
  EXPECT_GT(f.covered_fraction, 0.97);  // a capsule is a swept sphere: few spheres fill it
  EXPECT_LT(f.overshoot_fraction, 1e-3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.clump.spheres[i].radius, 1.0, 0.5 * r.voxel);
    EXPECT_LT(std::hypot(r.clump.spheres[i].center.y(), r.clump.spheres[i].center.z()), r.voxel);
  }
}

TEST(Fill, ZeroToleranceKeepsEverySphereInside) {
  Rng rng(3);
  const Mesh b = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
  FillOptions o;
  o.spheres = 60;
  o.tolerance_relative = 0.0;
  o.spend_budget = false;  // the per-sphere rule alone: with no tolerance, every sphere inside
  const FillResult r = fill(b, o);
  const MeshIndex d(b);
  for (const auto& s : r.clump.spheres) EXPECT_LE(s.radius, d.distance(s.center) + 1e-9);
  const Fidelity f = assess_fidelity(b, r.clump, r.voxel / 2);
  EXPECT_LT(f.overshoot_fraction, 1e-4);
  EXPECT_LT(f.overshoot_depth_max, 1e-9);
}

// Unit cube, 50 spheres, covered >= 0.905, overshoot <= 0.01 (0.9082 at the 40 voxels across
// of the default, 0.9067 at the finer grid the count asks for: the greedy choices change).
TEST(Fill, UnitCubeFiftySpheres) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  FillOptions o;
  o.spheres = 50;
  const FillResult r = fill(cube, o);
  const Fidelity f = assess_fidelity(cube, r.clump, r.voxel / 2);
  EXPECT_GE(f.covered_fraction, 0.905);
  EXPECT_LE(f.overshoot_fraction, 0.01);
}

// The block of Jin et al. 2017 at the sphere counts of its Table 2, mean over seeds 1-5.
TEST(Fill, SeedZeroBlockCoverageAtEqualSphereCount) {
  const int counts[3] = {47, 93, 344};
  const double goals[3] = {0.86, 0.91, 0.965};
  double covered[3] = {0, 0, 0}, overshoot[3] = {0, 0, 0};
  // The sanitizer pass fills the block of seed 1 alone (a fifth of the fills, the same checks:
  // every seed clears the goals on its own, seed 1 with about 0.905, 0.943 and 0.977); the
  // Release pass takes the mean over the five.
  const int seeds = kSanitized ? 1 : 5;
  for (int seed = 1; seed <= seeds; ++seed) {
    Rng rng(seed);
    const Mesh b = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
    for (int q = 0; q < 3; ++q) {
      FillOptions o;
      o.spheres = counts[q];
      const FillResult r = fill(b, o);
      ASSERT_EQ(static_cast<int>(r.clump.spheres.size()), counts[q]);
      const Fidelity f = assess_fidelity(b, r.clump, r.voxel / 2);
      covered[q] += f.covered_fraction / seeds;
      overshoot[q] += f.overshoot_fraction / seeds;
    }
  }
  for (int q = 0; q < 3; ++q) {
    EXPECT_GE(covered[q], goals[q]) << counts[q] << " spheres";
    EXPECT_LE(overshoot[q], 0.01) << counts[q] << " spheres";
  }
}

TEST(Fill, CoverageIncreasesAndStopRulesHold) {
  Rng rng(1);
  const Mesh b = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
  FillOptions o;
  o.coverage = 0.9;
  const FillResult r = fill(b, o);
  EXPECT_EQ(r.stopped_by, "coverage");
  EXPECT_GE(r.coverage_curve.back(), 0.9);
  EXPECT_LT(r.coverage_curve[r.coverage_curve.size() - 2], 0.9);
  for (std::size_t i = 1; i < r.coverage_curve.size(); ++i)
    EXPECT_GT(r.coverage_curve[i], r.coverage_curve[i - 1]);
  // The first sphere is the largest.
  for (const auto& s : r.clump.spheres) EXPECT_LE(s.radius, r.clump.spheres[0].radius);

  FillOptions m;
  m.min_radius = 8.0;
  const FillResult big = fill(b, m);
  EXPECT_FALSE(big.clump.spheres.empty());
  for (const auto& s : big.clump.spheres) EXPECT_GE(s.radius, 8.0);
}

TEST(Fill, DeterministicAndTranslationInvariant) {
  Rng rng(2);
  Mesh b = make_block(BlockParams{60, 50, 40, 2, 0.8, 1.2}, rng);
  FillOptions o;
  o.spheres = 30;
  const FillResult a = fill(b, o), again = fill(b, o);
  ASSERT_EQ(a.clump.spheres.size(), again.clump.spheres.size());
  for (std::size_t i = 0; i < a.clump.spheres.size(); ++i) {
    EXPECT_EQ(a.clump.spheres[i].center, again.clump.spheres[i].center);
    EXPECT_EQ(a.clump.spheres[i].radius, again.clump.spheres[i].radius);
  }
  // A translated mesh gives (nearly) the same clump volume: the lattice moves with the box.
  const Vec3 t(1000.25, -500.5, 20.125);
  transform(b, Mat3::Identity(), t);
  const FillResult moved = fill(b, o);
  const Fidelity fa = assess_fidelity(b, Clump{[&] {
                                        auto s = a.clump.spheres;
                                        for (auto& x : s) x.center += t;
                                        return s;
                                      }()},
                                      a.voxel / 2);
  const Fidelity fm = assess_fidelity(b, moved.clump, moved.voxel / 2);
  EXPECT_NEAR(fa.covered_fraction, fm.covered_fraction, 0.01);
}

TEST(Fill, RejectsBadOptions) {
  const Mesh cube = make_box(Vec3(1, 1, 1));
  FillOptions o;
  o.spheres = -1;
  EXPECT_THROW(fill(cube, o), InvalidInput);
  o = FillOptions{};
  o.min_radius = -1;
  EXPECT_THROW(fill(cube, o), InvalidInput);
  o = FillOptions{};
  o.coverage = 1.5;
  EXPECT_THROW(fill(cube, o), InvalidInput);
  o = FillOptions{};
  o.field.voxels = 2;
  EXPECT_THROW(fill(cube, o), InvalidInput);
}

// A mesh that is not watertight (one triangle missing) is filled with inside/outside from Embree
// ray-parity voting, as well as the closed mesh is.
TEST(Fill, OpenMeshByRayVoting) {
  Rng rng(1);
  const Mesh closed = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
  Mesh open = closed;
  open.triangles.erase(open.triangles.begin());
  FillOptions o;
  o.spheres = 47;
  o.field.vote_sign = true;
  const FillResult r = fill(open, o);
  ASSERT_EQ(r.clump.spheres.size(), 47u);
  const Fidelity truth = assess_fidelity(closed, r.clump, r.voxel / 2);
  EXPECT_GT(truth.covered_fraction, 0.86);
  EXPECT_LT(truth.overshoot_fraction, 0.01);
  const Fidelity voted = assess_fidelity(open, r.clump, r.voxel / 2);
  EXPECT_FALSE(voted.watertight);
  EXPECT_NEAR(voted.mesh_volume, truth.mesh_volume, 0.01 * truth.mesh_volume);
  EXPECT_NEAR(voted.covered_fraction, truth.covered_fraction, 0.01);
}

TEST(Fill, InterrupterHearsTheBudgetFractionAndStopsTheFill) {
  Mesh box = make_box(Vec3(3, 2, 1));
  FillOptions o;
  o.spheres = 40;
  o.field.voxels = 20;
  o.refine_iterations = 0;  // the refinement polls at 1.0 before each sphere it searches,
  o.spend_budget = false;   // and the budget pass before each step
  std::vector<double> heard;
  const FillResult full = fill(box, o, [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "fill");
    heard.push_back(fraction);
    return false;
  });
  ASSERT_EQ(full.clump.spheres.size(), 40u);
  // Before each sphere after the first (the largest inscribed one), and at the budget: 1/40, …, 1.
  ASSERT_EQ(heard.size(), 40u);
  for (std::size_t i = 0; i < heard.size(); ++i) EXPECT_DOUBLE_EQ(heard[i], (i + 1) / 40.0);
  // Without an interrupter, the same spheres; stopped at the 10th, Interrupted.
  const FillResult plain = fill(box, o);
  ASSERT_EQ(plain.clump.spheres.size(), 40u);
  for (std::size_t i = 0; i < 40; ++i)
    EXPECT_EQ(plain.clump.spheres[i].center, full.clump.spheres[i].center);
  int calls = 0;
  EXPECT_THROW(fill(box, o, [&](std::string_view, double) { return ++calls == 10; }),
               clumpkit::Interrupted);
  EXPECT_EQ(calls, 10);
}
