// A crushable particle in the World: its cells' bodies carry the parent's exact mass and place
// their corners where the cells are; moved as one rigid piece it carries no bond force.
#include "dem/core/crushable.h"

#include "dem/core/timestep.h"
#include "geom/errors.h"
#include "geom/shapes/polyhedron.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

struct Particle {
  Tessellation cells;
  std::vector<CellBond> bonds;
};

Particle particle() {
  PolyhedronParams pp;
  pp.diameter = 0.0275;
  Rng shape(3);
  const Mesh parent = make_polyhedron(pp, shape);
  CellOptions o;
  o.cell_size = 0.0065;
  Rng seeds(4), factors(5);
  Particle p;
  p.cells = voronoi_cells(parent, o, seeds);
  p.bonds = cell_bonds(p.cells, default_strength_factor(), factors);
  return p;
}

}  // namespace

TEST(CrushableParticle, CellBodiesCarryTheExactMassAndSitWhereTheCellsAre) {
  const Particle p = particle();
  WorldOptions o;
  o.gravity = Vec3::Zero();
  const World w = crushable_particle(p.cells, p.bonds, 2650, o);
  ASSERT_EQ(w.bodies().size(), p.cells.cells.size());
  ASSERT_EQ(w.bonds().size(), p.bonds.size());
  double mass = 0;
  Vec3 moment = Vec3::Zero();
  for (std::size_t k = 0; k < w.bodies().size(); ++k) {
    const Body& b = w.bodies()[k];
    const Cell& c = p.cells.cells[k];
    mass += b.mass;
    moment += b.mass * b.position;
    // Corners back in the parent's frame, and the inertia tensor back from the principal one.
    ASSERT_EQ(b.vertices.size(), c.vertices.size());
    for (std::size_t v = 0; v < c.vertices.size(); ++v)
      EXPECT_LT((b.position + b.orientation * b.vertices[v] - c.vertices[v]).norm(), 1e-15);
    const Mat3 r = b.orientation.toRotationMatrix();
    const Mat3 inertia = r * b.moments.asDiagonal() * r.transpose();
    EXPECT_LT((inertia - 2650 * c.mass.inertia).norm(), 1e-9 * (2650 * c.mass.inertia).norm());
    EXPECT_LE(b.moments.x(), b.moments.y());
    EXPECT_LE(b.moments.y(), b.moments.z());
    // The sphere lies inside its cell: below every face plane.
    const double radius = b.spheres[0].radius;
    for (const CellFace& f : c.faces) {
      const PolygonProperties pp = polygon_properties(c.vertices, f.vertices);
      if (pp.area > 0) {
        EXPECT_GE(pp.normal.dot(pp.centroid - b.position), radius * (1 - 1e-12));
      }
    }
  }
  EXPECT_NEAR(mass / (2650 * p.cells.parent_volume), 1.0, 1e-12);
  EXPECT_THROW(cell_body(p.cells.cells[0], -1.0), InvalidInput);
}

TEST(CrushableParticle, MovedAsOneRigidPieceItCarriesNoBondForce) {
  const Particle p = particle();
  WorldOptions o;
  o.gravity = Vec3::Zero();
  World w = crushable_particle(p.cells, p.bonds, 2650, o);
  w.options().timestep = 0.2 * critical_timestep(w);
  for (Body& b : w.bodies()) b.velocity = Vec3(0.3, -0.2, 0.1);
  w.step(2000);
  const double scale = 1e-9 * w.options().cohesive.sigma_n * 0.0065 * 0.0065;
  for (const Body& b : w.bodies()) {
    EXPECT_LT(b.force.norm(), scale);
    EXPECT_LT(b.torque.norm(), scale * 0.0065);
  }
  EXPECT_TRUE(w.contacts().empty());
  for (const Bond& b : w.bonds()) EXPECT_EQ(b.points[0].state.damage, 0.0);
}

