#include "geom/descriptors/descriptors.h"

#include "geom/errors.h"
#include "geom/mesh/mesh.h"
#include "geom/random.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

namespace clumpkit {
namespace {

using Vec2 = Eigen::Vector2d;

// ---- Small local mesh builders (the shape generators live elsewhere) ----

// Orients every triangle of a mesh that is convex about `inside` so its normal points outward.
void orient_about(Mesh& m, const Vec3& inside) {
  for (auto& t : m.triangles) {
    const Vec3& a = m.vertices[t[0]];
    const Vec3 n = (m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a);
    if (n.dot(a - inside) < 0.0) std::swap(t[1], t[2]);
  }
}

// Axis-aligned box a × b × c centred at the origin (8 vertices, 12 triangles).
Mesh box_mesh(double a, double b, double c) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1 ? 0.5 : -0.5) * a, (i & 2 ? 0.5 : -0.5) * b,
                            (i & 4 ? 0.5 : -0.5) * c);
  const int quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  orient_about(m, Vec3::Zero());
  return m;
}

// Regular tetrahedron with edge length 1.
Mesh tetrahedron_mesh() {
  Mesh m;
  const double s = 1.0 / (2.0 * std::sqrt(2.0));
  m.vertices = {Vec3(1, 1, 1) * s, Vec3(1, -1, -1) * s, Vec3(-1, 1, -1) * s, Vec3(-1, -1, 1) * s};
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  orient_about(m, Vec3::Zero());
  return m;
}

// Unit icosphere (the library's make_icosphere, outward oriented).
Mesh icosphere_mesh(int level) {
  return make_icosphere(level);
}

// Prism over a counter-clockwise polygon that is star-shaped from its first vertex, z in [0, h].
Mesh prism_mesh(const std::vector<Vec2>& poly, double h) {
  Mesh m;
  const int n = static_cast<int>(poly.size());
  for (const auto& p : poly) m.vertices.emplace_back(p.x(), p.y(), 0.0);
  for (const auto& p : poly) m.vertices.emplace_back(p.x(), p.y(), h);
  for (int k = 1; k + 1 < n; ++k) {
    m.triangles.push_back({n, n + k, n + k + 1});  // top, +z
    m.triangles.push_back({0, k + 1, k});          // bottom, -z
  }
  for (int k = 0; k < n; ++k) {
    const int a = k, b = (k + 1) % n;
    m.triangles.push_back({a, b, n + b});
    m.triangles.push_back({a, n + b, n + a});
  }
  return m;
}

