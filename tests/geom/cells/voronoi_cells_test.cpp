// Voronoi cells of a convex parent: the cells tile the parent exactly, shared faces match, two
// independent constructions agree, and the result moves with the parent.
#include "geom/cells/voronoi_cells.h"

#include "geom/errors.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace clumpkit;

namespace {

Mesh parent(std::uint64_t seed, double diameter = 0.0275) {
  PolyhedronParams p;
  p.diameter = diameter;
  Rng rng(seed);
  return make_polyhedron(p, rng);
}

Tessellation cut(const Mesh& m, int count, int lloyd = 3, std::uint64_t seed = 7) {
  CellOptions o;
  o.count = count;
  o.lloyd = lloyd;
  Rng rng(seed);
  return voronoi_cells(m, o, rng);
}

double cv_of_volumes(const Tessellation& t) {
  double s = 0, s2 = 0;
  for (const Cell& c : t.cells) s += c.mass.volume, s2 += c.mass.volume * c.mass.volume;
  const double n = static_cast<double>(t.cells.size()), mean = s / n;
  return std::sqrt(s2 / n - mean * mean) / mean;
}

}  // namespace

TEST(VoronoiCells, CellsTileTheParentAndShareFacesExactly) {
  const Mesh m = parent(3);
  const Tessellation t = cut(m, 75);
  ASSERT_EQ(t.cells.size(), 75u);
  EXPECT_DOUBLE_EQ(t.parent_volume, signed_volume(m));
  double sum = 0;
  for (const Cell& c : t.cells) {
    EXPECT_GT(c.mass.volume, 0.0);
    EXPECT_GE(c.faces.size(), 4u);
    sum += c.mass.volume;
    // The cell mesh is closed and outward: its signed volume is its mass volume.
    EXPECT_TRUE(check_mesh(cell_mesh(c)).closed);
  }
  EXPECT_NEAR(sum / t.parent_volume, 1.0, 1e-9);
  // Each internal face appears in exactly two cells, with equal areas and opposite normals.
  std::map<std::pair<int, int>, std::vector<PolygonProperties>> shared;
  int surface_faces = 0;
  for (std::size_t i = 0; i < t.cells.size(); ++i)
    for (const CellFace& f : t.cells[i].faces) {
      if (f.neighbour < 0) {
        ++surface_faces;
        continue;
      }
      ASSERT_NE(f.neighbour, static_cast<int>(i));
      shared[{static_cast<int>(i), f.neighbour}].push_back(
          polygon_properties(t.cells[i].vertices, f.vertices));
    }
  EXPECT_GT(surface_faces, 75);
  for (const auto& [key, faces] : shared) {
    const auto back = shared.find({key.second, key.first});
    ASSERT_NE(back, shared.end()) << key.first << "-" << key.second;
    ASSERT_EQ(faces.size(), 1u);
    ASSERT_EQ(back->second.size(), 1u);
    const PolygonProperties &p = faces[0], &q = back->second[0];
    EXPECT_NEAR(p.area / q.area, 1.0, 1e-9);
    EXPECT_NEAR(p.normal.dot(q.normal), -1.0, 1e-9);
    EXPECT_LT((p.centroid - q.centroid).norm(), 1e-9 * 0.0275);
    // The face is the bisector of the two seeds: its normal points from seed i to seed j.
    const Vec3 d = (t.cells[key.second].seed - t.cells[key.first].seed).normalized();
    EXPECT_NEAR(p.normal.dot(d), 1.0, 1e-9);
  }
}

TEST(VoronoiCells, Voro_plus_plusAndHalfspaceIntersectionAgree) {
  const Mesh m = parent(11);
  const Tessellation t = cut(m, 40, 2);
  std::vector<Vec3> seeds;
  for (const Cell& c : t.cells) seeds.push_back(c.seed);
  const std::vector<Mesh> other = voronoi_cells_by_halfspaces(m, seeds);
  ASSERT_EQ(other.size(), t.cells.size());
  for (std::size_t i = 0; i < other.size(); ++i) {
    EXPECT_NEAR(signed_volume(other[i]) / t.cells[i].mass.volume, 1.0, 1e-9) << i;
    EXPECT_LT((solid_centroid(other[i]) - t.cells[i].mass.centroid).norm(), 1e-9 * 0.0275) << i;
  }
}

