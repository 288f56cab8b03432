#include "io/pipeline/specimen.h"

#include "dem/measure/fragment_sizes.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"
#include "io/formats/bonds_csv.h"
#include "io/formats/library_table.h"
#include "io/formats/specimen_csv.h"
#include "io/formats/specimen_vtp.h"
#include "io/pipeline/library.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"
#include "io/pipeline/stage_files.h"
#include "io/recipes/recipe.h"
#include "io/recipes/specimen_build.h"
#include "io/reports/specimen_report.h"

#include <cmath>
#include <filesystem>
#include <vector>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

/// The report's library entry: where the library will be once DIR.partial is published.
std::string library_entry(const std::string& library, const fs::path& staging,
                          const fs::path& out) {
  return library.rfind(staging.string(), 0) == 0 ? (out / fs::path(library).filename()).string()
                                                 : library;
}

/// report.json (with the total seconds since `started`) and manifest.json into `staging`.
void write_report_and_manifest(const fs::path& staging, const SpecimenRecipe& recipe,
                               nlohmann::ordered_json& report,
                               std::chrono::steady_clock::time_point started) {
  report["seconds"]["total"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  add_units(report, si_length());
  write_file_atomically((staging / "report.json").string(),
                        [&](std::ostream& s) { s << report.dump(2) << "\n"; });
  nlohmann::ordered_json manifest =
      manifest_head("specimen", recipe.path, recipe.text, recipe.seed);
  add_units(manifest, si_length());
  write_file_atomically((staging / "manifest.json").string(),
                        [&](std::ostream& s) { s << manifest.dump(2) << "\n"; });
}

/// A gravity-free specimen (preparation.method = "compression"): one stage, checkpointed in
/// DIR.partial/checkpoints like the stages of a deposited specimen; its files go to DIR.partial,
/// published at the end.
SpecimenJobResult compress_into(const SpecimenRecipe& recipe, const std::string& out_dir,
                                const fs::path& staging, std::vector<dem::RockTemplate> templates,
                                const std::string& library, const dem::StageControl& control,
                                std::chrono::steady_clock::time_point started) {
  const dem::CompressionResult result =
      dem::compress_specimen(compression_spec(recipe, std::move(templates)), control);
  const std::vector<SpecimenBody> bodies = specimen_bodies(result.world);
  write_specimen_csv((staging / "specimen.csv").string(), bodies);
  write_specimen_vtp((staging / "specimen.vtp").string(), bodies);
  nlohmann::ordered_json report = compression_report(recipe, result);
  if (recipe.crushable) {  // the bonds between the cells, beside specimen.csv
    const dem::World& w = result.world;
    write_bonds_csv((staging / "bonds.csv").string(), {w.options().cohesive, w.bonds()});
    const dem::CohesiveParams& l = w.options().cohesive;
    report["crushable"] = {{"particles", dem::fragment_pieces(w.bodies(), w.bonds()).size()},
                           {"cells", w.bodies().size()},
                           {"bonds", w.bonds().size()},
                           {"bond_scale", recipe.bond_scale},
                           {"bond_law",
                            {{"kn", l.kn},
                             {"kt", l.kt},
                             {"sigma_n", l.sigma_n},
                             {"sigma_t", l.sigma_t},
                             {"g_n", l.g_n},
                             {"g_t", l.g_t},
                             {"friction", l.friction}}}};
  }
  if (!library.empty()) report["library"] = library_entry(library, staging, out_dir);
  write_report_and_manifest(staging, recipe, report, started);
  fs::remove_all(staging / "checkpoints");
  publish_directory(staging.string(), out_dir);
  SpecimenJobResult job;
  job.specimen.world = result.world;
  job.specimen.porosity = result.porosity;
  job.specimen.height = result.height;
  job.specimen.coordination = result.coordination;
  job.report = std::move(report);
  return job;
}

/// The job inside DIR.partial (`staging`), published to `out_dir` at the end.
SpecimenJobResult build_into(const SpecimenRecipe& recipe, const std::string& out_dir,
                             const fs::path& staging, const SpecimenJobOptions& options,
                             const Interrupter& interrupter,
                             std::chrono::steady_clock::time_point started) {
  const fs::path out = out_dir;
  // The rock library: given, or built (resumable) into the output.
  std::string library = recipe.library;
  if (library.empty() && !recipe.library_recipe.empty()) {
    const fs::path lib = staging / "library";
    if (!(options.resume && fs::exists(lib / "manifest.json"))) {
      LibraryOptions lo;
      lo.max_memory_bytes = options.max_memory_bytes;
      run_library(read_shape_recipe(recipe.library_recipe), lib.string(), lo, interrupter);
    }
    library = lib.string();
  }
  std::vector<dem::RockTemplate> templates;
  if (!library.empty()) templates = read_rock_templates(library);
  StageFiles stages((staging / "checkpoints").string(), options.resume);
  dem::StageControl control;
  control.store = &stages;
  control.checkpoint_every_seconds = options.checkpoint_seconds;
  control.interrupter = interrupter;
  if (recipe.compression)
    return compress_into(recipe, out_dir, staging, std::move(templates), library, control, started);
  const dem::SpecimenSpec spec = specimen_spec(recipe, std::move(templates));
  SpecimenJobResult job;
  job.specimen = dem::build_specimen(spec, control);
  const dem::SpecimenResult& result = job.specimen;

  const std::vector<SpecimenBody> bodies = specimen_bodies(result);
  write_specimen_csv((staging / "specimen.csv").string(), bodies);
  write_specimen_vtp((staging / "specimen.vtp").string(), bodies);
  write_calibration_csv((staging / "calibration.csv").string(), result);
  write_calibration_plot((staging / "calibration.png").string(), result,
                         recipe.target_relative_density);
  std::vector<double> heights;
  const int slices = 2 * recipe.layers + 1;
  for (int k = 1; k <= slices; ++k) heights.push_back(result.height * k / (slices + 1));
  write_slices((staging / "slices").string(), result, spec.radius, heights);
  nlohmann::ordered_json report = specimen_report(recipe, result);
  report["library"] = library_entry(library, staging, out);
  write_report_and_manifest(staging, recipe, report, started);
  fs::remove_all(staging / "checkpoints");
  publish_directory(staging.string(), out_dir);
  job.report = std::move(report);
  return job;
}

}  // namespace