// L-shaped prism: the union of unit cubes at (0,0), (1,0), (0,1) in the xy plane, height 1.
// Cross-section area 3, perimeter 8; convex hull volume 3.5.
Mesh l_prism_mesh() {
  return prism_mesh({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1.0);
}

// Square ring (picture frame): outer square 3 × 3, centred square hole 1 × 1, height 1 (genus 1).
Mesh ring_mesh() {
  const Vec2 outer[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  const Vec2 inner[4] = {{1, 1}, {2, 1}, {2, 2}, {1, 2}};
  Mesh m;
  for (double z : {0.0, 1.0})
    for (const auto& p : outer) m.vertices.emplace_back(p.x(), p.y(), z);
  for (double z : {0.0, 1.0})
    for (const auto& p : inner) m.vertices.emplace_back(p.x(), p.y(), z);
  auto ob = [](int k) { return k % 4; };
  auto ot = [](int k) { return 4 + k % 4; };
  auto ib = [](int k) { return 8 + k % 4; };
  auto it = [](int k) { return 12 + k % 4; };
  for (int k = 0; k < 4; ++k) {
    m.triangles.push_back({ob(k), ob(k + 1), ot(k + 1)});  // outer wall
    m.triangles.push_back({ob(k), ot(k + 1), ot(k)});
    m.triangles.push_back({ib(k + 1), ib(k), it(k)});  // inner wall, facing the hole
    m.triangles.push_back({ib(k + 1), it(k), it(k + 1)});
    m.triangles.push_back({ot(k), ot(k + 1), it(k + 1)});  // top annulus
    m.triangles.push_back({ot(k), it(k + 1), it(k)});
    m.triangles.push_back({ob(k), ib(k + 1), ob(k + 1)});  // bottom annulus
    m.triangles.push_back({ob(k), ib(k), ib(k + 1)});
  }
  return m;
}

// Star-shaped bumpy sphere, 192 triangles: a non-convex mesh of typical particle size.
Mesh bumpy_mesh() {
  const int rings = 9, seg = 12;
  auto radius = [](double th, double ph) {
    return 1.0 + 0.3 * std::sin(3.0 * ph) * std::sin(2.0 * th) + 0.15 * std::cos(5.0 * th);
  };
  Mesh m;
  m.vertices.emplace_back(0, 0, radius(0, 0));
  for (int j = 1; j < rings; ++j) {
    const double th = M_PI * j / rings;
    for (int i = 0; i < seg; ++i) {
      const double ph = 2.0 * M_PI * i / seg;
      const double r = radius(th, ph);
      m.vertices.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph),
                              r * std::cos(th));
    }
  }
  m.vertices.emplace_back(0, 0, -radius(M_PI, 0));
  const int south = static_cast<int>(m.vertices.size()) - 1;
  auto id = [&](int j, int i) { return 1 + (j - 1) * seg + (i % seg); };
  for (int i = 0; i < seg; ++i) {
    m.triangles.push_back({0, id(1, i), id(1, i + 1)});
    m.triangles.push_back({south, id(rings - 1, i + 1), id(rings - 1, i)});
    for (int j = 1; j + 1 < rings; ++j) {
      m.triangles.push_back({id(j, i), id(j + 1, i), id(j + 1, i + 1)});
      m.triangles.push_back({id(j, i), id(j + 1, i + 1), id(j, i + 1)});
    }
  }
  if (signed_volume(m) < 0.0) flip_orientation(m);
  return m;
}

Mat3 some_rotation() {
  return (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(-1.9, Vec3(-2, 0.5, 1).normalized()))
      .toRotationMatrix();
}
const Vec3 kShift(12.5, -3.25, 7.0);

double poly_area(const std::vector<Vec2>& p) {
  double a = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& q = p[i];
    const Vec2& r = p[(i + 1) % p.size()];
    a += q.x() * r.y() - q.y() * r.x();
  }
  return 0.5 * a;
}

double poly_perimeter(const std::vector<Vec2>& p) {
  double s = 0.0;
  for (size_t i = 0; i < p.size(); ++i) s += (p[(i + 1) % p.size()] - p[i]).norm();
  return s;
}

// Area of the union of the projected triangles, by rasterizing on an n × n grid of cell centres.
double raster_projected_area(const Mesh& m, const Vec3& dir, int n) {
  const Vec3 d = dir.normalized();
  const Vec3 u = d.unitOrthogonal(), v = d.cross(u);
  std::vector<Vec2> p;
  for (const auto& x : m.vertices) p.emplace_back(x.dot(u), x.dot(v));
  Vec2 lo = p[0], hi = p[0];
  for (const auto& q : p) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Vec2 cell = (hi - lo) / n;
  std::vector<char> in(static_cast<size_t>(n) * n, 0);
  for (const auto& t : m.triangles) {
    const Vec2 a = p[t[0]], b = p[t[1]], c = p[t[2]];
    const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (std::abs(det) < 1e-300) continue;
    const Vec2 tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
    const int i0 = std::max(0, static_cast<int>((tlo.x() - lo.x()) / cell.x()) - 1);
    const int i1 = std::min(n - 1, static_cast<int>((thi.x() - lo.x()) / cell.x()) + 1);
    const int j0 = std::max(0, static_cast<int>((tlo.y() - lo.y()) / cell.y()) - 1);
    const int j1 = std::min(n - 1, static_cast<int>((thi.y() - lo.y()) / cell.y()) + 1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const Vec2 q = lo + Vec2((i + 0.5) * cell.x(), (j + 0.5) * cell.y()) - a;
        const double s = (q.x() * (c - a).y() - q.y() * (c - a).x()) / det;
        const double r = ((b - a).x() * q.y() - (b - a).y() * q.x()) / det;
        if (s >= 0 && r >= 0 && s + r <= 1) in[static_cast<size_t>(i) * n + j] = 1;
      }
  }
  double count = 0;
  for (char c : in) count += c;
  return count * cell.x() * cell.y();
}

