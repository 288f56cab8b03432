// MeshIndex (Embree BVH): nearest-triangle distances against brute force, bounded searches, row
// crossings against analytic boxes; closest_point_on_triangle against dense sampling.
#include "geom/mesh/mesh_index.h"
#include "geom/random.h"
#include "geom/shapes/block.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <cmath>
#include <limits>

using namespace clumpkit;

namespace {

double brute_distance(const Mesh& m, const Vec3& p, int* which = nullptr) {
  double best = std::numeric_limits<double>::infinity();
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    const auto& tri = m.triangles[t];
    const double d =
        (closest_point_on_triangle(p, m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]) -
         p)
            .norm();
    if (d < best) {
      best = d;
      if (which) *which = t;
    }
  }
  return best;
}

}  // namespace

TEST(ClosestPointOnTriangle, NoSampledPointOfTheTriangleIsCloser) {
  Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = rng.uniform(Vec3::Constant(-1), Vec3::Constant(1));
    const Vec3 b = rng.uniform(Vec3::Constant(-1), Vec3::Constant(1));
    const Vec3 c = rng.uniform(Vec3::Constant(-1), Vec3::Constant(1));
    const Vec3 p = rng.uniform(Vec3::Constant(-2), Vec3::Constant(2));
    const Vec3 q = closest_point_on_triangle(p, a, b, c);
    // q lies in the triangle: barycentric coordinates in [0, 1] (up to rounding).
    const Vec3 n = (b - a).cross(c - a);
    const double area = n.norm();
    const double u = (b - q).cross(c - q).dot(n) / (area * area);
    const double v = (c - q).cross(a - q).dot(n) / (area * area);
    EXPECT_GE(u, -1e-9);
    EXPECT_GE(v, -1e-9);
    EXPECT_LE(u + v, 1.0 + 1e-9);
    const double d = (q - p).norm();
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; i + j <= 40; ++j) {
        const Vec3 s = a + (b - a) * (i / 40.0) + (c - a) * (j / 40.0);
        ASSERT_LE(d, (s - p).norm() + 1e-12);
      }
  }
}

TEST(MeshIndex, DistancesAreTheBruteForceMinimumAndBoundsOnlyCut) {
  Rng rng(5);
  const Mesh block = make_block(BlockParams{75.1, 58.0, 49.8, 2, 0.8, 1.2}, rng);
  const Mesh ellipsoid = make_ellipsoid(Vec3(2.0, 1.0, 1.0), 4);
  for (const Mesh* m : {&block, &ellipsoid}) {
    const MeshIndex index(*m);
    const auto bb = bounding_box(*m);
    for (int s = 0; s < 300; ++s) {
      const Vec3 p = rng.uniform(bb[0], bb[1]);
      int which = -1;
      const double exact = brute_distance(*m, p, &which);
      EXPECT_NEAR(index.distance(p), exact, 1e-12 * (1 + exact));
      const auto n = index.nearest(p, 2.0 * exact + 1e-9);
      EXPECT_NEAR(n.distance, exact, 1e-12 * (1 + exact));
      EXPECT_NEAR(index.distance_to_triangle(p, n.triangle), exact, 1e-12 * (1 + exact));
      // Below the distance, the bounded search finds nothing and says so.
      const auto none = index.nearest(p, 0.5 * exact);
      EXPECT_EQ(none.triangle, -1);
      EXPECT_EQ(none.distance, 0.5 * exact);
    }
  }
}

TEST(MeshIndex, RowsCrossABoxAtItsFacesAndAnEllipsoidAtItsChord) {
  const Mesh box = make_box(Vec3(2.0, 3.0, 4.0));  // centred at the origin
  const MeshIndex index(box);
  const auto xs = index.crossings_x(0.3, -0.7);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0].x, -1.0, 1e-6);
  EXPECT_NEAR(xs[1].x, 1.0, 1e-6);
  EXPECT_TRUE(index.crossings_x(2.0, 0.0).empty());
  // Through a face diagonal (an edge shared by two triangles): still one crossing per face.
  const auto diag = index.crossings_x(0.0, 0.0);
  EXPECT_EQ(diag.size() % 2, 0u);

  const Mesh e = make_ellipsoid(Vec3(2.0, 1.0, 1.0), 5);
  const MeshIndex ei(e);
  for (double y : {0.0, 0.3, 0.61, 0.9}) {
    const auto c = ei.crossings_x(y, 0.1);
    ASSERT_EQ(c.size(), 2u) << y;
    const double half = 2.0 * std::sqrt(1.0 - y * y - 0.01);  // the smooth ellipsoid's chord
    EXPECT_NEAR(c[1].x - c[0].x, 2.0 * half, 2e-3 * half) << y;
    EXPECT_LT(c[0].x, c[1].x);
  }
}

// The descent of the field's deep voxels: from the nearest triangle of a point a little away
// (a neighbour voxel's feature), it ends at the brute-force nearest, inside an ellipsoid of
// 20,480 triangles and outside it; from any triangle at all, outside (the sublevel sets of the
// distance on a convex surface seen from outside are connected); never above its start.
TEST(MeshIndex, DescentOverTheSurfaceReachesTheNearestTriangle) {
  const Mesh m = make_ellipsoid(Vec3(2.0, 1.0, 1.0), 5);
  const MeshIndex index(m);
  Rng rng(17);
  for (int s = 0; s < 300; ++s) {
    const bool outside = s % 2 == 1;
    const Vec3 u = rng.uniform(Vec3::Constant(-1), Vec3::Constant(1));
    const Vec3 p = (outside ? 1.6 : 0.9) * Vec3(2.0 * u.x(), u.y(), u.z());
    int which = -1;
    const double truth = brute_distance(m, p, &which);
    const Vec3 off = rng.uniform(Vec3::Constant(-0.05), Vec3::Constant(0.05));
    int start = -1;
    brute_distance(m, p + off, &start);
    if (outside && s % 4 == 1)
      start = static_cast<int>(rng.uniform(0.0, double(m.triangles.size()) - 1.0));
    const auto from = MeshIndex::Nearest{index.distance_to_triangle(p, start), start};
    const auto end = index.descend(p, from);
    EXPECT_NEAR(end.distance, truth, 1e-12) << s;
    EXPECT_LE(end.distance, from.distance) << s;
  }
}

// Embree enforces a device's "threads=N" by a process-wide tbb::global_control; an index must
// not hold the program's parallel loops to one thread while it lives.
TEST(MeshIndex, LeavesTheProcessParallelismAsItWas) {
  const auto parallelism = [] {
    return tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  };
  const std::size_t before = parallelism();
  const Mesh m = make_ellipsoid(Vec3(2.0, 1.0, 1.0), 3);
  const MeshIndex index(m);
  EXPECT_EQ(parallelism(), before);
  EXPECT_NEAR(index.distance(Vec3::Zero()), 1.0, 0.05);
}
