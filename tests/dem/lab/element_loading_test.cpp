// Element tests of dem/lab/element_loading.h on a small compressed cube (about 130 spheres): a
// triaxial and an isotropic test, each the same bytes for 1 and 2 threads. The CLI's element tests
// run the same drive on the tiny specimen (tests/cli/element_test_test.cpp, label long); these are
// their short siblings in the sanitizer pass.
#include "dem/lab/element_loading.h"

#include "dem/core/timestep.h"
#include "dem/specimen/compression.h"
#include "geom/errors.h"
#include "tests/dem/compressed_cube.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

std::vector<CurveRow> run(const ElementTestSettings& settings, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  CellSpecimen s = test::cube_in_cell();
  const ElementTestResult r = run_element_test(s.world, s.cell, settings);
  EXPECT_TRUE(r.consolidated);
  return r.curve;
}

void expect_same_bytes(const std::vector<CurveRow>& a, const std::vector<CurveRow>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].step, b[k].step);
    for (const auto field :
         {&CurveRow::axial_strain, &CurveRow::volumetric_strain, &CurveRow::axial_stress,
          &CurveRow::lateral_stress, &CurveRow::porosity, &CurveRow::coordination,
          &CurveRow::unbalanced, &CurveRow::interior_axial_strain})
      EXPECT_EQ(std::memcmp(&(a[k].*field), &(b[k].*field), sizeof(double)), 0) << "row " << k;
  }
}

}  // namespace

TEST(DemElementTest, TriaxialLoadsAboveTheConfiningStressSameBytesForOneAndTwoThreads) {
  ElementTestSettings t;
  t.path = &kTriaxialPath;
  t.confining = test::compressed_cube().mean_stress;  // consolidated where it was built
  t.strain_rate = 2.0;
  t.max_axial_strain = 0.004;
  t.record_every = 500;
  t.consolidation_tolerance = 0.05;  // a short consolidation: the curve's start is what it is
  t.consolidation_unbalanced = 2e-2;
  t.max_consolidation_steps = 60000;
  const std::vector<CurveRow> one = run(t, 1);
  ASSERT_GE(one.size(), 3u);
  // Consolidated to the confining stress, then sheared: q grows, σ_r stays held.
  EXPECT_NEAR(one.front().axial_stress / t.confining, 1.0, 0.02);
  EXPECT_NEAR(one.front().lateral_stress / t.confining, 1.0, 0.02);
  EXPECT_EQ(one.front().axial_strain, 0.0);
  EXPECT_GE(one.back().axial_strain, 0.99 * t.max_axial_strain);
  EXPECT_GT(one.back().q, 0.03 * t.confining);  // q/p ≈ 0.075 at 0.4 % (measured)
  EXPECT_GT(one.back().q, one[1].q);
  EXPECT_NEAR(one.back().lateral_stress / t.confining, 1.0, 0.1);
  EXPECT_GT(one.back().coordination, 3.0);
  // The middle half shortens with the whole: its strain is of the platens' order (1.24 × here,
  // measured: the cube is five diameters high, so its middle half is two).
  EXPECT_EQ(one.front().interior_axial_strain, 0.0);
  EXPECT_GT(one.back().interior_axial_strain, 0.3 * one.back().axial_strain);
  EXPECT_LT(one.back().interior_axial_strain, 2.0 * one.back().axial_strain);
  expect_same_bytes(one, run(t, 2));
}

TEST(DemElementTest, IsotropicReachesItsFinalStressSameBytesForOneAndTwoThreads) {
  ElementTestSettings t;
  t.path = &kIsotropicPath;
  t.confining = test::compressed_cube().mean_stress;  // consolidated where it was built
  t.final_stress = 2 * t.confining;
  t.stress_rate = 1e11;
  t.record_every = 500;
  t.consolidation_tolerance = 0.05;  // a short consolidation: the curve's start is what it is
  t.consolidation_unbalanced = 2e-2;
  t.max_consolidation_steps = 60000;
  const std::vector<CurveRow> one = run(t, 1);
  ASSERT_GE(one.size(), 3u);
  EXPECT_NEAR(one.back().p / t.final_stress, 1.0, 0.05);
  EXPECT_GT(one.back().volumetric_strain, 0.0);  // compressed further
  EXPECT_LT(one.back().porosity, one.front().porosity);
  expect_same_bytes(one, run(t, 2));
}

