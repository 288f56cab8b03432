// `clumpkit specimen --recipe R.toml --out DIR`: a DEM specimen at a target relative density.
#include "geom/errors.h"
#include "io/atomic_file.h"
#include "io/cli/common.h"
#include "io/library.h"
#include "io/recipe.h"
#include "io/shape_batch.h"
#include "io/specimen_io.h"
#include "io/specimen_recipe.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

namespace fs = std::filesystem;

void register_specimen(CLI::App& app) {
  struct Opts {
    std::string recipe, out;
    int threads = 0;
    double checkpoint_seconds = 60;
    bool resume = false, quiet = false, json = false;
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
      "--checkpoint-seconds); a killed run continues with --resume to the same bytes. Same seed, "
      "same bytes, for any --threads.");
  c->add_option("--recipe", o->recipe, "Specimen recipe file (see assets/recipes/)")->required();
  c->add_option("--out", o->out, "Output directory")->required();
  c->add_option("--threads", o->threads, "Worker threads (0 = all cores)")->capture_default_str();
  c->add_option("--checkpoint-seconds", o->checkpoint_seconds,
                "Wall-clock seconds between checkpoints of a running stage")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  c->add_flag("--resume", o->resume, "Continue a killed run from DIR.partial");
  c->add_flag("--quiet", o->quiet, "No progress bar");
  c->add_flag("--json", o->json, "Print report.json on stdout");
  c->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    set_threads(o->threads);
    const SpecimenRecipe recipe = read_specimen_recipe(o->recipe);
    const fs::path out = o->out;
    check_output_directory(o->out);
    const fs::path staging = o->out + ".partial";
    if (!o->resume) fs::remove_all(staging);
    fs::create_directories(staging);

    ProgressBar bar("specimen", o->quiet);
    // The rock library: given, or built (resumable) into the output.
    std::string library = recipe.library;
    if (library.empty() && !recipe.library_recipe.empty()) {
      const fs::path lib = staging / "library";
      if (!(o->resume && fs::exists(lib / "library.json"))) {
        bar.set_label("specimen: rock library");
        run_library(read_shape_recipe(recipe.library_recipe), lib.string(), {},
                    [&](std::size_t d, std::size_t t) { bar.update(d, t); });
      }
      library = lib.string();
    }
    std::vector<dem::RockTemplate> templates;
    if (!library.empty()) templates = read_rock_templates(library);
    const dem::SpecimenSpec spec = specimen_spec(recipe, std::move(templates));

    dem::SpecimenControl control;
    control.checkpoint_dir = (staging / "checkpoints").string();
    control.resume = o->resume;
    control.checkpoint_every_seconds = o->checkpoint_seconds;
    control.progress = [&](const std::string& stage, double fraction) {
      bar.set_label("specimen: " + stage);
      bar.update(static_cast<std::size_t>(1000 * fraction), 1000);
    };
    const dem::SpecimenResult result = dem::build_specimen(spec, control);
    bar.finish();

    write_specimen_csv((staging / "specimen.csv").string(), result);
    write_specimen_vtp((staging / "specimen.vtp").string(), result);
    write_calibration_csv((staging / "calibration.csv").string(), result);
    write_calibration_plot((staging / "calibration.png").string(), result,
                           recipe.target_relative_density);
    std::vector<double> heights;
    const int slices = 2 * recipe.layers + 1;
    for (int k = 1; k <= slices; ++k) heights.push_back(result.height * k / (slices + 1));
    write_slices((staging / "slices").string(), result, spec.radius, heights);
    nlohmann::ordered_json report = specimen_report(recipe, result);
    report["library"] = library.rfind(staging.string(), 0) == 0
                            ? (out / fs::path(library).filename()).string()
                            : library;
    report["seconds"]["total"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_file_atomically((staging / "report.json").string(),
                          [&](std::ostream& s) { s << report.dump(2) << "\n"; });
    nlohmann::ordered_json manifest;
    manifest["tool"] = "clumpkit";
    manifest["format_version"] = kManifestFormat;
    manifest["version"] = CLUMPKIT_VERSION;
    manifest["command"] = "specimen";
    manifest["recipe_path"] = recipe.path;
    manifest["recipe"] = recipe.text;
    manifest["seed"] = recipe.seed;
    write_file_atomically((staging / "manifest.json").string(),
                          [&](std::ostream& s) { s << manifest.dump(2) << "\n"; });
    fs::remove_all(staging / "checkpoints");
    publish_directory(staging.string(), o->out);

    if (o->json) {
      std::cout << report.dump(2) << "\n";
    } else {
      std::printf(
          "specimen %s: %zu bodies, porosity %.4f, relative density %.3f (target %.2f), height "
          "%.4f m, mu* %.3f, %.0f s\n",
          o->out.c_str(), result.world.bodies().size(), result.porosity, result.relative_density,
          recipe.target_relative_density, result.height, result.friction_compaction,
          report["seconds"]["total"].get<double>());
    }
  });
}

}  // namespace clumpkit::cli
