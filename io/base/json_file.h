// The JSON files of clumpkit outputs: read with errors that name the file, and sealed records
// (a checksum inside) that a changed byte makes unreadable rather than wrong.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

/// The checksum of a per-particle record: FNV-1a 64 of its compact JSON without the field. A
/// record changed on disk (a flipped byte, an edit) no longer matches and is redone, never reused.
std::string record_checksum(const nlohmann::ordered_json& record);

/// Writes `record` to `path` atomically, as indented JSON with its "checksum" added last.
void write_sealed_record(const std::string& path, const nlohmann::ordered_json& record);

/// Reads a record written by write_sealed_record into `record` (its checksum removed); false when
/// it does not parse or fails its checksum (atomic writes cannot leave one, but disks and users
/// can). Throws IoError when the file cannot be read.
bool read_sealed_record(const std::string& path, nlohmann::ordered_json& record);

/// A JSON file of a clumpkit output (report.json, manifest.json). Throws IoError when it cannot
/// be opened and InvalidInput naming it when it is not JSON.
nlohmann::json read_json_file(const std::string& path);

}  // namespace clumpkit