TEST(CrushableParticle, FilledCellsKeepTheCellsMassAndShapeAndBondedOnesNeverTouch) {
  const Particle p = particle();
  FillOptions fill;  // a few spheres on a coarse grid: what a packing of many cells affords
  fill.spheres = 6;
  fill.field.voxels = 16;
  fill.voxels_from_count = false;
  WorldOptions o;
  o.gravity = Vec3::Zero();
  World w(o);
  add_crushable(w, crushable_bodies(p.cells, p.bonds, 2650, &fill), Eigen::Quaterniond::Identity(),
                Vec3::Zero());
  ASSERT_EQ(w.bodies().size(), p.cells.cells.size());
  int overlapping = 0;  // sphere pairs of bonded cells that overlap across their face
  for (std::size_t k = 0; k < w.bodies().size(); ++k) {
    const Body& b = w.bodies()[k];
    const Cell& c = p.cells.cells[k];
    EXPECT_NEAR(b.mass, 2650 * c.mass.volume, 1e-12 * b.mass);  // the cell's, not the clump's
    EXPECT_TRUE(b.vertices.empty());                            // its spheres meet the walls
    ASSERT_GE(b.spheres.size(), 2u);
    ASSERT_LE(b.spheres.size(), 6u);
    // Each sphere reaches past the cell's faces by at most a tenth of its radius (the fill's
    // tolerance is 3 % of the radius plus a voxel).
    for (const Sphere& s : b.spheres) {
      const Vec3 x = b.position + b.orientation * s.center;
      for (const CellFace& f : c.faces) {
        const PolygonProperties pp = polygon_properties(c.vertices, f.vertices);
        if (pp.area > 0) {
          EXPECT_GT(pp.normal.dot(pp.centroid - x), 0.9 * s.radius);
        }
      }
    }
  }
  for (const CellBond& f : p.bonds)
    for (const Sphere& sa : w.bodies()[f.a].spheres)
      for (const Sphere& sb : w.bodies()[f.b].spheres) {
        const Body &a = w.bodies()[f.a], &b = w.bodies()[f.b];
        const double gap =
            (a.position + a.orientation * sa.center - (b.position + b.orientation * sb.center))
                .norm() -
            sa.radius - sb.radius;
        overlapping += gap < 0 ? 1 : 0;
      }
  EXPECT_GT(overlapping, 0);
  // Bonded, those spheres carry no contact: at rest nothing moves and no force acts.
  w.options().timestep = 0.2 * critical_timestep(w);
  w.step(200);
  EXPECT_TRUE(w.contacts().empty());
  const double scale = 1e-9 * w.options().cohesive.sigma_n * 0.0065 * 0.0065;
  for (const Body& b : w.bodies()) EXPECT_LT(b.force.norm(), scale);
}

TEST(CrushableParticle, MovedAnywhereWithItsBondsItStaysAtRest) {
  // The particle built where its cells are, then added turned and shifted: every cell where the
  // rigid motion puts it, and its bonds (points and normals in the cells' frames) unloaded.
  const Particle p = particle();
  const CrushableBodies bodies = crushable_bodies(p.cells, p.bonds, 2650);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 0.5).normalized()));
  const Vec3 t(0.4, -0.2, 0.9);
  WorldOptions o;
  o.gravity = Vec3::Zero();
  World w(o);
  w.add_body(bodies.cells.front());  // a body before it: the bonds are renumbered
  ASSERT_EQ(add_crushable(w, bodies, q, t), 1);
  ASSERT_EQ(w.bonds().size(), p.bonds.size());
  for (std::size_t k = 0; k < p.cells.cells.size(); ++k) {
    const Body& b = w.bodies()[k + 1];
    for (std::size_t v = 0; v < b.vertices.size(); ++v)
      EXPECT_LT(
          (b.position + b.orientation * b.vertices[v] - (q * p.cells.cells[k].vertices[v] + t))
              .norm(),
          1e-15);
  }
  w.bodies().front().position.z() += 1.0;  // out of the way
  w.options().timestep = 0.2 * critical_timestep(w);
  w.step(200);
  const double scale = 1e-9 * w.options().cohesive.sigma_n * 0.0065 * 0.0065;
  for (const Body& b : w.bodies()) EXPECT_LT(b.force.norm(), scale);
  for (const Bond& b : w.bonds()) EXPECT_EQ(b.points[0].state.damage, 0.0);
  EXPECT_EQ(w.bonds().front().a, p.bonds.front().a + 1);
}