TEST(DemElementTest, WorldOptionsAndInertialNumberOfASpecimen) {
  const CompressionResult& c = test::compressed_cube();
  const std::vector<Body>& bodies = c.world.bodies();
  const WorldOptions o = element_test_world_options(bodies, c.world.options().contact);
  EXPECT_EQ(o.gravity, Vec3::Zero());
  EXPECT_EQ(o.sort_every, 1000);
  double r_min = 1;
  for (const Body& b : bodies) r_min = std::min(r_min, b.spheres[0].radius);
  EXPECT_EQ(o.skin, 0.2 * r_min);
  EXPECT_EQ(o.contact.kn, c.world.options().contact.kn);
  // Equal spheres of d ≈ 10 mm, ρ = 2650: I = ε̇·d·sqrt(ρ/p) within the 1 % size spread.
  EXPECT_NEAR(inertial_number(bodies, 0.5, 1e5), 0.5 * 0.01 * std::sqrt(2650 / 1e5), 1e-6);
  EXPECT_THROW(element_test_world_options({}, c.world.options().contact), InvalidInput);
}

TEST(DemElementTest, CrushableSkinIsAFractionOfTheMedianSphere) {
  // Radii 1..5 mm in one body and 9 mm in another: the median of six is the fourth, 4 mm.
  Body a, b;
  for (int k = 1; k <= 5; ++k) a.spheres.push_back(Sphere{Vec3(k, 0, 0), 1e-3 * k});
  b.spheres.push_back(Sphere{Vec3::Zero(), 9e-3});
  EXPECT_DOUBLE_EQ(crushable_skin({a, b}), 0.75 * 4e-3);
  EXPECT_DOUBLE_EQ(crushable_skin({b, a}), 0.75 * 4e-3);  // any body order
  EXPECT_THROW(crushable_skin({}), InvalidInput);
  EXPECT_THROW(crushable_skin({Body{}}), InvalidInput);
}

TEST(DemElementTest, OedometerHoldsTheInertialNumberAtTheStressReached) {
  ElementTestSettings t;
  t.path = &kOedometerPath;
  t.confining = test::compressed_cube().mean_stress;
  t.final_stress = 3 * t.confining;
  t.strain_rate = 1.0;  // the floor
  t.record_every = 200;
  t.consolidation_tolerance = 0.05;
  t.consolidation_unbalanced = 2e-2;
  t.max_consolidation_steps = 60000;
  const std::vector<Body>& bodies = test::compressed_cube().world.bodies();
  const GrainScale grains = grain_scale(bodies);
  // Twice the floor's rate at the confining stress: the held rate governs from the start.
  t.inertial_number = inertial_number(bodies, 2.0, t.confining);
  CellSpecimen s = test::cube_in_cell();
  const double dt = s.world.options().timestep;
  const std::vector<CurveRow> c = run_element_test(s.world, s.cell, t).curve;
  ASSERT_GE(c.size(), 4u);
  EXPECT_GE(c.back().axial_stress, t.final_stress);
  // Each record's strain is the rate the last row's stress gave, times its steps; ε is
  // (h0 − h)/h0 and the platen moves at ε̇·h0.
  double first = 0, last = 0;
  for (std::size_t k = 1; k < c.size(); ++k) {
    const double rate =
        std::max(t.strain_rate, inertial_strain_rate(grains, t.inertial_number,
                                                     std::max(c[k - 1].axial_stress, t.confining)));
    const double expected = rate * dt * double(c[k].step - c[k - 1].step);
    EXPECT_NEAR(c[k].axial_strain - c[k - 1].axial_strain, expected, 1e-9 * expected) << k;
    if (k == 1) first = rate;
    last = rate;
  }
  EXPECT_NEAR(first, 2.0, 1e-9);                 // I held at the confining stress
  EXPECT_GT(last, 2.0 * std::sqrt(2.0) * 0.99);  // and still at twice the stress and more
}

TEST(DemElementTest, GrainScaleOfParticlesMadeOfSeveralBodies) {
  Body a, b, c;
  a.volume = b.volume = 1e-6, c.volume = 2e-6;
  a.mass = b.mass = 2.65e-3, c.mass = 5.3e-3;
  const double d2 = std::cbrt(6.0 * 2e-6 / M_PI), d1 = std::cbrt(6.0 * 1e-6 / M_PI);
  // Bodies alone: three grains; a and b one particle: two grains of 2e-6 m³.
  EXPECT_NEAR(grain_scale({a, b, c}).diameter, (2 * d1 + d2) / 3, 1e-15);
  EXPECT_NEAR(grain_scale({a, b, c}, {0, 0, 2}).diameter, d2, 1e-15);
  EXPECT_NEAR(grain_scale({a, b, c}, {0, 0, 2}).density, 2650, 1e-9);
  EXPECT_NEAR(inertial_strain_rate(GrainScale{0.01, 2650}, 1e-3, 2650e4), 1e-3 * 100 / 0.01, 1e-12);
  EXPECT_THROW(grain_scale({a, b}, {0}), InvalidInput);
}

