// Where a staged DEM run (a specimen build, a compression, an element test) keeps finished stages
// and running checkpoints: dem says what is kept, the pipeline layer
// (io/pipeline/stage_files.h) where and how. One protocol for every resumable run.
#pragma once

#include "dem/core/world.h"
#include "geom/progress.h"

#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace clumpkit::dem {

/// The results of a finished stage, or the state of a running one: key -> one word of text
/// (numbers by format_number, which reads back to the same double).
using StageRecord = std::map<std::string, std::string>;

/// Caller data saved with a running stage's world: the stage and the state the stage needs to
/// continue exactly (the step it is at, the reference value of a stop rule, a curve so far).
struct CheckpointInfo {
  std::string stage;
  StageRecord state;
};

/// Storage of a staged run. The default stores nothing: a run stays in memory and never
/// resumes. An implementation decides where records and worlds go and whether an earlier run is
/// resumed.
class StageStore {
 public:
  virtual ~StageStore() = default;
  /// Called once before the first stage with the fingerprint of everything that decides the
  /// result (e.g. spec_fingerprint): a store that resumes must refuse stages of another one.
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

/// Progress, interruption and stage storage of a staged run.
struct StageControl {
  /// Where finished stages and running checkpoints are kept (and taken from when resuming);
  /// null = nowhere (in memory only). Stages may run in parallel: each calls the store for its
  /// own stage, from its own thread.
  StageStore* store = nullptr;
  double checkpoint_every_seconds = 60;  ///< wall-clock period of a running stage's checkpoints
  /// Told the stage and the fraction of the whole run done (0..1); when it asks to stop, the
  /// running stages save a checkpoint and the run throws Interrupted.
  Interrupter interrupter;
};

/// `record[key]` = format_number(value).
void put_number(StageRecord& record, const std::string& key, double value);

/// The number at `key`, read exactly (format_number's text) or as an integer. Throws
/// InvalidInput naming `where` and the key when it is missing or not a number.
double record_number(const StageRecord& record, const std::string& key, const std::string& where);
long long record_integer(const StageRecord& record, const std::string& key,
                         const std::string& where);

/// The comma-separated numbers at `key` (put there as format_number texts joined by commas).
/// Throws InvalidInput naming `where` and the key when it is missing or not such a list.
std::vector<double> record_list(const StageRecord& record, const std::string& key,
                                const std::string& where);

/// A curve kept in a record: "curve.rows" and one key per row ("curve.000000", …) holding the
/// row's numbers as record_list reads them (exact; a step count as a double is exact to 2^53).
void put_curve(StageRecord& record, const std::vector<std::vector<double>>& rows);

/// The rows of put_curve, each of `fields` numbers. Throws InvalidInput naming `where` and the
/// key for a missing or malformed entry.
std::vector<std::vector<double>> record_curve(const StageRecord& record, std::size_t fields,
                                              const std::string& where);

/// control.store, or where it is null a store that keeps nothing (the base StageStore: the run
/// stays in memory and never resumes; it holds no state, so one serves every run and thread).
StageStore& store_of(const StageControl& control);

/// The checkpoints of one running stage: asked between units of work, it saves the world and
/// the stage's state every control.checkpoint_every_seconds (when the store keeps checkpoints)
/// and whenever the interrupter asks to stop.
class StageCheckpoints {
 public:
  StageCheckpoints(StageStore& store, const StageControl& control, std::string stage);
  /// Saves a checkpoint when the period has passed; then tells the interrupter (`what`,
  /// `fraction`) and, when it asks to stop, saves one and returns true. `state` is called only
  /// when a checkpoint is saved.
  bool check(const World& world, const std::function<StageRecord()>& state, std::string_view what,
             double fraction);
  /// Saves a checkpoint now (when the store keeps checkpoints).
  void save(const World& world, const StageRecord& state);

 private:
  StageStore& store_;
  const StageControl& control_;
  std::string stage_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace clumpkit::dem