// ---- Test meshes are sound ----

TEST(DescriptorsFixtures, LocalMeshesAreClosedAndOutward) {
  for (const Mesh& m : {box_mesh(2, 1, 1), tetrahedron_mesh(), icosphere_mesh(2), l_prism_mesh(),
                        ring_mesh(), bumpy_mesh()}) {
    const MeshCheck c = check_mesh(m);
    EXPECT_TRUE(c.closed);
    EXPECT_TRUE(c.oriented);
    EXPECT_FALSE(c.degenerate);
    EXPECT_GT(c.volume, 0.0);
  }
  EXPECT_NEAR(signed_volume(l_prism_mesh()), 3.0, 1e-12);
  EXPECT_NEAR(signed_volume(ring_mesh()), 8.0, 1e-12);
}

// ---- Sphericity (closed-form shape descriptors) ----

TEST(Descriptors, SphericityOfCube) {
  EXPECT_NEAR(describe(box_mesh(1, 1, 1)).sphericity, 0.805995977008, 1e-9);
}

TEST(Descriptors, SphericityOfBox2x1x1) {
  EXPECT_NEAR(describe(box_mesh(2, 1, 1)).sphericity, 0.767663317071, 1e-9);
}

TEST(Descriptors, SphericityOfRegularTetrahedron) {
  EXPECT_NEAR(describe(tetrahedron_mesh()).sphericity, 0.671139291313, 1e-9);
}

TEST(Descriptors, SphericityOfIcosphereNearOne) {
  const Descriptors d = describe(icosphere_mesh(4));
  EXPECT_NEAR(d.sphericity, 1.0, 0.01);
  EXPECT_LE(d.sphericity, 1.0);
  EXPECT_NEAR(d.equivalent_diameter, 2.0, 0.02);
  EXPECT_NEAR(d.roundness.weighted, 1.0, 0.01);
  EXPECT_NEAR(d.convexity, 1.0, 1e-9);
}

TEST(Descriptors, EquivalentDiameterOfCube) {
  EXPECT_NEAR(describe(box_mesh(2, 2, 2)).equivalent_diameter, std::cbrt(48.0 / M_PI), 1e-12);
}

TEST(Descriptors, RejectsInvertedMesh) {
  Mesh m = box_mesh(1, 1, 1);
  flip_orientation(m);
  EXPECT_THROW(describe(m), InvalidInput);
  EXPECT_THROW(principal_frame(m), InvalidInput);
}

// ---- 2-D roundness and silhouettes ----

