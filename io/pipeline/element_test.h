// The job of `clumpkit test isotropic|oedometer|triaxial`: a specimen directory tested in a
// servo-controlled cell, written as curve.csv, curve.png, report.json and manifest.json.
#pragma once

#include "dem/lab/element_test.h"
#include "geom/progress.h"
#include "io/recipes/test_recipe.h"

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
/// radial_stress_pa, p_pa, q_pa, porosity, coordination_number, unbalanced_force,
/// interior_axial_strain), curve.png, report.json and manifest.json. The interrupter is told
/// the stage ("test").
/// Options of run_element_test_job.
struct ElementTestJobOptions {
  /// Continue the work kept in DIR.partial (its checkpoint; refused, naming both fingerprints,
  /// when it was made by another test, recipe, specimen or version; without one it starts
  /// afresh, saying so).
  bool resume = false;
  double checkpoint_seconds = 60;  ///< wall-clock seconds between checkpoints (≤ 0: none)
  /// Run a test whose inertial number I = ε̇·d·sqrt(ρ/σ3) exceeds 1e-2 (refused otherwise: a
  /// dynamic test, not a quasi-static element test).
  bool allow_dynamic = false;
  /// Also write DIR/consolidated: the specimen at the end of consolidation as a specimen
  /// directory (specimen.csv, report.json, manifest.json) that `clumpkit export` reads — the
  /// cylinder cell as its container (bottom platen at z = 0), gravity 0, the test's contact law
  /// with the specimen's viscous damping ratio — so another engine can run the same test from
  /// the same state. Cylinder cells only (exports model cylinders).
  bool save_consolidated = false;
};

/// What run_element_test_job did: report.json as written, and whether it continued a checkpoint
/// (with --resume, the reason it could not, when it started afresh).
struct ElementTestJobResult {
  nlohmann::ordered_json report;
  bool resumed = false;
  std::string afresh_reason;
};

/// Work goes to DIR.partial; the test runs as the stage "test" of a StageFiles store in
/// DIR.partial/checkpoints (the protocol of specimen builds: spec.fingerprint of the test, recipe,
/// specimen and version; test.ckpt, the world with where the test is and its curve so far),
/// saved every checkpoint_seconds and when the interrupter asks to stop (then Interrupted is
/// thrown, saying to --resume). A resumed test ends with the same bytes as one never stopped.
ElementTestJobResult run_element_test_job(dem::TestKind kind, const std::string& specimen_dir,
                                          const TestRecipe& recipe, const std::string& out_dir,
                                          const ElementTestJobOptions& options = {},
                                          const Interrupter& interrupter = {});

}  // namespace clumpkit
