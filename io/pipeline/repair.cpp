#include "io/pipeline/repair.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/pipeline/output_dir.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace clumpkit {

namespace {

nlohmann::ordered_json point_json(const Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

std::string point_text(const Vec3& p, const LengthUnit& length) {
  return "(" + format_number(p.x(), 6) + ", " + format_number(p.y(), 6) + ", " +
         format_number(p.z(), 6) + ") " + length.symbol;
}

}  // namespace

RepairedMesh read_repaired_mesh(const std::string& path, const MeshReadOptions& options,
                                const RepairOptions& repair) {
  RepairedMesh r;
  r.mesh = read_mesh_raw(path, options, &r.read);
  for (std::size_t i = 0; i < r.mesh.vertices.size(); ++i)
    if (!r.mesh.vertices[i].allFinite())
      throw InvalidInput(path + ": vertex " + std::to_string(i) +
                         " (counting from 0) has a coordinate that is not finite");
  try {
    r.repair = repair_mesh(r.mesh, repair);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
  return r;
}

nlohmann::ordered_json repair_json(const RepairReport& p, const MeshReadReport& read,
                                   const RepairOptions& options) {
  nlohmann::ordered_json j;
  j["merged_vertices"] = read.merged_vertices;
  j["boundary_edges_before"] = p.boundary_edges_before;
  j["boundary_edges_after"] = p.boundary_edges_after;
  j["volume_before"] = p.volume_before;
  j["volume_after"] = p.volume_after;
  j["repeated_vertex_triangles"] =
      p.repeated_vertex_triangles + static_cast<int>(read.removed_triangles);
  j["duplicate_triangles"] = p.duplicate_triangles;
  j["double_wall_triangles"] = p.double_wall_triangles;
  j["nonmanifold_edges"] = p.nonmanifold_edges;
  j["split_vertices"] = p.split_vertices;
  j["rejoined_vertices"] = p.rejoined_vertices;
  j["degenerate_triangles"] = p.degenerate_triangles;
  j["small_components"] = p.small_components;
  j["small_component_triangles"] = p.small_component_triangles;
  j["holes"] = p.holes;
  nlohmann::ordered_json holes = nlohmann::ordered_json::array();
  for (const RepairHole& h : p.closed_holes)
    holes.push_back({{"edges", h.edges}, {"method", h.method}, {"at", point_json(h.at)}});
  j["closed_holes"] = holes;
  nlohmann::ordered_json si;
  si["volume_capped"] = p.volume_capped;
  si["crossings_within_shells"] = p.crossings_within;
  si["crossings_between_shells"] = p.crossings_between;
  nlohmann::ordered_json rounds = nlohmann::ordered_json::array();
  for (const CrossingRound& c : p.local_rounds)
    rounds.push_back(
        {{"shell", c.shell}, {"pairs_before", c.pairs_before}, {"pairs_after", c.pairs_after}});
  si["local_rounds"] = rounds;
  si["united_shells"] = p.united_shells;
  si["slivers"] = p.slivers;
  j["self_intersections"] = si;
  nlohmann::ordered_json w;
  w["mode"] = to_string(options.wrap);
  w["applied"] = p.wrapped;
  w["alpha_fraction"] = options.wrap_alpha;
  w["offset_fraction"] = options.wrap_offset;
  if (p.wrapped) {
    w["alpha"] = p.wrap_alpha;
    w["offset"] = p.wrap_offset;
    w["seconds"] = p.wrap_seconds;
  }
  j["wrap"] = w;
  j["mended_by"] = p.mended_by;
  j["changed"] = p.changed;
  j["diagonal"] = p.diagonal;
  if (p.changed)
    j["distance"] = {{"max_fraction", p.distance_max},
                     {"mean_fraction", p.distance_mean},
                     {"max_at", point_json(p.distance_max_at)}};
  j["warnings"] = p.warnings;
  j["reoriented"] = p.reoriented;
  return j;
}

std::vector<std::string> repair_lines(const RepairReport& p, const MeshReadReport& read,
                                      const LengthUnit& length) {
  const std::string l = length.symbol, l3 = length.pow(3);
  std::vector<std::string> out;
  char line[512];
  auto add = [&](const char* format, auto... values) {
    std::snprintf(line, sizeof line, format, values...);
    out.emplace_back(line);
  };
  add("weld: %zu vertices merged", read.merged_vertices);
  add("duplicates: %d triangles with a repeated corner, %d further copies, %d double-wall "
      "triangles removed",
      p.repeated_vertex_triangles + static_cast<int>(read.removed_triangles), p.duplicate_triangles,
      p.double_wall_triangles);
  add("non-manifold: %d edges shared by more than two triangles; %d vertices split",
      p.nonmanifold_edges, p.split_vertices);
  add("degenerate: %d zero-area triangles collapsed", p.degenerate_triangles);
  add("small components: %d removed (%d triangles)", p.small_components,
      p.small_component_triangles);
  add("holes: %d closed", p.holes);
  for (const RepairHole& h : p.closed_holes)
    add("  %d edges at %s: %s", h.edges, point_text(h.at, length).c_str(), h.method.c_str());
  add("volume: the closed surface bounds %s %s", format_number(p.volume_capped, 6).c_str(),
      l3.c_str());
  add("self-intersections: %d pairs of faces cross within a shell, %d between shells",
      p.crossings_within, p.crossings_between);
  for (const CrossingRound& c : p.local_rounds)
    add("  local round on shell %d: %d -> %d pairs", c.shell, c.pairs_before, c.pairs_after);
  if (p.united_shells > 0) add("  union: %d shells joined into another", p.united_shells);
  if (p.slivers > 0) add("  slivers: %d triangles of (nearly) zero area collapsed", p.slivers);
  if (p.wrapped)
    add("wrap: alpha %s %s, offset %s %s, %.2f s", format_number(p.wrap_alpha, 4).c_str(),
        l.c_str(), format_number(p.wrap_offset, 4).c_str(), l.c_str(), p.wrap_seconds);
  else
    add("wrap: not needed");
  if (!p.mended_by.empty()) add("mended by: %s", p.mended_by.c_str());
  if (p.changed)
    add("changed beyond welding and hole closing: volume %s -> %s %s (%+.3f %%), distance to "
        "the closed input max %.3g %% (at %s), mean %.3g %% of the diagonal %s %s",
        format_number(std::abs(p.volume_capped), 6).c_str(),
        format_number(p.volume_after, 6).c_str(), l3.c_str(),
        100.0 * (p.volume_after / std::abs(p.volume_capped) - 1.0), 100.0 * p.distance_max,
        point_text(p.distance_max_at, length).c_str(), 100.0 * p.distance_mean,
        format_number(p.diagonal, 6).c_str(), l.c_str());
  add("orientation: %s", p.reoriented ? "re-oriented" : "kept");
  return out;
}

RepairJobResult run_repair_job(const std::string& path, const std::string& out,
                               const MeshReadOptions& options, const RepairOptions& repair,
                               const LengthUnit& length) {
  const auto t0 = std::chrono::steady_clock::now();
  check_not_input(out, "--output", path);
  mesh_format_from_path(out);  // an unknown extension is refused before the work
  RepairedMesh m = read_repaired_mesh(path, options, repair);
  write_mesh(out, m.mesh);
  RepairJobResult r;
  r.repair = std::move(m.repair);
  r.read = m.read;
  r.triangles = m.mesh.triangles.size();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::ordered_json& j = r.report;
  j["input"] = path;
  j["output"] = out;
  j.update(repair_json(r.repair, r.read, repair));
  j["triangles"] = r.triangles;
  j["seconds"] = r.seconds;
  add_units(j, length);
  return r;
}

}  // namespace clumpkit
