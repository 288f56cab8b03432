// STL, ASCII and binary: read (three corners per triangle, exact copies welded as read) and
// written.
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/weld.h"
#include "io/base/little_endian.h"
#include "io/formats/mesh_formats.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace clumpkit::mesh_format {

namespace {

// Corners are welded as they are read: a scan's soup of 4·10⁶ corners is never held.
void add_triangle(Mesh& mesh, VertexWelder& weld, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int i = weld.add(a), j = weld.add(b), k = weld.add(c);
  mesh.triangles.push_back({i, j, k});
}

Vec3 corner(const std::string& data, uint32_t triangle, int k) {
  const char* p = data.data() + 84 + 50 * size_t(triangle) + 12 * (k + 1);  // past the normal
  return Vec3(load_le<float>(p), load_le<float>(p + 4), load_le<float>(p + 8));
}

// Binary STL welded within the tolerance as it is read, in one table: the box of all corners
// comes first from a pass over the floats (sequential, a few per cent of the reading), then
// each corner goes to its cell. The same mesh as welding exact copies and then their survivors
// by cell (weld_vertices), one pass and one table fewer. A non-finite corner leaves the mesh
// welded exactly, for read_mesh to name the coordinate.
Mesh read_binary_stl(const std::string& data, uint32_t n, double relative_tolerance,
                     std::size_t& dropped) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  bool finite = true;
  for (uint32_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const Vec3 v = corner(data, i, k);
      finite = finite && v.allFinite();
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
  Mesh mesh;
  mesh.triangles.reserve(n);
  // A closed mesh has about half as many vertices as triangles.
  VertexWelder weld(n / 2 + 16, lo, finite ? relative_tolerance * (hi - lo).norm() : 0.0);
  constexpr uint32_t kBlock = 1024;  // triangles welded at once (the welder fetches ahead)
  std::vector<Vec3> corners(3 * kBlock);
  std::vector<int> index(3 * kBlock);
  for (uint32_t first = 0; first < n; first += kBlock) {
    const uint32_t m = std::min(kBlock, n - first);
    for (uint32_t i = 0; i < m; ++i)
      for (int k = 0; k < 3; ++k) corners[3 * i + k] = corner(data, first + i, k);
    weld.add(corners.data(), 3 * std::size_t(m), index.data());
    for (uint32_t i = 0; i < m; ++i) {
      const int a = index[3 * i], b = index[3 * i + 1], c = index[3 * i + 2];
      if (!finite || (a != b && b != c && a != c)) mesh.triangles.push_back({a, b, c});
    }
  }
  dropped = n - mesh.triangles.size();
  mesh.vertices = weld.take_vertices();
  return mesh;
}

Mesh read_ascii_stl(const std::string& path, const std::string& data) {
  Mesh mesh;
  VertexWelder weld;
  std::vector<Vec3> loop;
  std::vector<std::string_view> tok;
  Lines lines(data);
  // Only vertex coordinates matter; facet normals are recomputed from them, so they are not
  // parsed and other keywords are accepted as they come.
  while (lines.next(tok)) {
    if (tok.empty()) continue;
    if (tok[0] == "outer") {
      loop.clear();
    } else if (tok[0] == "vertex") {
      const std::string where = at_line(path, lines.line());
      if (tok.size() != 4) throw InvalidInput(where + ": expected 'vertex x y z'");
      loop.emplace_back(parse_number(tok[1], where), parse_number(tok[2], where),
                        parse_number(tok[3], where));
    } else if (tok[0] == "endloop") {
      if (loop.size() != 3)
        throw InvalidInput(at_line(path, lines.line()) + ": facet has " +
                           std::to_string(loop.size()) + " vertices, expected 3");
      add_triangle(mesh, weld, loop[0], loop[1], loop[2]);
      loop.clear();
    }
  }
  if (!loop.empty()) bad(path, "ASCII STL ends inside a facet (missing 'endloop')");
  mesh.vertices = weld.take_vertices();
  return mesh;
}

// Text STL: only printable bytes and whitespace (UTF-8 names allowed). Binary STL practically
// always has control bytes (the zero attribute words, float bytes), even under a "solid" header.
bool is_text(const std::string& data) {
  return std::none_of(data.begin(), data.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c == 0x7f || (c < 0x20 && !std::isspace(c));
  });
}

}  // namespace

