#include "io/formats/mesh_io.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/limits.h"
#include "geom/mesh/cgal_mesh.h"
#include "io/base/atomic_file.h"
#include "io/base/little_endian.h"
#include "io/base/text.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

namespace clumpkit {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  throw InvalidInput(path + ": " + what);
}

std::string at_line(const std::string& path, int line) {
  return path + ": line " + std::to_string(line);
}

std::string plural(size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// Echoes a file token in a message: printable ASCII only (messages end up in terminals and JSON
// reports, which reject invalid UTF-8), at most 40 characters.
std::string shown(std::string_view token) {
  std::string s;
  for (const char ch : token.substr(0, 40)) {
    const auto c = static_cast<unsigned char>(ch);
    char buf[8];
    std::snprintf(buf, sizeof buf, c >= 0x20 && c < 0x7f ? "%c" : "\\x%02x", c);
    s += buf;
  }
  return token.size() > 40 ? s + "..." : s;
}

double parse_number(std::string_view tok, const std::string& where) {
  const std::optional<double> v = to_number(tok);
  if (!v) throw InvalidInput(where + ": cannot parse '" + shown(tok) + "' as a number");
  return *v;
}

long long parse_integer(std::string_view tok, const std::string& where) {
  const std::optional<long long> v = to_integer(tok);
  if (!v) throw InvalidInput(where + ": cannot parse '" + shown(tok) + "' as an integer");
  return *v;
}

// Whitespace-separated tokens of text, one line at a time, with 1-based line numbers.
class Lines {
 public:
  explicit Lines(std::string_view text, int first_line = 1) : text_(text), line_(first_line - 1) {}

  bool next(std::vector<std::string_view>& tokens) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    const std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    tokens.clear();
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      const size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i > start) tokens.push_back(line.substr(start, i - start));
    }
    return true;
  }
  int line() const { return line_; }
  size_t offset() const { return std::min(pos_, text_.size()); }  ///< start of the next line

 private:
  std::string_view text_;
  size_t pos_ = 0;
  int line_;
};

std::string read_whole_file(const std::string& path) {
  std::string data = read_file(path, "mesh file");
  if (data.empty()) bad(path, "file is empty");
  return data;
}

// ---- STL ----

void add_triangle_soup(Mesh& mesh, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int n = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
  mesh.triangles.push_back({n, n + 1, n + 2});
}

Mesh read_binary_stl(const std::string& data, uint32_t n) {
  Mesh mesh;
  mesh.vertices.reserve(3 * size_t(n));
  mesh.triangles.reserve(n);
  for (uint32_t i = 0; i < n; ++i) {
    const char* p = data.data() + 84 + 50 * size_t(i) + 12;  // skip the stored normal
    Vec3 v[3];
    for (int k = 0; k < 9; ++k) v[k / 3][k % 3] = load_le<float>(p + 4 * k);
    add_triangle_soup(mesh, v[0], v[1], v[2]);
  }
  return mesh;
}

Mesh read_ascii_stl(const std::string& path, const std::string& data) {
  Mesh mesh;
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
      add_triangle_soup(mesh, loop[0], loop[1], loop[2]);
      loop.clear();
    }
  }
  if (!loop.empty()) bad(path, "ASCII STL ends inside a facet (missing 'endloop')");
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

Mesh read_stl(const std::string& path, const std::string& data) {
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
    mesh = read_binary_stl(data, n);
  } else if (says_solid && (is_text(data) || data.find("endloop", 80) != std::string::npos)) {
    mesh = read_ascii_stl(path, data);
  } else if (size < 84) {
    bad(path, "truncated binary STL: the file has " + std::to_string(size) +
                  " bytes, less than the 84-byte header");
  } else {
    bad(path, std::string(size < expected ? "truncated binary STL" : "binary STL size mismatch") +
                  ": header says " + std::to_string(n) + " triangles (" + std::to_string(expected) +
                  " bytes) but the file has " + std::to_string(size) + " bytes");
  }
  // Welding a non-finite coordinate would collapse the whole grid; leave such a soup as it is
  // so that read_mesh reports the coordinate instead of a misleading "no triangles".
  const bool finite = std::all_of(mesh.vertices.begin(), mesh.vertices.end(),
                                  [](const Vec3& p) { return p.allFinite(); });
  if (finite) weld_vertices(mesh);
  return mesh;
}

// ---- OBJ ----