TEST(VoronoiCells, GridSeedsInACubeGiveCubes) {
  const Mesh cube = make_box(Vec3(2, 2, 2));  // centred on the origin
  std::vector<Vec3> seeds;
  for (int i = 0; i < 8; ++i)
    seeds.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  const Tessellation t = voronoi_cells(cube, seeds);
  ASSERT_EQ(t.cells.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    const Cell& c = t.cells[i];
    EXPECT_NEAR(c.mass.volume, 1.0, 1e-12);
    EXPECT_LT((c.mass.centroid - seeds[i]).norm(), 1e-12);
    EXPECT_NEAR(c.mass.inertia(0, 0), 1.0 / 6.0, 1e-12);  // a unit cube: (1 + 1)/12
    EXPECT_EQ(c.faces.size(), 6u);
    int inner = 0;
    for (const CellFace& f : c.faces) inner += f.neighbour >= 0;
    EXPECT_EQ(inner, 3);
  }
  EXPECT_THROW(voronoi_cells(cube, {Vec3(0, 0, 0), Vec3(0, 0, 1.5)}), InvalidInput);
}

TEST(VoronoiCells, LloydStepsEvenTheCellSizes) {
  const Mesh m = parent(5);
  const double raw = cv_of_volumes(cut(m, 75, 0));
  const double relaxed = cv_of_volumes(cut(m, 75, 3));
  EXPECT_GT(raw, 0.25);  // Poisson–Voronoi cells: a CV near 0.42
  EXPECT_LT(relaxed, 0.6 * raw);
}

TEST(VoronoiCells, SameSeedSameBitsAndTheCellsMoveWithTheParent) {
  const Mesh m = parent(9);
  const Tessellation a = cut(m, 30), b = cut(m, 30);
  for (std::size_t i = 0; i < a.cells.size(); ++i) {
    ASSERT_EQ(a.cells[i].vertices.size(), b.cells[i].vertices.size());
    for (std::size_t k = 0; k < a.cells[i].vertices.size(); ++k)
      EXPECT_EQ(a.cells[i].vertices[k], b.cells[i].vertices[k]);
  }
  EXPECT_NE(cut(m, 30, 3, 8).cells[0].seed, a.cells[0].seed);
  // Translated and scaled by 1000 (millimetres): the same cells, moved and scaled.
  Mesh moved = m;
  const Vec3 shift(0.3, -1.2, 4.0);
  for (Vec3& v : moved.vertices) v = 1000.0 * v + shift;
  const Tessellation c = cut(moved, 30);
  for (std::size_t i = 0; i < a.cells.size(); ++i) {
    EXPECT_NEAR(c.cells[i].mass.volume / (1e9 * a.cells[i].mass.volume), 1.0, 1e-9);
    EXPECT_LT((c.cells[i].mass.centroid - (1000.0 * a.cells[i].mass.centroid + shift)).norm(),
              1e-9 * 27.5);
  }
}

TEST(VoronoiCells, CountFromCellSizeAndBadInput) {
  // Hu et al. 2023 Table 1: 75, 114, 165, 229 and 307 cells at ℓ ≈ 6.5 mm (here within one).
  const double sizes[] = {27.5, 31.6, 35.7, 39.7, 43.9};
  const int paper[] = {75, 114, 165, 229, 307};
  for (int k = 0; k < 5; ++k) {
    CellOptions o;
    o.cell_size = 6.5;
    const double v = M_PI / 6.0 * std::pow(sizes[k], 3.0);
    EXPECT_NEAR(cell_count(o, v), paper[k], 1) << sizes[k];
  }
  CellOptions big;
  big.cell_size = 30.0;
  EXPECT_THROW(cell_count(big, M_PI / 6.0 * std::pow(27.5, 3.0)), InvalidInput);
  const Mesh m = parent(1);
  Rng rng(1);
  for (CellOptions o :
       {CellOptions{0, 0.0, 3}, CellOptions{10, 0.005, 3}, CellOptions{1, 0.0, 3},
        CellOptions{10, 0.0, -1}, CellOptions{0, -0.005, 3}, CellOptions{0, std::nan(""), 3}})
    EXPECT_THROW(voronoi_cells(m, o, rng), InvalidInput);
  // A non-convex parent: a box with one corner pushed in past the plane of its neighbours.
  Mesh dented = make_box(Vec3(1, 1, 1));
  dented.vertices[0] *= 0.2;
  try {
    convex_planes(dented);
    ADD_FAILURE() << "a dented box passed as convex";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("not convex"), std::string::npos) << e.what();
  }
  EXPECT_THROW(voronoi_cells(dented, CellOptions{8, 0.0, 0}, rng), InvalidInput);
  // A box has six distinct planes (its twelve triangles merged).
  EXPECT_EQ(convex_planes(make_box(Vec3(1, 2, 3))).size(), 6u);
}
