// The job of `clumpkit test` for the element tests (io/pipeline/test_kinds.h): a specimen
// directory tested in a servo-controlled cell, written as curve.csv, curve.png, report.json and
// manifest.json.
#pragma once

#include "dem/lab/element_loading.h"
#include "geom/progress.h"
#include "io/pipeline/lab_setup.h"
#include "io/recipes/lab_recipe.h"

#include <nlohmann/json.hpp>

#include <string>

namespace clumpkit {

struct TestKind;

/// Tests the specimen in `specimen_dir` (specimen.csv, report.json of `clumpkit specimen`) in
/// its container as a frictionless cylinder cell (radius from report.json, platens at the
/// specimen's bottom and top), gravity off, with the specimen's contact law unless the recipe
/// overrides it, along kind.path (see dem::run_element_test); report.json has the fields every
/// test has and those of kind.report. Writes into `out_dir` (DIR.partial renamed at the
/// end, job.h): curve.csv (step, axial_strain, volumetric_strain, axial_stress, radial_stress,
/// p, q, porosity, coordination_number, unbalanced_force, interior_axial_strain; units in the
/// header cells), curve.png, report.json and manifest.json. The interrupter is told
/// the stage ("test").
/// Work goes to DIR.partial; the test runs as the stage "test" of a StageFiles store in
/// DIR.partial/checkpoints (the protocol of specimen builds: spec.fingerprint of the test, recipe,
/// specimen and version; test.ckpt, the world with where the test is and its curve so far),
/// saved every checkpoint_seconds and when the interrupter asks to stop (then Interrupted is
/// thrown, saying to --resume). A resumed test ends with the same bytes as one never stopped.
LabJobResult run_element_test_job(const TestKind& kind, const std::string& specimen_dir,
                                  const TestRecipe& recipe, const std::string& out_dir,
                                  const LabJobOptions& options = {},
                                  const Interrupter& interrupter = {});

}  // namespace clumpkit
