// Fuzzes the clump CSV reader (x,y,z,r; also every library template CSV).
#include "fuzz_input.h"
#include "io/formats/clump_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::as_file(data, size, "clump.csv");
  fuzz::refuse_only_cleanly([&] { clumpkit::read_clump(path); });
  return 0;
}
