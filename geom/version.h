// What this build of clumpkit is: its version, the commit it was built from and the versions of
// the libraries it was compiled against (`clumpkit --version`, the Python module, manifests).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace clumpkit {

/// The release version, "MAJOR.MINOR.PATCH" (CMake's project version).
const char* version();

/// The git commit the sources were at when built ("abc1234", "abc1234-dirty" with uncommitted
/// changes, or "unknown" outside a git clone).
const char* commit();

/// The libraries compiled in, with their versions as their headers declare them: CGAL, OpenVDB,
/// Embree, Eigen, OpenCV, oneTBB.
std::vector<std::pair<std::string, std::string>> library_versions();

/// The text of `clumpkit --version`: "clumpkit VERSION (commit COMMIT)" and one line per library.
std::string version_text();

}  // namespace clumpkit
