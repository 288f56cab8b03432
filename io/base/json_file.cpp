#include "io/base/json_file.h"

#include "geom/errors.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"

#include <string_view>

namespace clumpkit {

std::string record_checksum(const nlohmann::ordered_json& record) {
  Fnv1a h;
  h.add(std::string_view(record.dump()));
  return h.hex();
}

void write_sealed_record(const std::string& path, const nlohmann::ordered_json& record) {
  nlohmann::ordered_json sealed = record;
  sealed["checksum"] = record_checksum(record);
  write_file_atomically(path, [&](std::ostream& o) { o << sealed.dump(1) << "\n"; });
}

bool read_sealed_record(const std::string& path, nlohmann::ordered_json& record) {
  try {
    nlohmann::ordered_json r = nlohmann::ordered_json::parse(read_file(path));
    const std::string stored = r.value("checksum", std::string());
    r.erase("checksum");
    if (stored != record_checksum(r)) return false;
    record = std::move(r);
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

nlohmann::json read_json_file(const std::string& path) {
  const std::string text = read_file(path, "JSON file");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput(path + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace clumpkit
