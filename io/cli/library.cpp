// `clumpkit library --recipe R.toml --out DIR`: shapes + sphere fill + fidelity per particle.
#include "io/pipeline/library.h"
#include "io/base/units.h"
#include "io/cli/common.h"
#include "io/recipes/recipe.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_library(CLI::App& app) {
  struct Opts {
    RecipeJobOptions run;
    double max_memory_gib = 0;  // 0: half of this machine's memory
    bool png = false, vtp = false, repair = false;
    RepairOptions repair_options;
    std::string wrap;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "library",
      "Clump library from a recipe (TOML, lengths in m; [fill] table for the sphere fill): "
      "DIR/particles/NNNNN.stl (mesh), NNNNN.csv (clump x,y,z,r), NNNNN.json (record), "
      "DIR/library.csv, DIR/recipe.toml and DIR/manifest.json, written in DIR.partial and renamed "
      "at "
      "the end. A killed or interrupted (Ctrl-C) run restarted with the same command resumes; "
      "same seed, same bytes, for any --threads.");
  add_recipe_job_options(c, o->run, "Shape recipe with a [fill] table (see assets/recipes/)",
                         JobKind::parallel, "Print a JSON summary on stdout");
  c->add_flag("--png", o->png,
              "Also write NNNNN.png (900 px: front, side, top and oblique views, spheres shaded "
              "and coloured under the translucent mesh) and DIR/contact_sheet.png (every "
              "particle, oblique)");
  c->add_flag("--vtp", o->vtp,
              "Also write NNNNN.vtp for ParaView: the mesh as polygons, the spheres as vertices "
              "with radius and diameter (Glyph: Sphere, Scale Array diameter, Scale Factor 1)");
  c->add_flag("--repair", o->repair,
              "Repair the files of mesh fractions (method = \"mesh\") in memory before their "
              "fill, as `clumpkit repair` does (holes closed, crossings mended, a wrap as the "
              "last resort), so a folder of raw scans becomes a library in one command; each "
              "NNNNN.json's `repair` says what it did");
  add_repair_options(c, o->repair_options, o->wrap);
  add_max_memory_option(c, o->max_memory_gib,
                        "a particle whose fill is estimated to need more than this many GiB "
                        "divided by the threads");
  c->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    set_threads(o->run.job.threads);
    const ShapeRecipe recipe = read_shape_recipe(o->run.recipe);
    ProgressBar bar("library", o->run.job.quiet);
    LibraryOptions lo;
    lo.png = o->png;
    lo.vtp = o->vtp;
    lo.max_memory_bytes = max_memory_bytes(o->max_memory_gib);
    lo.repair = o->repair;
    lo.repair_options = repair_options_from(o->repair_options, o->wrap);
    const auto r = run_library(recipe, o->run.out, lo, signal_interrupter(bar, "library"));
    bar.finish();
    warn_redone(o->run.out, r.redone);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (o->run.job.json) {
      nlohmann::ordered_json j = {{"particles", r.particles},
                                  {"resumed", r.resumed},
                                  {"out", r.out_dir},
                                  {"seconds", seconds}};
      add_units(j, si_length());
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf(
          "wrote %zu particles to %s (%zu kept from an earlier run) in %.1f s: particles/, "
          "library.csv, manifest.json\n",
          r.particles, r.out_dir.c_str(), r.resumed, seconds);
    }
    finish_page(o->run);
  });
}

}  // namespace clumpkit::cli
