// The cone penetration test of dem/lab/cpt.h on a small compressed cube (about 130 spheres of
// 10 mm, a 10 mm probe): the push resists, the cell's stresses are held, the same bytes for 1 and
// 2 threads and after a stop; its stage record round-trips.
#include "dem/lab/cpt.h"
#include "dem/core/timestep.h"
#include "dem/specimen/compression.h"
#include "geom/errors.h"
#include "tests/dem/compressed_cube.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

CellSpecimen setup() {
  return test::cube_in_cell();
}

CptSettings settings() {
  CptSettings t;
  t.cell.confining = test::compressed_cube().mean_stress;  // consolidated where it was built
  t.cell.record_every = 1000;
  t.cell.consolidation_tolerance = 0.05;
  t.cell.consolidation_unbalanced = 2e-2;
  t.cell.max_consolidation_steps = 60000;
  t.probe.diameter = 0.01;
  t.probe.velocity = 2.0;
  t.probe.depth = 0.009;
  return t;
}

// The probe of settings() at 100 kPa, for the checks that need no specimen.
CptSettings probe_only() {
  CptSettings t;
  t.cell.confining = 1e5;
  t.probe.diameter = 0.01;
  t.probe.velocity = 2.0;
  t.probe.depth = 0.01;
  return t;
}

std::vector<CptRow> run(const CptSettings& t, int threads, int stop_at = -1) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  CellSpecimen s = setup();
  CptState state;
  int asked = 0;
  const auto stop = [&] { return ++asked == stop_at; };
  CptResult r = run_cpt(s.world, s.cell, t, state, stop);
  if (stop_at > 0) {
    EXPECT_TRUE(r.stopped);
    r = run_cpt(s.world, s.cell, t, state, stop);  // continues where it stopped
  }
  EXPECT_FALSE(r.stopped);
  EXPECT_TRUE(r.consolidated);
  return r.curve;
}

void expect_same_bytes(const std::vector<CptRow>& a, const std::vector<CptRow>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].step, b[k].step);
    for (const auto field : {&CptRow::depth, &CptRow::tip_force, &CptRow::sleeve_force, &CptRow::qc,
                             &CptRow::fs, &CptRow::axial_stress, &CptRow::lateral_stress})
      EXPECT_EQ(std::memcmp(&(a[k].*field), &(b[k].*field), sizeof(double)), 0) << "row " << k;
  }
}

}  // namespace

TEST(DemCpt, ProbeMeetsResistanceWithTheCellHeldSameBytesForOneAndTwoThreadsAndAfterAStop) {
  const CptSettings t = settings();
  const std::vector<CptRow> one = run(t, 1);
  ASSERT_GE(one.size(), 5u);
  // The push starts at the specimen's top with nothing on the probe, and goes down at its speed.
  EXPECT_EQ(one.front().depth, 0.0);
  EXPECT_EQ(one.front().tip_force, 0.0);
  EXPECT_GE(one.back().depth, t.probe.depth);
  double qc_max = 0.0;
  for (std::size_t k = 1; k < one.size(); ++k) {
    EXPECT_GT(one[k].depth, one[k - 1].depth);
    qc_max = std::max(qc_max, one[k].qc);
    EXPECT_GE(one[k].tip_force, -1e-9 * std::abs(one[k].tip_force));  // the soil pushes up
    EXPECT_NEAR(one[k].lateral_stress / t.cell.confining, 1.0, 0.5) << k;
  }
  // The cone's resistance is several times the confining stress (9.3 times at most here,
  // measured; with the base free as well as the top the probe carried the specimen down and qc
  // stayed below the confining stress).
  EXPECT_GT(qc_max, 3.0 * t.cell.confining);
  // The sleeve is never pulled down (the probe only goes down; the sleeve's own law is checked
  // on one sphere in tests/dem/core/probe_wall_test.cpp: here the spheres the cone pushed aside
  // stay off the short length of shaft below the top).
  for (const CptRow& c : one) {
    EXPECT_GE(c.sleeve_force, 0.0);
    if (c.fs != 0.0) {
      EXPECT_GT(c.depth, 0.5 * t.probe.diameter * std::sqrt(3.0));
    }
  }
  // One sphere rides on the cone from 1.1 mm on: the tip force never drops to zero again.
  for (const CptRow& c : one)
    if (c.depth > 0.002) {
      EXPECT_GT(c.tip_force, 0.0) << c.depth;
    }
  expect_same_bytes(one, run(t, 2));
  expect_same_bytes(one, run(t, 1, 3));  // stopped at the push's second row, continued
}

