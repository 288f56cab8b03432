// Shared by the mesh reading tests (mesh_io_test.cpp, mesh_exports_test.cpp): a cube, the
// expected-error check and a fixture with a scratch directory of its own.
#pragma once

#include "geom/errors.h"
#include "io/formats/mesh_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace clumpkit::mesh_test {

namespace fs = std::filesystem;

// Axis-aligned box, outward triangles; vertex i has corner bits x = i&1, y = i&2, z = i&4.
inline Mesh cube(const Vec3& lo = Vec3(0.1, -0.3, 1.0 / 3.0),
                 const Vec3& hi = Vec3(1.7, 0.9, 2.2)) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                            i & 4 ? hi.z() : lo.z());
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

inline double cube_volume() {
  return 1.6 * 1.2 * (2.2 - 1.0 / 3.0);
}

inline bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// Runs f, expects exception E whose message contains every part.
template <class E>
void expect_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    ADD_FAILURE() << "expected an exception mentioning " << parts.front();
  } catch (const E& e) {
    for (const auto& p : parts)
      EXPECT_TRUE(contains(e.what(), p)) << "message: " << e.what() << "\nmissing: " << p;
  }
}

class MeshIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("clumpkit_mesh_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }

  std::string slurp(const std::string& p) const {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }

  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

}  // namespace clumpkit::mesh_test
