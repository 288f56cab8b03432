// Fuzzes the report.json and manifest.json readers an export starts from.
#include "fuzz_input.h"
#include "io/base/json_file.h"
#include "io/export/engine_settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::as_file(data, size, "report.json");
  fuzz::refuse_only_cleanly([&] {
    const nlohmann::json report = clumpkit::read_json_file(path);
    clumpkit::engine_settings_from_report(report, path);
  });
  return 0;
}
