#include "io/formats/mesh_io.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/shapes/primitives.h"
#include "io/base/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

namespace clumpkit {
namespace {

namespace fs = std::filesystem;

// Axis-aligned box, outward triangles; vertex i has corner bits x = i&1, y = i&2, z = i&4.
Mesh cube(const Vec3& lo = Vec3(0.1, -0.3, 1.0 / 3.0), const Vec3& hi = Vec3(1.7, 0.9, 2.2)) {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                            i & 4 ? hi.z() : lo.z());
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

double cube_volume() {
  return 1.6 * 1.2 * (2.2 - 1.0 / 3.0);
}

// Octahedron with semi-axes 0.7, 1.3, 0.45 (volume 4/3 * product), rotated and shifted so that
// no coordinate is a short decimal or a float.
Mesh octahedron() {
  const Vec3 r(0.7, 1.3, 0.45);
  Mesh m;
  for (int k = 0; k < 3; ++k)
    for (double s : {1.0, -1.0}) m.vertices.push_back(s * r[k] * Vec3::Unit(k));
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const int x = sx, y = 2 + sy, z = 4 + sz;  // vertex indices of the chosen octant
        if ((sx + sy + sz) % 2 == 0)
          m.triangles.push_back({x, y, z});
        else
          m.triangles.push_back({x, z, y});
      }
  const Mat3 rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  transform(m, rot, Vec3(0.25, -1.0 / 7.0, 0.6));
  return m;
}

double octahedron_volume() {
  return 4.0 / 3.0 * 0.7 * 1.3 * 0.45;
}

bool contains(const std::string& s, const std::string& part) {
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

TEST(MeshFormatFromPath, ExtensionsAreCaseInsensitive) {
  EXPECT_EQ(mesh_format_from_path("/a/b.stl"), MeshFormat::Stl);
  EXPECT_EQ(mesh_format_from_path("B.STL"), MeshFormat::Stl);
  EXPECT_EQ(mesh_format_from_path("x.Obj"), MeshFormat::Obj);
  EXPECT_EQ(mesh_format_from_path("dir.v2/x.PLY"), MeshFormat::Ply);
  expect_error<InvalidInput>([] { mesh_format_from_path("/x/shape.off"); },
                             {"/x/shape.off", ".off"});
  expect_error<InvalidInput>([] { mesh_format_from_path("/x/shape"); }, {"/x/shape", "extension"});
}

TEST_F(MeshIoTest, ObjAndPlyRoundTripsAreExact) {
  for (const Mesh& m : {cube(), octahedron()}) {
    for (const char* name : {"m.obj", "m.ply"}) {
      write_mesh(path(name), m);
      MeshReadReport report;
      report.reoriented = true;
      const Mesh r = read_mesh(path(name), &report);
      EXPECT_FALSE(report.reoriented) << name;
      ASSERT_EQ(r.vertices.size(), m.vertices.size()) << name;
      for (size_t i = 0; i < m.vertices.size(); ++i)
        EXPECT_EQ(r.vertices[i], m.vertices[i]) << name << " vertex " << i;
      EXPECT_EQ(r.triangles, m.triangles) << name;
      EXPECT_EQ(signed_volume(r), signed_volume(m)) << name;
    }
  }
  EXPECT_NEAR(signed_volume(cube()), cube_volume(), 1e-12);
  EXPECT_NEAR(signed_volume(octahedron()), octahedron_volume(), 1e-12);
}

TEST_F(MeshIoTest, StlRoundTripsKeepFloatPrecision) {
  // The ellipsoid's 1,280 triangles span more than one of the binary writer's 1,024-record blocks.
  for (const Mesh& m : {cube(), octahedron(), make_ellipsoid(Vec3(2.0, 1.0, 0.5), 3)}) {
    for (MeshFormat format : {MeshFormat::Stl, MeshFormat::StlAscii}) {
      const bool binary = format == MeshFormat::Stl;
      write_mesh(path("m.stl"), m, format);
      EXPECT_EQ(slurp(path("m.stl")).size() == 84 + 50 * m.triangles.size(), binary);
      const Mesh r = read_mesh(path("m.stl"));
      // Welding restores the shared vertices; triangle order and corner order are kept.
      EXPECT_EQ(r.vertices.size(), m.vertices.size());
      ASSERT_EQ(r.triangles.size(), m.triangles.size());
      for (size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
          const Vec3& p = m.vertices[m.triangles[t][k]];
          const Vec3& q = r.vertices[r.triangles[t][k]];
          if (binary)  // float32 storage: exactly the rounded value
            EXPECT_EQ(q, p.cast<float>().cast<double>());
          else  // %.9g: nine significant digits
            EXPECT_LE((q - p).cwiseAbs().maxCoeff(), 1e-8 * p.cwiseAbs().maxCoeff());
        }
      EXPECT_NEAR(signed_volume(r), signed_volume(m), 1e-6 * signed_volume(m));
    }
  }
}

TEST_F(MeshIoTest, AsciiStlStartingWithSolidReads) {
  write_mesh(path("a.stl"), cube(), MeshFormat::StlAscii);
  EXPECT_EQ(slurp(path("a.stl")).rfind("solid", 0), 0u);
  // Hand-written: CRLF line ends, odd spacing, a named solid, zero normals, '+' signs.
  const std::string text =
      "solid my part\r\n"
      " facet normal 0 0 0\r\n  outer loop\r\n   vertex 0 0 0\r\n   vertex 0 1 0\r\n"
      "   vertex 1 0 0\r\n  endloop\r\n endfacet\r\n"
      " facet normal 0 0 0\r\n  outer loop\r\n   vertex 0 0 0\r\n   vertex 1 0 0\r\n"
      "   vertex 0 0 1\r\n  endloop\r\n endfacet\r\n"
      " facet normal 0 0 0\r\n  outer loop\r\n   vertex 0 0 0\r\n   vertex 0 0 1\r\n"
      "   vertex 0 1 0\r\n  endloop\r\n endfacet\r\n"
      "facet normal 0 0 0\n outer loop\n\tvertex +1.0e0 0 0\n vertex 0 1 0\n vertex 0 0 1\n"
      " endloop\nendfacet\nendsolid my part\r\n";
  MeshReadReport report;
  const Mesh m = read_mesh(write("tet.stl", text), &report);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.triangles.size(), 4u);
  EXPECT_DOUBLE_EQ(signed_volume(m), 1.0 / 6.0);
  EXPECT_FALSE(report.reoriented);
}

TEST_F(MeshIoTest, BinaryStlWhoseHeaderStartsWithSolidReads) {
  write_mesh(path("b.stl"), cube());
  std::string bytes = slurp(path("b.stl"));
  const std::string header = "solid exported by a CAD program that ignores the STL convention";
  bytes.replace(0, 80, header + std::string(80 - header.size(), ' '));
  const Mesh m = read_mesh(write("solid.stl", bytes));
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(m), cube_volume(), 1e-6);
}

