// repair_mesh (geom/mesh/repair.h) on the defects of scans, each built here: a fin on an edge, a
// bow-tie, two cubes sharing an edge, a fold, holes meeting at a vertex, floating debris and a
// double wall. Each closes to the intended solid's volume within 1 % or is refused naming the
// step and the place.
#include "geom/mesh/repair.h"

#include "geom/errors.h"
#include "geom/mesh/crossings.h"
#include "geom/mesh/mesh.h"
#include "geom/mesh/weld.h"
#include "geom/random.h"
#include "geom/shapes/primitives.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace clumpkit {
namespace repair_test {

double volume_of(const Mesh& m) {
  return check_mesh(m).volume;
}

// Triangles of `m` using vertex v.
std::vector<int> fan(const Mesh& m, int v) {
  std::vector<int> out;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    for (int c : m.triangles[t])
      if (c == v) out.push_back(t);
  return out;
}

void erase_triangles(Mesh& m, const std::set<int>& gone) {
  std::vector<std::array<int, 3>> kept;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    if (!gone.count(t)) kept.push_back(m.triangles[t]);
  m.triangles = kept;
}

TEST(MeshRepair, AFinOnAnEdgeIsSplitOffAsDebrisAndTheSphereKept) {
  const Mesh sphere = make_icosphere(3);
  Mesh m = sphere;
  const auto t = m.triangles[100];
  const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]];
  m.vertices.push_back(0.5 * (a + b) * 1.3);  // a blade standing out of the surface
  m.triangles.push_back({t[0], t[1], static_cast<int>(m.vertices.size()) - 1});
  ASSERT_EQ(check_mesh(m).nonmanifold_edges, 1);
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.nonmanifold_edges, 1);
  EXPECT_GE(r.small_components, 1);
  EXPECT_TRUE(check_mesh(m).closed && check_mesh(m).manifold);
  EXPECT_NEAR(volume_of(m) / volume_of(sphere), 1.0, 0.01);
}

