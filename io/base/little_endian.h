// Little-endian bytes, the order of binary STL, binary PLY and clumpkit checkpoints, on any host
// (and big-endian reads, PLY's other byte order).
#pragma once

#include <algorithm>
#include <cstring>
#include <ostream>
#include <string>

namespace clumpkit {

/// The value of type T (an integer or floating-point type) stored little-endian at `p`.
template <class T>
T load_le(const char* p) {
  char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  std::reverse(b, b + sizeof(T));
#endif
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

/// The value of type T stored big-endian at `p`.
template <class T>
T load_be(const char* p) {
  char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
#if __BYTE_ORDER__ != __ORDER_BIG_ENDIAN__
  std::reverse(b, b + sizeof(T));
#endif
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

/// Stores `v` little-endian at `b` (sizeof(T) bytes).
template <class T>
void store_le(char* b, T v) {
  std::memcpy(b, &v, sizeof(T));
#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  std::reverse(b, b + sizeof(T));
#endif
}

/// Writes `v` little-endian to a stream.
template <class T>
void store_le(std::ostream& os, T v) {
  char b[sizeof(T)];
  store_le(b, v);
  os.write(b, sizeof(T));
}

/// Appends `v` little-endian to a byte string.
template <class T>
void append_le(std::string& bytes, T v) {
  char b[sizeof(T)];
  store_le(b, v);
  bytes.append(b, sizeof(T));
}

}  // namespace clumpkit