namespace {

// The cube's oedometer to 2 × its consolidation stress, held at 1.5 × and at the final stress.
// Its loading is nearly all of its steps (each hold ends at its first check, after 100 steps).
// Under the sanitizers it loads at 4 /s instead of 1 /s: the same two holds in a quarter of the
// steps (about 16,000 loading steps against 65,000; the two tests below ~3.5x faster), with a row
// every 100 steps, so that a 100-step hold always spans a row's end (where the stopped test
// stops). The Release pass runs it at 1 /s with a row every 300 steps.
ElementTestSettings held_oedometer() {
  ElementTestSettings t;
  t.path = &kOedometerPath;
  t.confining = test::compressed_cube().mean_stress;
  t.final_stress = 2.0 * t.confining;
  t.hold_stresses = {1.5 * t.confining, t.final_stress};
  t.strain_rate = kSanitized ? 4.0 : 1.0;
  t.record_every = kSanitized ? 100 : 300;
  t.consolidation_tolerance = 0.05;
  t.consolidation_unbalanced = 2e-2;
  t.max_consolidation_steps = 60000;
  return t;
}

// Its curve on one thread, run once for the tests below.
const std::vector<CurveRow>& held_oedometer_curve() {
  static const std::vector<CurveRow> curve = run(held_oedometer(), 1);
  return curve;
}

}  // namespace

TEST(DemElementTest, OedometerHoldsEachStressUntilEquilibriumSameBytesForOneAndTwoThreads) {
  const ElementTestSettings t = held_oedometer();
  const std::vector<CurveRow>& one = held_oedometer_curve();
  // Each hold ends in a row of its own at equilibrium: the axial stress within the tolerance of
  // its target and the unbalanced-force ratio at most the limit (measured at that step).
  std::vector<std::size_t> ends;
  for (std::size_t k = 0; k < one.size(); ++k)
    if (one[k].held >= 2) ends.push_back(k);
  ASSERT_EQ(ends.size(), t.hold_stresses.size());
  for (std::size_t h = 0; h < ends.size(); ++h) {
    const CurveRow& c = one[ends[h]];
    EXPECT_EQ(c.held, 2) << "hold " << h;
    EXPECT_LE(std::abs(c.axial_stress / t.hold_stresses[h] - 1), t.consolidation_tolerance) << h;
    EXPECT_LE(c.unbalanced, t.consolidation_unbalanced) << h;
    // The row before the end is within the hold (or its start).
    EXPECT_TRUE(one[ends[h] - 1].held == 1 || one[ends[h] - 1].held == 0) << h;
  }
  // The test ends with the last hold, which holds the final stress; it loaded in between (a row
  // marked 0 after the first hold, whose stress rises above it).
  EXPECT_EQ(ends.back(), one.size() - 1);
  EXPECT_EQ(one[ends[0] + 1].held, 0);
  EXPECT_GT(one[ends[0] + 1].axial_strain, one[ends[0]].axial_strain);
  // A hold's rows stay near its target; the platen moves in by the creep only.
  for (std::size_t k = 1; k < one.size(); ++k) {
    if (one[k].held != 1 || one[k - 1].held != 1) continue;
    const double target =
        t.hold_stresses[std::upper_bound(ends.begin(), ends.end(), k) - ends.begin()];
    EXPECT_NEAR(one[k].axial_stress / target, 1.0, 0.25) << "row " << k;
  }
  const std::vector<CurveRow> two = run(t, 2);
  expect_same_bytes(one, two);
  for (std::size_t k = 0; k < std::min(one.size(), two.size()); ++k)
    EXPECT_EQ(one[k].held, two[k].held) << "row " << k;
}

