// `clumpkit specimen --recipe R.toml --out DIR`: a DEM specimen at a target relative density.
#include "io/pipeline/specimen.h"
#include "io/cli/common.h"
#include "io/recipes/specimen_recipe.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_specimen(CLI::App& app) {
  struct Opts {
    RecipeJobOptions run;
    double max_memory_gib = 0;  // 0: half of this machine's memory
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "specimen",
      "DEM specimen from a recipe (TOML, SI units; see assets/recipes/srm40-triaxial.toml): "
      "calibration of porosity against friction by quasi-vibration compaction, one layer "
      "compacted to the target relative density, layered duplication, measurement. Writes "
      "DIR/specimen.csv (bodies, then spheres), specimen.vtp (ParaView: Glyph by radius), "
      "report.json (porosity, relative_density, target_relative_density, porosity_max, "
      "porosity_min, friction_compaction, height, bodies, spheres, layer_porosity, steps, "
      "seconds, ...), calibration.csv and calibration.png (n against mu), slices/*.png (rock "
      "red, soil blue) and manifest.json. Work goes to DIR.partial (checkpoints every "
      "--checkpoint-seconds, and on Ctrl-C); a killed or interrupted run continues with --resume "
      "to the same bytes. With [preparation] method = \"compression\" (gravity off; container "
      "shape cuboid with size = [x, y, z], or cylinder): the particles are placed loose in the "
      "container enlarged 1.4 times and compressed homogeneously by its rigid frictionless walls "
      "to the target porosity at preparation.friction (the specimens of `clumpkit test`); "
      "report.json gives porosity, coordination_number, mean_stress and the container box (no "
      "calibration or slices; it checkpoints and resumes the same way). Same seed, same bytes, for "
      "any --threads.");
  add_recipe_job_options(c, o->run, "Specimen recipe file (see assets/recipes/)", JobKind::staged,
                         "Print report.json on stdout");
  add_max_memory_option(c, o->max_memory_gib,
                        "a recipe whose estimated memory exceeds this many GiB");
  c->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    set_threads(o->run.job.threads);
    const SpecimenRecipe recipe = read_specimen_recipe(o->run.recipe);
    ProgressBar bar("specimen", o->run.job.quiet);
    SpecimenJobOptions options;
    options.resume = o->run.job.resume;
    options.checkpoint_seconds = o->run.job.checkpoint_seconds;
    options.max_memory_bytes = max_memory_bytes(o->max_memory_gib);
    const SpecimenJobResult job =
        run_specimen(recipe, o->run.out, options, signal_interrupter(bar, "specimen"), t0);
    bar.finish();
    const dem::SpecimenResult& result = job.specimen;
    const nlohmann::ordered_json& report = job.report;

    if (o->run.job.json) {
      std::cout << report.dump(2) << "\n";
    } else if (recipe.compression) {
      std::printf(
          "specimen %s: %zu bodies, porosity %.4f (compressed at mu %.3f), coordination %.2f, "
          "mean stress %.4g Pa, %.0f s\n",
          o->run.out.c_str(), result.world.bodies().size(), result.porosity,
          recipe.compression_friction, result.coordination, report["mean_stress"].get<double>(),
          report["seconds"]["total"].get<double>());
    } else {
      std::printf(
          "specimen %s: %zu bodies, porosity %.4f, relative density %.3f (target %.2f), height "
          "%.4f m, mu* %.3f, %.0f s\n",
          o->run.out.c_str(), result.world.bodies().size(), result.porosity,
          result.relative_density, recipe.target_relative_density, result.height,
          result.friction_compaction, report["seconds"]["total"].get<double>());
    }
    finish_page(o->run);
  });
}

}  // namespace clumpkit::cli
