// Fuzzes the specimen.csv reader (bodies and spheres of a specimen directory).
#include "fuzz_input.h"
#include "io/formats/specimen_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::as_file(data, size, "specimen.csv");
  fuzz::refuse_only_cleanly([&] { clumpkit::read_specimen_csv(path); });
  return 0;
}