TEST(DemElementTest, OedometerStoppedWithinAHoldContinuesToTheSameBytes) {
  const ElementTestSettings t = held_oedometer();
  const std::vector<CurveRow>& whole = held_oedometer_curve();
  CellSpecimen s = test::cube_in_cell();
  ElementTestState state;
  // Stopped at the first record within a hold; its state through a stage record (as a
  // checkpoint keeps it) and continued on the same world.
  const ElementTestResult first =
      run_element_test(s.world, s.cell, t, state, [&] { return state.holding; });
  ASSERT_TRUE(first.stopped);
  ASSERT_TRUE(state.holding);
  ElementTestState back;
  TestCell cell;
  read_element_test_record(element_test_record(state, s.cell), "checkpoint", back, cell);
  EXPECT_EQ(back.next_hold, state.next_hold);
  EXPECT_EQ(back.hold_steps, state.hold_steps);
  EXPECT_TRUE(back.holding);
  const ElementTestResult rest = run_element_test(s.world, cell, t, back);
  EXPECT_FALSE(rest.stopped);
  expect_same_bytes(whole, rest.curve);
  for (std::size_t k = 0; k < std::min(whole.size(), rest.curve.size()); ++k)
    EXPECT_EQ(whole[k].held, rest.curve[k].held) << "row " << k;
}

TEST(DemElementTest, HoldsOutsideTheOedometerOrOutOfOrderAreRefused) {
  const auto refused = [](ElementTestSettings t, const std::string& named) {
    CellSpecimen s = test::cube_in_cell();
    try {
      run_element_test(s.world, s.cell, t);
      ADD_FAILURE() << "ran";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
    }
  };
  ElementTestSettings t = held_oedometer();
  t.path = &kTriaxialPath;
  refused(t, "oedometer test only");
  t = held_oedometer();
  t.hold_stresses = {2 * t.confining, 1.5 * t.confining};
  refused(t, "must rise");
  t.hold_stresses = {t.confining};
  refused(t, "must rise");
  t.hold_stresses = {3 * t.final_stress};
  refused(t, "at most the final stress");
  t = held_oedometer();
  t.max_hold_steps = 50;
  refused(t, "max_hold_steps");
}

// The constant-p′ triaxial against the triaxial from the same consolidated state: the same first
// row, bit for bit (the same consolidation); the mean stress held (the triaxial's rises by q/3);
// and where both are elastic, the moduli agree as isotropic elasticity says they must: the
// constant-p′ path gives dq/dεa = 3G, the triaxial's own volume change K = dp/dεv, and its
// dq/dεa must then be Young's E = 9KG/(3K + G). Past the first rows' transient (measured: 0.3 %
// apart; the constant-p′ curve read as a triaxial's, 3G taken for E, misses by 10 %).
TEST(DemElementTest, ConstantMeanStressTriaxialHoldsPAndAgreesWithTheTriaxialsModuli) {
  ElementTestSettings t;
  t.confining = test::compressed_cube().mean_stress;
  t.strain_rate = 2.0;
  t.max_axial_strain = 0.004;
  t.record_every = 500;
  t.consolidation_tolerance = 0.05;
  t.consolidation_unbalanced = 2e-2;
  t.max_consolidation_steps = 60000;
  const std::vector<CurveRow> tri = run(t, 1);
  t.path = &kConstantMeanStressPath;
  const std::vector<CurveRow> cp = run(t, 1);
  ASSERT_GE(cp.size(), 6u);
  ASSERT_GE(tri.size(), 6u);
  expect_same_bytes({cp.front()}, {tri.front()});
  EXPECT_GE(cp.back().axial_strain, 0.99 * t.max_axial_strain);
  double drift = 0;
  for (std::size_t k = 1; k < cp.size(); ++k)
    drift = std::max(drift, std::abs(cp[k].p / cp[1].p - 1.0));
  EXPECT_LT(drift, 1e-3);                          // measured 2e-4
  EXPECT_GT(tri.back().p / tri[1].p - 1.0, 0.01);  // the triaxial's p rises (2.3 % measured)
  EXPECT_LT(cp.back().lateral_stress, cp[1].lateral_stress);  // σr = (3p′ − σa)/2 falls
  const std::size_t a = 3;                                    // past the start's transient
  const CurveRow &c0 = cp[a], &c1 = cp.back(), &t0 = tri[a], &t1 = tri.back();
  const double three_g = (c1.q - c0.q) / (c1.axial_strain - c0.axial_strain);
  const double young = (t1.q - t0.q) / (t1.axial_strain - t0.axial_strain);
  const double bulk = (t1.p - t0.p) / (t1.volumetric_strain - t0.volumetric_strain);
  const double g = three_g / 3.0;
  EXPECT_NEAR(9.0 * bulk * g / (3.0 * bulk + g) / young, 1.0, 0.05);
  EXPECT_GT(three_g / young, 1.05);  // 3G > E: the two paths differ
}
