#include "dem/run/run.h"

#include "dem/measure/region_volume.h"
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

namespace {

/// Steps from `step` to the next multiple of `every` (every > 0): in 1..every.
long to_multiple(std::uint64_t step, long every) {
  return every - static_cast<long>(step % static_cast<std::uint64_t>(every));
}

/// The first stop rule of `limits` that holds after a chunk, or null. Updates the height
/// reference at window boundaries.
const char* rule_met(const World& world, const RunLimits& limits, RunState& state) {
  if (limits.kinetic_energy_below > 0 && kinetic_energy(world) < limits.kinetic_energy_below)
    return "kinetic_energy";
  if (limits.unbalanced_ratio_below > 0 &&
      mean_unbalanced_force_ratio(world) < limits.unbalanced_ratio_below)
    return "unbalanced_ratio";
  if (limits.weight_ratio_below > 0 &&
      unbalanced_to_weight_ratio(world) < limits.weight_ratio_below)
    return "weight_ratio";
  if (limits.height_window > 0 && world.steps() % limits.height_window == 0) {
    const double h = column_height(world);
    if (std::isfinite(state.height_reference) &&
        std::abs(h - state.height_reference) < limits.height_tolerance &&
        unbalanced_to_weight_ratio(world) < 1.0)
      return "settled_height";
    state.height_reference = h;
  }
  return nullptr;
}

}  // namespace

RunOutcome run_until(World& world, const RunLimits& limits, const Interrupter& interrupter) {
  if (limits.max_steps < 0)
    throw InvalidInput("run_until: max_steps must be non-negative, got " +
                       std::to_string(limits.max_steps));
  if (limits.check_every <= 0)
    throw InvalidInput("run_until: check_every must be positive, got " +
                       std::to_string(limits.check_every));
  if (limits.height_window < 0)
    throw InvalidInput("run_until: height_window must be non-negative, got " +
                       std::to_string(limits.height_window));
  if (!(limits.kinetic_energy_below >= 0) || !(limits.unbalanced_ratio_below >= 0) ||
      !(limits.weight_ratio_below >= 0) || !(limits.height_tolerance >= 0) ||
      !(limits.checkpoint_every_seconds >= 0))
    throw InvalidInput("run_until: thresholds and checkpoint period must be non-negative");

  using Clock = std::chrono::steady_clock;
  auto last_checkpoint = Clock::now();

  RunOutcome outcome;
  outcome.state = limits.state;
  // The reference of a run that starts on a window boundary (a fresh stage at step 0).
  if (limits.height_window > 0 && world.steps() % limits.height_window == 0 &&
      !std::isfinite(outcome.state.height_reference))
    outcome.state.height_reference = column_height(world);

  while (outcome.steps < limits.max_steps) {
    long chunk =
        std::min(to_multiple(world.steps(), limits.check_every), limits.max_steps - outcome.steps);
    if (limits.height_window > 0)
      chunk = std::min(chunk, to_multiple(world.steps(), limits.height_window));
    world.step(static_cast<int>(chunk));
    outcome.steps += chunk;

    if (const char* rule = rule_met(world, limits, outcome.state)) {
      outcome.stopped_by = rule;
      return outcome;
    }
    // After the rules: a checkpoint at step s means no rule held at s, so a run resumed from it
    // (which first steps on) takes the same path as one never interrupted.
    const bool stop =
        interrupted(interrupter, "run",
                    static_cast<double>(outcome.steps) / static_cast<double>(limits.max_steps));
    if (limits.checkpoint &&
        (stop || (limits.checkpoint_every_seconds > 0 &&
                  std::chrono::duration<double>(Clock::now() - last_checkpoint).count() >=
                      limits.checkpoint_every_seconds))) {
      limits.checkpoint(world, outcome.state);
      last_checkpoint = Clock::now();
    }
    if (stop) {
      outcome.stopped_by = "interrupted";
      return outcome;
    }
  }
  outcome.stopped_by = "step_cap";
  return outcome;
}

}  // namespace clumpkit::dem
