// The job of `clumpkit repair`: a mesh file welded, cleaned, closed and oriented into a solid; the
// same chain in memory for `fill --repair`.
#pragma once

#include "geom/mesh/repair.h"
#include "io/base/units.h"
#include "io/formats/mesh_io.h"

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

/// A mesh file read and repaired in memory.
struct RepairedMesh {
  Mesh mesh;
  RepairReport repair;
  MeshReadReport read;
};

/// Reads `path` (read_mesh_raw: welded with `options`) and repairs it (geom/mesh/repair.h).
/// Throws InvalidInput "<path>: <what>" for a non-finite coordinate and for what cannot be
/// repaired, and what read_mesh_raw throws.
RepairedMesh read_repaired_mesh(const std::string& path, const MeshReadOptions& options,
                                const RepairOptions& repair);

/// What the repair did, per step, as JSON: merged_vertices, boundary_edges_before/after,
/// volume_before/after, repeated_vertex_triangles, duplicate_triangles, double_wall_triangles,
/// nonmanifold_edges, split_vertices, rejoined_vertices, degenerate_triangles,
/// small_components, small_component_triangles, holes (count) and closed_holes (edges, method,
/// at), then self_intersections (volume_capped, crossings_within_shells,
/// crossings_between_shells, rounds of the local mend: shell, pairs_before, pairs_after;
/// united_shells, slivers), wrap (mode, applied, alpha, offset in mesh units and as fractions of
/// the diagonal, seconds), mended_by, changed, diagonal, and, when changed, distance (max and mean
/// as fractions of the diagonal, max_at), warnings; reoriented.
nlohmann::ordered_json repair_json(const RepairReport& repair, const MeshReadReport& read,
                                   const RepairOptions& options);

/// One line per step of what the repair did (the text `clumpkit repair` prints, without the
/// final "wrote" line); the local mend one line per round. Lengths, areas and volumes carry the
/// unit `length` ("L": the mesh's, unnamed).
std::vector<std::string> repair_lines(const RepairReport& repair, const MeshReadReport& read,
                                      const LengthUnit& length = {});

/// What the repair job did: the repair, the read, and the report of `repair --json`.
struct RepairJobResult {
  RepairReport repair;
  MeshReadReport read;
  std::size_t triangles = 0;  ///< of the written mesh
  double seconds = 0;         ///< the whole job
  nlohmann::ordered_json report;
};

/// Reads and repairs `mesh` (read_repaired_mesh) and writes the solid to `out` (.stl, .obj or
/// .ply), which must not be the input. Throws InvalidInput naming the input for what cannot be
/// repaired (nothing is written then), and what read_mesh_raw and write_mesh throw. The report:
/// input, output, then repair_json's keys, then triangles and seconds, then the "units" of every
/// number (add_units, lengths in `length`).
RepairJobResult run_repair_job(const std::string& mesh, const std::string& out,
                               const MeshReadOptions& options = {},
                               const RepairOptions& repair = {}, const LengthUnit& length = {});

}  // namespace clumpkit
