// Running a DEM world until a stop rule holds: every stop rule of the engine, periodic
// checkpoints and the interrupter.
#pragma once

#include "dem/core/world.h"
#include "geom/progress.h"

#include <cmath>
#include <functional>
#include <string>

namespace clumpkit::dem {

/// What run_until carries from one check to the next besides the world. It is saved with every
/// checkpoint, so a run resumed from one tests its rules as the uninterrupted run does.
struct RunState {
  /// Column height (column_height) at the last height-window boundary (m); NaN = none yet.
  double height_reference = NAN;
};

/// Stop rules and checkpointing of run_until. A threshold of 0 disables its rule.
struct RunLimits {
  long max_steps = 0;                 ///< step cap: most steps this call takes (≥ 0)
  double kinetic_energy_below = 0;    ///< stop once kinetic_energy(world) < this (J)
  double unbalanced_ratio_below = 0;  ///< stop once mean_unbalanced_force_ratio < this
  double weight_ratio_below = 0;      ///< stop once unbalanced_to_weight_ratio < this
  /// Settled-height rule (0 = off): at every absolute multiple of height_window steps the
  /// column height is compared with the one at the previous multiple; the run stops once it
  /// moved less than height_tolerance (m) while unbalanced_to_weight_ratio < 1 (the bodies
  /// rest on each other rather than fall).
  long height_window = 0;
  double height_tolerance = 0;          ///< m
  RunState state;                       ///< where to start from (a checkpoint's state)
  double checkpoint_every_seconds = 0;  ///< wall-clock period of checkpoints (s); 0 = none
  /// Saves a checkpoint of the world and the run's state; empty = none.
  std::function<void(const World&, const RunState&)> checkpoint;
  int check_every = 100;  ///< steps between rule checks (> 0)
};

/// Σ|F_net| / Σ m·|g| over the bodies (from the last step): 1 in free fall, 0 in static
/// equilibrium. Unlike the mean unbalanced-force ratio it cannot be made small by a few hard
/// impacts while most bodies still fall. 0 for a world without bodies or gravity.
double unbalanced_to_weight_ratio(const World& world);

/// How run_until ended: the steps it took, the rule that stopped it (one of "kinetic_energy",
/// "unbalanced_ratio", "weight_ratio", "settled_height", "step_cap" or "interrupted") and the
/// state to resume from.
struct RunOutcome {
  long steps = 0;
  std::string stopped_by;
  RunState state;
};

/// Steps `world` in chunks that end where world.steps() is a multiple of check_every or of
/// height_window (or at the cap), so the checks fall on the same absolute steps after a resume
/// from a checkpoint. After each chunk the rules are tested in this order and the first one met
/// stops the run: kinetic energy, mean unbalanced-force ratio, unbalanced-to-weight ratio,
/// settled height (at window boundaries), step cap. Then the interrupter is told ("run",
/// steps done / max_steps); when it asks to stop, a checkpoint is saved (if `checkpoint` is set)
/// and the run returns "interrupted". Otherwise, when checkpoint_every_seconds > 0, a
/// checkpoint is saved after the first chunk ending at least that many wall-clock seconds after
/// the start or the previous one. A checkpoint is thus only taken where no rule held, and
/// saving only reads the world, so a run resumed from one (which steps on before testing again)
/// follows the uninterrupted run bit for bit. Rules are only tested after at least one step
/// (max_steps = 0 returns at once, "step_cap"). Throws InvalidInput for a negative max_steps or
/// height_window, check_every ≤ 0, or negative thresholds.
RunOutcome run_until(World& world, const RunLimits& limits, const Interrupter& interrupter = {});

}  // namespace clumpkit::dem
