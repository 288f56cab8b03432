// PLY, ASCII and binary of either byte order: read by the declared layout of every element,
// and written (binary little-endian).
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/little_endian.h"
#include "io/formats/mesh_formats.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace clumpkit::mesh_format {

namespace {

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

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

// The value of `type` stored at `p` in the byte order of `format`.
template <class T>
double load(const char* p, PlyFormat format) {
  return format == PlyFormat::binary_big_endian ? double(load_be<T>(p)) : double(load_le<T>(p));
}

// Reads successive property values from the PLY body, as bytes or, in ASCII, as the tokens of
// one line per element item (the PLY format's rule): values past the declared ones at the end of
// a line are ignored and counted (writers such as VCG append properties they never declared), a
// line with too few values is an error naming the line and the property.
class PlyBody {
 public:
  PlyBody(const std::string& path, std::string_view body, PlyFormat format, int first_line)
      : path_(path),
        body_(body),
        binary_(format != PlyFormat::ascii),
        format_(format),
        lines_(body, first_line) {}

  // The start of item `item` of `element`: in ASCII, its line (blank lines skipped).
  void begin(const PlyElement& element, long long item) {
    if (binary_) return;
    do {
      if (!lines_.next(tokens_))
        bad(path_, "PLY file ends inside element '" + shown(element.name) + "' " +
                       std::to_string(item) + " of " + std::to_string(element.count));
    } while (tokens_.empty());
    next_ = 0;
  }

  // The end of an item: in ASCII, values left on its line are counted, not read.
  void end() {
    if (!binary_ && next_ < tokens_.size()) ++lines_with_extra_;
  }

  double read(PlyType type, const PlyElement& element, long long item,
              const PlyProperty& property) {
    if (binary_) return read_binary(type, element, item);
    const std::string where = at_line(path_, lines_.line());
    if (next_ >= tokens_.size())
      throw InvalidInput(where + ": too few values for element '" + shown(element.name) + "' " +
                         std::to_string(item) + ": the line ends before property '" +
                         shown(property.name) + "' (" + plural(tokens_.size(), "value") +
                         " on the line)");
    const std::string_view tok = tokens_[next_++];
    if (type == PlyType::F32 || type == PlyType::F64) return parse_number(tok, where);
    return static_cast<double>(parse_integer(tok, where));
  }

  std::size_t lines_with_extra() const { return lines_with_extra_; }

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
        return load<int8_t>(p, format_);
      case PlyType::U8:
        return load<uint8_t>(p, format_);
      case PlyType::I16:
        return load<int16_t>(p, format_);
      case PlyType::U16:
        return load<uint16_t>(p, format_);
      case PlyType::I32:
        return load<int32_t>(p, format_);
      case PlyType::U32:
        return load<uint32_t>(p, format_);
      case PlyType::F32:
        return load<float>(p, format_);
      case PlyType::F64:
        return load<double>(p, format_);
    }
    return 0.0;
  }

  const std::string& path_;
  std::string_view body_;
  bool binary_;
  PlyFormat format_;
  size_t pos_ = 0;
  Lines lines_;
  std::vector<std::string_view> tokens_;
  size_t next_ = 0;
  std::size_t lines_with_extra_ = 0;
};

}  // namespace

Mesh read_ply(const std::string& path, const std::string& data, std::size_t* lines_with_extra) {
  // Header: "ply", "format ...", then element / property / comment lines up to "end_header".
  std::vector<PlyElement> elements;
  std::vector<std::string_view> tok;
  Lines lines(data);
  std::optional<PlyFormat> format;
  bool ended = false;
  while (!ended && lines.next(tok)) {
    const std::string where = at_line(path, lines.line());
    if (lines.line() == 1) {
      if (tok.size() != 1 || tok[0] != "ply") bad(path, "not a PLY file: first line is not 'ply'");
    } else if (tok.empty() || tok[0] == "comment" || tok[0] == "obj_info") {
      continue;
    } else if (tok[0] == "format" && tok.size() >= 2) {
      if (tok[1] == "ascii")
        format = PlyFormat::ascii;
      else if (tok[1] == "binary_little_endian")
        format = PlyFormat::binary_little_endian;
      else if (tok[1] == "binary_big_endian")
        format = PlyFormat::binary_big_endian;
      else
        throw InvalidInput(where + ": unsupported PLY format '" + shown(tok[1]) +
                           "' (ascii, binary_little_endian and binary_big_endian are supported)");
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
  if (!format) bad(path, "PLY header has no 'format' line");

  long long nv = 0;
  for (const auto& e : elements)
    if (e.name == "vertex") nv = e.count;
  Mesh mesh;
  PlyBody body(path, std::string_view(data).substr(lines.offset()), *format, lines.line() + 1);
  // Faces are triangulated as they come, or once every vertex is read when the faces come
  // first (legal PLY; a polygon's shape decides its triangles).
  std::vector<int> later, later_start;
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
      body.begin(e, i);
      Vec3 p = Vec3::Zero();
      for (int j = 0; j < static_cast<int>(e.properties.size()); ++j) {
        const PlyProperty& prop = e.properties[j];
        if (!prop.list) {
          const double v = body.read(prop.type, e, i, prop);
          for (int k = 0; k < 3; ++k)
            if (j == axis_of[k]) p[k] = v;
          continue;
        }
        const double n = body.read(prop.count_type, e, i, prop);
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
          const double idx = body.read(prop.type, e, i, prop);
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
        if (static_cast<long long>(mesh.vertices.size()) == nv) {
          triangulate_polygon(mesh.vertices, face, mesh.triangles);
        } else {
          later_start.push_back(static_cast<int>(later.size()));
          later.insert(later.end(), face.begin(), face.end());
        }
      }
      if (is_vertex) mesh.vertices.push_back(p);
      body.end();
    }
  }
  if (lines_with_extra) *lines_with_extra = body.lines_with_extra();
  later_start.push_back(static_cast<int>(later.size()));
  for (std::size_t f = 0; f + 1 < later_start.size(); ++f)
    triangulate_polygon(
        mesh.vertices,
        std::vector<int>(later.begin() + later_start[f], later.begin() + later_start[f + 1]),
        mesh.triangles);
  return mesh;
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

}  // namespace clumpkit::mesh_format