TEST(MeshRepair, ABowTieOfTwoTetrahedraIsTwoSolids) {
  // Two tetrahedra sharing only the origin, listed with one vertex there.
  Mesh m;
  m.vertices = {Vec3(0, 0, 0),  Vec3(1, 0, 0),  Vec3(0, 1, 0), Vec3(0, 0, 1),
                Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                 {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
  const RepairReport r = repair_mesh(m);
  EXPECT_GE(r.split_vertices, 1);
  EXPECT_EQ(r.holes, 0);
  EXPECT_NEAR(volume_of(m), 2.0 / 6.0, 1e-12);
}

// Unit cubes centred at the origin and at (1, 1, 0): they share the edge x = y = 0.5 once welded.
Mesh cubes_on_an_edge() {
  Mesh m = make_box(Vec3(1, 1, 1));
  Mesh other = make_box(Vec3(1, 1, 1));
  transform(other, Mat3::Identity(), Vec3(1, 1, 0));
  append_mesh(m, other);
  return m;
}

TEST(MeshRepair, TwoCubesSharingAnEdgeAreTwoCubes) {
  Mesh m = cubes_on_an_edge();
  weld_vertices(m);
  ASSERT_EQ(check_mesh(m).nonmanifold_edges, 1);
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.nonmanifold_edges, 1);
  EXPECT_EQ(r.split_vertices, 2);
  EXPECT_EQ(r.small_components, 0);
  EXPECT_NEAR(volume_of(m), 2.0, 1e-12);
}

// One vertex dragged across its neighbours, as a bad decimation leaves it: its fan doubles back
// over the surface next to it.
void fold_at(Mesh& m, int v, double by = 2.5) {
  const auto ring = fan(m, v);
  const int w = m.triangles[ring[0]][0] == v ? m.triangles[ring[0]][1] : m.triangles[ring[0]][0];
  m.vertices[v] = m.vertices[v] + by * (m.vertices[w] - m.vertices[v]);
}

TEST(MeshRepair, AFoldIsMendedLocallyAndRefusedWithoutTheMendsNamingTheCheckAndThePlace) {
  const Mesh sphere = make_icosphere(3);
  Mesh folded = sphere;
  fold_at(folded, 40);
  Mesh m = folded;
  const RepairReport r = repair_mesh(m);
  EXPECT_GT(r.crossings_within, 0);
  EXPECT_EQ(r.crossings_between, 0);
  ASSERT_FALSE(r.local_rounds.empty());
  EXPECT_EQ(r.local_rounds.back().pairs_after, 0);
  EXPECT_EQ(r.mended_by, "local");
  EXPECT_FALSE(r.wrapped);
  EXPECT_TRUE(r.changed);
  EXPECT_TRUE(check_mesh(m).closed && check_mesh(m).manifold);
  EXPECT_NEAR(volume_of(m) / volume_of(sphere), 1.0, 0.01);
  // The distance from the result to the input: at most the fold's reach, reported as a fraction.
  EXPECT_GT(r.distance_max, 0.0);
  EXPECT_LT(r.distance_max, 0.1);
  EXPECT_LE(r.distance_mean, r.distance_max);
  // Without the local mend, the wrap mends it and is named.
  RepairOptions no_local;
  no_local.local_rounds = 0;
  Mesh wrapped = folded;
  const RepairReport w = repair_mesh(wrapped, no_local);
  EXPECT_TRUE(w.wrapped);
  EXPECT_EQ(w.mended_by, "wrap");
  EXPECT_TRUE(check_mesh(wrapped).closed && check_mesh(wrapped).manifold);
  EXPECT_EQ(find_crossings(wrapped).total(), 0);
  EXPECT_NEAR(volume_of(wrapped) / volume_of(sphere), 1.0, 0.02);
  // Without the local mend and the wrap, the fold is refused naming the check and the place.
  RepairOptions none;
  none.local_rounds = 0;
  none.wrap = WrapMode::never;
  Mesh refused = folded;
  try {
    repair_mesh(refused, none);
    FAIL() << "a folded surface was repaired";
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("step 'self-intersection check'"), std::string::npos) << msg;
    EXPECT_NE(msg.find(" at ("), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}

// Acceptance 1(a): two closed spheres through each other, one soup, close to the exact union.
TEST(MeshRepair, TwoSpheresThroughEachOtherBecomeTheirUnion) {
  const double d = 1.0;  // unit spheres, centres d apart
  // The wrap below is most of the time (it grows about as 1/alpha²), the union most of the rest
  // (it grows with the triangles). The sanitizer pass unites icospheres of level 4 (5,120
  // triangles each) and wraps them at twice the default alpha (a quarter of the work; union/exact
  // 1.0002 and wrap/exact 1.005 there); the Release pass runs level 5 at the default alpha.
  const int level = kSanitized ? 4 : 5;
  Mesh m = make_icosphere(level);
  Mesh other = make_icosphere(level);
  transform(other, Mat3::Identity(), Vec3(d, 0, 0));
  append_mesh(m, other);
  const double sphere = volume_of(make_icosphere(level));
  // Two-sphere lens: π (4r + d)(2r − d)² / 12; the union is two balls less the lens, scaled by
  // the icosphere's own volume against the ball's so that only the union step is measured.
  const double pi = 3.14159265358979323846;
  const double ball = 4.0 / 3.0 * pi;
  const double lens = pi * (4.0 + d) * (2.0 - d) * (2.0 - d) / 12.0;
  const double exact = (2.0 * ball - lens) * sphere / ball;
  const RepairReport r = repair_mesh(m);
  EXPECT_GT(r.crossings_between, 0);
  EXPECT_EQ(r.united_shells, 1);
  EXPECT_EQ(r.mended_by, "union");
  EXPECT_FALSE(r.wrapped);
  EXPECT_TRUE(check_mesh(m).closed && check_mesh(m).manifold);
  EXPECT_NEAR(r.volume_capped / (2.0 * sphere), 1.0, 1e-9);  // counted twice before
  EXPECT_NEAR(volume_of(m) / exact, 1.0, 0.01);
  EXPECT_NEAR(r.volume_after, volume_of(m), 1e-12);
  std::printf("two spheres through each other: union/exact %.6f\n", volume_of(m) / exact);
  // Wrapped instead (the union's fallback), the result still holds the union within 1 %.
  Mesh wrapped = make_icosphere(level);
  append_mesh(wrapped, other);
  RepairOptions always;
  always.wrap = WrapMode::always;
  if (kSanitized) always.wrap_alpha = 0.02;
  const RepairReport w = repair_mesh(wrapped, always);
  EXPECT_TRUE(w.wrapped);
  EXPECT_EQ(w.united_shells, 0);
  EXPECT_TRUE(check_mesh(wrapped).closed && check_mesh(wrapped).manifold);
  EXPECT_NEAR(volume_of(wrapped) / exact, 1.0, 0.01);
  std::printf("two spheres through each other: wrap/exact %.6f, %zu triangles\n",
              volume_of(wrapped) / exact, wrapped.triangles.size());
  EXPECT_GT(volume_of(wrapped), volume_of(m));  // the wrap lies outside, by the offset
}

// Acceptance 1(b): a sphere scan with folds, holes and opposite copies of triangles.
TEST(MeshRepair, AScannedSphereWithFoldsHolesAndDoubleWallsClosesNearItsVolume) {
  const Mesh sphere = make_icosphere(5);  // 20,480 triangles
  Mesh m = sphere;
  Rng rng(78);
  const int n = static_cast<int>(m.vertices.size());
  // 3 % of the vertices pushed across a neighbour (folds), spread over the sphere.
  std::set<int> folded;
  while (static_cast<int>(folded.size()) < n * 3 / 100) {
    const int v = static_cast<int>(rng.uniform(0.0, n - 1e-9));
    bool apart = true;  // no two folds in one fan, so each is a fold and not a tear
    for (int t : fan(m, v))
      for (int c : m.triangles[t]) apart = apart && !folded.count(c);
    if (apart && folded.insert(v).second) fold_at(m, v, 1.6);
  }
  // 80 opposite copies of triangles away from the folds, then 7 holes (a vertex's fan each).
  std::set<int> near_fold;
  for (int v : folded)
    for (int t : fan(m, v)) near_fold.insert(t);
  int copies = 0;
  for (int t = 0; t < static_cast<int>(m.triangles.size()) && copies < 80; t += 97)
    if (!near_fold.count(t)) {
      const auto tri = m.triangles[t];
      m.triangles.push_back({tri[0], tri[2], tri[1]});
      ++copies;
    }
  std::set<int> gone;
  for (int k = 0, v = 11; k < 7; ++k, v += 1499) {
    while (folded.count(v)) ++v;
    for (int t : fan(m, v)) gone.insert(t);
  }
  erase_triangles(m, gone);
  ASSERT_GT(check_mesh(m).boundary_edges, 0);
  // The folds are mended by the wrap, most of the time (it grows as 1/alpha²). The sanitizer pass
  // wraps at twice the default alpha (a quarter of the wrap's work; volume/sphere 1.002 there, the
  // defects and the steps before the wrap the same); the Release pass at the default.
  RepairOptions o;
  if (kSanitized) o.wrap_alpha = 0.02;
  const RepairReport r = repair_mesh(m, o);
  EXPECT_EQ(r.double_wall_triangles, 160);
  EXPECT_GE(r.holes, 7);
  EXPECT_GT(r.crossings_within, 0);
  EXPECT_FALSE(r.mended_by.empty());
  EXPECT_TRUE(r.changed);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed && c.manifold && c.oriented);
  EXPECT_NEAR(volume_of(m) / volume_of(sphere), 1.0, 0.02);
  std::printf(
      "scanned sphere: %d folds, %d holes, %d crossing pairs, mended by %s, volume/sphere "
      "%.6f\n",
      static_cast<int>(folded.size()), r.holes, r.crossings_within, r.mended_by.c_str(),
      volume_of(m) / volume_of(sphere));
}

// Acceptance 1(c): two cubes sharing an edge (split) and a box whose face is pushed through one
// of them (joined by union); the report names the step that mended each.
TEST(MeshRepair, CubesOnAnEdgeAndABoxPushedThroughOneCloseNamingTheStep) {
  Mesh m = cubes_on_an_edge();
  // A box of section 0.5 × 0.5 beside the second cube (x from 2.0 to 2.5), its face towards the
  // cube pushed 0.7 through that cube's face: x from 1.3 to 2.5.
  Mesh pushed = make_box(Vec3(1.2, 0.5, 0.5));
  transform(pushed, Mat3::Identity(), Vec3(1.9, 1, 0));
  append_mesh(m, pushed);
  weld_vertices(m);
  ASSERT_EQ(check_mesh(m).nonmanifold_edges, 1);
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.split_vertices, 2);
  EXPECT_GT(r.crossings_between, 0);
  EXPECT_EQ(r.crossings_within, 0);
  EXPECT_EQ(r.united_shells, 1);
  EXPECT_EQ(r.mended_by, "union");
  EXPECT_TRUE(check_mesh(m).closed);
  // Two unit cubes and the part of the box outside the second: the box spans x 1.3..2.5, the
  // cube x 0.5..1.5, so 1.0 of its length (section 0.5 × 0.5) lies outside.
  EXPECT_NEAR(volume_of(m), 2.0 + 1.0 * 0.25, 1e-9);
}