Mesh read_obj(const std::string& path, const std::string& data) {
  Mesh mesh;
  std::vector<std::string_view> tok;
  std::vector<int> face;
  Lines lines(data);
  while (lines.next(tok)) {
    if (tok.empty()) continue;
    if (tok[0] == "v") {
      const std::string where = at_line(path, lines.line());
      if (tok.size() < 4) throw InvalidInput(where + ": expected 'v x y z'");
      mesh.vertices.emplace_back(parse_number(tok[1], where), parse_number(tok[2], where),
                                 parse_number(tok[3], where));
    } else if (tok[0] == "f") {
      const std::string where = at_line(path, lines.line());
      const long long nv = static_cast<long long>(mesh.vertices.size());
      face.clear();
      for (size_t k = 1; k < tok.size(); ++k) {
        // "i", "i/t", "i//n", "i/t/n": the position index comes first.
        const std::string_view s = tok[k].substr(0, tok[k].find('/'));
        const long long i = parse_integer(s, where);
        const long long idx = i > 0 ? i - 1 : nv + i;  // negative: relative to the last vertex
        if (i == 0 || idx < 0 || idx >= nv)
          throw InvalidInput(where + ": vertex index " + std::string(s) + " out of range (" +
                             std::to_string(nv) + " vertices defined so far)");
        face.push_back(static_cast<int>(idx));
      }
      if (face.size() < 3)
        throw InvalidInput(where + ": face has " + std::to_string(face.size()) +
                           " vertices, at least 3 needed");
      for (size_t k = 1; k + 1 < face.size(); ++k)
        mesh.triangles.push_back({face[0], face[k], face[k + 1]});
    }
  }
  return mesh;
}

// ---- PLY ----

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::F64;
  bool list = false;
  PlyType count_type = PlyType::U8;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

PlyType ply_type(std::string_view s, const std::string& where) {
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::I8},    {"int8", PlyType::I8},     {"uchar", PlyType::U8},
      {"uint8", PlyType::U8},   {"short", PlyType::I16},   {"int16", PlyType::I16},
      {"ushort", PlyType::U16}, {"uint16", PlyType::U16},  {"int", PlyType::I32},
      {"int32", PlyType::I32},  {"uint", PlyType::U32},    {"uint32", PlyType::U32},
      {"float", PlyType::F32},  {"float32", PlyType::F32}, {"double", PlyType::F64},
      {"float64", PlyType::F64}};
  for (const auto& [name, type] : names)
    if (s == name) return type;
  throw InvalidInput(where + ": unknown PLY property type '" + shown(s) + "'");
}

// Reads successive property values from the PLY body, as text tokens or little-endian bytes.
class PlyBody {
 public:
  PlyBody(const std::string& path, std::string_view body, bool binary, int first_line)
      : path_(path), body_(body), binary_(binary), lines_(body, first_line) {}

  double read(PlyType type, const PlyElement& element, long long item) {
    if (binary_) return read_binary(type, element, item);
    while (next_ >= tokens_.size()) {
      if (!lines_.next(tokens_))
        bad(path_, "PLY file ends inside element '" + shown(element.name) + "' " +
                       std::to_string(item) + " of " + std::to_string(element.count));
      next_ = 0;
    }
    const std::string_view tok = tokens_[next_++];
    const std::string where = at_line(path_, lines_.line());
    if (type == PlyType::F32 || type == PlyType::F64) return parse_number(tok, where);
    return static_cast<double>(parse_integer(tok, where));
  }

 private:
  double read_binary(PlyType type, const PlyElement& element, long long item) {
    static const size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    const size_t n = sizes[static_cast<int>(type)];
    if (pos_ + n > body_.size())
      bad(path_, "truncated binary PLY: data ends inside element '" + shown(element.name) + "' " +
                     std::to_string(item) + " of " + std::to_string(element.count));
    const char* p = body_.data() + pos_;
    pos_ += n;
    switch (type) {
      case PlyType::I8:
        return load_le<int8_t>(p);
      case PlyType::U8:
        return load_le<uint8_t>(p);
      case PlyType::I16:
        return load_le<int16_t>(p);
      case PlyType::U16:
        return load_le<uint16_t>(p);
      case PlyType::I32:
        return load_le<int32_t>(p);
      case PlyType::U32:
        return load_le<uint32_t>(p);
      case PlyType::F32:
        return load_le<float>(p);
      case PlyType::F64:
        return load_le<double>(p);
    }
    return 0.0;
  }

  const std::string& path_;
  std::string_view body_;
  bool binary_;
  size_t pos_ = 0;
  Lines lines_;
  std::vector<std::string_view> tokens_;
  size_t next_ = 0;
};

