// `clumpkit export FORMAT SRC --out DIR`: a specimen, library or clump into a DEM engine.
#include "io/pipeline/export.h"
#include "geom/errors.h"
#include "io/base/units.h"
#include "io/cli/common.h"
#include "io/export/formats.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace clumpkit::cli {

void register_export(CLI::App& app) {
  struct Opts {
    std::string format, source, out, test, tile;
    bool json = false;
    ExportOptions options;
  };
  auto o = std::make_shared<Opts>();
  std::string about =
      "A specimen directory (from `clumpkit specimen`), a clump library (from `clumpkit "
      "library`: its templates) or one clump CSV into a DEM engine, with clumpkit's exact "
      "mass properties forced on the engine. A library or clump is laid out one body per "
      "template on a grid in a container made for it; for lammps it also gets molecule "
      "templates (clump_NNNNN.mol, molecules.csv) and in.deposit (fix deposit ... mol).";
  for (const ExportFormat& f : export_formats())
    about += std::string(" ") + f.name + ": " + f.files + ".";
  about += " Written in DIR.partial, renamed at the end.";
  auto* c = app.add_subcommand("export", about);
  c->add_option("FORMAT", o->format, export_format_names(" or "))->required();
  c->add_option("SRC", o->source, "Specimen directory, library directory or clump CSV")->required();
  c->add_option("--out", o->out, "Output directory")->required();
  c->add_option("--test", o->test,
                "lammps only: oedometer (after the settle, a top platen at a constant strain "
                "rate; strain and vertical stress in oedometer.csv) or cpt (the cone "
                "penetration test of --recipe, no settle: the probe pushed from the specimen's "
                "top in the probe's frame, tip and sleeve forces apart in cpt.csv with the "
                "columns of `clumpkit test cpt`'s curve.csv; lid and lateral wall held at the "
                "recipe's confining stress, base fixed (BC1); segments keep their radial walls; "
                "stiffness ∝ d as one atom type per size class)")
      ->check(CLI::IsMember({"oedometer", "cpt"}));
  c->add_option("--recipe", o->options.cpt_recipe,
                "--test cpt: the test recipe with its [probe] (as for `clumpkit test cpt`)");
  c->add_option("--max-strain", o->options.lammps.max_strain,
                "Oedometer: the vertical strain the platen stops at")
      ->capture_default_str();
  c->add_option("--strain-rate", o->options.lammps.strain_rate, "Oedometer: strain rate (1/s)")
      ->capture_default_str();
  c->add_option("--tile", o->tile,
                "lammps only: NXxNY copies of the specimen side by side in one box (a scale-out "
                "run; the box's side planes replace the cylinders), e.g. 6x6");
  c->add_option("--density", o->options.source.density,
                "Library or clump CSV (required there): the particle density in kg/m3; mass "
                "and inertia are this times the exact union volume and moments of its spheres");
  c->add_option("--length-unit", o->options.source.length_unit,
                "Library or clump CSV: what the file's numbers are, m (default) or mm; exports "
                "are SI");
  c->add_option("--mass", o->options.source.mass,
                "Library or clump CSV: clump (default: density x V_clump) or mesh (Jin et al. "
                "2017 §2.2's mass equivalence: density x V_mesh, moments scaled alike; a clump "
                "CSV needs its mesh STEM.stl beside it)");
  c->add_flag("--json", o->json, "Print format, bodies, spheres, files and run as JSON");
  c->callback([o] {
    o->options.lammps.oedometer = o->test == "oedometer";
    if ((o->test == "cpt") != !o->options.cpt_recipe.empty())
      throw InvalidInput(o->test == "cpt" ? "export: --test cpt needs --recipe TEST.toml"
                                          : "export: --recipe is for --test cpt");
    if (!o->tile.empty()) {
      const std::size_t x = o->tile.find('x');
      try {
        std::size_t used_x = 0, used_y = 0;
        o->options.lammps.tiles_x = std::stoi(o->tile.substr(0, x), &used_x);
        o->options.lammps.tiles_y = std::stoi(o->tile.substr(x + 1), &used_y);
        if (x == std::string::npos || used_x != x || used_y != o->tile.size() - x - 1)
          throw std::invalid_argument("tile");
      } catch (const std::exception&) {
        throw InvalidInput("export: --tile must be NXxNY, e.g. 6x6, got '" + o->tile + "'");
      }
    }
    const ExportResult r = run_export(o->format, o->source, o->out, o->options);
    if (o->json) {
      nlohmann::ordered_json j{{"format", r.format},
                               {"bodies", r.bodies},
                               {"spheres", r.spheres},
                               {"files", r.files},
                               {"run", r.run}};
      add_units(j, si_length());
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("exported %zu bodies (%zu spheres) for %s to %s; run: cd %s && %s\n", r.bodies,
                  r.spheres, r.format.c_str(), o->out.c_str(), o->out.c_str(), r.run.c_str());
    }
  });
}

}  // namespace clumpkit::cli
