// What every `clumpkit test` job does before its test runs: the specimen directory read, the
// contact law, the quasi-static check, the specimen in its cell, DIR.partial and its
// checkpoint store.
#pragma once

#include "dem/lab/element_test.h"
#include "io/pipeline/element_test.h"
#include "io/pipeline/job.h"
#include "io/pipeline/stage_files.h"
#include "io/recipes/test_recipe.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace clumpkit {

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
ElementTestJobResult finish_test_job(const TestSetup& setup, const std::string& out_dir,
                                     const TestRecipe& recipe, const std::string& test,
                                     const std::string& specimen_dir,
                                     const nlohmann::ordered_json& report,
                                     const std::vector<std::string>& files, bool resume,
                                     bool resumed);

}  // namespace clumpkit
