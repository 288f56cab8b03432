// Tests of the shape generators: block (Jin et al. 2017), hull (Zhang & Zhou 2015),
// polyhedron (Hu et al. 2023), primitives.
#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/mesh/cgal_mesh.h"
#include "geom/shapes/block.h"
#include "geom/shapes/hull.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;

namespace {
void expect_valid_solid(const Mesh& m, const std::string& what) {
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed) << what;
  EXPECT_TRUE(c.manifold) << what;
  EXPECT_TRUE(c.oriented) << what;
  EXPECT_FALSE(c.degenerate) << what;
  EXPECT_GT(c.volume, 0.0) << what;
}
}  // namespace

TEST(Primitives, BoxIsExact) {
  const Mesh b = make_box(Vec3(2, 1, 0.5));
  expect_valid_solid(b, "box");
  EXPECT_NEAR(signed_volume(b), 1.0, 1e-15);
  EXPECT_NEAR(surface_area(b), 2 * (2 + 1 + 0.5), 1e-14);
  EXPECT_FALSE(self_intersects(b));
}

TEST(Primitives, CylinderIsAnExactPrism) {
  for (int n : {3, 6, 64}) {
    const Mesh c = make_cylinder(0.05, 0.02, n);
    const MeshCheck k = check_mesh(c);
    EXPECT_TRUE(k.closed && k.manifold && k.oriented && !k.degenerate) << n;
    // n triangles of the inscribed polygon, each (r²/2)·sin(2π/n), times the height.
    const double area = n * 0.5 * 0.025 * 0.025 * std::sin(2 * M_PI / n);
    EXPECT_NEAR(signed_volume(c) / (area * 0.02), 1.0, 1e-12) << n;
    EXPECT_NEAR(solid_centroid(c).norm(), 0.0, 1e-15) << n;
    const auto box = bounding_box(c);
    EXPECT_DOUBLE_EQ(box[1].x(), 0.025);
    EXPECT_DOUBLE_EQ(box[1].z() - box[0].z(), 0.02);
  }
  // 64 sides: within 0.16 % of the round cylinder.
  EXPECT_NEAR(signed_volume(make_cylinder(0.05, 0.05)) / (M_PI * 0.025 * 0.025 * 0.05), 1.0,
              1.7e-3);
  EXPECT_THROW(make_cylinder(0.05, 0.05, 2), InvalidInput);
  EXPECT_THROW(make_cylinder(-0.05, 0.05), InvalidInput);
  EXPECT_THROW(make_cylinder(0.05, std::nan("")), InvalidInput);
}

TEST(Primitives, IcosphereConvergesToSphere) {
  double prev_err = 1e300;
  for (int level = 0; level <= 5; ++level) {
    const Mesh s = make_icosphere(level);
    expect_valid_solid(s, "icosphere");
    EXPECT_EQ(s.triangles.size(), 20u << (2 * level));
    const double err = std::abs(signed_volume(s) - 4.0 * M_PI / 3.0);
    EXPECT_LT(err, prev_err);
    prev_err = err;
  }
  EXPECT_LT(prev_err / (4.0 * M_PI / 3.0), 2e-3);
}

TEST(Primitives, EllipsoidVolume) {
  const Mesh e = make_ellipsoid(Vec3(2, 1, 0.5), 5);
  expect_valid_solid(e, "ellipsoid");
  EXPECT_NEAR(signed_volume(e) / (4.0 * M_PI / 3.0 * 2 * 1 * 0.5), 1.0, 2e-3);
  EXPECT_THROW(make_ellipsoid(Vec3(1, -1, 1)), InvalidInput);
}

TEST(Block, UnscaledIsTheCuboid) {
  Rng rng(3);
  BlockParams p{75.1, 58.0, 49.8, 3, 1.0, 1.0};
  const Mesh m = make_block(p, rng);
  expect_valid_solid(m, "cuboid");
  EXPECT_EQ(m.vertices.size(), 6u * 9 + 2);  // V = 6 Nd² + 2 for a meshed cube surface
  EXPECT_EQ(m.triangles.size(), 12u * 9);
  EXPECT_NEAR(signed_volume(m), 75.1 * 58.0 * 49.8, 1e-8);
}

TEST(Block, RadialScalingStaysWithinBounds) {
  Rng rng(11);
  BlockParams p{60, 60, 60, 2, 0.8, 1.2};
  const Mesh m = make_block(p, rng);
  // Every node's radius is the cuboid node radius times a factor in [0.8, 1.2].
  Rng again(11);
  const Mesh base = make_block(BlockParams{60, 60, 60, 2, 1.0, 1.0}, again);
  ASSERT_EQ(m.vertices.size(), base.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const double f = m.vertices[i].norm() / base.vertices[i].norm();
    EXPECT_GE(f, 0.8);
    EXPECT_LT(f, 1.2);
    EXPECT_NEAR((m.vertices[i].normalized() - base.vertices[i].normalized()).norm(), 0.0, 1e-12);
  }
}