TEST(PolygonRoundness, SquareRectangleAndCircle) {
  EXPECT_NEAR(polygon_roundness({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), 4.0 / M_PI, 1e-12);
  EXPECT_NEAR(polygon_roundness({{0, 0}, {2, 0}, {2, 1}, {0, 1}}), 1.432394487827, 1e-12);
  // Clockwise input gives the same value.
  EXPECT_NEAR(polygon_roundness({{0, 1}, {2, 1}, {2, 0}, {0, 0}}), 1.432394487827, 1e-12);
  std::vector<Vec2> circle;
  for (int i = 0; i < 2000; ++i)
    circle.emplace_back(std::cos(2 * M_PI * i / 2000), std::sin(2 * M_PI * i / 2000));
  EXPECT_NEAR(polygon_roundness(circle), 1.0, 1e-5);
  std::vector<Vec2> ellipse;
  for (int i = 0; i < 4000; ++i)
    ellipse.emplace_back(2 * std::cos(2 * M_PI * i / 4000), std::sin(2 * M_PI * i / 4000));
  EXPECT_NEAR(polygon_roundness(ellipse), 1.18882714, 1e-6);
  EXPECT_THROW(polygon_roundness({{0, 0}, {1, 0}}), InvalidInput);
  EXPECT_THROW(polygon_roundness({{0, 0}, {1, 0}, {2, 0}}), InvalidInput);
}

TEST(Silhouette, SquareAndRectangleViewsBothPaths) {
  for (bool convex : {true, false}) {
    SCOPED_TRACE(convex ? "convex" : "arrangement");
    const auto sq = silhouette(box_mesh(1, 1, 1), Vec3::UnitZ(), convex);
    EXPECT_NEAR(polygon_roundness(sq), 4.0 / M_PI, 0.005 * 4.0 / M_PI);
    EXPECT_NEAR(polygon_roundness(sq), 4.0 / M_PI, 1e-9);
    EXPECT_EQ(sq.size(), 4u);
    EXPECT_NEAR(poly_area(sq), 1.0, 1e-12);  // counter-clockwise
    const auto rect = silhouette(box_mesh(2, 1, 1), Vec3::UnitY(), convex);
    EXPECT_NEAR(polygon_roundness(rect), 1.432394487827, 0.005 * 1.432394487827);
    EXPECT_NEAR(polygon_roundness(rect), 1.432394487827, 1e-9);
    EXPECT_NEAR(poly_area(rect), 2.0, 1e-12);
    // Rotated and translated box seen along its rotated axis.
    Mesh m = box_mesh(2, 1, 1);
    const Mat3 R = some_rotation();
    transform(m, R, kShift);
    const auto rr = silhouette(m, R * Vec3::UnitZ(), convex);
    EXPECT_NEAR(polygon_roundness(rr), 1.432394487827, 1e-6);
    EXPECT_NEAR(poly_area(rr), 2.0, 1e-9);
  }
}

TEST(Silhouette, LPrismByHand) {
  const Mesh m = l_prism_mesh();
  // Along z: the L itself, area 3, perimeter 8, C = 64 / (12π).
  const auto l = silhouette(m, Vec3::UnitZ(), false);
  EXPECT_EQ(l.size(), 6u);
  EXPECT_NEAR(poly_area(l), 3.0, 1e-12);
  EXPECT_NEAR(poly_perimeter(l), 8.0, 1e-12);
  EXPECT_NEAR(polygon_roundness(l), 16.0 / (3.0 * M_PI), 1e-12);
  // The convex path gives the hull of the L: area 3.5, perimeter 6 + √2.
  const auto h = silhouette(m, Vec3::UnitZ(), true);
  EXPECT_NEAR(poly_area(h), 3.5, 1e-12);
  EXPECT_NEAR(poly_perimeter(h), 6.0 + std::sqrt(2.0), 1e-12);
  // Along x: rectangle 2 (y) × 1 (z).
  const auto side = silhouette(m, Vec3::UnitX(), false);
  EXPECT_NEAR(poly_area(side), 2.0, 1e-12);
  EXPECT_NEAR(poly_perimeter(side), 6.0, 1e-12);
  // Along the diagonal (1,1,0): rectangle 2√2 × 1.
  const auto diag = silhouette(m, Vec3(1, 1, 0), false);
  EXPECT_NEAR(poly_area(diag), 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(poly_perimeter(diag), 2.0 * (2.0 * std::sqrt(2.0) + 1.0), 1e-12);
  // Rigid motion of mesh and view together leaves the outline unchanged.
  Mesh moved = m;
  const Mat3 R = some_rotation();
  transform(moved, R, kShift);
  const auto lm = silhouette(moved, R * Vec3::UnitZ(), false);
  EXPECT_NEAR(poly_area(lm), 3.0, 1e-9);
  EXPECT_NEAR(poly_perimeter(lm), 8.0, 1e-9);
}

TEST(Silhouette, LPrismObliqueView) {
  // Oblique views: projected top, bottom and walls overlap and contour edges cross. Compare the
  // outline area with a raster of the union of the projected triangles.
  const Mesh m = l_prism_mesh();
  for (const Vec3& dir : {Vec3(1, 2, 2), Vec3(-0.3, 0.4, 1.0), Vec3(1, -1, 0.5)}) {
    const auto s = silhouette(m, dir, false);
    EXPECT_GT(poly_area(s), 0.0);
    EXPECT_NEAR(poly_area(s), raster_projected_area(m, dir, 800), 0.005 * poly_area(s));
  }
}

TEST(Silhouette, NonConvexMeshMatchesRaster) {
  const Mesh m = bumpy_mesh();
  EXPECT_LT(describe(m).convexity, 0.99);
  double smallest_ratio = 1.0;  // outline area / hull area over the views
  for (const Vec3& dir : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.3, -0.8, 0.5), Vec3(1, 1, 1)}) {
    const auto s = silhouette(m, dir, false);
    const auto h = silhouette(m, dir, true);
    EXPECT_GT(poly_area(s), 0.0);
    EXPECT_NEAR(poly_area(s), raster_projected_area(m, dir, 800), 0.005 * poly_area(s));
    EXPECT_LE(poly_area(s), poly_area(h) + 1e-12);
    smallest_ratio = std::min(smallest_ratio, poly_area(s) / poly_area(h));
  }
  EXPECT_LT(smallest_ratio, 0.99);  // some outline is genuinely non-convex
}

