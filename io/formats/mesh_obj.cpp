// Wavefront OBJ: `v` and `f` statements read (`o`, `g`, `usemtl`, `mtllib`, `vt`, `vn` and
// the rest ignored), and written.
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/little_endian.h"
#include "io/formats/mesh_formats.h"

#include <string>
#include <vector>

namespace clumpkit::mesh_format {

Mesh read_obj(const std::string& path, const std::string& data) {
  Mesh mesh;
  std::vector<std::string_view> tok;
  std::vector<int> face;
  Lines lines(data, 1, true);  // `\` at a line's end continues it
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
      triangulate_polygon(mesh.vertices, face, mesh.triangles);
    }
  }
  return mesh;
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

}  // namespace clumpkit::mesh_format