TEST_F(MeshIoTest, ObjPolygonsNegativeIndicesAndSlashSyntax) {
  const std::string text =
      "# unit cube as quads\nmtllib none.mtl\no cube\n"
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
      "vt 0 0\nvn 0 0 1\ns off\n"
      "f -8/1/1 -6/1/1 -5/1/1 -7/1/1\n"  // bottom, relative indices
      "f 5//1 6//1 8//1 7//1\n"          // top, v//vn
      "f 1/1 2/1 6/1 5/1\n"              // front, v/vt
      "f 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
  MeshReadReport report;
  const Mesh m = read_mesh(write("quads.obj", text), &report);
  EXPECT_EQ(m.vertices.size(), 8u);
  ASSERT_EQ(m.triangles.size(), 12u);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 2, 3}));  // fan from the first corner
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 3, 1}));
  EXPECT_EQ(signed_volume(m), 1.0);
  EXPECT_FALSE(report.reoriented);
}

TEST_F(MeshIoTest, AsciiPlySkipsOtherPropertiesAndElements) {
  std::string text =
      "ply\r\nformat ascii 1.0\ncomment made by hand\n"
      "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty uchar red\n"
      "element face 6\nproperty list uchar int vertex_indices\nproperty uchar flags\n"
      "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  for (int i = 0; i < 8; ++i)
    text += std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " +
            std::to_string((i >> 2) & 1) + " 0.5 255\n";
  text += "4 0 2 3 1 7\n4 4 5 7 6 7\n4 0 1 5 4 7\n4 2 6 7 3 7\n4 0 4 6 2 7\n4 1 3 7 5 7\n0 1\n";
  const Mesh m = read_mesh(write("cube.ply", text));
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.vertices[7], Vec3(1, 1, 1));
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_EQ(signed_volume(m), 1.0);
}

