// Bonded cells in the World: a column of cubic cells (from geom/cells) under uniaxial tension and
// compression has the modulus K_I·a and the strength σ_eI; bonded spheres never touch, broken
// ones do, without the overlap they had across the face when the bond broke; thread counts and
// body sorting change nothing.
#include "geom/errors.h"
#include "geom/random.h"
#include "tests/dem/bonded_column.h"

#include <tbb/global_control.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

constexpr double kA = test::kCellEdge;

World column(double velocity) {
  return test::bonded_column(velocity);
}

// Stress on the top layer (tension positive) and strain between the driven layers' centres.
double stress(const World& w) {
  double f = 0;
  for (int c = 12; c < 16; ++c) f -= w.bodies()[c].force.z();
  return f / (4 * kA * kA);
}
double strain(const World& w) {
  double top = 0, bottom = 0;
  for (int c = 0; c < 4; ++c) bottom += w.bodies()[c].position.z() / 4;
  for (int c = 12; c < 16; ++c) top += w.bodies()[c].position.z() / 4;
  return (top - bottom - 3 * kA) / (3 * kA);
}

}  // namespace

TEST(WorldBonds, CubicCellColumnHasModulusKaAndStrengthSigma) {
  const CohesiveParams law;               // granite, Hu et al. 2023
  for (const double v : {0.02, -0.02}) {  // tension, then compression
    SCOPED_TRACE(v);
    World w = column(v);
    ASSERT_EQ(w.bonds().size(), 28u);  // 2·2·3 vertical + 2·4·2 horizontal
    // To half the onset opening of each of the three interfaces.
    const double onset = law.sigma_n / law.kn;
    const int steps = static_cast<int>(1.5 * onset / std::abs(v) / w.options().timestep);
    w.step(steps);
    EXPECT_TRUE(w.contacts().empty());  // the inscribed spheres touch, but are bonded
    EXPECT_NEAR(stress(w) / strain(w) / (law.kn * kA), 1.0, 0.01);
    std::printf("%s: E/(K_I·a) = %.5f after %d steps\n", v > 0 ? "tension" : "compression",
                stress(w) / strain(w) / (law.kn * kA), steps);
    if (v < 0) continue;
    // On to failure: the largest stress is the faces' tensile strength.
    double peak = 0;
    for (int k = 0; k < 400 && w.bonds()[0].holds(); ++k) {
      w.step(steps / 50);
      peak = std::max(peak, stress(w));
    }
    EXPECT_NEAR(peak / law.sigma_n, 1.0, 0.01);
    std::printf("peak stress / σ_eI = %.5f\n", peak / law.sigma_n);
  }
}

TEST(WorldBonds, SameBitsForOneAndTwoThreadsAndBrokenCellsTouch) {
  std::vector<World> runs;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    World w = column(0.5);
    w.step(3000);
    runs.push_back(std::move(w));
  }
  for (std::size_t b = 0; b < runs[0].bodies().size(); ++b)
    EXPECT_EQ(runs[0].bodies()[b].position, runs[1].bodies()[b].position) << b;
  // Broken, pushed back together: the spheres of the former neighbours now touch.
  World& w = runs[0];
  int holding = 0;
  for (const Bond& b : w.bonds()) holding += b.holds();
  EXPECT_LT(holding, 28);
  for (int c = 12; c < 16; ++c) w.bodies()[c].velocity = Vec3(0, 0, -2.0);
  w.step(6000);
  EXPECT_FALSE(w.contacts().empty());
}

