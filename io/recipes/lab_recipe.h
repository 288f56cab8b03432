// Element-test recipes (`clumpkit test`): loading, rates and the contact law, read from TOML.
#pragma once

#include "dem/core/contact.h"
#include "dem/lab/cpt.h"
#include "dem/lab/element_loading.h"
#include "io/recipes/section_table.h"

#include <optional>
#include <string>

namespace clumpkit {

/// A test recipe. [test]: confining (Pa), final_stress (Pa; isotropic and oedometer),
/// strain_rate (1/s), stress_rate (Pa/s, isotropic; default 20·confining·strain_rate),
/// max_axial_strain (triaxial, default 0.2), critical_fraction (the last fraction of the curve
/// averaged for the critical angle, default 0.1), friction (μ during the test; default the
/// specimen's), consolidation_friction (μ while consolidating; default friction), servo_strain_rate
/// (speed limit of the servo walls as a strain rate, 1/s; default 1e-6 of the height per step or 10
/// × the platen's), record_every (steps), timestep_safety (fraction of the critical step, default
/// 0.2), modulus_range ([lo, hi] Pa, default [confining, final_stress] or [p0, 4 p0]). [contact]
/// (optional, overrides the specimen's law): stiffness_scaling ("none" | "linear"), kn_ref (N/m),
/// d_ref (m), ks_over_kn, damping_ratio (default 0: no viscous damping in a quasi-static test),
/// local_damping (default the specimen's). [probe] (`clumpkit test cpt` only, and required
/// there): diameter (m, default 0.018), apex_deg (default 60), velocity (m/s, default 0.02),
/// depth (m: the push below the specimen's top; required), friction (μ probe–sphere, default
/// the test's).
struct TestRecipe {
  std::string path, text;
  dem::ElementTestSettings settings;
  double critical_fraction = 0.1;  ///< in dem::kCriticalFraction
  double timestep_safety = 0.2;    ///< in dem::kTimestepSafety
  /// [test] density_scaling λ, in dem::kDensityScaling: every body's mass and moments × λ for
  /// the test, so the time step grows by √λ (long CPT pushes); quasi-static results keep their
  /// stresses while the inertial number, checked on the scaled masses, grows by √λ. Reported.
  double density_scaling = 1.0;
  std::optional<std::pair<double, double>> modulus_range;
  // [contact] overrides: unset fields keep the specimen's values. kn_ref in
  // dem::kNormalStiffness, d_ref in dem::kReferenceDiameter, ks_over_kn in dem::kStiffnessRatio,
  // damping_ratio in dem::kDampingRatio, local_damping in dem::kLocalDamping.
  std::optional<dem::StiffnessScaling> scaling;
  std::optional<double> kn_ref, d_ref, ks_over_kn, damping_ratio, local_damping;
  std::optional<dem::ProbeSettings> probe;  ///< [probe], when given
};

/// Parses a test recipe; throws InvalidInput naming the file, the field and the value for an
/// unknown key, a wrong type or a value out of range, and IoError for a missing file.
TestRecipe parse_test_recipe(const std::string& text, const std::string& path);
TestRecipe read_test_recipe(const std::string& path);

/// The tables of the [test] and [probe] sections (io/recipes/section_table.h).
const RecipeSection<TestRecipe>& test_section();
const RecipeSection<dem::ProbeSettings>& probe_section();
/// The table of a test's [contact], overrides of the specimen's law; defaults from TestRecipe{}.
const RecipeSection<TestRecipe>& contact_override_section();

}  // namespace clumpkit
