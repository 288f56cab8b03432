#include "io/base/atomic_file.h"

#include "geom/errors.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace clumpkit {

namespace fs = std::filesystem;

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill,
                           bool binary) {
  // Process id + per-process counter make the name unique across processes and threads, so two
  // writers of the same target never share a temporary file.
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  const fs::path tmp =
      target.parent_path() / ("." + target.filename().string() + ".tmp-" +
                              std::to_string(::getpid()) + "-" + std::to_string(counter++));
  auto fail = [&](const std::string& what) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw IoError(path + ": " + what);
  };
  std::ofstream out(tmp, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                                : std::ios::out | std::ios::trunc);
  if (!out)
    fail(std::string("cannot create a temporary file for writing: ") + std::strerror(errno));
  // The first failing write(2) leaves its errno (ENOSPC, EFBIG, EIO); later calls may not touch
  // it, so the reason is taken as soon as the stream fails.
  int reason = 0;
  try {
    errno = 0;
    fill(out);
    if (!out) reason = errno;
  } catch (...) {
    out.close();
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
  out.close();  // flushes; a full disk shows up here as a failed stream
  if (!out) {
    if (reason == 0) reason = errno;
    fail(std::string("write failed: ") + (reason != 0 ? std::strerror(reason) : "I/O error"));
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) fail("cannot rename the temporary file into place: " + ec.message());
}

void remove_stray_temporaries(const std::string& dir) {
  std::error_code ec;
  std::vector<fs::path> stray;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() > 1 && name[0] == '.' && name.find(".tmp-") != std::string::npos &&
        it->is_regular_file(ec))
      stray.push_back(it->path());
  }
  for (const fs::path& p : stray) fs::remove(p, ec);
}

}  // namespace clumpkit
