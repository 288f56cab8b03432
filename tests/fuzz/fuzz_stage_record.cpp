// Fuzzes the stage record reader (STAGE.done, spec.fingerprint). Each input is read as it is and
// with a correct "checksum HEX" line appended, so the fuzzer reaches the parsing behind it.
#include "fuzz_input.h"
#include "geom/hash.h"
#include "io/pipeline/stage_files.h"

#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::refuse_only_cleanly([&] { clumpkit::read_stage_record(fuzz::as_file(text, "a.done")); });
  clumpkit::Fnv1a h;
  h.add(std::string_view(text));
  const std::string sealed = text + "checksum " + h.hex() + "\n";
  fuzz::refuse_only_cleanly([&] { clumpkit::read_stage_record(fuzz::as_file(sealed, "b.done")); });
  return 0;
}