// Acceptance 1(d): what encloses no volume is refused with one line saying so.
TEST(MeshRepair, AFlatSheetASingleTriangleAndAPointCloudAreRefusedAsEnclosingNoVolume) {
  Mesh sheet;
  const int k = 10;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) sheet.vertices.emplace_back(i * 0.1, j * 0.1, 0.0);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
      sheet.triangles.push_back({a, b, d});
      sheet.triangles.push_back({a, d, c});
    }
  Mesh triangle;
  triangle.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  triangle.triangles = {{0, 1, 2}};
  Mesh cloud;  // points saved as faces of three copies of one point, or collinear points
  for (int i = 0; i < 30; ++i) cloud.vertices.emplace_back(i * 0.1, 0.5 * i * 0.1, 0.0);
  for (int i = 0; i + 2 < 30; ++i) cloud.triangles.push_back({i, i + 1, i + 2});
  for (Mesh* m : {&sheet, &triangle, &cloud}) {
    for (WrapMode mode : {WrapMode::fallback, WrapMode::always}) {
      Mesh copy = *m;
      RepairOptions o;
      o.wrap = mode;
      try {
        repair_mesh(copy, o);
        FAIL() << "a mesh enclosing no volume was repaired";
      } catch (const InvalidInput& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("enclose"), std::string::npos) << msg;
        EXPECT_NE(msg.find("no volume"), std::string::npos) << msg;
        EXPECT_EQ(msg.find("intersects itself"), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      }
    }
  }
}