TEST_F(MeshIoTest, BinaryPlyWithFloatVerticesAndUintIndices) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\n"
      "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
      "property short quality\n"
      "element face 6\nproperty list uchar uint vertex_indices\nend_header\n";
  auto put = [&](auto v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); };
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) put(float((i >> k) & 1) * 2.5f);
    put(short(-3));
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    put(uint8_t(4));
    for (int v : q) put(uint32_t(v));
  }
  const Mesh m = read_mesh(write("float.ply", bytes));
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_EQ(signed_volume(m), 2.5 * 2.5 * 2.5);
}

TEST_F(MeshIoTest, InwardAndPartlyFlippedCubesAreReoriented) {
  Mesh inward = cube();
  flip_orientation(inward);
  Mesh one_flipped = cube();
  std::swap(one_flipped.triangles[5][1], one_flipped.triangles[5][2]);
  for (const char* name : {"m.obj", "m.stl", "m.ply"}) {
    for (const Mesh* m : {&inward, &one_flipped}) {
      write_mesh(path(name), *m);
      MeshReadReport report;
      const Mesh r = read_mesh(path(name), &report);
      EXPECT_TRUE(report.reoriented) << name;
      EXPECT_TRUE(check_mesh(r).oriented) << name;
      EXPECT_NEAR(signed_volume(r), cube_volume(), 1e-6) << name;
    }
  }
}

TEST_F(MeshIoTest, OpenMeshIsRejectedButReadRaw) {
  Mesh open = cube();
  open.triangles.resize(10);  // drop the +x face
  write_mesh(path("open.obj"), open);
  expect_error<InvalidInput>([&] { read_mesh(path("open.obj")); },
                             {path("open.obj") + ": mesh is open: 4 boundary edges", "--allow-open",
                              "clumpkit repair " + path("open.obj")});
  const Mesh raw = read_mesh_raw(path("open.obj"));
  EXPECT_EQ(raw.triangles, open.triangles);
}

TEST_F(MeshIoTest, MissingAndEmptyFiles) {
  expect_error<IoError>([&] { read_mesh(path("nope.stl")); }, {path("nope.stl"), "not found"});
  expect_error<IoError>([&] { read_mesh_raw(path("nope.obj")); }, {path("nope.obj")});
  for (const char* name : {"e.stl", "e.obj", "e.ply"})
    expect_error<InvalidInput>([&] { read_mesh(write(name, "")); },
                               {path(name) + ": file is empty"});
}

TEST_F(MeshIoTest, TruncatedBinaryStlSaysExpectedAndActualBytes) {
  write_mesh(path("c.stl"), cube());
  std::string bytes = slurp(path("c.stl"));
  ASSERT_EQ(bytes.size(), 684u);
  write("t.stl", bytes.substr(0, 500));
  expect_error<InvalidInput>([&] { read_mesh(path("t.stl")); },
                             {path("t.stl") + ": truncated binary STL: header says 12 triangles "
                                              "(684 bytes) but the file has 500 bytes"});
  // Also when the header begins with "solid", which must not send it to the ASCII parser.
  bytes.replace(0, 5, "solid");
  write("ts.stl", bytes.substr(0, 600));
  expect_error<InvalidInput>([&] { read_mesh(path("ts.stl")); },
                             {path("ts.stl"), "truncated binary STL", "600 bytes"});
  write("tiny.stl", bytes.substr(0, 40));
  expect_error<InvalidInput>([&] { read_mesh(path("tiny.stl")); },
                             {path("tiny.stl"), "truncated binary STL", "40 bytes"});
}

TEST_F(MeshIoTest, TruncatedBinaryPly) {
  write_mesh(path("c.ply"), cube());
  const std::string bytes = slurp(path("c.ply"));
  write("t.ply", bytes.substr(0, bytes.size() - 5));
  expect_error<InvalidInput>([&] { read_mesh(path("t.ply")); },
                             {path("t.ply"), "truncated binary PLY", "element 'face' 11 of 12"});
}

TEST_F(MeshIoTest, UnparsableNumbersNameLineAndToken) {
  write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1.2.3 0\nf 1 2 3\n");
  expect_error<InvalidInput>([&] { read_mesh(path("n.obj")); },
                             {path("n.obj") + ": line 3: cannot parse '1.2.3' as a number"});
  write("n.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 O 0\n");
  expect_error<InvalidInput>([&] { read_mesh(path("n.stl")); },
                             {path("n.stl") + ": line 5: cannot parse 'O' as a number"});
  write("n.ply",
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
        "property double z\nend_header\n0 1,5 0\n");
  expect_error<InvalidInput>([&] { read_mesh(path("n.ply")); },
                             {path("n.ply") + ": line 8: cannot parse '1,5' as a number"});
  write("i.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x3\n");
  expect_error<InvalidInput>([&] { read_mesh(path("i.obj")); }, {path("i.obj"), "line 4", "'x3'"});
}

