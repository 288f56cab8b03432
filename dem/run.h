// Running a DEM world until a stop rule holds, with wall-clock-periodic checkpoints.
#pragma once

#include "dem/world.h"

#include <functional>
#include <string>

namespace clumpkit::dem {

/// Stop rules and checkpointing of run_until. A threshold of 0 disables its rule.
struct RunLimits {
  long max_steps = 0;                   ///< step cap: most steps this call takes (≥ 0)
  double kinetic_energy_below = 0;      ///< stop once kinetic_energy(world) < this (J)
  double unbalanced_ratio_below = 0;    ///< stop once mean_unbalanced_force_ratio < this
  double weight_ratio_below = 0;        ///< stop once unbalanced_to_weight_ratio < this
  double checkpoint_every_seconds = 0;  ///< wall-clock period of checkpoints (s); 0 = none
  /// Saves a checkpoint of the world (e.g. StageStore::checkpoint); empty = none.
  std::function<void(const World&)> checkpoint;
  int check_every = 100;  ///< steps between rule checks (> 0)
};

/// Σ|F_net| / Σ m·|g| over the bodies (from the last step): 1 in free fall, 0 in static
/// equilibrium. Unlike the mean unbalanced-force ratio it cannot be made small by a few hard
/// impacts while most bodies still fall. 0 for a world without bodies or gravity.
double unbalanced_to_weight_ratio(const World& world);

/// How run_until ended: the steps it took and the rule that stopped it, one of
/// "kinetic_energy", "unbalanced_ratio", "weight_ratio" or "step_cap".
struct RunOutcome {
  long steps = 0;
  std::string stopped_by;
};

/// Steps `world` in chunks that end where world.steps() is a multiple of check_every (or at
/// the cap), so the checks fall on the same absolute steps after a resume from a checkpoint.
/// After each chunk `progress(done, max_steps)` is called and the rules are tested in this
/// order; the first one met stops the run: kinetic energy below its threshold, mean
/// unbalanced-force ratio below its threshold, unbalanced-to-weight ratio below its threshold,
/// step cap reached. Rules are only tested after at least one step (max_steps = 0 returns at
/// once, "step_cap"). When checkpoint_every_seconds > 0 and `checkpoint` is set, it is called
/// after the first chunk that ends at least
/// that many wall-clock seconds after the start or the previous checkpoint and at which no rule
/// held; saving only reads the world, so the result does not depend on when checkpoints happen,
/// and a run resumed from one (which steps on before testing again) follows the uninterrupted
/// run. Throws InvalidInput for a negative max_steps, check_every ≤ 0 or negative
/// thresholds.
RunOutcome run_until(World& world, const RunLimits& limits,
                     const std::function<void(long, long)>& progress = {});

}  // namespace clumpkit::dem