TEST(MeshRepair, AlwaysWrappingGivesAClosedManifoldSurfaceWithoutCrossingsNearTheInput) {
  const Mesh sphere = make_icosphere(4);
  Mesh m = sphere;
  RepairOptions o;
  o.wrap = WrapMode::always;
  // The two wraps are most of the time (they grow as 1/alpha²). The sanitizer pass wraps at twice
  // the default alpha (a quarter of the work; the wrap's vertices still lie on the offset surface:
  // distance max 1.0, mean 0.91 of the offset, volume gain 0.9 of offset × area, as at the
  // default); the Release pass at the default.
  if (kSanitized) o.wrap_alpha = 0.02;
  const RepairReport r = repair_mesh(m, o);
  EXPECT_TRUE(r.wrapped);
  EXPECT_EQ(r.mended_by, "");
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed && c.manifold && c.oriented);
  EXPECT_EQ(find_crossings(m).total(), 0);
  // Outside by the offset: the volume grows by about offset × area, and no point of the wrap lies
  // much farther from the sphere than the offset.
  const double offset = o.wrap_offset * r.diagonal;
  EXPECT_NEAR(r.wrap_offset, offset, 1e-15);
  EXPECT_NEAR(volume_of(m) - volume_of(sphere), offset * surface_area(sphere),
              0.5 * offset * surface_area(sphere));
  EXPECT_LT(r.distance_max * r.diagonal, 3.0 * offset);
  EXPECT_GT(r.distance_mean * r.diagonal, 0.5 * offset);
  // Within the bound no warning; past a bound below the offset, one naming the place.
  EXPECT_TRUE(r.warnings.empty());
  Mesh again = sphere;
  o.wrap_warn_distance = 0.5 * o.wrap_offset;
  const RepairReport w = repair_mesh(again, o);
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_NE(w.warnings[0].find("the wrap moved the surface"), std::string::npos) << w.warnings[0];
  EXPECT_NE(w.warnings[0].find(" at ("), std::string::npos) << w.warnings[0];
}

TEST(MeshRepair, BadWrapOptionsAreRefusedNamingTheOption) {
  Mesh m = make_icosphere(1);
  RepairOptions o;
  o.wrap_alpha = 0;
  EXPECT_THROW(repair_mesh(m, o), InvalidInput);
  o = {};
  o.wrap_offset = std::nan("");
  EXPECT_THROW(repair_mesh(m, o), InvalidInput);
  EXPECT_THROW(wrap_mode_from_string("sometimes", "--wrap"), InvalidInput);
  EXPECT_EQ(wrap_mode_from_string("never", "--wrap"), WrapMode::never);
}

