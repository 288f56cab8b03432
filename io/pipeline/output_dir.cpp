#include "io/pipeline/output_dir.h"

#include "geom/errors.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace clumpkit {

void check_output_directory(const std::string& dir) {
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw InvalidInput(dir + ": --out exists and is not a directory");
  if (fs::exists(dir) && !fs::exists(fs::path(dir) / "manifest.json") && !fs::is_empty(dir))
    throw InvalidInput(dir +
                       ": output directory exists and is not a clumpkit output; "
                       "remove it or choose another --out");
}

bool lies_within(const std::string& path, const std::string& dir) {
  std::error_code ec;
  const fs::path d = fs::weakly_canonical(dir, ec), p = fs::weakly_canonical(path, ec);
  return !d.empty() && std::mismatch(d.begin(), d.end(), p.begin(), p.end()).first == d.end();
}

void check_output_spares(const std::string& dir, const std::string& input,
                         const std::string& what) {
  if (lies_within(input, dir))
    throw InvalidInput("--out " + dir + " would replace " + what + " " + input +
                       ": choose another --out");
}

void check_not_input(const std::string& out, const std::string& option, const std::string& in) {
  std::error_code ec;  // hard links are the same file too
  if (fs::equivalent(out, in, ec) || lies_within(out, in))
    throw InvalidInput(option + " " + out + " is the input " + in +
                       ", which would be overwritten: choose another output");
}

void publish_directory(const std::string& staging, const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir)) {
    check_output_directory(dir);
    fs::remove_all(dir, ec);
    if (ec) throw IoError(dir + ": cannot replace output directory: " + ec.message());
  }
  fs::rename(staging, dir, ec);
  if (ec) throw IoError(dir + ": cannot move finished output into place: " + ec.message());
}

std::string begin_staging(const std::string& dir) {
  check_output_directory(dir);
  const std::filesystem::path staging = dir + ".partial";
  std::error_code ec;
  std::filesystem::remove_all(staging, ec);
  std::filesystem::create_directories(staging, ec);
  if (ec) throw IoError(staging.string() + ": cannot create directory: " + ec.message());
  return staging.string();
}

void write_staged(const std::string& dir, const std::function<void(const std::string&)>& write) {
  const std::string staging = begin_staging(dir);
  try {
    write(staging);
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove_all(staging, ec);
    throw;
  }
  publish_directory(staging, dir);
}

}  // namespace clumpkit