TEST_F(MeshIoTest, IndexOutOfRange) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (const char* face : {"f 1 2 4\n", "f 1 2 0\n", "f -1 -2 -4\n"}) {
    write("r.obj", v + face);
    expect_error<InvalidInput>([&] { read_mesh(path("r.obj")); },
                               {path("r.obj") + ": line 4: vertex index", "out of range"});
  }
  write("r.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expect_error<InvalidInput>(
      [&] { read_mesh(path("r.ply")); },
      {path("r.ply") + ": face 0: vertex index 3 out of range (3 vertices)"});
}

TEST_F(MeshIoTest, NoTriangles) {
  write("v.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_error<InvalidInput>([&] { read_mesh(path("v.obj")); },
                             {path("v.obj") + ": mesh has no triangles"});
  write("v.stl", "solid nothing\nendsolid nothing\n");
  expect_error<InvalidInput>([&] { read_mesh(path("v.stl")); },
                             {path("v.stl") + ": mesh has no triangles"});
}

TEST_F(MeshIoTest, NonManifoldEdgeIsCounted) {
  // Two tetrahedra sharing the edge 0-1: four triangles meet there.
  Mesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0),  Vec3(0, 1, 0),
                Vec3(0, 0, 1), Vec3(0, -1, 0), Vec3(0, 0, -1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                 {0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}};
  write_mesh(path("nm.obj"), m);
  expect_error<InvalidInput>(
      [&] { read_mesh(path("nm.obj")); },
      {path("nm.obj") + ": mesh is not manifold: 1 edge shared by more than two triangles"});
}

TEST_F(MeshIoTest, DegenerateTrianglesAreRemovedWhereTheMeshStaysClosedElseRejected) {
  Mesh repeated = cube();
  repeated.triangles.push_back({0, 1, 0});  // a repeated corner: dropped on reading
  write_mesh(path("r.ply"), repeated);
  MeshReadReport report;
  const Mesh read = read_mesh(path("r.ply"), &report);
  EXPECT_EQ(read.triangles.size(), 12u);
  EXPECT_EQ(report.removed_triangles, 1u);
  EXPECT_NEAR(signed_volume(read), cube_volume(), 1e-12);
  Mesh sliver = cube();
  sliver.vertices.push_back(0.5 * (sliver.vertices[0] + sliver.vertices[1]));
  sliver.triangles.push_back({0, 1, 8});  // collinear corners on a used edge: not manifold
  write_mesh(path("d.ply"), sliver);
  expect_error<InvalidInput>([&] { read_mesh(path("d.ply")); },
                             {path("d.ply") + ": mesh has a degenerate triangle"});
}

TEST_F(MeshIoTest, FlatClosedMeshHasNoVolume) {
  Mesh flat;  // a tetrahedron squashed into the plane z = 0
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  flat.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  write_mesh(path("flat.obj"), flat);
  expect_error<InvalidInput>([&] { read_mesh(path("flat.obj")); },
                             {path("flat.obj") + ": mesh encloses no volume"});
}

TEST_F(MeshIoTest, NonFiniteCoordinatesAreRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Mesh m = cube();
  m.vertices[3].y() = nan;
  write_mesh(path("nan.ply"), m);
  write_mesh(path("nan.stl"), m);
  m.vertices[3].y() = inf;
  write_mesh(path("inf.obj"), m);
  write_mesh(path("inf.stl"), m, MeshFormat::StlAscii);
  m.vertices[3].y() = 1e300;  // finite, but its cube overflows in the volume
  write_mesh(path("huge.ply"), m);
  for (const char* name : {"nan.ply", "nan.stl", "inf.obj", "inf.stl", "huge.ply"})
    expect_error<InvalidInput>([&] { read_mesh(path(name)); },
                               {path(name) + ": vertex", "not finite or beyond 1e30"});
}

TEST_F(MeshIoTest, UnsupportedPlyFormat) {
  write("me.ply", "ply\nformat binary_middle_endian 1.0\nelement vertex 0\nend_header\n");
  expect_error<InvalidInput>([&] { read_mesh(path("me.ply")); },
                             {path("me.ply"), "binary_middle_endian"});
  write("not.ply", "solid\n");
  expect_error<InvalidInput>([&] { read_mesh(path("not.ply")); }, {path("not.ply"), "not a PLY"});
}