double estimated_specimen_bytes(const dem::SpecimenSpec& spec, double container_volume) {
  // Bodies ≈ the container's solid volume shared out by mass over the classes, each class's
  // particles of the volume of its mean sieve size; about 2.2 KiB per body (the body, its spheres,
  // contacts and neighbour lists), held three times (calibration, layer and specimen worlds).
  // Measured on srm40-triaxial (tests/bench/RESULTS.md, "Memory estimate"): a peak of 329 MiB for
  // 51,147 bodies and 108,693 spheres, estimated 0.343 GiB (351 MiB, +7 %) from 54,600 bodies.
  const double solid = container_volume * (1 - spec.porosity_guess);
  double bodies = 0;
  for (const dem::ParticleClass& c : spec.classes) {
    const double d = 0.5 * (c.min_size + c.max_size);
    bodies += 0.01 * c.mass_percent * solid / (M_PI / 6 * d * d * d);
  }
  return 3 * 2253 * bodies;
}

SpecimenJobResult run_specimen(const SpecimenRecipe& recipe, const std::string& out_dir,
                               const SpecimenJobOptions& options, const Interrupter& interrupter,
                               std::chrono::steady_clock::time_point started) {
  check_output_directory(out_dir);
  if (options.max_memory_bytes > 0) {
    const auto& e = recipe.container_size;
    const double sector = recipe.segment ? recipe.segment_angle_deg / 360.0 : 1.0;
    const double volume = recipe.cuboid ? e[0] * e[1] * e[2]
                                        : sector * M_PI / 4 * recipe.container_diameter *
                                              recipe.container_diameter * recipe.container_height;
    const double need = estimated_specimen_bytes(specimen_spec(recipe, {}), volume);
    if (!(need <= options.max_memory_bytes))
      throw InvalidInput(
          recipe.path + ": the specimen would need about " + format_number(need / 1073741824.0, 3) +
          " GiB (estimated from the container and the gradation), over --max-memory " +
          format_number(options.max_memory_bytes / 1073741824.0, 3) + " GiB");
  }
  const fs::path staging = out_dir + ".partial";
  if (!options.resume) fs::remove_all(staging);
  remove_stray_temporaries(staging.string());  // a killed run's half-written files
  fs::create_directories(staging);

  try {
    return build_into(recipe, out_dir, staging, options, interrupter, started);
  } catch (const Interrupted& e) {
    throw Interrupted(std::string(e.what()) + "; " + staging.string() +
                      " is kept: continue with --resume");
  }
}

}  // namespace clumpkit
