#include "io/pipeline/stage_files.h"

#include "geom/errors.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/formats/checkpoint.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

bool plain_word(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') return false;
  return true;
}

std::string record_text(const dem::StageRecord& record, const std::string& path) {
  std::string text;
  for (const auto& [k, v] : record) {
    if (!plain_word(k) || !plain_word(v))
      throw InvalidInput(path + ": stage record key and value must be single words, got '" + k +
                         "' = '" + v + "'");
    text += k + " " + v + "\n";
  }
  return text;
}

}  // namespace

void write_stage_record(const std::string& path, const dem::StageRecord& record) {
  const std::string text = record_text(record, path);
  Fnv1a h;
  h.add(std::string_view(text));
  write_file_atomically(
      path, [&](std::ostream& out) { out << text << "checksum " << h.hex() << "\n"; }, false);
}

dem::StageRecord read_stage_record(const std::string& path) {
  const std::string bytes = read_file(path, "stage record");
  const std::size_t last = bytes.rfind("checksum ");
  if (last == std::string::npos || (last > 0 && bytes[last - 1] != '\n'))
    throw InvalidInput(path + ": stage record has no checksum line (corrupt or truncated)");
  const std::string body = bytes.substr(0, last);
  std::string stored = bytes.substr(last + 9);
  while (!stored.empty() && (stored.back() == '\n' || stored.back() == '\r')) stored.pop_back();
  Fnv1a h;
  h.add(std::string_view(body));
  if (stored != h.hex())
    throw InvalidInput(path + ": stage record checksum mismatch (stored " + stored + ", content " +
                       h.hex() +
                       "); the file is corrupt: remove it or run without "
                       "--resume");
  dem::StageRecord record;
  std::istringstream lines(body);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::size_t space = line.find(' ');
    if (space == std::string::npos || space == 0 || space + 1 == line.size())
      throw InvalidInput(path + ": line " + std::to_string(number) + ": expected 'key value'");
    record[line.substr(0, space)] = line.substr(space + 1);
  }
  return record;
}

StageFiles::StageFiles(std::string dir, bool resume) : dir_(std::move(dir)), resume_(resume) {}

std::string StageFiles::path(const std::string& stage, const char* ext) const {
  return (fs::path(dir_) / (stage + ext)).string();
}

void StageFiles::open(const std::string& fingerprint) {
  const std::string fp = path("spec", ".fingerprint");
  if (resume_ && fs::exists(fp)) {
    const dem::StageRecord r = read_stage_record(fp);
    const auto it = r.find("fingerprint");
    const std::string old = it == r.end() ? std::string("none") : it->second;
    if (old != fingerprint)
      throw InvalidInput(dir_ +
                         ": checkpoints are of other inputs (another recipe, specimen, library or "
                         "program version; fingerprint " +
                         old + ", this run " + fingerprint + "); remove them or drop --resume");
  } else {
    fs::remove_all(dir_);
  }
  fs::create_directories(dir_);
  write_stage_record(fp, {{"fingerprint", fingerprint}});
}

std::optional<dem::StageRecord> StageFiles::finished(const std::string& stage) {
  const std::string done = path(stage, ".done");
  if (!resume_ || !fs::exists(done)) return std::nullopt;
  return read_stage_record(done);
}

dem::World StageFiles::finished_world(const std::string& stage) {
  return load_checkpoint(path(stage, ".world"));
}

std::optional<dem::World> StageFiles::running(const std::string& stage, dem::CheckpointInfo& info) {
  const std::string ckpt = path(stage, ".ckpt");
  if (!resume_ || !fs::exists(ckpt)) return std::nullopt;
  return load_checkpoint(ckpt, &info);
}

void StageFiles::checkpoint(const std::string& stage, const dem::World& world,
                            const dem::CheckpointInfo& info) {
  save_checkpoint(path(stage, ".ckpt"), world, info);
}

void StageFiles::finish(const std::string& stage, const dem::StageRecord& record,
                        const dem::World* world) {
  if (world) save_checkpoint(path(stage, ".world"), *world);
  write_stage_record(path(stage, ".done"), record);
  fs::remove(path(stage, ".ckpt"));
}

}  // namespace clumpkit