TEST(Silhouette, ConvexAndArrangementPathsAgreeOnConvexMesh) {
  const Mesh m = icosphere_mesh(2);
  for (const Vec3& dir : {Vec3(0, 0, 1), Vec3(0.3, -0.8, 0.5), Vec3(1, 1, 1), Vec3(-2, 1, 0.1)}) {
    const auto a = silhouette(m, dir, true);
    const auto b = silhouette(m, dir, false);
    EXPECT_NEAR(poly_area(a), poly_area(b), 1e-9);
    EXPECT_NEAR(poly_perimeter(a), poly_perimeter(b), 1e-9);
    EXPECT_EQ(a.size(), b.size());
  }
}

TEST(Silhouette, HolesAreIgnored) {
  // The frame seen along its axis: outer square 3 × 3, the 1 × 1 hole is not subtracted.
  const auto s = silhouette(ring_mesh(), Vec3::UnitZ(), false);
  EXPECT_EQ(s.size(), 4u);
  EXPECT_NEAR(poly_area(s), 9.0, 1e-12);
  EXPECT_NEAR(poly_perimeter(s), 12.0, 1e-12);
}

TEST(Silhouette, RejectsZeroDirection) {
  EXPECT_THROW(silhouette(box_mesh(1, 1, 1), Vec3::Zero(), true), InvalidInput);
}

// ---- Weighted roundness (Zhang & Zhou 2015 eq. 2) ----

TEST(WeightedRoundness, Box2x1x1) {
  const Mesh m = box_mesh(2, 1, 1);
  const PrincipalFrame f = principal_frame(m);
  for (bool convex : {true, false}) {
    const Roundness r = weighted_roundness(m, f, convex);
    EXPECT_NEAR(r.weighted, 1.400563499209, 0.005 * 1.400563499209);
    EXPECT_NEAR(r.weighted, 1.400563499209, 1e-9);
    EXPECT_NEAR(r.view[2], 4.0 / M_PI, 1e-9);  // along the long axis: the square
    EXPECT_NEAR(r.view_area[2], 1.0, 1e-9);
  }
  EXPECT_NEAR(describe(m).roundness.weighted, 1.400563499209, 1e-9);
}

TEST(WeightedRoundness, Box2x1x1RotatedAndTranslated) {
  Mesh m = box_mesh(2, 1, 1);
  transform(m, some_rotation(), kShift);
  const PrincipalFrame f = principal_frame(m);
  for (bool convex : {true, false}) {
    const Roundness r = weighted_roundness(m, f, convex);
    EXPECT_NEAR(r.weighted, 1.400563499209, 0.005 * 1.400563499209);
    EXPECT_NEAR(r.weighted, 1.400563499209, 1e-8);
  }
  EXPECT_NEAR(describe(m).roundness.weighted, 1.400563499209, 1e-8);
}