TEST_F(MeshIoTest, WritesLeaveNoTemporaryOrPartialFiles) {
  write_mesh(path("a.stl"), cube());
  write_mesh(path("a.obj"), cube());
  write_mesh(path("a.ply"), cube());
  write_mesh(path("a.stl"), octahedron(), MeshFormat::StlAscii);  // replaces the binary file
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.obj", "a.ply", "a.stl"}));
  EXPECT_EQ(read_mesh(path("a.stl")).triangles.size(), 8u);

  // A failing writer leaves the old file untouched and no temporary behind.
  const std::string before = slurp(path("a.obj"));
  EXPECT_THROW(write_file_atomically(path("a.obj"),
                                     [](std::ostream& os) {
                                       os << "partial";
                                       throw std::runtime_error("boom");
                                     }),
               std::runtime_error);
  EXPECT_EQ(slurp(path("a.obj")), before);
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.obj", "a.ply", "a.stl"}));

  const std::string missing_dir = path("no/such/dir/x.stl");
  expect_error<IoError>([&] { write_mesh(missing_dir, cube()); }, {missing_dir});
  expect_error<InvalidInput>([&] { write_mesh(path("x.off"), cube()); }, {path("x.off")});
  Mesh bad = cube();
  bad.triangles[0][0] = 8;
  expect_error<InvalidInput>([&] { write_mesh(path("bad.obj"), bad); },
                             {path("bad.obj"), "out of range"});
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.obj", "a.ply", "a.stl"}));
}

// ---- Meshes as exporters write them (issue: weld on read, complete parsers) ----

// The six faces of the unit cube, each as four corners counter-clockwise seen from outside, and
// its outward normal.
struct CubeFace {
  std::array<Vec3, 4> corner;
  Vec3 normal;
};
std::vector<CubeFace> cube_faces() {
  std::vector<CubeFace> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      CubeFace f;
      f.normal = (side ? 1.0 : -1.0) * Vec3::Unit(axis);
      const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k) {
        Vec3 p = Vec3::Zero();
        p[axis] = side;
        p[u] = uv[side ? k : 3 - k][0];
        p[w] = uv[side ? k : 3 - k][1];
        f.corner[k] = p;
      }
      faces.push_back(f);
    }
  return faces;
}

// The cube as STL: each quad as the fan (0 1 2), (0 2 3), the order every reader triangulates.
Mesh cube_soup() {
  Mesh m;
  for (const CubeFace& f : cube_faces()) {
    const int n = static_cast<int>(m.vertices.size());
    for (const Vec3& c : f.corner) m.vertices.push_back(c);
    m.triangles.push_back({n, n + 1, n + 2});
    m.triangles.push_back({n, n + 2, n + 3});
  }
  return m;
}

std::string number(double v) {
  return format_number(v);
}

// An ASCII or binary PLY of the cube with 24 vertices (position, normal, UV, colour) and quads
// carrying a texcoord list and colours after the indices, as MeshLab writes them.
std::string cube_ply(const std::string& format) {
  const std::vector<CubeFace> faces = cube_faces();
  std::string s = "ply\nformat " + format +
                  " 1.0\ncomment VCGLIB generated\ncomment TextureFile t.png\n"
                  "element vertex 24\nproperty float x\nproperty float y\nproperty float z\n"
                  "property float nx\nproperty float ny\nproperty float nz\n"
                  "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                  "property float s\nproperty float t\n"
                  "element face 6\nproperty list uchar int vertex_indices\n"
                  "property list uchar float texcoord\nproperty uchar red\nproperty uchar green\n"
                  "property uchar blue\nproperty uchar alpha\nend_header\n";
  const bool ascii = format == "ascii", big = format == "binary_big_endian";
  const auto put = [&](auto v) {
    char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    if (big) std::reverse(b, b + sizeof v);
    s.append(b, sizeof v);
  };
  for (const CubeFace& f : faces)
    for (int k = 0; k < 4; ++k) {
      if (ascii) {
        for (int a = 0; a < 3; ++a) s += number(f.corner[k][a]) + " ";
        for (int a = 0; a < 3; ++a) s += number(f.normal[a]) + " ";
        s += "200 100 50 " + number(k & 1) + " " + number(k >> 1) + "\n";
      } else {
        for (int a = 0; a < 3; ++a) put(float(f.corner[k][a]));
        for (int a = 0; a < 3; ++a) put(float(f.normal[a]));
        for (unsigned char c : {200, 100, 50}) put(c);
        put(float(k & 1)), put(float(k >> 1));
      }
    }
  for (int f = 0; f < 6; ++f) {
    if (ascii) {
      s += "4";
      for (int k = 0; k < 4; ++k) s += " " + std::to_string(4 * f + k);
      s += " 8 0 0 1 0 1 1 0 1 255 255 255 255\n";
    } else {
      put(static_cast<unsigned char>(4));
      for (int k = 0; k < 4; ++k) put(std::int32_t(4 * f + k));
      put(static_cast<unsigned char>(8));
      for (float t : {0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f, 1.f}) put(t);
      for (int c = 0; c < 4; ++c) put(static_cast<unsigned char>(255));
    }
  }
  return s;
}

