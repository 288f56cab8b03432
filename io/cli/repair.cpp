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
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "repair",
      "Turn a scanned or exported mesh into a closed solid: weld vertices (--weld-tolerance), "
      "drop triangles with a repeated corner and second copies of a triangle, collapse zero-area "
      "triangles, close every hole with a patch refined and faired into the surface (CGAL "
      "triangulate_refine_and_fair_hole), orient it to bound a volume. Prints the boundary "
      "edges and the volume before and after; refuses (exit 2, nothing written) when the result "
      "intersects itself.");
  c->add_option("MESH", o->mesh, "Mesh file (STL, OBJ, PLY)")->required();
  c->add_option("-o,--output", o->out, "Repaired mesh to write (.stl, .obj or .ply)")->required();
  c->add_flag("--json", o->json, "Print the report as JSON on stdout");
  add_weld_option(c, o->read.weld_tolerance);
  c->callback([o] {
    const RepairJobResult r = run_repair_job(o->mesh, o->out, o->read);
    if (o->json) {
      std::cout << r.report.dump(2) << "\n";
      return;
    }
    std::printf(
        "wrote %s: %zu triangles; boundary edges %d -> %d, volume %s -> %s (%d holes closed, "
        "%zu vertices merged, %d duplicate and %d degenerate triangles removed%s)\n",
        o->out.c_str(), r.triangles, r.repair.boundary_edges_before, r.repair.boundary_edges_after,
        format_number(r.repair.volume_before, 6).c_str(),
        format_number(r.repair.volume_after, 6).c_str(), r.repair.holes, r.read.merged_vertices,
        r.repair.duplicate_triangles,
        r.repair.degenerate_triangles + r.repair.repeated_vertex_triangles +
            static_cast<int>(r.read.removed_triangles),
        r.repair.reoriented ? ", re-oriented" : "");
  });
}

}  // namespace clumpkit::cli
