// Fuzzes the STL reader (read_mesh: parse, then the watertightness and orientation checks).
#include "fuzz_input.h"
#include "io/formats/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::as_file(data, size, "mesh.stl");
  fuzz::refuse_only_cleanly([&] { clumpkit::read_mesh(path); });
  return 0;
}
