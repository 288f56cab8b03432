// The job of `clumpkit page`: a static HTML page that a person browses, offline, for clumpkit
// output folders — a library or shape set, a specimen, an element test or CPT (several side by
// side), a crushing run — read from each folder's manifest.json.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace clumpkit {

struct PageOptions {
  std::vector<std::filesystem::path> dirs;  ///< output folders; several: tests of one kind
  std::filesystem::path out;                ///< where index.html goes; empty: the one folder
  /// A specimen's spheres beyond this are decimated for the view (every k-th drawn, the full
  /// count stated).
  std::size_t max_spheres = 400000;
};

struct PageResult {
  std::filesystem::path index;  ///< the page's index.html
  std::string kind;             ///< library, specimen, test or crush
  std::size_t items = 0;        ///< particles, spheres, curve rows or crushed particles shown
};

/// Reads every folder before writing anything: a folder without manifest.json, a damaged JSON or
/// CSV, a command without a page (cells, export, import) or a mix of folders is refused with one
/// line (InvalidInput or IoError naming the file), and nothing is written. Then writes
/// OUT/index.html and OUT/page/ (io/reports/page_files.h).
PageResult write_page(const PageOptions& options);

}  // namespace clumpkit