TEST(WeightedRoundness, LPrismByHand) {
  // Principal axes: S = z, I = (1,1,0)/√2, L = (1,-1,0)/√2. Views: the L (P 8, A 3), a rectangle
  // 2√2 × 1 and a rectangle (3/√2) × 1. R = Σ P² / (4π Σ A).
  const Mesh m = l_prism_mesh();
  const Descriptors d = describe(m);
  const double s2 = std::sqrt(2.0);
  const double p[3] = {8.0, 2.0 * (2.0 * s2 + 1.0), 2.0 * (3.0 / s2 + 1.0)};
  const double a[3] = {3.0, 2.0 * s2, 3.0 / s2};
  const double expected =
      (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / (4.0 * M_PI * (a[0] + a[1] + a[2]));
  EXPECT_NEAR(d.roundness.weighted, expected, 1e-9);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(d.roundness.view_area[i], a[i], 1e-9);
    EXPECT_NEAR(d.roundness.view[i], p[i] * p[i] / (4.0 * M_PI * a[i]), 1e-9);
  }
  EXPECT_NEAR(d.axes(0), 1.0, 1e-12);
  EXPECT_NEAR(d.axes(1), 3.0 / s2, 1e-12);
  EXPECT_NEAR(d.axes(2), 2.0 * s2, 1e-12);
}

// ---- Principal frame ----

void expect_rotation(const Mat3& a) {
  EXPECT_LT((a.transpose() * a - Mat3::Identity()).norm(), 1e-12);
  EXPECT_NEAR(a.determinant(), 1.0, 1e-12);
}

TEST(PrincipalFrame, CubeExtentsAreOneEvenWhenRotated) {
  for (bool rotate : {false, true}) {
    Mesh m = box_mesh(1, 1, 1);
    if (rotate) transform(m, some_rotation(), kShift);
    const PrincipalFrame f = principal_frame(m);
    EXPECT_LT((f.extents - Vec3(1, 1, 1)).norm(), 1e-9);
    expect_rotation(f.axes);
    EXPECT_LT((f.centroid - (rotate ? kShift : Vec3::Zero())).norm(), 1e-12);
  }
}

TEST(PrincipalFrame, EqualExtentsKeepTheirLabelsUnderRotation) {
  // Polyhedra of E = F = 1 are stretched to three equal principal extents, so S, I and L differ
  // only in rounding; the labels follow the moments of inertia instead, and the per-view
  // roundness of a rotated and moved copy is the original's view for view.
  const PolyhedronParams params{1.0, 30, 1.0, 1.0};
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Rng rng(seed);
    const Mesh m = make_polyhedron(params, rng);
    Mesh moved = m;
    transform(moved, some_rotation(), kShift);
    const Descriptors a = describe(m), b = describe(moved);
    ASSERT_NEAR(a.axes(0), a.axes(2), 1e-12) << "seed " << seed;  // the tie this is about
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(a.roundness.view[i], b.roundness.view[i], 1e-9)
          << "seed " << seed << " view " << i;
      EXPECT_NEAR(a.roundness.view_area[i], b.roundness.view_area[i], 1e-9) << "seed " << seed;
    }
    EXPECT_NEAR(a.roundness.weighted, b.roundness.weighted, 1e-9);
  }
}

