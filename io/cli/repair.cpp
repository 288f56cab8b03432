// `clumpkit repair MESH -o OUT`: a mesh closed and oriented into a solid that the other
// commands accept.
#include "io/pipeline/repair.h"
#include "geom/format.h"
#include "io/cli/common.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_repair(CLI::App& app) {
  struct Opts {
    std::string mesh, out;
    bool json = false;
    MeshReadOptions read;
    RepairOptions repair;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "repair",
      "Turn a scanned or exported mesh into a closed solid, in named steps: weld vertices "
      "(--weld-tolerance); duplicates (a repeated corner dropped, further copies of a triangle "
      "dropped, a triangle present in both orientations - a double wall - dropped with every "
      "copy); non-manifold (edges of more than two triangles and vertices where separate fans "
      "meet split by duplicating their vertices, CGAL orient_polygon_soup); degenerate "
      "(zero-area triangles collapsed); small components (--min-component); holes (each closed "
      "by a patch refined and faired into the surface, else triangulated, else a planar cap); "
      "orientation; self-intersection check. Prints what each step did; refuses (exit 2, "
      "nothing written) naming the step and the first place when it cannot finish.");
  c->add_option("MESH", o->mesh, "Mesh file (STL, OBJ, PLY)")->required();
  c->add_option("-o,--output", o->out, "Repaired mesh to write (.stl, .obj or .ply)")->required();
  c->add_flag("--json", o->json, "Print the report as JSON on stdout");
  c->add_option("--min-component", o->repair.min_component,
                "Remove components with fewer triangles than this fraction of the largest "
                "one's (fins, loose triangles, debris); 0 keeps all")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  add_weld_option(c, o->read.weld_tolerance);
  c->callback([o] {
    const RepairJobResult r = run_repair_job(o->mesh, o->out, o->read, o->repair);
    if (o->json) {
      std::cout << r.report.dump(2) << "\n";
      return;
    }
    const RepairReport& p = r.repair;
    std::printf("weld: %zu vertices merged\n", r.read.merged_vertices);
    std::printf(
        "duplicates: %d triangles with a repeated corner, %d further copies, %d double-wall "
        "triangles removed\n",
        p.repeated_vertex_triangles + static_cast<int>(r.read.removed_triangles),
        p.duplicate_triangles, p.double_wall_triangles);
    std::printf("non-manifold: %d edges shared by more than two triangles; %d vertices split\n",
                p.nonmanifold_edges, p.split_vertices);
    std::printf("degenerate: %d zero-area triangles collapsed\n", p.degenerate_triangles);
    std::printf("small components: %d removed (%d triangles)\n", p.small_components,
                p.small_component_triangles);
    std::printf("holes: %d closed\n", p.holes);
    for (const RepairHole& h : p.closed_holes)
      std::printf("  %d edges at (%s, %s, %s): %s\n", h.edges, format_number(h.at.x(), 6).c_str(),
                  format_number(h.at.y(), 6).c_str(), format_number(h.at.z(), 6).c_str(),
                  h.method.c_str());
    std::printf("orientation: %s\n", p.reoriented ? "re-oriented" : "kept");
    std::printf("wrote %s: %zu triangles; boundary edges %d -> %d, volume %s -> %s\n",
                o->out.c_str(), r.triangles, p.boundary_edges_before, p.boundary_edges_after,
                format_number(p.volume_before, 6).c_str(),
                format_number(p.volume_after, 6).c_str());
  });
}

}  // namespace clumpkit::cli
