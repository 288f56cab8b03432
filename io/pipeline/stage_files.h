// Stage storage of a resumable run (specimen build, compression, element test) in a directory:
// checksummed stage records and the fingerprint, binary checkpoints for running stages and saved
// worlds, all written atomically.
#pragma once

#include "dem/run/stage_store.h"

#include <string>

namespace clumpkit {

/// A dem::StageStore in `dir`:
///   spec.fingerprint      the build's fingerprint (a record),
///   STAGE.done            a finished stage's record: "key value" lines, then "checksum HEX"
///                         (FNV-1a 64 of the lines before it),
///   STAGE.world           the world a finished stage ended with (io/formats/checkpoint.h format),
///   STAGE.ckpt            the latest checkpoint of a running stage.
/// With `resume`, open() accepts the directory only if its fingerprint is the build's (else
/// InvalidInput naming both) and finished()/running() return what is there; a record whose
/// checksum does not match is refused (InvalidInput naming the file), never used. Without
/// `resume`, or when the directory holds no fingerprint, open() empties the directory: the store
/// owns it, so pass a directory of its own (the specimen and test jobs use
/// DIR.partial/checkpoints).
class StageFiles : public dem::StageStore {
 public:
  StageFiles(std::string dir, bool resume);
  void open(const std::string& fingerprint) override;
  std::optional<dem::StageRecord> finished(const std::string& stage) override;
  dem::World finished_world(const std::string& stage) override;
  std::optional<dem::World> running(const std::string& stage, dem::CheckpointInfo& info) override;
  bool keeps_checkpoints() const override { return true; }
  void checkpoint(const std::string& stage, const dem::World& world,
                  const dem::CheckpointInfo& info) override;
  void finish(const std::string& stage, const dem::StageRecord& record,
              const dem::World* world) override;

 private:
  std::string path(const std::string& stage, const char* ext) const;
  std::string dir_;
  bool resume_;
};

/// Writes a record file atomically: "key value" lines in key order, then "checksum HEX".
/// Throws InvalidInput for a key or value that is empty or holds white space.
void write_stage_record(const std::string& path, const dem::StageRecord& record);

/// Reads a record file written by write_stage_record. Throws IoError when it cannot be read and
/// InvalidInput naming the file for a malformed line or a checksum that does not match.
dem::StageRecord read_stage_record(const std::string& path);

}  // namespace clumpkit