// The cube as a textured OBJ: 24 positions (one per face corner), per-face normals, UVs,
// `o`, `g`, `usemtl`, `mtllib`, negative indices and a continued face line.
std::string cube_obj() {
  std::string s = "mtllib cube.mtl\no Cube\n";
  const std::vector<CubeFace> faces = cube_faces();
  for (const CubeFace& f : faces)
    for (const Vec3& c : f.corner)
      s += "v " + number(c.x()) + " " + number(c.y()) + " " + number(c.z()) + "\n";
  s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  for (const CubeFace& f : faces)
    s += "vn " + number(f.normal.x()) + " " + number(f.normal.y()) + " " + number(f.normal.z()) +
         "\n";
  s += "g side\nusemtl stone\ns off\n";
  for (int f = 0; f < 6; ++f) {
    s += "f";
    for (int k = 0; k < 4; ++k) {
      // Faces 0-2 by absolute indices v/vt/vn, 3-5 by negative ones v//vn; face 4 continued.
      const int v = 4 * f + k + 1;
      s += f < 3
               ? " " + std::to_string(v) + "/" + std::to_string(k + 1) + "/" + std::to_string(f + 1)
               : " " + std::to_string(v - 25) + "//" + std::to_string(f + 1);
      if (f == 4 && k == 1) s += " \\\n ";
    }
    s += "\n";
  }
  return s;
}

// MeshLab's triangle soup: three fresh vertices per triangle.
std::string cube_soup_obj() {
  const Mesh m = cube_soup();
  std::string s;
  for (const auto& t : m.triangles)
    for (int v : t)
      s += "v " + number(m.vertices[v].x()) + " " + number(m.vertices[v].y()) + " " +
           number(m.vertices[v].z()) + "\n";
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    s += "f " + std::to_string(3 * t + 1) + " " + std::to_string(3 * t + 2) + " " +
         std::to_string(3 * t + 3) + "\n";
  return s;
}

TEST_F(MeshIoTest, SeamSplitCubesInEveryFormatReadAsTheStlCubeVertexForVertex) {
  write_mesh(path("cube.stl"), cube_soup());
  MeshReadReport stl_report;
  const Mesh stl = read_mesh(path("cube.stl"), &stl_report);
  ASSERT_EQ(stl.vertices.size(), 8u);
  EXPECT_NEAR(signed_volume(stl), 1.0, 1e-12);
  EXPECT_EQ(stl_report.merged_vertices, 0u);  // STL corners are never shared: not counted
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"ascii.ply", cube_ply("ascii")},
           {"le.ply", cube_ply("binary_little_endian")},
           {"be.ply", cube_ply("binary_big_endian")},
           {"textured.obj", cube_obj()},
           {"soup.obj", cube_soup_obj()}}) {
    write(name, bytes);
    MeshReadReport report;
    const Mesh m = read_mesh(path(name), &report);
    EXPECT_NEAR(signed_volume(m), 1.0, 1e-12) << name;
    EXPECT_EQ(m.vertices, stl.vertices) << name;  // so every command gives the same bytes
    EXPECT_EQ(m.triangles, stl.triangles) << name;
    EXPECT_EQ(report.merged_vertices, name == "soup.obj" ? 28u : 16u) << name;
    EXPECT_FALSE(report.reoriented) << name;
    EXPECT_EQ(mesh_read_notes(path(name), report).size(), 1u) << name;  // the merge
  }
}