// 1000 random parameter sets, each mesh closed, 2-manifold, outward and free of
// self-intersections (CGAL).
TEST(Block, ThousandRandomParameterSetsAreValidSolids) {
  Rng draw(2024);
  for (int i = 0; i < 1000; ++i) {
    BlockParams p;
    p.L = draw.uniform(10, 100);
    p.W = draw.uniform(10, 100);
    p.H = draw.uniform(10, 100);
    p.nd = 1 + static_cast<int>(draw.below(4));
    p.sl = draw.uniform(0.6, 1.4);
    p.su = draw.uniform(p.sl, 1.4);
    Rng rng = Rng::stream(77, i);
    const Mesh m = make_block(p, rng);
    const MeshCheck c = check_mesh(m);
    ASSERT_TRUE(c.closed && c.manifold && c.oriented && !c.degenerate && c.volume > 0)
        << "set " << i << " nd=" << p.nd;
    ASSERT_FALSE(self_intersects(m)) << "set " << i;
  }
}

TEST(Block, SameSeedSameMesh) {
  BlockParams p{75.1, 58.0, 49.8, 2, 0.8, 1.2};
  Rng a(7), b(7), c(8);
  const Mesh ma = make_block(p, a), mb = make_block(p, b), mc = make_block(p, c);
  ASSERT_EQ(ma.vertices.size(), mb.vertices.size());
  for (std::size_t i = 0; i < ma.vertices.size(); ++i) EXPECT_EQ(ma.vertices[i], mb.vertices[i]);
  EXPECT_NE(signed_volume(ma), signed_volume(mc));
}

TEST(Block, RejectsBadParameters) {
  Rng rng(1);
  EXPECT_THROW(make_block(BlockParams{1, 1, 1, 2, 1.2, 0.8}, rng), InvalidInput);
  EXPECT_THROW(make_block(BlockParams{-1, 1, 1, 2, 0.8, 1.2}, rng), InvalidInput);
  EXPECT_THROW(make_block(BlockParams{NAN, 1, 1, 2, 0.8, 1.2}, rng), InvalidInput);
  EXPECT_THROW(make_block(BlockParams{1, 1, 1, 0, 0.8, 1.2}, rng), InvalidInput);
  try {
    make_block(BlockParams{1, 1, 1, 2, 1.2, 0.8}, rng);
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("sl"), std::string::npos);
  }
}

// 100 grains per roundness band of Zhang & Zhou 2015, each inside its band when measured
// independently by describe().
TEST(Hull, HundredGrainsPerBandAreInTheirBand) {
  const double bands[3][2] = {{1.1, 1.2}, {1.2, 1.4}, {1.4, 1.6}};
  for (const auto& band : bands) {
    HullParams p;
    p.diameter = 10.0;
    p.points = 20;
    p.roundness_min = band[0];
    p.roundness_max = band[1];
    for (int i = 0; i < 100; ++i) {
      Rng rng = Rng::stream(2015, i);
      const HullResult r = make_hull(p, rng);
      expect_valid_solid(r.mesh, "hull");
      const Descriptors d = describe(r.mesh);
      EXPECT_NEAR(d.convexity, 1.0, 1e-9);
      EXPECT_GE(d.roundness.weighted, band[0]);
      EXPECT_LE(d.roundness.weighted, band[1]);
      EXPECT_NEAR(d.roundness.weighted, r.roundness, 1e-9);
      EXPECT_GE(r.attempts, 1);
      EXPECT_LE(d.L, 10.0 + 1e-9);  // points lie on the sphere of diameter d
    }
  }
}

TEST(Hull, UnreachableBandFailsClearly) {
  HullParams p;
  p.diameter = 1;
  p.roundness_min = 3.0;
  p.roundness_max = 3.1;
  p.aspect_min = 1.0;
  p.max_attempts = 20;
  Rng rng(1);
  try {
    make_hull(p, rng);
    FAIL() << "expected an error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("after 20 attempts"), std::string::npos) << e.what();
  }
}

TEST(Polyhedron, MatchesAxisRatiosAndDiameter) {
  const double targets[3][2] = {{1.0, 1.0}, {2.0 / 3.0, 1.0}, {2.0 / 3.0, 2.0 / 3.0}};
  for (const auto& t : targets) {
    for (int seed = 1; seed <= 5; ++seed) {
      PolyhedronParams p;
      p.diameter = 27.5;
      p.E = t[0];
      p.F = t[1];
      Rng rng(seed);
      const Mesh m = make_polyhedron(p, rng);
      expect_valid_solid(m, "polyhedron");
      const Descriptors d = describe(m);
      EXPECT_NEAR(d.equivalent_diameter, 27.5, 1e-9);
      EXPECT_NEAR(d.convexity, 1.0, 1e-9);
      EXPECT_NEAR(d.E, t[0], 0.01) << "seed " << seed;
      EXPECT_NEAR(d.F, t[1], 0.01) << "seed " << seed;
      EXPECT_LT(d.sphericity, 0.99);  // angular: clearly cut
      EXPECT_NEAR(solid_centroid(m).norm(), 0.0, 1e-9);
    }
  }
}
