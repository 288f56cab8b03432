// Triangle mesh files: read and validate STL / OBJ / PLY, write them atomically.
#pragma once

#include "geom/mesh/mesh.h"

#include <string>

namespace clumpkit {

/// Mesh file formats. `Stl` is binary STL; `StlAscii` is only ever chosen explicitly for writing.
enum class MeshFormat { Stl, StlAscii, Obj, Ply };

/// Format from the extension (.stl .obj .ply, case-insensitive); throws InvalidInput naming the
/// file otherwise. Never returns StlAscii: reading detects ASCII vs binary STL from the content.
MeshFormat mesh_format_from_path(const std::string& path);

/// Raw read without topological validation, format chosen by the extension:
/// - STL: ASCII or binary, auto-detected. A file is binary when its size is exactly 84 + 50 n
///   for the triangle count n in its header (binary headers may start with "solid"), ASCII when
///   it starts with "solid" and holds only text. Vertices are welded (weld_vertices), because
///   STL stores every triangle's corners separately.
/// - OBJ: `v` and `f` lines; polygons are fan-triangulated; negative (relative) indices and
///   `v/vt/vn` syntax are accepted; other statements are ignored.
/// - PLY: ascii and binary_little_endian; any scalar types for vertex x y z, face list
///   `vertex_indices` (or `vertex_index`) of any integer types; other properties and elements
///   are skipped. Polygons are fan-triangulated.
/// Throws IoError if the file cannot be read, InvalidInput ("<path>: <what>") if it cannot be
/// parsed into a Mesh: empty file, truncated or mis-sized binary data, unparsable number (with
/// line number and token), vertex index out of range. Coordinates may be non-finite; the mesh
/// may be open, non-manifold, degenerate or inward-facing.
Mesh read_mesh_raw(const std::string& path);

/// What read_mesh changed while validating.
struct MeshReadReport {
  bool reoriented = false;  ///< some triangles were flipped to make the mesh consistent and outward
};

/// Reads with read_mesh_raw, then validates the mesh as a solid. Throws IoError for a missing or
/// unreadable file and InvalidInput with a one-line "<path>: <what>" message for: empty file,
/// truncated binary STL (expected vs actual bytes), unparsable number (line and token), index
/// out of range, non-finite coordinate, no triangles, degenerate triangle, open mesh (number of
/// boundary edges), non-manifold mesh (number of edges shared by more than two triangles), and
/// non-positive enclosed volume. A closed manifold mesh that is inconsistently oriented or faces
/// inward is re-oriented with orient_outward() and `report->reoriented` is set.
Mesh read_mesh(const std::string& path, MeshReadReport* report = nullptr);

/// Writes the mesh in the format given by the extension of `path` (.stl is binary STL).
/// Atomic (see write_mesh below). Throws InvalidInput for an unknown extension or a triangle
/// index out of range, IoError naming the path if writing fails.
void write_mesh(const std::string& path, const Mesh& mesh);

/// Writes STL (binary, float32 coordinates), ASCII STL (%.9g, enough to round-trip float32),
/// OBJ (format_number: shortest exact decimal) or PLY (binary little endian, float64), so OBJ and
/// PLY round trips are exact. Writes to a temporary file in the same directory and renames it, so
/// no partial file is ever left; throws IoError naming the path on failure.
void write_mesh(const std::string& path, const Mesh& mesh, MeshFormat format);

}  // namespace clumpkit