Mesh read_ply(const std::string& path, const std::string& data) {
  // Header: "ply", "format ...", then element / property / comment lines up to "end_header".
  std::vector<PlyElement> elements;
  std::vector<std::string_view> tok;
  Lines lines(data);
  int format = -1;  // 0 ascii, 1 binary little endian
  bool ended = false;
  while (!ended && lines.next(tok)) {
    const std::string where = at_line(path, lines.line());
    if (lines.line() == 1) {
      if (tok.size() != 1 || tok[0] != "ply") bad(path, "not a PLY file: first line is not 'ply'");
    } else if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") {
      continue;
    } else if (tok[0] == "format" && tok.size() >= 2) {
      if (tok[1] == "ascii")
        format = 0;
      else if (tok[1] == "binary_little_endian")
        format = 1;
      else
        throw InvalidInput(where + ": unsupported PLY format '" + shown(tok[1]) +
                           "' (ascii and binary_little_endian are supported)");
    } else if (tok[0] == "element" && tok.size() == 3) {
      const long long count = parse_integer(tok[2], where);
      if (count < 0 || count > INT_MAX)
        throw InvalidInput(where + ": bad element count " + shown(tok[2]));
      elements.push_back({std::string(tok[1]), count, {}});
    } else if (tok[0] == "property" && !elements.empty() && tok.size() == 3) {
      elements.back().properties.push_back({std::string(tok[2]), ply_type(tok[1], where)});
    } else if (tok[0] == "property" && !elements.empty() && tok.size() == 5 && tok[1] == "list") {
      elements.back().properties.push_back(
          {std::string(tok[4]), ply_type(tok[3], where), true, ply_type(tok[2], where)});
    } else if (tok[0] == "end_header") {
      ended = true;
    } else {
      throw InvalidInput(where + ": unexpected PLY header line starting with '" + shown(tok[0]) +
                         "'");
    }
  }
  if (!ended) bad(path, "PLY header has no 'end_header' line");
  if (format < 0) bad(path, "PLY header has no 'format' line");

  long long nv = 0;
  for (const auto& e : elements)
    if (e.name == "vertex") nv = e.count;
  Mesh mesh;
  PlyBody body(path, std::string_view(data).substr(lines.offset()), format == 1, lines.line() + 1);
  std::vector<int> face;
  for (const auto& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    int axis_of[3] = {-1, -1, -1};  // property index of x, y, z
    for (int j = 0; j < static_cast<int>(e.properties.size()); ++j)
      for (int k = 0; k < 3; ++k)
        if (!e.properties[j].list && e.properties[j].name == std::string_view(&"xyz"[k], 1))
          axis_of[k] = j;
    if (is_vertex && std::count(axis_of, axis_of + 3, -1) > 0)
      bad(path, "PLY vertex element lacks an x, y or z property");
    // Do not trust the header count for allocation: a corrupt count must not exhaust memory.
    if (is_vertex) mesh.vertices.reserve(std::min<size_t>(e.count, data.size()));
    for (long long i = 0; i < e.count; ++i) {
      Vec3 p = Vec3::Zero();
      for (int j = 0; j < static_cast<int>(e.properties.size()); ++j) {
        const PlyProperty& prop = e.properties[j];
        if (!prop.list) {
          const double v = body.read(prop.type, e, i);
          for (int k = 0; k < 3; ++k)
            if (j == axis_of[k]) p[k] = v;
          continue;
        }
        const double n = body.read(prop.count_type, e, i);
        if (!(n >= 0))  // also rejects NaN from a float count type
          bad(path, "negative list length in element '" + shown(e.name) + "' " + std::to_string(i));
        // A float count type can hold any magnitude; past 2^31 entries no file is that long.
        if (n > 2147483647.0)
          bad(path, "list length " + format_number(n) + " in element '" + shown(e.name) + "' " +
                        std::to_string(i) + " is beyond any file");
        const bool indices =
            is_face && (prop.name == "vertex_indices" || prop.name == "vertex_index");
        face.clear();
        for (long long k = 0; k < static_cast<long long>(n); ++k) {
          const double idx = body.read(prop.type, e, i);
          if (!indices) continue;
          if (!(idx >= 0 && idx < nv))
            bad(path, "face " + std::to_string(i) + ": vertex index " + format_fixed(idx, 0) +
                          " out of range (" + std::to_string(nv) + " vertices)");
          face.push_back(static_cast<int>(idx));
        }
        if (!indices) continue;
        if (face.size() < 3)
          bad(path, "face " + std::to_string(i) + " has " + std::to_string(face.size()) +
                        " vertices, at least 3 needed");
        for (size_t k = 1; k + 1 < face.size(); ++k)
          mesh.triangles.push_back({face[0], face[k], face[k + 1]});
      }
      if (is_vertex) mesh.vertices.push_back(p);
    }
  }
  return mesh;
}

// ---- writers ----

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

void write_obj(std::ostream& os, const Mesh& mesh) {
  // 17 significant digits make the decimal round trip of a double exact.
  os << "# written by clumpkit\n";
  for (const auto& v : mesh.vertices)
    os << "v " << format_number(v.x()) << " " << format_number(v.y()) << " " << format_number(v.z())
       << "\n";
  for (const auto& t : mesh.triangles)
    os << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
}

