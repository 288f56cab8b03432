// Bonds between Voronoi cells: one per shared face, integration points that integrate the face
// exactly (area and first moment), and strength factors from the recipe's distribution.
#include "geom/cells/cell_bonds.h"

#include "geom/errors.h"
#include "geom/shapes/polyhedron.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

#include <set>

using namespace clumpkit;

TEST(CellBonds, OneBondPerSharedFaceWithExactIntegrationPoints) {
  PolyhedronParams pp;
  pp.diameter = 0.0275;
  Rng shape(4);
  const Mesh m = make_polyhedron(pp, shape);
  CellOptions o;
  o.count = 75;
  Rng rng(2);
  const Tessellation t = voronoi_cells(m, o, rng);
  Rng draw(3);
  const std::vector<CellBond> bonds = cell_bonds(t, default_strength_factor(), draw);
  std::set<std::pair<int, int>> faces;
  for (std::size_t i = 0; i < t.cells.size(); ++i)
    for (const CellFace& f : t.cells[i].faces)
      if (f.neighbour >= 0)
        faces.insert({std::min<int>(i, f.neighbour), std::max<int>(i, f.neighbour)});
  ASSERT_EQ(bonds.size(), faces.size());
  double mean = 0;
  for (std::size_t k = 0; k < bonds.size(); ++k) {
    const CellBond& b = bonds[k];
    ASSERT_LT(b.a, b.b);
    EXPECT_TRUE(faces.count({b.a, b.b}));
    if (k > 0) {
      EXPECT_LT(std::make_pair(bonds[k - 1].a, bonds[k - 1].b), std::make_pair(b.a, b.b));
    }
    EXPECT_GE(b.points.size(), 3u);
    double area = 0;
    Vec3 moment = Vec3::Zero();
    for (const FacePoint& p : b.points) {
      area += p.area;
      moment += p.area * p.position;
      EXPECT_NEAR(b.normal.dot(p.position - b.centroid), 0.0, 1e-12);  // on the face
    }
    EXPECT_NEAR(area / b.area, 1.0, 1e-12);
    EXPECT_LT((moment / area - b.centroid).norm(), 1e-12);
    // The normal points from a to b.
    EXPECT_GT(b.normal.dot(t.cells[b.b].mass.centroid - t.cells[b.a].mass.centroid), 0.0);
    EXPECT_GE(b.strength_factor, 0.75);
    EXPECT_LE(b.strength_factor, 1.25);
    mean += b.strength_factor / bonds.size();
  }
  EXPECT_NEAR(mean, 1.0, 0.03);
  // A constant factor is that constant; the same draw stream gives the same factors.
  Rng again(3);
  EXPECT_EQ(cell_bonds(t, default_strength_factor(), again)[7].strength_factor,
            bonds[7].strength_factor);
  Rng any(5);
  for (const CellBond& b : cell_bonds(t, constant(1.0), any)) EXPECT_EQ(b.strength_factor, 1.0);
  // Subdivided fans: 4^s times the points, the same area, first and second moments of the face
  // within rounding (the points' spread grows toward the face's own).
  Rng fine_draw(3);
  const std::vector<CellBond> fine = cell_bonds(t, default_strength_factor(), fine_draw, 1);
  ASSERT_EQ(fine.size(), bonds.size());
  for (std::size_t k = 0; k < bonds.size(); ++k) {
    ASSERT_EQ(fine[k].points.size(), 4 * bonds[k].points.size());
    EXPECT_EQ(fine[k].strength_factor, bonds[k].strength_factor);
    double area = 0;
    Vec3 moment = Vec3::Zero();
    for (const FacePoint& p : fine[k].points) area += p.area, moment += p.area * p.position;
    EXPECT_NEAR(area / bonds[k].area, 1.0, 1e-12);
    EXPECT_LT((moment / area - bonds[k].centroid).norm(), 1e-12);
  }
  Rng bad(3);
  EXPECT_THROW(cell_bonds(t, default_strength_factor(), bad, 4), InvalidInput);
}

TEST(CellBonds, EightCubesHaveTwelveSquareBonds) {
  std::vector<Vec3> seeds;
  for (int i = 0; i < 8; ++i)
    seeds.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  const Tessellation t = voronoi_cells(make_box(Vec3(2, 2, 2)), seeds);
  Rng rng(1);
  const std::vector<CellBond> bonds = cell_bonds(t, constant(1.0), rng);
  ASSERT_EQ(bonds.size(), 12u);
  for (const CellBond& b : bonds) {
    EXPECT_NEAR(b.area, 1.0, 1e-12);
    EXPECT_EQ(b.points.size(), 4u);  // a square fanned from its centre
    EXPECT_NEAR(b.normal.cwiseAbs().maxCoeff(), 1.0, 1e-12);
  }
}
