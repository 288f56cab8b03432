// `clumpkit refine MESH --triangles N -o OUT`: the same surface with at least N triangles.
#include "geom/mesh/refine.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/cli/common.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/output_dir.h"

#include <cstdio>
#include <memory>

namespace clumpkit::cli {

void register_refine(CLI::App& app) {
  struct Opts {
    std::string mesh, out;
    std::int64_t triangles = 0;
    MeshReadOptions read;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "refine",
      "Subdivide a closed mesh to at least N triangles without changing its shape (every "
      "triangle split in four at its edge midpoints, as often as needed; planar faces stay "
      "planar): scan-sized meshes for testing fills.");
  c->add_option("MESH", o->mesh, "Closed mesh (STL, OBJ, PLY)")->required();
  c->add_option("--triangles", o->triangles, "At least this many triangles (1 to 5e7)")->required();
  c->add_option("-o,--output", o->out, "Mesh to write (.stl, .obj or .ply)")->required();
  add_weld_option(c, o->read.weld_tolerance);
  c->callback([o] {
    if (o->triangles < 1)
      throw InvalidInput("--triangles must be at least 1, got " + std::to_string(o->triangles));
    check_not_input(o->out, "--output", o->mesh);
    MeshReadReport report;
    const Mesh mesh = read_mesh(o->mesh, &report, o->read);
    for (const std::string& line : mesh_read_notes(o->mesh, report)) note(line);
    const Mesh fine = refine(mesh, o->triangles);
    write_mesh(o->out, fine);
    std::printf("wrote %s: %zu triangles (from %zu), volume %s\n", o->out.c_str(),
                fine.triangles.size(), mesh.triangles.size(),
                format_number(signed_volume(fine)).c_str());
  });
}

}  // namespace clumpkit::cli
