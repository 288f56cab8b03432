#include "io/pipeline/repair.h"

#include "geom/errors.h"
#include "io/pipeline/output_dir.h"

namespace clumpkit {

RepairJobResult run_repair_job(const std::string& path, const std::string& out,
                               const MeshReadOptions& options, const RepairOptions& repair) {
  check_not_input(out, "--output", path);
  mesh_format_from_path(out);  // an unknown extension is refused before the work
  RepairJobResult r;
  Mesh mesh = read_mesh_raw(path, options, &r.read);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      throw InvalidInput(path + ": vertex " + std::to_string(i) +
                         " (counting from 0) has a coordinate that is not finite");
  try {
    r.repair = repair_mesh(mesh, repair);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
  write_mesh(out, mesh);
  r.triangles = mesh.triangles.size();
  nlohmann::ordered_json& j = r.report;
  j["input"] = path;
  j["output"] = out;
  j["merged_vertices"] = r.read.merged_vertices;
  j["boundary_edges_before"] = r.repair.boundary_edges_before;
  j["boundary_edges_after"] = r.repair.boundary_edges_after;
  j["volume_before"] = r.repair.volume_before;
  j["volume_after"] = r.repair.volume_after;
  j["repeated_vertex_triangles"] =
      r.repair.repeated_vertex_triangles + static_cast<int>(r.read.removed_triangles);
  j["duplicate_triangles"] = r.repair.duplicate_triangles;
  j["double_wall_triangles"] = r.repair.double_wall_triangles;
  j["nonmanifold_edges"] = r.repair.nonmanifold_edges;
  j["split_vertices"] = r.repair.split_vertices;
  j["rejoined_vertices"] = r.repair.rejoined_vertices;
  j["degenerate_triangles"] = r.repair.degenerate_triangles;
  j["small_components"] = r.repair.small_components;
  j["small_component_triangles"] = r.repair.small_component_triangles;
  j["holes"] = r.repair.holes;
  nlohmann::ordered_json holes = nlohmann::ordered_json::array();
  for (const RepairHole& h : r.repair.closed_holes)
    holes.push_back(
        {{"edges", h.edges}, {"method", h.method}, {"at", {h.at.x(), h.at.y(), h.at.z()}}});
  j["closed_holes"] = holes;
  j["reoriented"] = r.repair.reoriented;
  j["triangles"] = r.triangles;
  return r;
}

}  // namespace clumpkit
