// A run that is one resumable stage (an element test, the cone penetration test): the store
// opened, a running checkpoint taken up, checkpoints while it runs, Interrupted when asked to stop,
// the stage finished — the protocol of dem/run/stage_store.h in one call.
#pragma once

#include "dem/core/world.h"
#include "dem/run/stage_store.h"

#include <functional>
#include <string>

namespace clumpkit::dem {

/// What run_single_stage needs to know of the run.
struct SingleStage {
  std::string stage;  ///< the stage's name in the store (and the interrupter's)
  std::string what;   ///< the run's name in the Interrupted message ("test", "cpt")
  /// Takes up a running checkpoint: its record read into the run's state and its world checked
  /// (InvalidInput for a record or world that does not fit the run).
  std::function<void(const StageRecord& record, const World& world)> resume;
  /// The run's state as a record (called only when a checkpoint is saved).
  std::function<StageRecord()> record;
  /// The fraction of the run done, for the interrupter.
  std::function<double()> fraction;
};

/// Opens store_of(control) with `fingerprint`; where it holds a running checkpoint of the stage,
/// calls stage.resume and moves the checkpoint's world into `world`. Then calls work(stop): stop()
/// saves a checkpoint each control period and returns true when the interrupter asks to stop, and
/// work returns whether it stopped. Stopped: throws Interrupted "WHAT: stopped on request
/// (checkpoint kept)"; else the stage is finished with finish_record(). Returns whether a
/// checkpoint was taken up.
bool run_single_stage(World& world, const StageControl& control, const std::string& fingerprint,
                      const SingleStage& stage,
                      const std::function<bool(const std::function<bool()>& stop)>& work,
                      const std::function<StageRecord()>& finish_record);

}  // namespace clumpkit::dem
