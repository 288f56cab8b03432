// Inside io/formats: the readers and writers of each mesh format (mesh_stl.cpp, mesh_obj.cpp,
// mesh_ply.cpp) and the text helpers they share. Use io/formats/mesh_io.h instead.
#pragma once

#include "geom/mesh/mesh.h"

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace clumpkit::mesh_format {

/// Throws InvalidInput("<path>: <what>").
[[noreturn]] void bad(const std::string& path, const std::string& what);

/// "<path>: line N".
std::string at_line(const std::string& path, int line);

/// "n noun" or "n nouns".
std::string plural(std::size_t n, const std::string& noun);

/// A file token echoed in a message: printable ASCII only (messages end up in terminals and
/// JSON reports, which reject invalid UTF-8), at most 40 characters.
std::string shown(std::string_view token);

/// The number or integer `tok`; throws InvalidInput "<where>: cannot parse '<tok>' as ...".
double parse_number(std::string_view tok, const std::string& where);
long long parse_integer(std::string_view tok, const std::string& where);

/// Whitespace-separated tokens of text, one line at a time, with 1-based line numbers. With
/// `continuation`, a line ending in a backslash goes on on the next one (OBJ).
class Lines {
 public:
  explicit Lines(std::string_view text, int first_line = 1, bool continuation = false)
      : text_(text), line_(first_line - 1), continuation_(continuation) {}
  bool next(std::vector<std::string_view>& tokens);
  int line() const { return line_; }  ///< the (last) line of the tokens
  std::size_t offset() const;         ///< start of the next line

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_;
  bool continuation_;
};

/// Appends the triangles of the polygon `face` (vertex indices into `vertices`, in order) to
/// `triangles`: a fan from the first corner when the polygon is convex in the plane of its
/// Newell normal (what every reader did before, so convex faces keep their triangles), else ear
/// clipping, which stays inside a non-convex polygon.
void triangulate_polygon(const std::vector<Vec3>& vertices, const std::vector<int>& face,
                         std::vector<std::array<int, 3>>& triangles);

/// The readers: a Mesh as stored (OBJ, PLY: unwelded). Throw InvalidInput naming the file (and
/// line) for what cannot be parsed. STL comes back welded within `relative_tolerance` of its
/// bounding-box diagonal (weld_vertices), `dropped` the triangles that became degenerate; unwelded
/// beyond exact copies when a corner is not finite.
Mesh read_stl(const std::string& path, const std::string& data, double relative_tolerance,
              std::size_t& dropped);
Mesh read_obj(const std::string& path, const std::string& data);
/// PLY: `lines_with_extra`, if given, receives the number of ASCII lines that carry more values
/// than the header declares for their element (the extra values are ignored).
Mesh read_ply(const std::string& path, const std::string& data,
              std::size_t* lines_with_extra = nullptr);

/// The writers (indices already checked).
void write_stl_binary(std::ostream& os, const Mesh& mesh);
void write_stl_ascii(std::ostream& os, const Mesh& mesh);
void write_obj(std::ostream& os, const Mesh& mesh);
void write_ply(std::ostream& os, const Mesh& mesh);

}  // namespace clumpkit::mesh_format
