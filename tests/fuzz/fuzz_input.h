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
#include <system_error>

namespace fuzz {

/// A scratch directory of this process, removed at a normal exit (libFuzzer's exit after
/// -max_total_time or -runs); a crash leaves it, with what the crashing input wrote there.
inline const std::filesystem::path& scratch() {
  struct Dir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("clumpkit-fuzz-" + std::to_string(static_cast<long>(getpid())));
    Dir() { std::filesystem::create_directories(path); }
    Dir(const Dir&) = delete;
    Dir& operator=(const Dir&) = delete;
    ~Dir() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Dir dir;
  return dir.path;
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