// A bond that breaks between two filters of the near list adds its cells' sphere pairs to the
// list by a merge (World::add_freed_candidates) instead of a filter of the whole skin list: the
// next step must be the one a whole filter gives. A copy of the world restored from its lists
// filters the whole skin list at its next step; both step once and are compared to the bit. The
// spheres overlap across the faces by 0.1·a, so a freed pair touches at once (with its overlap
// excused): a pair left out of the list would lose that contact.
TEST(WorldBonds, ABrokenBondAddsItsCellsPairsAsAWholeFilterWould) {
  for (const bool octants : {false, true}) {
    SCOPED_TRACE(octants ? "eight spheres a cell" : "one sphere a cell");
    World w = test::bonded_column(0.5, octants, 0.1);
    // Each driven cell of the top layer at its own speed, so that faces fail one after another.
    for (int c = 12; c < 16; ++c) w.bodies()[c].velocity = Vec3(0, 0, 0.2 + 0.1 * (c - 12));
    auto holding = [&] {
      int n = 0;
      for (const Bond& b : w.bonds()) n += b.holds();
      return n;
    };
    int breaks = 0, merged = 0, touching_after_break = 0;
    for (int s = 0; s < 4000; ++s) {
      if (s == 2000)  // the broken layers pushed back together, so the freed spheres touch
        for (int c = 12; c < 16; ++c) w.bodies()[c].velocity = Vec3(0, 0, -1.0 - 0.2 * (c - 12));
      const int before = holding();
      w.step(1);
      if (holding() == before) continue;
      ++breaks;
      const World::ListState at_break = w.list_state();
      World whole = w;
      whole.restore(w.list_state(), w.contacts(), w.wall_contacts());
      w.step(1);
      whole.step(1);
      const World::ListState after = w.list_state();
      // The merge ran when the near list was made again without the spheres' positions moving on.
      merged += after.filters == at_break.filters + 1 &&
                after.filter_positions == at_break.filter_positions;
      touching_after_break += !whole.contacts().empty();
      ASSERT_EQ(w.contacts().size(), whole.contacts().size()) << "step " << s;
      for (std::size_t k = 0; k < w.contacts().size(); ++k) {
        const PairContact &c = w.contacts()[k], &d = whole.contacts()[k];
        ASSERT_EQ(std::make_pair(c.i, c.j), std::make_pair(d.i, d.j)) << "step " << s;
        EXPECT_EQ(c.state.normal_force, d.state.normal_force) << "step " << s;
        EXPECT_EQ(c.state.shear, d.state.shear) << "step " << s;
        EXPECT_EQ(c.state.excused, d.state.excused) << "step " << s;
      }
      for (std::size_t b = 0; b < w.bodies().size(); ++b) {
        EXPECT_EQ(w.bodies()[b].position, whole.bodies()[b].position) << "step " << s;
        EXPECT_EQ(w.bodies()[b].velocity, whole.bodies()[b].velocity) << "step " << s;
      }
    }
    EXPECT_GT(breaks, 2);
    EXPECT_GT(merged, 0);
    std::printf("%d steps with a break, %d merged into the near list\n", breaks, merged);
    EXPECT_GT(touching_after_break, 0);
    EXPECT_FALSE(w.contacts().empty());
  }
}

TEST(WorldBonds, SortingKeepsEachBondOnItsBodies) {
  World w = column(0.0);
  // Reverse the bodies (by editing positions the sort key sees, then sorting back is a no-op):
  // move every cell far along x in reverse order of index, so the sort reverses them.
  for (std::size_t c = 0; c < w.bodies().size(); ++c)
    w.bodies()[c].position.x() += (16.0 - c) * 10 * kA;
  ASSERT_TRUE(w.sort_bodies());
  for (const Bond& bond : w.bonds()) {
    const Body &a = w.bodies()[bond.a], &b = w.bodies()[bond.b];
    // The bond's points, seen from each side, are one face apart by the x shift only.
    const Vec3 xa = a.position + a.orientation * bond.points[0].in_a;
    const Vec3 xb = b.position + b.orientation * bond.points[0].in_b;
    EXPECT_NEAR(std::abs(xb.x() - xa.x()) / (10 * kA),
                std::round(std::abs(xb.x() - xa.x()) / (10 * kA)), 1e-9);
    EXPECT_NEAR(xb.y(), xa.y(), 1e-12);
    EXPECT_NEAR(xb.z(), xa.z(), 1e-12);
  }
  EXPECT_THROW(w.add_bond(Bond{}), InvalidInput);
  Bond self = w.bonds()[0];
  self.b = self.a;
  EXPECT_THROW(w.add_bond(self), InvalidInput);
}

namespace {

// Two cubic cells of edge a bonded on their face, each body one sphere of radius 0.55·a, so the
// spheres overlap by 0.1·a across the face, as the fill's spheres of two cells do. A weak law
// (σ_eI = 1 MPa, G_I = 10 J/m²: the face fails at an opening of 2·G_I/σ_eI = 20 µm, far below
// the 650 µm overlap) and no gravity; the cells fly apart at ±speed along z.
World parted_pair(double speed) {
  const double a = kA, rho = 2650;
  const Tessellation cells =
      voronoi_cells(make_box(Vec3(a, a, 2 * a)), {Vec3(0, 0, -0.5 * a), Vec3(0, 0, 0.5 * a)});
  Rng rng(1);
  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.cohesive.sigma_n = 1e6;
  o.cohesive.sigma_t = 1.2e6;
  o.cohesive.g_n = 10;
  o.cohesive.g_t = 12;
  World w(o);
  for (std::size_t c = 0; c < 2; ++c) {
    Body b = test::cube_cell_body(cells.cells[c], a, 0.55 * a, rho);
    b.velocity = Vec3(0, 0, c == 0 ? -speed : speed);
    w.add_body(b);
  }
  add_cell_bonds(w, cell_bonds(cells, constant(1.0), rng));
  w.options().timestep = 0.2 * critical_timestep(w);
  return w;
}

double cells_kinetic_energy(const World& w) {
  double e = 0;
  for (const Body& b : w.bodies()) e += 0.5 * b.mass * b.velocity.squaredNorm();
  return e;
}

}  // namespace

