// `clumpkit shapes --recipe R.toml --out DIR`: a shape library from a recipe.
#include "io/pipeline/shapes.h"
#include "io/base/units.h"
#include "io/cli/common.h"
#include "io/recipes/recipe.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_shapes(CLI::App& app) {
  struct Opts {
    RecipeJobOptions run;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "shapes",
      "Generate a shape library from a recipe (TOML, lengths in m): DIR/meshes/NNNNN.stl, "
      "DIR/shapes.csv (parameters + descriptors per particle), DIR/manifest.json. Same seed, same "
      "bytes, for any --threads.");
  add_recipe_job_options(c, o->run, "Shape recipe (see assets/recipes/)", JobKind::parallel,
                         "Print a JSON summary on stdout");
  c->callback([o] {
    set_threads(o->run.job.threads);
    const ShapeRecipe recipe = read_shape_recipe(o->run.recipe);
    ProgressBar bar("shapes", o->run.job.quiet);
    const auto r = run_shape_batch(recipe, o->run.out, signal_interrupter(bar, "shapes"));
    bar.finish();
    if (o->run.job.json) {
      nlohmann::ordered_json j = {{"particles", r.particles}, {"out", r.out_dir}};
      add_units(j, si_length());
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf("wrote %zu particles to %s (meshes/, shapes.csv, manifest.json)\n", r.particles,
                  r.out_dir.c_str());
    }
    finish_page(o->run);
  });
}

}  // namespace clumpkit::cli
