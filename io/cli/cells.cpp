// `clumpkit cells MESH (--cell-size L | --count N) --seed S --out DIR`: Voronoi cells of a convex
// particle, bonded on their shared faces (Hu et al. 2023).
#include "io/pipeline/cells.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/cli/common.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_cells(CLI::App& app) {
  struct Opts {
    CellsJobOptions job;
    double strength_sd = 0.125;
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "cells",
      "Cut a convex particle (STL, OBJ, PLY; units of the mesh) into Voronoi cells glued face to "
      "face, the crushable particle of Hu et al. 2023: seeds uniform in the particle, Lloyd "
      "steps toward cells of similar size, cells clipped by the particle's faces (voro++), "
      "exact mass properties per cell, one bond per shared face with one integration point per "
      "fan triangle and a strength factor. Writes DIR/cells.vtp (colour by 'cell'), cells.csv, "
      "bonds.csv, bond_points.csv, report.json, manifest.json. A non-convex mesh is refused.");
  c->add_option("MESH", o->job.mesh, "Convex closed mesh")->required();
  auto* size =
      c->add_option("--cell-size", o->job.cells.cell_size,
                    "Cell size ℓ (volume-equivalent diameter of a cell): N = round((D/ℓ)³) "
                    "cells for a parent of volume-equivalent diameter D (Hu et al. 2023: "
                    "ℓ ≈ 6.5 mm)");
  auto* count = c->add_option("--count", o->job.cells.count, "Number of cells, at least 2");
  size->excludes(count);
  c->add_option("--seed", o->job.seed, "Random seed")->capture_default_str();
  c->add_option("--lloyd", o->job.cells.lloyd,
                "Lloyd steps (seeds moved to their cells' centroids); 0 keeps Poisson-Voronoi "
                "cells")
      ->capture_default_str();
  c->add_option("--strength-sd", o->strength_sd,
                "Spread of the bonds' strength factors: normal with mean 1 and this standard "
                "deviation, truncated to 1 ± 2 sd (the paper's [0.75, 1.25] at the default); 0 "
                "gives every bond factor 1")
      ->capture_default_str();
  c->add_option("--out", o->job.out, "Output directory")->required();
  c->add_flag("--json", o->json, "Print the report as one JSON object on stdout");
  add_weld_option(c, o->job.read.weld_tolerance);
  c->callback([o] {
    if (!(o->strength_sd >= 0.0 && o->strength_sd <= 0.5))
      throw InvalidInput("--strength-sd must be in [0, 0.5], got " + format_number(o->strength_sd));
    if (o->strength_sd == 0.0) {
      o->job.strength = constant(1.0);
    } else {
      o->job.strength = default_strength_factor();
      o->job.strength.b = o->strength_sd;
      o->job.strength.min = 1.0 - 2.0 * o->strength_sd;
      o->job.strength.max = 1.0 + 2.0 * o->strength_sd;
    }
    const nlohmann::ordered_json r = run_cells_job(o->job, note);
    if (o->json) {
      std::cout << r.dump(2) << "\n";
      return;
    }
    std::printf(
        "wrote %s: %d cells (mean diameter %s, volume CV %.3f, %.1f faces each), %d bonds with "
        "%d points; cells' volume %s against the parent's %s (relative error %.2g), %.3f s\n",
        o->job.out.c_str(), r["cells"].get<int>(),
        format_number(r["cell_diameter"].get<double>(), 4).c_str(),
        r["cell_volume_cv"].get<double>(), r["faces_per_cell"].get<double>(), r["bonds"].get<int>(),
        r["bond_points"].get<int>(), format_number(r["cells_volume"].get<double>(), 10).c_str(),
        format_number(r["parent_volume"].get<double>(), 10).c_str(),
        r["volume_error"].get<double>(), r["seconds"].get<double>());
  });
}

}  // namespace clumpkit::cli
