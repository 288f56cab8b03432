#include "dem/run.h"

#include "geom/errors.h"

#include <algorithm>
#include <chrono>

namespace clumpkit::dem {

double unbalanced_to_weight_ratio(const World& world) {
  double unbalanced = 0.0, weight = 0.0;
  const double g = world.options().gravity.norm();
  for (const Body& b : world.bodies()) {
    unbalanced += b.force.norm();
    weight += b.mass * g;
  }
  return weight > 0.0 ? unbalanced / weight : 0.0;
}

RunOutcome run_until(World& world, const RunLimits& limits,
                     const std::function<void(long, long)>& progress) {
  if (limits.max_steps < 0)
    throw InvalidInput("run_until: max_steps must be non-negative, got " +
                       std::to_string(limits.max_steps));
  if (limits.check_every <= 0)
    throw InvalidInput("run_until: check_every must be positive, got " +
                       std::to_string(limits.check_every));
  if (!(limits.kinetic_energy_below >= 0) || !(limits.unbalanced_ratio_below >= 0) ||
      !(limits.weight_ratio_below >= 0) || !(limits.checkpoint_every_seconds >= 0))
    throw InvalidInput("run_until: thresholds and checkpoint period must be non-negative");

  using Clock = std::chrono::steady_clock;
  const bool checkpoints = limits.checkpoint_every_seconds > 0 && limits.checkpoint;
  auto last_checkpoint = Clock::now();

  RunOutcome outcome;
  while (outcome.steps < limits.max_steps) {
    const long to_boundary =
        limits.check_every - static_cast<long>(world.steps() % limits.check_every);
    const long chunk = std::min(to_boundary, limits.max_steps - outcome.steps);
    world.step(static_cast<int>(chunk));
    outcome.steps += chunk;

    if (progress) progress(outcome.steps, limits.max_steps);

    if (limits.kinetic_energy_below > 0 && kinetic_energy(world) < limits.kinetic_energy_below) {
      outcome.stopped_by = "kinetic_energy";
      return outcome;
    }
    if (limits.unbalanced_ratio_below > 0 &&
        mean_unbalanced_force_ratio(world) < limits.unbalanced_ratio_below) {
      outcome.stopped_by = "unbalanced_ratio";
      return outcome;
    }
    if (limits.weight_ratio_below > 0 &&
        unbalanced_to_weight_ratio(world) < limits.weight_ratio_below) {
      outcome.stopped_by = "weight_ratio";
      return outcome;
    }

    // After the rules: a checkpoint at step s means the rules did not hold at s, so a run resumed
    // from it (which first steps on) takes the same path as one never interrupted.
    if (checkpoints) {
      const auto now = Clock::now();
      if (std::chrono::duration<double>(now - last_checkpoint).count() >=
          limits.checkpoint_every_seconds) {
        limits.checkpoint(world);
        last_checkpoint = Clock::now();
      }
    }
  }
  outcome.stopped_by = "step_cap";
  return outcome;
}

}  // namespace clumpkit::dem
