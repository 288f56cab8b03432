#include "geom/version.h"

#include <CGAL/version_macros.h>
#include <embree3/rtcore_config.h>
#include <oneapi/tbb/version.h>
#include <openvdb/version.h>
#include <Eigen/Core>
#include <opencv2/core/version.hpp>

// Written at every build by cmake/commit.cmake (only when the commit changes).
extern "C" const char* clumpkit_build_commit();

namespace clumpkit {

#define CLUMPKIT_STR2(x) #x
#define CLUMPKIT_STR(x) CLUMPKIT_STR2(x)

const char* version() {
  return CLUMPKIT_VERSION;
}

const char* commit() {
  return clumpkit_build_commit();
}

std::vector<std::pair<std::string, std::string>> library_versions() {
  return {{"CGAL", CGAL_VERSION_STR},
          {"OpenVDB", OPENVDB_LIBRARY_VERSION_STRING},
          {"Embree", RTC_VERSION_STRING},
          {"Eigen", CLUMPKIT_STR(EIGEN_WORLD_VERSION) "." CLUMPKIT_STR(
                        EIGEN_MAJOR_VERSION) "." CLUMPKIT_STR(EIGEN_MINOR_VERSION)},
          {"OpenCV", CV_VERSION},
          {"oneTBB", TBB_VERSION_STRING}};
}

std::string version_text() {
  std::string t = std::string("clumpkit ") + version() + " (commit " + commit() + ")\n";
  for (const auto& [name, v] : library_versions()) t += "  " + name + " " + v + "\n";
  return t;
}

}  // namespace clumpkit
