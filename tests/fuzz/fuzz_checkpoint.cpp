// Fuzzes the binary checkpoint reader. Each input is read twice: as it is (the checksum refuses
// almost all of it), and with its trailing 8 bytes replaced by the FNV-1a 64 checksum of the rest,
// so the fuzzer reaches the decoding of every field behind the checksum.
#include "fuzz_input.h"
#include "geom/hash.h"
#include "io/formats/checkpoint.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  fuzz::refuse_only_cleanly([&] { clumpkit::load_checkpoint(fuzz::as_file(bytes, "a.ckpt")); });
  if (bytes.size() >= 8) {
    clumpkit::Fnv1a h;
    h.add_bytes(bytes.data(), bytes.size() - 8);
    for (int k = 0; k < 8; ++k)
      bytes[bytes.size() - 8 + k] = static_cast<char>((h.value >> (8 * k)) & 0xffU);
    fuzz::refuse_only_cleanly([&] { clumpkit::load_checkpoint(fuzz::as_file(bytes, "b.ckpt")); });
  }
  return 0;
}