void write_ply(std::ostream& os, const Mesh& mesh) {
  os << "ply\nformat binary_little_endian 1.0\ncomment written by clumpkit\n"
     << "element vertex " << mesh.vertices.size()
     << "\nproperty double x\nproperty double y\nproperty double z\n"
     << "element face " << mesh.triangles.size()
     << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) store_le<double>(os, v[k]);
  for (const auto& t : mesh.triangles) {
    store_le<uint8_t>(os, 3);
    for (int k = 0; k < 3; ++k) store_le<int32_t>(os, t[k]);
  }
}

}  // namespace

MeshFormat mesh_format_from_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  bad(path, ext.empty() ? "no file extension; expected .stl, .obj or .ply"
                        : "unknown mesh format '" + ext + "'; expected .stl, .obj or .ply");
}

Mesh read_mesh_raw(const std::string& path) {
  const MeshFormat format = mesh_format_from_path(path);
  const std::string data = read_whole_file(path);
  switch (format) {
    case MeshFormat::Obj:
      return read_obj(path, data);
    case MeshFormat::Ply:
      return read_ply(path, data);
    default:
      return read_stl(path, data);
  }
}

Mesh read_mesh(const std::string& path, MeshReadReport* report) {
  Mesh mesh = read_mesh_raw(path);
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    if (!p.allFinite() || !(p.cwiseAbs().maxCoeff() <= kMaxLength))
      bad(path, "vertex " + std::to_string(i) +
                    " (counting from 0) has a coordinate that is not finite or beyond 1e30 (" +
                    format_number(p.x()) + ", " + format_number(p.y()) + ", " +
                    format_number(p.z()) + ")");
  }
  if (mesh.triangles.empty()) bad(path, "mesh has no triangles");
  const MeshCheck check = check_mesh(mesh);
  // Degeneracy first: check_mesh skips triangles with repeated vertices when counting edges,
  // which would otherwise surface as a misleading "open" message.
  if (check.degenerate) bad(path, "mesh has a degenerate triangle (zero area or repeated vertex)");
  if (check.boundary_edges > 0)
    bad(path, "mesh is open: " + plural(check.boundary_edges, "boundary edge"));
  if (check.nonmanifold_edges > 0)
    bad(path, "mesh is not manifold: " + plural(check.nonmanifold_edges, "edge") +
                  " shared by more than two triangles");
  if (!check.manifold) bad(path, "mesh is not manifold: a vertex joins separate surface sheets");
  bool reoriented = false;
  if (!check.oriented || check.volume < 0) {
    try {
      reoriented = orient_outward(mesh);
    } catch (const InvalidInput& e) {
      bad(path, std::string("cannot orient the mesh: ") + e.what());
    }
  }
  // Relative to the bounding box so that a flat "solid" with round-off volume is rejected too.
  const auto bb = bounding_box(mesh);
  if (!((bb[1] - bb[0]).norm() >= kMinLength))
    bad(path, "mesh is smaller than 1e-30 across: bounding-box diagonal " +
                  format_number((bb[1] - bb[0]).norm()));
  const double volume = signed_volume(mesh);
  if (!(volume > 1e-12 * std::pow((bb[1] - bb[0]).norm(), 3)))
    bad(path, "mesh encloses no volume: signed volume " + format_number(volume, 6) +
                  " after orientation");
  if (report) report->reoriented = reoriented;
  return mesh;
}

void write_mesh(const std::string& path, const Mesh& mesh) {
  write_mesh(path, mesh, mesh_format_from_path(path));
}

void write_mesh(const std::string& path, const Mesh& mesh, MeshFormat format) {
  const int nv = static_cast<int>(mesh.vertices.size());
  for (const auto& t : mesh.triangles)
    for (int k : t)
      if (k < 0 || k >= nv)
        bad(path, "cannot write mesh: vertex index " + std::to_string(k) + " out of range (" +
                      std::to_string(nv) + " vertices)");
  if (format == MeshFormat::Stl && mesh.triangles.size() > UINT32_MAX)
    bad(path, "too many triangles for binary STL");
  const bool text = format == MeshFormat::StlAscii || format == MeshFormat::Obj;
  write_file_atomically(
      path,
      [&](std::ostream& os) {
        switch (format) {
          case MeshFormat::Stl:
            return write_stl_binary(os, mesh);
          case MeshFormat::StlAscii:
            return write_stl_ascii(os, mesh);
          case MeshFormat::Obj:
            return write_obj(os, mesh);
          case MeshFormat::Ply:
            return write_ply(os, mesh);
        }
      },
      !text);
}

}  // namespace clumpkit
