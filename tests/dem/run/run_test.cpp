// Stop rules of run_until (dem/run/run.h): step caps in aligned chunks, kinetic energy and the
// unbalanced-force ratio. Checkpointed and resumed runs: tests/io/formats/checkpoint_test.cpp.
#include "dem/run/run.h"

#include "geom/errors.h"
#include "tests/dem/deposition_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string_view>
#include <vector>

namespace clumpkit::dem {
namespace {

using test::make_deposition;

TEST(DemRun, StopsAtStepCapInAlignedChunks) {
  World world = make_deposition(30);
  std::vector<long> reports;
  RunLimits limits;
  limits.max_steps = 250;
  // The interrupter hears ("run", steps done / max_steps) after each chunk.
  const auto record = [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "run");
    reports.push_back(std::lround(fraction * static_cast<double>(limits.max_steps)));
    return false;
  };
  const RunOutcome out = run_until(world, limits, record);
  EXPECT_EQ(out.steps, 250);
  EXPECT_EQ(out.stopped_by, "step_cap");
  EXPECT_EQ(world.steps(), 250);
  EXPECT_EQ(reports, (std::vector<long>{100, 200, 250}));
  // A later call checks on absolute multiples of check_every.
  reports.clear();
  limits.max_steps = 120;
  EXPECT_EQ(run_until(world, limits, record).steps, 120);
  EXPECT_EQ(reports, (std::vector<long>{50, 120}));
  // Height windows add check points at their multiples.
  reports.clear();
  limits.height_window = 30;
  limits.max_steps = 70;
  EXPECT_EQ(run_until(world, limits, record).steps, 70);
  EXPECT_EQ(reports, (std::vector<long>{20, 30, 50, 70}));  // steps 390, 400, 420, 440
  limits.height_window = 0;
  limits.max_steps = 0;
  EXPECT_EQ(run_until(world, limits).stopped_by, "step_cap");
  limits.check_every = 0;
  EXPECT_THROW(run_until(world, limits), InvalidInput);
  limits.check_every = 100;
  limits.height_window = -1;
  EXPECT_THROW(run_until(world, limits), InvalidInput);
}

TEST(DemRun, StopsWhenSettledByKineticEnergyThenUnbalancedRatio) {
  World world = make_deposition(40, /*platen=*/false);
  world.options().contact.local_damping = 0.7;
  RunLimits limits;
  limits.max_steps = 200000;
  // J; the bodies' potential energy above the floor is ~2e-2 J. (Not much lower: a sphere left
  // spinning about its vertical contact normal keeps ~4e-7 J, as nothing resists twisting.)
  limits.kinetic_energy_below = 1e-6;
  const RunOutcome settled = run_until(world, limits);
  EXPECT_EQ(settled.stopped_by, "kinetic_energy");
  EXPECT_LT(settled.steps, limits.max_steps);
  EXPECT_EQ(settled.steps % 100, 0);
  EXPECT_LT(kinetic_energy(world), 1e-6);

  RunLimits ratio;
  ratio.max_steps = 200000;
  ratio.unbalanced_ratio_below = 0.05;
  const RunOutcome balanced = run_until(world, ratio);
  EXPECT_EQ(balanced.stopped_by, "unbalanced_ratio");
  EXPECT_LT(balanced.steps, ratio.max_steps);
  EXPECT_LT(mean_unbalanced_force_ratio(world), 0.05);
}

}  // namespace
}  // namespace clumpkit::dem
