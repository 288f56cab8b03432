// Single-particle crushing between platens: a Voronoi particle loaded quasi-statically until it
// fails, with the platens in balance and the same bytes for any thread count.
#include "dem/lab/crush.h"

#include "dem/core/crushable.h"
#include "geom/errors.h"
#include "geom/shapes/polyhedron.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// A 16 mm polyhedron cut into about 15 cells of 6.5 mm.
World small_particle(double* diameter) {
  PolyhedronParams pp;
  pp.diameter = 0.016;
  Rng shape(7);
  const Mesh parent = make_polyhedron(pp, shape);
  CellOptions o;
  o.cell_size = 0.0065;
  Rng seeds(8), factors(9);
  const Tessellation cells = voronoi_cells(parent, o, seeds);
  const std::vector<CellBond> bonds = cell_bonds(cells, default_strength_factor(), factors);
  *diameter = std::cbrt(6 * cells.parent_volume / M_PI);
  return crushable_particle(cells, bonds, 2650, WorldOptions{});
}

CrushOptions fast() {
  CrushOptions o;
  o.density_scaling =
      1000;  // as the recipes: quasi-static, and a tenth of the sanitizer pass's time
  return o;
}

}  // namespace

TEST(Crush, AParticleFailsUnderQuasiStaticLoadWithThePlatensInBalance) {
  double d = 0;
  World w = small_particle(&d);
  const std::size_t cells = w.bodies().size();
  ASSERT_GE(cells, 10u);
  const CrushResult r = crush_particle(w, d, fast());
  ASSERT_TRUE(r.peak.found);
  EXPECT_GT(r.peak.force, 0.0);
  EXPECT_GT(r.peak.detected, r.peak.index);
  // The peak is the largest force before failure, reached after some travel.
  for (std::size_t i = 0; i < r.peak.index; ++i) EXPECT_LE(r.samples[i].force, r.peak.force);
  EXPECT_GT(r.peak.travel, 0.0);
  EXPECT_LE(r.samples[r.peak.detected].force, 0.65 * r.peak.force);
  // Quasi-static: the two platens carry the same force up to the peak, within 2 % on average.
  EXPECT_LT(r.imbalance, 0.02);
  // Strength of the order of the bonds' (σ = Fp/D² between 0.05 and 3 × σ_eI): the load went
  // through the bonds, not around them.
  const double sigma = r.peak.force / (d * d);
  EXPECT_GT(sigma, 0.05 * 9e6);
  EXPECT_LT(sigma, 3 * 9e6);
  // The gap is the particle's extent along z, and the walls moved by the recorded travel.
  EXPECT_NEAR(w.walls()[1].point.z() - w.walls()[0].point.z(), r.gap - r.samples.back().travel,
              1e-9 * r.gap);
  EXPECT_GE(r.fragments, r.peak.by == "split" ? 2 : 1);
}

TEST(Crush, SameBytesForOneAndTwoThreads) {
  auto run = [](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    double d = 0;
    World w = small_particle(&d);
    return crush_particle(w, d, fast());
  };
  const CrushResult one = run(1), two = run(2);
  ASSERT_EQ(one.samples.size(), two.samples.size());
  for (std::size_t i = 0; i < one.samples.size(); ++i) {
    EXPECT_EQ(one.samples[i].force, two.samples[i].force);
    EXPECT_EQ(one.samples[i].split, two.samples[i].split);
  }
  EXPECT_EQ(one.peak.force, two.peak.force);
}

TEST(Crush, TheSeatHoldsTheLowestCellsSquareToThePlaten) {
  double d = 0;
  World w = small_particle(&d);
  std::vector<Eigen::Quaterniond> before;
  for (const Body& b : w.bodies()) before.push_back(b.orientation);
  CrushOptions o = fast();
  o.bed_depth = 0.2;
  const CrushResult r = crush_particle(w, d, o);
  ASSERT_TRUE(r.peak.found);
  // Bedded: the cells with a corner in the lowest fifth of the gap, some but not all of them.
  double low = 1e300;
  for (const Body& b : w.bodies())
    for (const Vec3& v : b.vertices) low = std::min(low, (b.position + b.orientation * v).z());
  int locked = 0;
  for (std::size_t k = 0; k < w.bodies().size(); ++k) {
    const Body& b = w.bodies()[k];
    if (!b.rotation_locked) continue;
    ++locked;
    // Held square: a bedded cell ends the test in the orientation it started with.
    EXPECT_EQ(b.orientation.coeffs(), before[k].coeffs()) << "cell " << k;
  }
  EXPECT_EQ(locked, r.bedded);
  EXPECT_GT(r.bedded, 0);
  EXPECT_LT(r.bedded, static_cast<int>(w.bodies().size()));
  // Without the seat nothing is held, and the cells turn as they are loaded.
  World free = small_particle(&d);
  const CrushResult f = crush_particle(free, d, fast());
  EXPECT_EQ(f.bedded, 0);
  int turned = 0;
  for (std::size_t k = 0; k < free.bodies().size(); ++k)
    turned += free.bodies()[k].orientation.coeffs() != before[k].coeffs() ? 1 : 0;
  EXPECT_GT(turned, 0);
}

TEST(Crush, RefusesBadSettings) {
  double d = 0;
  World w = small_particle(&d);
  CrushOptions o;
  o.strain_rate = -1;
  EXPECT_THROW(crush_particle(w, d, o), InvalidInput);
  o = CrushOptions{};
  o.axis = 3;
  EXPECT_THROW(crush_particle(w, d, o), InvalidInput);
  o = CrushOptions{};
  o.bed_depth = 0.5;
  EXPECT_THROW(crush_particle(w, d, o), InvalidInput);
  o = CrushOptions{};
  o.local_damping = 1;
  EXPECT_THROW(crush_particle(w, d, o), InvalidInput);
  EXPECT_THROW(crush_particle(w, -d, CrushOptions{}), InvalidInput);
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  EXPECT_THROW(crush_particle(w, d, CrushOptions{}), InvalidInput);
}
