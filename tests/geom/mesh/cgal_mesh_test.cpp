// convex_hull: the exact hull facets of a point set, whatever the order of the points and however
// many of them lie on the hull (every one on a scanned convex surface) or on one plane.
#include "geom/mesh/cgal_mesh.h"
#include "geom/errors.h"
#include "geom/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace clumpkit;

namespace {
// Largest signed distance of any point outside the plane of any facet (≤ 0: all inside).
double farthest_outside(const Mesh& hull, const std::vector<Vec3>& points) {
  double worst = -1e300;
  for (const auto& t : hull.triangles) {
    const Vec3& a = hull.vertices[t[0]];
    const Vec3 n = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).normalized();
    for (const Vec3& p : points) worst = std::max(worst, n.dot(p - a));
  }
  return worst;
}
}  // namespace

TEST(ConvexHull, EveryPointOfASphereIsAVertexAndTheHullIsClosedAndOutward) {
  // Points on a sphere are all extreme and nearly cospherical (the degenerate case of a Delaunay
  // triangulation): the hull keeps every one, as a closed surface of genus 0 (F = 2V − 4).
  Rng rng(5);
  std::vector<Vec3> points;
  for (int i = 0; i < 3000; ++i) {
    Vec3 g(rng.normal(), rng.normal(), rng.normal());
    points.push_back(2.0 * g.normalized() + Vec3(1.0, -3.0, 0.5));
  }
  const Mesh hull = convex_hull(points);
  EXPECT_EQ(hull.vertices.size(), points.size());
  EXPECT_EQ(hull.triangles.size(), 2 * points.size() - 4);
  const MeshCheck c = check_mesh(hull);
  EXPECT_TRUE(c.closed && c.manifold && c.oriented);
  EXPECT_LT(farthest_outside(hull, points), 1e-12);
  // Inscribed in the sphere of radius 2 and close to it: 3000 points leave ~0.2 % of its volume.
  const double sphere = 4.0 / 3.0 * M_PI * 8.0;
  EXPECT_GT(signed_volume(hull), 0.99 * sphere);
  EXPECT_LT(signed_volume(hull), sphere);
}

TEST(ConvexHull, CubeWithInteriorAndFacePointsHasTheCubeVolumeWhateverTheOrder) {
  // A 5 × 5 × 5 grid: 98 points on the faces (coplanar in groups of 25), 27 inside. The hull is
  // the unit cube; interior points are dropped, face points stay (they lie on the hull).
  std::vector<Vec3> points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) points.emplace_back(0.25 * i, 0.25 * j, 0.25 * k);
  const Mesh hull = convex_hull(points);
  EXPECT_EQ(hull.vertices.size(), 125u - 27u);
  EXPECT_EQ(hull.triangles.size(), 6u * 32u);  // each face: a 4 × 4 grid of squares, two each
  EXPECT_DOUBLE_EQ(signed_volume(hull), 1.0);
  EXPECT_LT(farthest_outside(hull, points), 1e-15);

  // The same points in another order and duplicated give the same mesh, byte for byte.
  std::vector<Vec3> shuffled = points;
  shuffled.insert(shuffled.end(), points.begin(), points.begin() + 40);
  Rng rng(11);
  for (std::size_t i = shuffled.size() - 1; i > 0; --i)
    std::swap(shuffled[i], shuffled[rng.below(i + 1)]);
  const Mesh again = convex_hull(shuffled);
  EXPECT_EQ(again.vertices, hull.vertices);
  EXPECT_EQ(again.triangles, hull.triangles);
}

TEST(ConvexHull, FlatOrTooFewOrNonFinitePointsAreRefused) {
  std::vector<Vec3> flat;
  for (int i = 0; i < 10; ++i) flat.emplace_back(i, i * i, 0.0);
  EXPECT_THROW(convex_hull(flat), InvalidInput);
  EXPECT_THROW(convex_hull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0)}),
               InvalidInput);
  EXPECT_THROW(convex_hull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, NAN)}),
               InvalidInput);
}