TEST(MeshRepair, HolesMeetingAtAVertexAreClosed) {
  // Two triangles of one vertex's fan that share only that vertex removed: the boundary passes
  // through it twice (a non-manifold vertex).
  const Mesh sphere = make_icosphere(3);
  Mesh m = sphere;
  const int v = 12;
  const auto ring = fan(m, v);
  ASSERT_GE(ring.size(), 5u);
  int second = -1;  // a fan triangle sharing no edge with the first
  for (std::size_t k = 1; k < ring.size() && second < 0; ++k) {
    int shared = 0;
    for (int a : m.triangles[ring[0]])
      for (int b : m.triangles[ring[k]]) shared += a == b;
    if (shared == 1) second = ring[k];
  }
  ASSERT_GE(second, 0);
  erase_triangles(m, {ring[0], second});
  const RepairReport r = repair_mesh(m);
  // One boundary of 6 edges through the vertex twice, or two of 3 (CGAL's choice): 6 in all.
  int edges = 0;
  for (const RepairHole& h : r.closed_holes) edges += h.edges;
  EXPECT_EQ(edges, 6);
  EXPECT_GE(r.holes, 1);
  EXPECT_EQ(r.boundary_edges_after, 0);
  EXPECT_NEAR(volume_of(m) / volume_of(sphere), 1.0, 0.01);
  // What is written reads back as a solid: its equal positions joined, a closed manifold. (The
  // patch through both copies of the vertex once left an edge of three triangles there, which
  // every reader refused; such a surface now goes to the wrap.)
  Mesh welded = m;
  weld_vertices(welded, 1e-9);
  EXPECT_TRUE(check_mesh(welded).closed && check_mesh(welded).manifold);
}

TEST(MeshRepair, FloatingDebrisIsRemovedAndEachClosedHoleIsReported) {
  const Mesh sphere = make_icosphere(3);
  Mesh m = sphere;
  const std::vector<int> cap = fan(m, 7);
  erase_triangles(m, std::set<int>(cap.begin(), cap.end()));  // a hole of 5 edges
  Mesh chip = make_box(Vec3(0.02, 0.02, 0.02));
  transform(chip, Mat3::Identity(), Vec3(3, 0, 0));
  append_mesh(m, chip);
  const int n = static_cast<int>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), {Vec3(0, 3, 0), Vec3(0.1, 3, 0), Vec3(0, 3.1, 0)});
  m.triangles.push_back({n, n + 1, n + 2});  // a loose triangle
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.small_components, 2);
  EXPECT_EQ(r.small_component_triangles, 13);
  ASSERT_EQ(r.closed_holes.size(), 1u);
  EXPECT_EQ(r.closed_holes[0].edges, 5);
  EXPECT_EQ(r.closed_holes[0].method, "refined and faired");
  EXPECT_LT((r.closed_holes[0].at - sphere.vertices[7]).norm(), 0.2);
  EXPECT_NEAR(volume_of(m) / volume_of(sphere), 1.0, 0.01);
  // With min_component 0 the debris stays: the chip is a solid of its own, the loose triangle a
  // hole closed by a planar patch on itself, which bounds nothing.
  Mesh keep = sphere;
  append_mesh(keep, chip);
  RepairOptions all;
  all.min_component = 0.0;
  repair_mesh(keep, all);
  EXPECT_NEAR(volume_of(keep), volume_of(sphere) + 0.02 * 0.02 * 0.02, 1e-12);
}

TEST(MeshRepair, ADoubleWallGoesWithBothCopiesAndSameOrientationCopiesKeepOne) {
  const Mesh sphere = make_icosphere(3);
  Mesh m = sphere;
  // Opposite copies of a patch around one vertex (a double wall), a same-orientation copy of a
  // triangle far from it.
  for (int t : fan(m, 3)) {
    const auto tri = m.triangles[t];
    m.triangles.push_back({tri[0], tri[2], tri[1]});
  }
  m.triangles.push_back(m.triangles[600]);
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.double_wall_triangles, 2 * static_cast<int>(fan(sphere, 3).size()));
  EXPECT_EQ(r.duplicate_triangles, 1);
  EXPECT_EQ(r.holes, 1);
  EXPECT_NEAR(volume_of(m) / volume_of(sphere), 1.0, 0.01);
}

TEST(MeshRepair, BadOptionsAndEmptyResultsNameTheStep) {
  Mesh m = make_icosphere(1);
  RepairOptions bad;
  bad.min_component = -0.5;
  EXPECT_THROW(repair_mesh(m, bad), InvalidInput);
  Mesh wall = make_icosphere(1);
  for (const auto t : make_icosphere(1).triangles) wall.triangles.push_back({t[0], t[2], t[1]});
  try {
    repair_mesh(wall);
    FAIL() << "a mesh of double walls only was repaired";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("step 'duplicates'"), std::string::npos) << e.what();
  }
}

}  // namespace repair_test
}  // namespace clumpkit
