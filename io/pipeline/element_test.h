// The job of `clumpkit test isotropic|oedometer|triaxial`: a specimen directory tested in a
// servo-controlled cell, written as curve.csv, curve.png, report.json and manifest.json.
#pragma once

#include "dem/element_test.h"
#include "geom/progress.h"
#include "io/test_recipe.h"

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

/// "isotropic", "oedometer" or "triaxial"; throws InvalidInput naming the known kinds.
dem::TestKind test_kind(const std::string& name);

/// Tests the specimen in `specimen_dir` (specimen.csv, report.json of `clumpkit specimen`) in
/// its container as a frictionless cylinder cell (radius from report.json, platens at the
/// specimen's bottom and top), gravity off, with the specimen's contact law unless the recipe
/// overrides it; see dem::run_element_test. Writes into `out_dir` (DIR.partial renamed at the
/// end, job.h): curve.csv (step, axial_strain, volumetric_strain, axial_stress_pa,
/// radial_stress_pa, p_pa, q_pa, porosity, coordination_number, unbalanced_force), curve.png,
/// report.json (returned) and manifest.json. The interrupter is told the stage ("consolidation"
/// or "loading") and stops the job with Interrupted.
nlohmann::ordered_json run_element_test_job(dem::TestKind kind, const std::string& specimen_dir,
                                            const TestRecipe& recipe, const std::string& out_dir,
                                            const Interrupter& interrupter = {});

}  // namespace clumpkit
