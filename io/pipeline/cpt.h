// The job of `clumpkit test cpt`: a cone pushed into a specimen in its consolidated cell, written
// as curve.csv, curve.png, report.json and manifest.json.
#pragma once

#include "io/pipeline/lab_setup.h"
#include "io/recipes/lab_recipe.h"

#include <string>

namespace clumpkit {

/// Consolidates the specimen in `specimen_dir` in its cell to [test] confining (servo on every
/// wall, gravity off, the specimen's contact law unless [contact] overrides it), then pushes the
/// recipe's [probe] down the cell's axis from the top platen with the cell's stresses held (see
/// dem::run_cpt). The probe's push rate v / D_c is the strain rate of the inertial-number check
/// (refused above 1e-2 unless allow_dynamic). Writes into `out_dir` (DIR.partial renamed at the
/// end): curve.csv (step, depth, tip_force, sleeve_force, qc, fs; SI units in the header),
/// curve.png (qc against depth), report.json and manifest.json; checkpoints and --resume as
/// run_element_test_job (the stage "cpt"). Throws InvalidInput before writing anything for a
/// recipe without [probe] or a probe the cell cannot take.
LabJobResult run_cpt_job(const std::string& specimen_dir, const TestRecipe& recipe,
                         const std::string& out_dir, const LabJobOptions& options = {},
                         const Interrupter& interrupter = {});

}  // namespace clumpkit
