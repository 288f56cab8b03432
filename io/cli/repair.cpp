// `clumpkit repair MESH -o OUT`: a mesh closed and oriented into a solid that the other
// commands accept.
#include "io/pipeline/repair.h"
#include "geom/format.h"
#include "io/base/units.h"
#include "io/cli/common.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_repair(CLI::App& app) {
  struct Opts {
    std::string mesh, out, wrap, length_unit = "L";
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
      "volume (a sheet or loose faces, enclosing nothing, are refused); self-intersections "
      "(crossings within a shell removed and re-closed locally in rounds, shells through each "
      "other joined by their union); wrap (--wrap: what still crosses replaced by an alpha wrap "
      "of the closed surface); orientation; self-intersection check. Prints what each step did "
      "and, when the surface changed beyond welding and hole closing, the volume before and "
      "after and the distance from the result to the input; refuses (exit 2, nothing written) "
      "naming the step and the first place when it cannot finish.");
  c->add_option("MESH", o->mesh, "Mesh file (STL, OBJ, PLY)")->required();
  c->add_option("-o,--output", o->out, "Repaired mesh to write (.stl, .obj or .ply)")->required();
  c->add_flag("--json", o->json, "Print the report as JSON on stdout");
  add_repair_options(c, o->repair, o->wrap);
  add_weld_option(c, o->read.weld_tolerance);
  add_length_unit_option(c, o->length_unit);
  c->callback([o] {
    const LengthUnit length = length_unit(o->length_unit);
    const RepairJobResult r =
        run_repair_job(o->mesh, o->out, o->read, repair_options_from(o->repair, o->wrap), length);
    for (const std::string& w : r.repair.warnings) warning(o->out + ": " + w);
    if (o->json) {
      std::cout << r.report.dump(2) << "\n";
      return;
    }
    for (const std::string& line : repair_lines(r.repair, r.read, length))
      std::printf("%s\n", line.c_str());
    const RepairReport& p = r.repair;
    std::printf("wrote %s: %zu triangles; boundary edges %d -> %d, volume %s -> %s %s; %.2f s\n",
                o->out.c_str(), r.triangles, p.boundary_edges_before, p.boundary_edges_after,
                format_number(p.volume_before, 6).c_str(), format_number(p.volume_after, 6).c_str(),
                length.pow(3).c_str(), r.seconds);
  });
}

}  // namespace clumpkit::cli
