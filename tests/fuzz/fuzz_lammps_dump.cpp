// Fuzzes the LAMMPS dump reader of `clumpkit import`.
#include "fuzz_input.h"
#include "io/export/lammps_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::as_file(data, size, "atoms.0.txt");
  fuzz::refuse_only_cleanly([&] { clumpkit::read_lammps_dump(path); });
  return 0;
}