Mesh read_stl(const std::string& path, const std::string& data, double relative_tolerance,
              std::size_t& dropped) {
  dropped = 0;
  const uint64_t size = data.size();
  Mesh mesh;
  uint32_t n = 0;
  uint64_t expected = 0;
  if (size >= 84) {
    n = load_le<uint32_t>(data.data() + 80);
    expected = 84 + 50 * uint64_t(n);
  }
  const size_t first = data.find_first_not_of(" \t\r\n");
  const bool says_solid = first != std::string::npos && data.compare(first, 5, "solid") == 0;
  // The size test comes first: many binary exporters begin the header with "solid", while an
  // ASCII file matching 84 + 50 n would need a count read from text bytes (>= 0x20202020).
  // "endloop" past the header keeps a text file with a stray control byte on the ASCII path,
  // where the bad token gets a line number.
  if (size >= 84 && size == expected) {
    if (3 * uint64_t(n) > INT_MAX) bad(path, "binary STL has too many triangles for int indices");
    return read_binary_stl(data, n, relative_tolerance, dropped);
  } else if (says_solid && (is_text(data) || data.find("endloop", 80) != std::string::npos)) {
    mesh = read_ascii_stl(path, data);
    const std::size_t read = mesh.triangles.size();
    weld_vertices(mesh, relative_tolerance);
    dropped = read - mesh.triangles.size();
  } else if (size < 84) {
    bad(path, "truncated binary STL: the file has " + std::to_string(size) +
                  " bytes, less than the 84-byte header");
  } else {
    bad(path, std::string(size < expected ? "truncated binary STL" : "binary STL size mismatch") +
                  ": header says " + std::to_string(n) + " triangles (" + std::to_string(expected) +
                  " bytes) but the file has " + std::to_string(size) + " bytes");
  }
  return mesh;
}

void write_stl_binary(std::ostream& os, const Mesh& mesh) {
  // The header must not start with "solid", or naive readers would take the file for ASCII.
  char header[80] = "binary STL written by clumpkit";
  os.write(header, sizeof header);
  store_le<uint32_t>(os, static_cast<uint32_t>(mesh.triangles.size()));
  // Records of 50 bytes gathered in blocks: one stream write per block, not 13 per triangle
  // (a scan-sized mesh has 10^5–10^6 of them).
  constexpr std::size_t kRecord = 50, kBlock = 1024;
  std::vector<char> block(kRecord * kBlock);
  std::size_t used = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    const Vec3 n = (b - a).cross(c - a).normalized();  // zero vector for a degenerate triangle
    char* r = block.data() + used;
    for (const Vec3* v : {&n, &a, &b, &c})
      for (int k = 0; k < 3; ++k, r += 4) store_le<float>(r, static_cast<float>((*v)[k]));
    store_le<uint16_t>(r, 0);
    used += kRecord;
    if (used == block.size()) {
      os.write(block.data(), std::streamsize(used));
      used = 0;
    }
  }
  os.write(block.data(), std::streamsize(used));
}

void write_stl_ascii(std::ostream& os, const Mesh& mesh) {
  // %.9g round-trips float32, the precision of STL, as in the binary variant.
  auto xyz = [](const Vec3& v) {
    return format_number(v.x(), 9) + " " + format_number(v.y(), 9) + " " + format_number(v.z(), 9);
  };
  os << "solid clumpkit\n";
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3& b = mesh.vertices[t[1]];
    const Vec3& c = mesh.vertices[t[2]];
    os << "  facet normal " << xyz((b - a).cross(c - a).normalized()) << "\n    outer loop\n";
    for (const Vec3* v : {&a, &b, &c}) os << "      vertex " << xyz(*v) << "\n";
    os << "    endloop\n  endfacet\n";
  }
  os << "endsolid clumpkit\n";
}

}  // namespace clumpkit::mesh_format
