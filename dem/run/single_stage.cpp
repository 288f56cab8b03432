#include "dem/run/single_stage.h"

#include "geom/errors.h"

#include <optional>
#include <utility>

namespace clumpkit::dem {

bool run_single_stage(World& world, const StageControl& control, const std::string& fingerprint,
                      const SingleStage& stage,
                      const std::function<bool(const std::function<bool()>& stop)>& work,
                      const std::function<StageRecord()>& finish_record) {
  StageStore& store = store_of(control);
  store.open(fingerprint);
  CheckpointInfo info;
  bool resumed = false;
  if (std::optional<World> running = store.running(stage.stage, info)) {
    stage.resume(info.state, *running);
    world = std::move(*running);
    resumed = true;
  }
  StageCheckpoints checkpoints(store, control, stage.stage);
  const auto stop = [&] {
    return checkpoints.check(world, stage.record, stage.stage, stage.fraction());
  };
  if (work(stop))
    throw Interrupted(stage.what + ": stopped on request" +
                      (store.keeps_checkpoints() ? " (checkpoint kept)" : ""));
  store.finish(stage.stage, finish_record(), nullptr);
  return resumed;
}

}  // namespace clumpkit::dem
