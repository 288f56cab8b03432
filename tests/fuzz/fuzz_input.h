// What every fuzz target shares: the fuzzer's bytes as a file a reader opens, and the error
// contract (a reader may refuse input only with InvalidInput or IoError).
#pragma once

#include "geom/errors.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace fuzz {

/// A scratch directory of this process (removed by nobody: /tmp is the fuzzer's to clean).
inline const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() /
                   ("clumpkit-fuzz-" + std::to_string(static_cast<long>(getpid())));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

/// Writes `size` bytes to `name` under scratch() (sub-directories created) and returns its path.
inline std::string as_file(const void* data, std::size_t size, const std::string& name) {
  const std::filesystem::path p = scratch() / name;
  std::filesystem::create_directories(p.parent_path());
  std::ofstream o(p, std::ios::binary | std::ios::trunc);
  o.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  return p.string();
}

inline std::string as_file(const std::string& text, const std::string& name) {
  return as_file(text.data(), text.size(), name);
}

/// Runs `read`; the refusals a reader may make are InvalidInput and IoError. Anything else (a
/// std::exception, a crash, a sanitizer report) escapes to libFuzzer and is a finding.
template <class Read>
void refuse_only_cleanly(Read&& read) {
  try {
    read();
  } catch (const clumpkit::InvalidInput&) {
  } catch (const clumpkit::IoError&) {
  }
}

}  // namespace fuzz
