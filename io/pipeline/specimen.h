// The specimen job: recipe -> rock library (given or built) -> dem::build_specimen -> the files
// of `clumpkit specimen` in DIR, written in DIR.partial and renamed at the end.
#pragma once

#include "dem/specimen/specimen.h"
#include "geom/progress.h"
#include "io/recipes/specimen_recipe.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <string>

namespace clumpkit {

struct SpecimenJobOptions {
  bool resume = false;  ///< continue from DIR.partial instead of starting afresh
  /// Wall-clock seconds between checkpoints of a stage (0: only when interrupted).
  double checkpoint_seconds = dem::StageControl{}.checkpoint_every_seconds;
  /// Refuse, before anything is built, a recipe whose estimated_specimen_bytes exceed this
  /// (0: no limit).
  double max_memory_bytes = 0;
};

/// A rough (within a few times) estimate of the memory a specimen build takes, from its
/// container's volume (m³) and gradation: bodies ≈ solid volume / mean particle volume per class,
/// 3 KiB each.
double estimated_specimen_bytes(const dem::SpecimenSpec& spec, double container_volume);

struct SpecimenJobResult {
  dem::SpecimenResult specimen;
  nlohmann::ordered_json report;  ///< report.json as written
};

/// Builds the specimen of `recipe` into `out`: the rock library (recipe.library, or built from
/// recipe.library_recipe into DIR.partial/library, resumable), the spec (specimen_spec), the
/// build (checkpoints in DIR.partial/checkpoints), then specimen.csv, specimen.vtp,
/// calibration.csv/.png, slices/, report.json and manifest.json; DIR.partial is renamed to DIR
/// at the end (check_output_directory decides whether an existing DIR may be replaced).
/// Without options.resume an old DIR.partial is removed first. The interrupter is told the stage
/// ("library", then the stages of dem::build_specimen) and the fraction of it (library) or of
/// the whole build done; asked to stop, the job keeps DIR.partial with its checkpoints (so
/// --resume goes on from there) and throws Interrupted. `started` is when the job began
/// (report.json's total seconds count from it).
SpecimenJobResult run_specimen(
    const SpecimenRecipe& recipe, const std::string& out, const SpecimenJobOptions& options,
    const Interrupter& interrupter = {},
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());

}  // namespace clumpkit
