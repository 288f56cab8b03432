// Where a staged DEM build keeps finished stages and running checkpoints: dem says what is kept,
// the pipeline layer (io/pipeline/stage_files.h) where and how.
#pragma once

#include "dem/core/world.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

namespace clumpkit::dem {

/// The results of a finished stage: key -> text (doubles in hexadecimal, so they round-trip).
using StageRecord = std::map<std::string, std::string>;

/// Caller data saved with a running stage's world: the stage and up to four words of state the
/// stage needs to continue exactly (e.g. the step it began at, a reference value of a stop rule).
struct CheckpointInfo {
  std::string stage;
  std::array<std::uint64_t, 4> random_state{};
};

/// Storage of a staged build (dem::build_specimen). The default stores nothing: a build runs in
/// memory and never resumes. An implementation decides where records and worlds go and whether
/// an earlier run is resumed.
class StageStore {
 public:
  virtual ~StageStore() = default;
  /// Called once before the first stage with the fingerprint of everything that decides the
  /// result (spec_fingerprint): a store that resumes must refuse stages of another fingerprint.
  virtual void open(const std::string& fingerprint) {}
  /// The record of `stage` when it finished in an earlier run that is being resumed.
  virtual std::optional<StageRecord> finished(const std::string& stage) { return std::nullopt; }
  /// The world a finished stage ended with (only for stages that kept one in finish()).
  virtual World finished_world(const std::string& stage) {
    throw std::logic_error("StageStore: no world kept for stage " + stage);
  }
  /// The last checkpoint of `stage` when it was running as an earlier run stopped; fills `info`.
  virtual std::optional<World> running(const std::string& stage, CheckpointInfo& info) {
    return std::nullopt;
  }
  /// Whether periodic checkpoints of running stages are wanted (each costs a write).
  virtual bool keeps_checkpoints() const { return false; }
  /// Saves a checkpoint of the running `stage` (world and info).
  virtual void checkpoint(const std::string& stage, const World& world,
                          const CheckpointInfo& info) {}
  /// Marks `stage` finished with its record and, if given, the world it ended with; its running
  /// checkpoint is dropped.
  virtual void finish(const std::string& stage, const StageRecord& record, const World* world) {}
};

}  // namespace clumpkit::dem