TEST_F(MeshIoTest, AsciiPlyWithTexcoordListsAndColoursEqualsItsBinaryTwins) {
  write("a.ply", cube_ply("ascii"));
  write("b.ply", cube_ply("binary_little_endian"));
  write("c.ply", cube_ply("binary_big_endian"));
  const Mesh a = read_mesh_raw(path("a.ply"), {}, nullptr);
  for (const char* twin : {"b.ply", "c.ply"}) {
    const Mesh b = read_mesh_raw(path(twin));
    EXPECT_EQ(a.vertices, b.vertices) << twin;
    EXPECT_EQ(a.triangles, b.triangles) << twin;
  }
  // A list longer than the file is refused by name, not read past the end.
  std::string truncated = cube_ply("binary_big_endian");
  truncated.resize(truncated.size() - 20);
  write("t.ply", truncated);
  expect_error<InvalidInput>([&] { read_mesh_raw(path("t.ply")); },
                             {path("t.ply"), "truncated binary PLY", "'face' 5 of 6"});
}

TEST_F(MeshIoTest, WeldToleranceMergesSeamCopiesThatDifferInTheLastDigits) {
  std::string obj = cube_obj();
  // Every coordinate 1 of face 2's corners written as 1.0000000000001: a seam of a sloppy export.
  std::string nudged;
  std::istringstream lines(obj);
  std::string line;
  int v = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("v ", 0) == 0 && v++ / 4 == 2) {
      std::string out;
      std::istringstream parts(line);
      std::string part;
      while (parts >> part)
        out += (out.empty() ? "" : " ") + (part == "1" ? "1.0000000000001" : part);
      line = out;
    }
    nudged += line + "\n";
  }
  write("nudged.obj", nudged);
  expect_error<InvalidInput>([&] { read_mesh(path("nudged.obj")); },
                             {path("nudged.obj"), "mesh is open"});
  MeshReadOptions weld;
  weld.weld_tolerance = 1e-9;
  const Mesh m = read_mesh(path("nudged.obj"), nullptr, weld);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_NEAR(signed_volume(m), 1.0, 1e-12);
  weld.weld_tolerance = -1;
  expect_error<InvalidInput>([&] { read_mesh(path("nudged.obj"), nullptr, weld); },
                             {path("nudged.obj"), "weld tolerance"});
}

TEST_F(MeshIoTest, UvSphereWithSplitPolesReadsAsItsTessellation) {
  // A UV sphere as exporters write it: the pole repeated once per segment (its own UV), the
  // pole rows as quads whose two pole corners coincide, so half their triangles have no area.
  const int rings = 8, segments = 12;
  std::vector<Vec3> ring_points;
  auto at = [&](int r, int s) {
    const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
    return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  std::string obj;
  std::vector<std::vector<int>> id(rings + 1, std::vector<int>(segments + 1));
  int n = 0;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {  // the seam column s = segments repeats s = 0
      const Vec3 p = r == 0 ? Vec3(0, 0, 1) : r == rings ? Vec3(0, 0, -1) : at(r, s % segments);
      obj += "v " + number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + "\n";
      id[r][s] = ++n;
    }
  Mesh ideal;  // the same surface with one vertex per pole and triangles at the poles
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const int a = id[r][s], b = id[r + 1][s], c = id[r + 1][s + 1], d = id[r][s + 1];
      obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " +
             std::to_string(d) + "\n";
      const Vec3 pa = r == 0 ? Vec3(0, 0, 1) : at(r, s), pd = r == 0 ? pa : at(r, s + 1);
      const Vec3 pb = r + 1 == rings ? Vec3(0, 0, -1) : at(r + 1, s);
      const Vec3 pc = r + 1 == rings ? pb : at(r + 1, s + 1);
      const int k = static_cast<int>(ideal.vertices.size());
      ideal.vertices.insert(ideal.vertices.end(), {pa, pb, pc, pd});
      if (r + 1 < rings) ideal.triangles.push_back({k, k + 1, k + 2});  // b = c at the south
      if (r > 0) ideal.triangles.push_back({k, k + 2, k + 3});          // a = d at the north
    }
  write("uv.obj", obj);
  MeshReadReport report;
  const Mesh m = read_mesh(path("uv.obj"), &report);
  EXPECT_NEAR(signed_volume(m), signed_volume(ideal), 1e-12);
  EXPECT_EQ(m.vertices.size(), std::size_t((rings - 1) * segments + 2));
  EXPECT_EQ(report.removed_triangles, std::size_t(2 * segments));
  EXPECT_GT(report.merged_vertices, 0u);
}