// A bond that breaks frees its bodies' spheres, which overlap across the face by the fill's
// reach: pushing them apart at that overlap (kn·0.1·a, 650 N here) would hand the pair a
// hundred times the energy it had. The contact starts with its overlap excused, so the cells
// leave with less energy than they came with (the face's fracture energy spent), and the excused
// part follows the overlap down: the law is kn·(δ − excused) at every step, and pressed back
// together the cells resist at once.
TEST(WorldBonds, BrokenBondsHandNoEnergyToOverlappingSpheres) {
  World w = parted_pair(1.0);
  const double before = cells_kinetic_energy(w);
  const double kn = w.options().contact.kn;
  int steps = 0;
  while (w.bonds()[0].holds() && steps < 2000) w.step(1), ++steps;
  ASSERT_FALSE(w.bonds()[0].holds()) << "the face did not fail in " << steps << " steps";
  w.step(1);  // the freed pair is a candidate from the next step
  ASSERT_EQ(w.contacts().size(), 1u);
  const double at_break = w.contacts()[0].state.excused;
  EXPECT_GT(at_break, 0.09 * kA);  // the 0.1·a overlap, less the opening at failure
  EXPECT_LT(at_break, 0.1 * kA);
  double excused = at_break;
  for (int k = 0; k < 20; ++k) {
    w.step(1);
    ASSERT_EQ(w.contacts().size(), 1u);
    const ContactState& c = w.contacts()[0].state;
    excused = std::min(excused, c.overlap);
    EXPECT_EQ(c.excused, excused) << "step " << k;
    EXPECT_EQ(c.normal_force, kn * (c.overlap - c.excused)) << "step " << k;
  }
  const double after = cells_kinetic_energy(w);
  EXPECT_LT(after, before);  // without the excuse: ~0.2 J from 7e-4 J
  std::printf("kinetic energy %.3e J before, %.3e J after the break; excused %.1f µm\n", before,
              after, at_break * 1e6);

  // Pressed back together: kn·(δ − excused) > 0 at once.
  for (Body& b : w.bodies()) b.velocity = -b.velocity;
  w.step(5);
  ASSERT_EQ(w.contacts().size(), 1u);
  const ContactState& c = w.contacts()[0].state;
  EXPECT_GT(c.overlap, c.excused);
  EXPECT_GT(c.normal_force, 0.0);
  EXPECT_EQ(c.normal_force, kn * (c.overlap - c.excused));
}

// Once a bond no longer holds, its points stand for the crack's faces only while the cells stay
// where it opened. The crushing rig keeps them (its cells meet only through one inner sphere);
// cells filled with spheres (broken_bonds_act = false) meet through those alone. Pressed back
// 5 µm past where they were bonded, the pair feels the faces' spring K_I·A·5 µm on top of the
// spheres' contact, or the contact alone.
TEST(WorldBonds, BrokenBondsActOnlyWhereTheWorldSaysSo) {
  for (const bool act : {true, false}) {
    SCOPED_TRACE(act);
    World w = parted_pair(1.0);
    w.options().broken_bonds_act = act;
    const std::vector<Body> start = w.bodies();
    int steps = 0;
    while (w.bonds()[0].holds() && steps < 2000) w.step(1), ++steps;
    ASSERT_FALSE(w.bonds()[0].holds());
    w.step(20);
    const double shift = 2.5e-6;
    for (int c = 0; c < 2; ++c) {
      Body& b = w.bodies()[c];
      b.position = start[c].position + Vec3(0, 0, c == 0 ? shift : -shift);
      b.orientation = start[c].orientation;
      b.velocity = b.angular_velocity = Vec3::Zero();
    }
    w.step(1);
    ASSERT_EQ(w.contacts().size(), 1u);
    const Vec3 contact = w.contacts()[0].state.force();  // on body 1, the upper cell
    const Vec3 bond = w.bodies()[1].force - contact;
    const double faces = w.options().cohesive.kn * kA * kA * 2 * shift;
    if (act) {
      EXPECT_NEAR(bond.z() / faces, 1.0, 0.02);  // the faces push the upper cell up
    } else {
      EXPECT_EQ(w.bodies()[1].force, contact);
      EXPECT_EQ(w.bodies()[0].force, -contact);
    }
    std::printf("broken bonds act %d: the bond's part of the force %.4g N (K_I·A·δ = %.4g N)\n",
                act, bond.z(), faces);
  }
}
