// FNV-1a 64, the one hash of clumpkit: checkpoint checksums, spec fingerprints, state hashes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace clumpkit {

/// Incremental FNV-1a 64-bit hash (Fowler–Noll–Vo). Not cryptographic: it detects accidental
/// corruption and tells states apart, which is all clumpkit asks of it. Doubles are hashed by
/// their IEEE-754 bytes in little-endian order, so equal hashes mean bit-identical values.
struct Fnv1a {
  std::uint64_t value = 0xcbf29ce484222325ULL;

  void add_bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) value = (value ^ p[k]) * 0x100000001b3ULL;
  }
  void add(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) value = (value ^ ((v >> (8 * k)) & 0xffU)) * 0x100000001b3ULL;
  }
  void add(double v) {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    add(u);
  }
  void add(std::string_view text) { add_bytes(text.data(), text.size()); }

  /// The value as 16 lower-case hexadecimal digits.
  std::string hex() const {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int k = 0; k < 16; ++k) out[15 - k] = kDigits[(value >> (4 * k)) & 0xfU];
    return out;
  }
};

/// FNV-1a 64 of a byte range.
inline std::uint64_t fnv1a(const void* data, std::size_t size) {
  Fnv1a h;
  h.add_bytes(data, size);
  return h.value;
}

}  // namespace clumpkit
