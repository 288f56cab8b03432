// The job of `clumpkit repair`: a mesh file welded, cleaned, closed and oriented into a solid.
#pragma once

#include "geom/mesh/repair.h"
#include "io/formats/mesh_io.h"

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

/// What the repair job did: the repair, the read, and the report of `repair --json`.
struct RepairJobResult {
  RepairReport repair;
  MeshReadReport read;
  std::size_t triangles = 0;  ///< of the written mesh
  nlohmann::ordered_json report;
};

/// Reads `mesh` (read_mesh_raw: welded with `options`), repairs it (geom/mesh/repair.h) and
/// writes the solid to `out` (.stl, .obj or .ply), which must not be the input. Throws
/// InvalidInput naming the input for what cannot be repaired (nothing is written then), and
/// what read_mesh_raw and write_mesh throw. The report: input, output, merged_vertices,
/// boundary_edges_before/after, volume_before/after, then per step of repair_mesh
/// repeated_vertex_triangles, duplicate_triangles, double_wall_triangles, nonmanifold_edges,
/// split_vertices, degenerate_triangles, small_components, small_component_triangles, holes
/// (count) and closed_holes (edges, method, at), reoriented; and triangles.
RepairJobResult run_repair_job(const std::string& mesh, const std::string& out,
                               const MeshReadOptions& options = {},
                               const RepairOptions& repair = {});

}  // namespace clumpkit
