// What every `clumpkit test` job does before its test runs: the specimen directory read, the
// contact law, the quasi-static check, the specimen in its cell, DIR.partial and its
// checkpoint store.
#pragma once

#include "dem/lab/element_loading.h"
#include "io/pipeline/stage_files.h"
#include "io/recipes/lab_recipe.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace clumpkit {

/// Options of a test job (element test, CPT).
struct LabJobOptions {
  /// Continue the work kept in DIR.partial (its checkpoint; refused, naming both fingerprints,
  /// when it was made by another test, recipe, specimen or version; without one it starts
  /// afresh, saying so).
  bool resume = false;
  /// Wall-clock seconds between checkpoints (0: only when interrupted).
  double checkpoint_seconds = dem::StageControl{}.checkpoint_every_seconds;
  /// Run a test whose inertial number I = ε̇·d·sqrt(ρ/σ3) exceeds 1e-2 (refused otherwise: a
  /// dynamic test, not a quasi-static element test).
  bool allow_dynamic = false;
  /// Also write DIR/consolidated: the specimen at the end of consolidation as a specimen
  /// directory (specimen.csv, report.json, manifest.json) that `clumpkit export` reads — the
  /// cylinder cell as its container (bottom platen at z = 0), gravity 0, the test's contact law
  /// with the specimen's viscous damping ratio — so another engine can run the same test from
  /// the same state (for the CPT, the state its probe starts from). Cylinder cells only (exports
  /// model cylinders).
  bool save_consolidated = false;
};

/// What a test job (element test, CPT) did: report.json as written, and whether it continued a
/// checkpoint (with --resume, the reason it could not, when it started afresh).
struct LabJobResult {
  nlohmann::ordered_json report;
  bool resumed = false;
  std::string afresh_reason;
};

/// A test ready to run.
struct TestSetup {
  nlohmann::json spec_report;  ///< the specimen's report.json
  std::string report_path;
  std::size_t bodies = 0;
  dem::WorldOptions options;  ///< the test's world options (element_test_world_options)
  double inertial = 0;        ///< inertial number of the test's strain rate
  std::string fingerprint;    ///< of the test kind, recipe, specimen and version
  std::filesystem::path out;  ///< DIR.partial
  std::unique_ptr<StageFiles> stages;
  dem::StageControl control;   ///< checkpoints into `stages`
  dem::CellSpecimen specimen;  ///< the bodies in their cell, the time step set
};

/// Reads the specimen in `specimen_dir` (specimen.csv, report.json), builds its world with the
/// recipe's contact law in its container as a frictionless cell (a cuboid at its recorded box,
/// else a cylinder of its diameter between the specimen's bottom and top), refuses an inertial
/// number of `strain_rate` (named `rate_field` in the message) above 1e-2 unless
/// `allow_dynamic`, calls `validate` (which throws for what the test cannot do), and only then
/// opens DIR.partial (afresh, or kept with `resume`) and its checkpoint store.
TestSetup setup_test(
    const std::string& kind, const std::string& specimen_dir, const TestRecipe& recipe,
    const std::string& out_dir, bool resume, double checkpoint_seconds, bool allow_dynamic,
    double strain_rate, const std::string& rate_field, const Interrupter& interrupter,
    const std::function<void(const nlohmann::json& spec_report, const std::string& report_path,
                             const dem::CellSpecimen& specimen)>& validate = {});

/// The end of a test job: report.json and manifest.json (command "test", the recipe, `test`,
/// the specimen, `files` besides them) written into DIR.partial, DIR.partial published as
/// `out_dir`, and what the job did (with `resume` but no checkpoint found, the reason it
/// started afresh).
LabJobResult finish_test_job(const TestSetup& setup, const std::string& out_dir,
                             const TestRecipe& recipe, const std::string& test,
                             const std::string& specimen_dir, const nlohmann::ordered_json& report,
                             const std::vector<std::string>& files, bool resume, bool resumed);

/// The radius of the core of small particles of a specimen zoned radially about the probe's
/// axis, from its report.json (0: not zoned so). Throws InvalidInput naming `report_path` for a
/// radial zoning without its first region's outer bound.
double radial_core_radius(const nlohmann::json& report, const std::string& report_path);

}  // namespace clumpkit