TEST(DemCpt, ProbesThatCannotBePushedAreRefused) {
  CellSpecimen s{World(WorldOptions{}), {}};
  s.world.add_body(make_sphere_body(Vec3(0.025, 0.025, 0.025), 0.005, 2650));
  s.cell = add_cuboid_test_cell(s.world, Vec3::Zero(), Vec3::Constant(0.05));
  for (const auto& [diameter, apex, velocity, depth] :
       std::vector<std::array<double, 4>>{{0.0, 60, 1, 0.01},
                                          {0.03, 60, 1, 0.01},  // wider than half the cell
                                          {0.01, 180, 1, 0.01},
                                          {0.01, 60, -1, 0.01},
                                          {0.01, 60, 1, 0.0}}) {
    CptSettings t = probe_only();
    t.probe = {diameter, apex, velocity, depth, -1.0};
    EXPECT_THROW(validate_cpt(s.world, s.cell, t), InvalidInput) << diameter << " " << apex;
  }
  EXPECT_NO_THROW(validate_cpt(s.world, s.cell, probe_only()));
}

TEST(CptRecord, StateAndCellRoundTripExactly) {
  CptState st;
  st.phase = CptState::Phase::push;
  st.consolidation_steps = 4321;
  st.consolidated = true;
  st.push_steps = 700;
  st.start_height = 0.1 / 3.0;
  st.test_friction = 0.5;
  st.apex0 = 0.05 / 7.0;
  st.probe = 6;
  st.reached_bottom = false;
  for (int k = 0; k < 3; ++k)
    st.curve.push_back({350LL * k, k / 7.0, k * 1.1, k / 3.0, 1e6 / 7.0 * k, k * 2.5, 1e5 / 3.0,
                        k == 2 ? std::nan("") : 1e5});
  TestCell cell;
  cell.shape = TestCell::Shape::cylinder;
  cell.lateral = {0};
  cell.bottom = 1;
  cell.top = 2;
  CptState back;
  TestCell cell_back;
  read_cpt_record(cpt_record(st, cell), "cpt.ckpt", back, cell_back);
  EXPECT_EQ(back.phase, st.phase);
  EXPECT_EQ(back.consolidation_steps, st.consolidation_steps);
  EXPECT_EQ(back.push_steps, st.push_steps);
  EXPECT_EQ(back.start_height, st.start_height);
  EXPECT_EQ(back.apex0, st.apex0);
  EXPECT_EQ(back.probe, 6);
  EXPECT_EQ(cell_back.lateral, cell.lateral);
  ASSERT_EQ(back.curve.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(back.curve[k].step, st.curve[k].step);
    EXPECT_EQ(back.curve[k].depth, st.curve[k].depth);
    EXPECT_EQ(back.curve[k].qc, st.curve[k].qc);
    EXPECT_EQ(std::memcmp(&back.curve[k].lateral_stress, &st.curve[k].lateral_stress, 8), 0);
  }
  StageRecord bad = cpt_record(st, cell);
  bad["curve.000001"] = "1,2";
  EXPECT_THROW(read_cpt_record(bad, "cpt.ckpt", back, cell_back), InvalidInput);
  bad = cpt_record(st, cell);
  bad.erase("apex0");
  EXPECT_THROW(read_cpt_record(bad, "cpt.ckpt", back, cell_back), InvalidInput);
}

// CTGU 2017's chamber in a segment: an 18 mm cone among 6 mm spheres. In a 30° segment the
// radial walls keep the spheres 8.6 mm from the axis, the cone's radius is 9 mm: refused. In a
// 90° segment they come within 1.2 mm: accepted.
TEST(DemCpt, ProbeInASegmentMustReachPastTheWallsExclusion) {
  for (const double degrees : {30.0, 90.0}) {
    World w(WorldOptions{});
    const double angle = degrees * M_PI / 180.0;
    const Vec3 dir(std::cos(angle / 2), std::sin(angle / 2), 0.0);
    for (int k = 0; k < 5; ++k)
      w.add_body(make_sphere_body((0.01 + 0.006 * k) * dir + Vec3(0, 0, 0.05), 0.003, 2650));
    const TestCell cell = add_segment_test_cell(w, 0.15, angle, 0.0, 0.1);
    CptSettings t = probe_only();
    t.probe.diameter = 0.018;
    if (degrees == 30.0)
      EXPECT_THROW(validate_cpt(w, cell, t), InvalidInput);
    else
      EXPECT_NO_THROW(validate_cpt(w, cell, t));
  }
}
