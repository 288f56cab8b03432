// Meshes as exporters write them, read by the one intake (io/formats/mesh_io.h): seam copies
// welded in every format, PLY of any layout and byte order, OBJ continuation and non-convex
// polygons, degenerate triangles removed, several shells read by orientation.
#include "io/formats/mesh_io.h"

#include "geom/format.h"
#include "tests/io/formats/mesh_test_support.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace clumpkit {
namespace {

using namespace mesh_test;

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

TEST_F(MeshIoTest, AsciiPlyReadsOneItemPerLineIgnoringUndeclaredTrailingValues) {
  // VCG writes face lines with more values than its header declares (after the indices and the
  // texcoord list, ten values where four colour bytes are named): the extra ones are ignored,
  // counted in one note, and the mesh is its binary twin's.
  std::string text = cube_ply("ascii");
  std::string extended;
  std::size_t lines = 0, at = 0;
  const std::size_t body = text.find("end_header\n") + 11;
  extended = text.substr(0, body);
  for (std::size_t p = body; p < text.size(); p = at + 1) {
    at = text.find('\n', p);
    std::string line = text.substr(p, at - p);
    if (line.rfind("4 ", 0) == 0 && line.size() < 80) line += " 0 0 0 0 0 0", ++lines;
    extended += line + "\n";
  }
  ASSERT_EQ(lines, 6u);
  write("x.ply", extended);
  write("b.ply", cube_ply("binary_little_endian"));
  MeshReadReport report;
  const Mesh a = read_mesh_raw(path("x.ply"), {}, &report);
  const Mesh b = read_mesh_raw(path("b.ply"));
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(report.lines_with_extra_values, 6u);
  const std::vector<std::string> notes = mesh_read_notes(path("x.ply"), report);
  EXPECT_EQ(std::count_if(notes.begin(), notes.end(),
                          [](const std::string& n) {
                            return n.find("ignored the values at the end of 6 lines") !=
                                   std::string::npos;
                          }),
            1);
  EXPECT_NE(notes[0].find("merged 16 vertex copies"), std::string::npos) << notes[0];
  // A line with too few values names the line and the property it ends before.
  std::string shortened = text;
  const std::size_t first = shortened.find("end_header\n") + 11;
  const std::size_t eol = shortened.find('\n', first);
  shortened.erase(shortened.rfind(' ', eol - 1), eol - shortened.rfind(' ', eol - 1));
  write("s.ply", shortened);
  const auto line = std::count(text.begin(), text.begin() + first, '\n') + 1;
  expect_error<InvalidInput>(
      [&] { read_mesh_raw(path("s.ply")); },
      {path("s.ply") + ": line " + std::to_string(line) + ": too few values for element 'vertex' 0",
       "before property 't'"});
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
Mesh shells(Mesh a, const Mesh& b) {
  append_mesh(a, b);
  return a;
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
