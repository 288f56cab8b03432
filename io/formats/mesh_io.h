// Triangle mesh files: read and validate STL / OBJ / PLY, write them atomically.
#pragma once

#include "geom/mesh/mesh.h"

#include <cstddef>
#include <string>
#include <vector>

namespace clumpkit {

/// Mesh file formats. `Stl` is binary STL; `StlAscii` is only ever chosen explicitly for writing.
enum class MeshFormat { Stl, StlAscii, Obj, Ply };

/// Format from the extension (.stl .obj .ply, case-insensitive); throws InvalidInput naming the
/// file otherwise. Never returns StlAscii: reading detects ASCII vs binary STL from the content.
MeshFormat mesh_format_from_path(const std::string& path);

/// How a mesh file is turned into a mesh.
struct MeshReadOptions {
  /// Vertices closer than this fraction of the bounding-box diagonal become one; 0 merges equal
  /// positions only (the copies that OBJ and PLY exporters write at normal and UV seams). STL
  /// files are welded at 1e-9 at least: their corners are float32 copies.
  double weld_tolerance = 0.0;
};

/// What reading changed while parsing and validating.
struct MeshReadReport {
  bool reoriented = false;  ///< some triangles were flipped to make the mesh consistent and outward
  /// OBJ and PLY vertices merged into an earlier one at the same position (or within the weld
  /// tolerance). Not counted for STL, whose corners are never shared.
  std::size_t merged_vertices = 0;
  std::size_t removed_triangles = 0;  ///< degenerate triangles removed (repeated corner, zero area)
  std::size_t shells = 1;             ///< closed shells of the solid
  /// ASCII PLY lines with more values than the header declares for their element (ignored).
  std::size_t lines_with_extra_values = 0;
  /// Vertices duplicated where closed lobes touch along an edge or at a vertex (edges of more
  /// than two triangles, pinched fans): the lobes are read as touching shells.
  std::size_t split_vertices = 0;
};

/// Read without topological validation, format chosen by the extension, then welded
/// (options.weld_tolerance; a mesh with a non-finite coordinate is left unwelded, so read_mesh
/// names the coordinate), which also drops the triangles whose corners became one:
/// - STL: ASCII or binary, auto-detected. A file is binary when its size is exactly 84 + 50 n
///   for the triangle count n in its header (binary headers may start with "solid"), ASCII when
///   it starts with "solid" and holds only text.
/// - OBJ: `v` and `f` lines (a line ending in `\` goes on on the next); negative (relative)
///   indices and `v/vt`, `v//vn`, `v/vt/vn` corners; `o`, `g`, `usemtl`, `mtllib` and every
///   other statement ignored.
/// - PLY: ascii, binary_little_endian and binary_big_endian; any scalar types for vertex x y z
///   and face list `vertex_indices` (or `vertex_index`) of any integer types; every other
///   property (scalar or list, in any order) and element is skipped by its declared layout.
///   ASCII is read one element item per line: values beyond the declared ones at the end of a
///   line are ignored (counted in report->lines_with_extra_values), too few are an error naming
///   the line and the property.
/// Polygons become a fan of triangles when convex, else are ear-clipped (non-convex faces).
/// Throws IoError if the file cannot be read, InvalidInput ("<path>: <what>") if it cannot be
/// parsed into a Mesh: empty file, truncated or mis-sized binary data, unparsable number (with
/// line number and token), vertex index out of range. Coordinates may be non-finite; the mesh
/// may be open, non-manifold, degenerate or inward-facing.
Mesh read_mesh_raw(const std::string& path, const MeshReadOptions& options = {},
                   MeshReadReport* report = nullptr);

/// Reads with read_mesh_raw, then validates the mesh as a solid. Zero-area triangles are
/// collapsed away (CGAL PMP remove_degenerate_faces) when that keeps the mesh closed. Throws
/// IoError for a missing or unreadable file and InvalidInput with a one-line "<path>: <what>"
/// message for: empty file, truncated binary STL (expected vs actual bytes), unparsable number
/// (line and token), index out of range, non-finite coordinate, no triangles, a degenerate
/// triangle that cannot be removed, open mesh (number of boundary edges, and the two ways out:
/// `fill --allow-open` and `clumpkit repair`), non-manifold mesh (number of edges shared by more
/// than two triangles) unless splitting those edges and pinched vertices (split_nonmanifold)
/// leaves closed lobes that only touch (read as touching shells, their volumes added; the
/// split is counted in `report->split_vertices`), shells that cross or nest the wrong way
/// (orient_shells), and
/// non-positive enclosed volume. A closed manifold mesh that is inconsistently oriented or faces
/// inward is re-oriented with orient_outward() and `report->reoriented` is set.
Mesh read_mesh(const std::string& path, MeshReadReport* report = nullptr,
               const MeshReadOptions& options = {});

/// The checks and repairs of read_mesh on a mesh made in memory (`name` stands for the path in
/// the messages): indices in range, finite coordinates, zero-area triangles collapsed, closed,
/// manifold, oriented outward (in place; `report` says what changed), enclosing a volume.
void validate_solid(Mesh& mesh, const std::string& name, MeshReadReport* report = nullptr);

/// What the user should hear about a read (one line each, "<path>: ..."): vertices merged,
/// degenerate triangles removed, triangles re-oriented, several shells.
std::vector<std::string> mesh_read_notes(const std::string& path, const MeshReadReport& report);

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