TEST(PrincipalFrame, Box4x2x1AxesAndSigns) {
  const Mat3 R = some_rotation();
  Mesh m = box_mesh(4, 2, 1);
  transform(m, R, kShift);
  const PrincipalFrame f = principal_frame(m);
  EXPECT_LT((f.extents - Vec3(1, 2, 4)).norm(), 1e-12);
  expect_rotation(f.axes);
  EXPECT_NEAR(std::abs(f.axes.col(0).dot(R.col(2))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(f.axes.col(1).dot(R.col(1))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(f.axes.col(2).dot(R.col(0))), 1.0, 1e-12);
  for (int j = 1; j < 3; ++j) {  // column 0 may be flipped for handedness
    Eigen::Index k;
    f.axes.col(j).cwiseAbs().maxCoeff(&k);
    EXPECT_GT(f.axes(k, j), 0.0);
  }
  // Deterministic: the same mesh gives the same frame.
  EXPECT_EQ((principal_frame(m).axes - f.axes).norm(), 0.0);
}

TEST(Descriptors, ShapeRatiosOfBox4x2x1) {
  Mesh m = box_mesh(4, 2, 1);
  transform(m, some_rotation(), kShift);
  const Descriptors d = describe(m);
  EXPECT_LT((d.axes - Vec3(1, 2, 4)).norm(), 1e-12);
  EXPECT_NEAR(d.E, 0.5, 1e-12);
  EXPECT_NEAR(d.F, 0.5, 1e-12);
  EXPECT_NEAR(d.AR, 0.25, 1e-12);
  EXPECT_NEAR(d.volume, 8.0, 1e-12);
  EXPECT_NEAR(d.area, 28.0, 1e-12);
}

// ---- Caliper dimensions ----

TEST(Caliper, RotatedBox3x2x1) {
  // L: the space diagonal, √14. Projected on the plane ⟂ (3,2,1), the longest vertex-pair is the
  // other diagonal (-3,2,1): |v|² - (v·d)² = 14 - 16/14, W = √(90/7), along (-5,6,3)/√70.
  // H is the extent along L × W ∝ (0,-1,2)/√5: (2·1 + 1·2)/√5 = 4/√5.
  const Mat3 R = some_rotation();
  Mesh m = box_mesh(3, 2, 1);
  transform(m, R, kShift);
  const CaliperDimensions c = caliper_dimensions(m);
  EXPECT_NEAR(c.L, std::sqrt(14.0), 1e-12);
  EXPECT_NEAR(c.W, std::sqrt(90.0 / 7.0), 1e-12);
  EXPECT_NEAR(c.H, 4.0 / std::sqrt(5.0), 1e-12);
  // Directions, in the box frame, up to the box's mirror symmetries.
  EXPECT_LT(((R.transpose() * c.dir_L).cwiseAbs() - Vec3(3, 2, 1) / std::sqrt(14.0)).norm(), 1e-12);
  EXPECT_LT(((R.transpose() * c.dir_W).cwiseAbs() - Vec3(5, 6, 3) / std::sqrt(70.0)).norm(), 1e-12);
  EXPECT_LT(((R.transpose() * c.dir_H).cwiseAbs() - Vec3(0, 1, 2) / std::sqrt(5.0)).norm(), 1e-12);
  Mat3 dirs;
  dirs << c.dir_L, c.dir_W, c.dir_H;
  expect_rotation(dirs);
  const Descriptors d = describe(m);
  EXPECT_NEAR(d.L, c.L, 1e-12);
  EXPECT_NEAR(d.W, c.W, 1e-12);
  EXPECT_NEAR(d.H, c.H, 1e-12);
}

TEST(Caliper, RegularTetrahedron) {
  // Edge 1: L = 1 along an edge AB. Seen along AB, A and B coincide and the opposite edge CD
  // (perpendicular to AB) keeps its length 1, while C and D lie √3/2 from AB: W = 1 along CD.
  // H is the distance between the skew lines AB and CD: 1/√2.
  const CaliperDimensions c = caliper_dimensions(tetrahedron_mesh());
  EXPECT_NEAR(c.L, 1.0, 1e-12);
  EXPECT_NEAR(c.W, 1.0, 1e-12);
  EXPECT_NEAR(c.H, 1.0 / std::sqrt(2.0), 1e-12);
}

// ---- Convexity ----

TEST(Descriptors, ConvexityOfBoxAndLPrism) {
  EXPECT_NEAR(describe(box_mesh(3, 2, 1)).convexity, 1.0, 1e-12);
  EXPECT_NEAR(describe(l_prism_mesh()).convexity, 3.0 / 3.5, 1e-12);
  EXPECT_NEAR(describe(ring_mesh()).convexity, 8.0 / 9.0, 1e-12);
}

// ---- Timing (printed, not asserted) ----

TEST(DescriptorsTiming, PrintTimePerDescribeCall) {
  const std::pair<const char*, Mesh> cases[] = {
      {"icosphere level 2 (320 triangles)", icosphere_mesh(2)},
      {"bumpy sphere (192 triangles, non-convex)", bumpy_mesh()},
      {"L-prism (20 triangles, non-convex)", l_prism_mesh()}};
  for (const auto& [name, mesh] : cases) {
    describe(mesh);  // warm-up
    int n = 0;
    const auto t0 = std::chrono::steady_clock::now();
    double elapsed = 0.0;
    while (elapsed < 0.3 || n < 5) {
      describe(mesh);
      ++n;
      elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    std::printf("[ timing ] describe(), %s: %.3f ms per call (%d calls)\n", name, 1e3 * elapsed / n,
                n);
  }
}

}  // namespace
}  // namespace clumpkit