TEST_F(MeshIoTest, ZeroAreaTriangleWithDistinctCornersIsCollapsedAndTheCubeStaysClosed) {
  // The unit cube with a vertex m in the middle of the edge c0 c1 that only one face splits at,
  // and the zero-area triangle (c1, m, c0) that closes the seam.
  Mesh m = cube(Vec3::Zero(), Vec3::Ones());
  // Triangle {0, 3, 1} of the cube's bottom uses the edge 1 -> 0; face {0, 1, 5} uses 0 -> 1.
  m.vertices.push_back(0.5 * (m.vertices[0] + m.vertices[1]));  // index 8
  for (auto& t : m.triangles)
    if (t == std::array<int, 3>{0, 1, 5}) t = {0, 8, 5};
  m.triangles.push_back({8, 1, 5});
  m.triangles.push_back({1, 8, 0});  // zero area: edges 1 -> 8, 8 -> 0, 0 -> 1
  ASSERT_TRUE(check_mesh(m).closed || check_mesh(m).boundary_edges == 0);
  write_mesh(path("needle.obj"), m);
  MeshReadReport report;
  const Mesh read = read_mesh(path("needle.obj"), &report);
  EXPECT_NEAR(signed_volume(read), 1.0, 1e-12);
  EXPECT_GE(report.removed_triangles, 1u);
  EXPECT_FALSE(check_mesh(read).degenerate);
}

TEST_F(MeshIoTest, NonConvexPolygonsAreEarClipped) {
  // An L-shaped prism (three unit squares, height 1) with its L faces as single hexagons: a fan
  // from the reflex corner would cover the notch and give the wrong volume.
  const std::vector<Eigen::Vector2d> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::string obj;
  for (double z : {0.0, 1.0})
    for (const auto& p : l)
      obj += "v " + number(p.x()) + " " + number(p.y()) + " " + number(z) + "\n";
  // Start both caps at the reflex corner (index 3) so a fan would fail.
  obj += "f 4 3 2 1 6 5\n";     // bottom, clockwise from above = outward (down)
  obj += "f 10 11 12 7 8 9\n";  // top, counter-clockwise from above
  for (int k = 0; k < 6; ++k) {
    const int a = k + 1, b = (k + 1) % 6 + 1;
    obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(b + 6) + " " +
           std::to_string(a + 6) + "\n";
  }
  write("l.obj", obj);
  const Mesh m = read_mesh(path("l.obj"));
  EXPECT_NEAR(signed_volume(m), 3.0, 1e-12);
  EXPECT_EQ(m.triangles.size(), 4u + 4u + 12u);
}

// Two meshes as the shells of one file.
Mesh shells(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const int n = static_cast<int>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) m.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  return m;
}

TEST_F(MeshIoTest, SeveralShellsAreOneSolidByOrientationAndCrossingShellsAreRefused) {
  const Mesh unit = cube(Vec3::Zero(), Vec3::Ones());
  // Two disjoint cubes: volume 2.
  write_mesh(path("two.obj"), shells(unit, cube(Vec3(3, 0, 0), Vec3(4, 1, 1))));
  MeshReadReport report;
  EXPECT_NEAR(signed_volume(read_mesh(path("two.obj"), &report)), 2.0, 1e-12);
  EXPECT_EQ(report.shells, 2u);
  // A unit cube inside a 3-cube, facing inward: a void, volume 27 - 1.
  Mesh hole = cube(Vec3::Ones(), Vec3::Constant(2));
  flip_orientation(hole);
  write_mesh(path("void.obj"), shells(cube(Vec3::Zero(), Vec3::Constant(3)), hole));
  EXPECT_NEAR(signed_volume(read_mesh(path("void.obj"))), 26.0, 1e-12);
  // The same cube facing outward: a solid inside a solid, refused naming both.
  write_mesh(path("nested.obj"),
             shells(cube(Vec3::Zero(), Vec3::Constant(3)), cube(Vec3::Ones(), Vec3::Constant(2))));
  expect_error<InvalidInput>([&] { read_mesh(path("nested.obj")); },
                             {path("nested.obj"), "shell 2 of 2 lies inside shell 1"});
  // A tetrahedron crossing the cube's surface: never read with the overlap counted twice.
  Mesh tet;
  tet.vertices = {Vec3(0.5, 0.5, 0.5), Vec3(1.5, 0.5, 0.5), Vec3(0.5, 1.5, 0.5),
                  Vec3(0.5, 0.5, 1.5)};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  write_mesh(path("cross.obj"), shells(unit, tet));
  expect_error<InvalidInput>([&] { read_mesh(path("cross.obj")); },
                             {path("cross.obj"), "shell 1 of 2 and shell 2 cross or touch"});
}

}  // namespace
}  // namespace clumpkit
