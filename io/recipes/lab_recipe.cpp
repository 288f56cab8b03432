#include "io/recipes/lab_recipe.h"

#include "dem/core/body.h"
#include "dem/core/contact.h"
#include "dem/core/timestep.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/text.h"
#include "io/recipes/section_table.h"
#include "io/recipes/toml_fields.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

namespace clumpkit {

namespace {

// [test] modulus_range: a strain range [lo, hi] with 0 <= lo < hi.
void read_modulus_range(const TomlFields& f, const toml::node& v, const std::string& field,
                        TestRecipe& r) {
  const auto range = f.pair(v, field);
  if (!(range.first >= 0 && range.second > range.first))
    f.fail(field, "must be [lo, hi] with 0 <= lo < hi, got " + toml_show(v));
  r.modulus_range = range;
}

}  // namespace

const RecipeSection<dem::ProbeSettings>& probe_section() {
  using P = dem::ProbeSettings;
  static const RecipeSection<P> s{
      "probe",
      "The cone of `clumpkit test cpt` and its push (required there; checked by "
      "dem::validate_probe, and against the cell and a zoned specimen's core once the specimen "
      "is read).",
      {range_key<P>("diameter", "m", dem::kProbeDiameter, "shaft diameter D_c",
                    [](P& p) -> double& { return p.diameter; }),
       range_key<P>("apex_deg", "degree", dem::kProbeApex, "apex angle of the cone",
                    [](P& p) -> double& { return p.apex_deg; }),
       range_key<P>("velocity", "m/s", dem::kProbeVelocity, "push speed",
                    [](P& p) -> double& { return p.velocity; }),
       shown_as(
           range_key<P>("depth", "m", dem::kProbeDepth, "push distance below the specimen's top",
                        [](P& p) -> double& { return p.depth; }),
           "required"),
       shown_as(range_key<P>("friction", "", dem::kFriction, "μ of probe–sphere contacts",
                             [](P& p) -> double& { return p.friction; }),
                "the test's")}};
  return s;
}

const RecipeSection<TestRecipe>& test_section() {
  using R = TestRecipe;
  static const RecipeSection<R> s{
      "test",
      "The loading of `clumpkit test` (consolidation to `confining`, then the test of its kind).",
      {range_key<R>("confining", "Pa", dem::kConfiningStress,
                    "consolidation stress, and the lateral stress of a triaxial or CPT",
                    [](R& r) -> double& { return r.settings.confining; }),
       shown_as(number_key<R>(
                    "final_stress", "Pa", "> confining",
                    "isotropic: stress at the end; oedometer: axial stress at the end",
                    [](R& r) -> double& { return r.settings.final_stress; }, &TomlFields::positive),
                "4 × confining"),
       range_key<R>("strain_rate", "1/s", dem::kTestStrainRate,
                    "axial strain rate of oedometer and triaxial",
                    [](R& r) -> double& { return r.settings.strain_rate; }),
       shown_as(range_key<R>("inertial_number", "", dem::kHeldInertialNumber,
                             "oedometer and triaxial: the platen speeds up with the axial stress "
                             "σa to hold the particles' inertial number I = ε̇·d·√(ρ/σa) here, "
                             "never slower than strain_rate (0: off)",
                             [](R& r) -> double& { return r.settings.inertial_number; }),
                "off: strain_rate throughout"),
       shown_as(range_key<R>("stress_rate", "Pa/s", dem::kStressRate,
                             "isotropic loading rate (0: the default)",
                             [](R& r) -> double& { return r.settings.stress_rate; }),
                "confining × strain_rate × 20"),
       range_key<R>("density_scaling", "", dem::kDensityScaling,
                    "every body's mass and moments × λ for the test (time step × √λ; reported)",
                    [](R& r) -> double& { return r.density_scaling; }),
       custom_key<R>("hold_stresses", "Pa", "ascending, in (confining, final_stress]",
                     "oedometer: stresses where the platen stops and its servo holds the stress "
                     "until equilibrium (consolidation_tolerance; unbalanced-force ratio 1e-3), "
                     "the load increments of a laboratory oedometer",
                     "none: continuous loading",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       r.settings.hold_stresses = f.numbers(v, field);
                     }),
       range_key<R>("max_hold_steps", "steps", dem::kMaxHoldSteps, "step limit of one hold",
                    [](R& r) -> long long& { return r.settings.max_hold_steps; }),
       range_key<R>("max_axial_strain", "", dem::kMaxAxialStrain, "where a triaxial test ends",
                    [](R& r) -> double& { return r.settings.max_axial_strain; }),
       range_key<R>("critical_fraction", "", dem::kCriticalFraction,
                    "last fraction of a triaxial curve averaged for the critical state",
                    [](R& r) -> double& { return r.critical_fraction; }),
       shown_as(range_key<R>("friction", "", dem::kFriction, "μ of the test",
                             [](R& r) -> double& { return r.settings.friction; }),
                "the specimen's"),
       shown_as(range_key<R>("consolidation_friction", "", dem::kFriction,
                             "μ during the consolidation (0: the densest packing at confining)",
                             [](R& r) -> double& { return r.settings.consolidation_friction; }),
                "the test's"),
       shown_as(range_key<R>("servo_strain_rate", "1/s", dem::kServoStrainRate,
                             "speed limit of the servo-driven walls as a strain rate (0: the "
                             "default)",
                             [](R& r) -> double& { return r.settings.servo_strain_rate; }),
                "10 × the platen speed"),
       range_key<R>("record_every", "steps", dem::kRecordEvery, "steps between curve rows",
                    [](R& r) -> int& { return r.settings.record_every; }),
       range_key<R>("timestep_safety", "", dem::kTimestepSafety, "time step over the critical one",
                    [](R& r) -> double& { return r.timestep_safety; }),
       custom_key<R>("modulus_range", "", "[lo, hi], 0 <= lo < hi",
                     "strain range of the tangent modulus", "the test's own", read_modulus_range),
       range_key<R>("consolidation_tolerance", "", dem::kConsolidationTolerance,
                    "relative stress error at the consolidation's equilibrium",
                    [](R& r) -> double& { return r.settings.consolidation_tolerance; })}};
  return s;
}

const RecipeSection<TestRecipe>& contact_override_section() {
  using R = TestRecipe;
  static const RecipeSection<R> s{
      "contact",
      "Overrides of the specimen's contact law for the test (optional; a key not given keeps the "
      "specimen's value).",
      {custom_key<R>("stiffness_scaling", "", "\"none\" or \"linear\"",
                     "linear: kn and ks scale with the bodies' diameters (CTGU 2017)",
                     "the specimen's",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const std::string rule = f.string(v, field);
                       if (rule != "none" && rule != "linear")
                         f.fail(field, "expected \"none\" or \"linear\", got " + toml_show(v));
                       r.scaling = rule == "linear" ? dem::StiffnessScaling::linear
                                                    : dem::StiffnessScaling::none;
                     }),
       // The overrides are optionals: a key given sets its value (emplace), one not given leaves
       // it unset, and the defaults shown are the rules that then apply.
       shown_as(range_key<R>("kn_ref", "N/m", dem::kNormalStiffness,
                             "normal stiffness (at d_ref with linear scaling)",
                             [](R& r) -> double& { return r.kn_ref.emplace(); }),
                "the specimen's kn"),
       shown_as(range_key<R>("d_ref", "m", dem::kReferenceDiameter,
                             "diameter at which kn holds (required with stiffness_scaling = "
                             "\"linear\")",
                             [](R& r) -> double& { return r.d_ref.emplace(); }),
                "the specimen's"),
       shown_as(range_key<R>("ks_over_kn", "", dem::kStiffnessRatio, "shear over normal stiffness",
                             [](R& r) -> double& { return r.ks_over_kn.emplace(); }),
                "the specimen's ks/kn"),
       shown_as(range_key<R>("damping_ratio", "", dem::kDampingRatio,
                             "viscous normal damping ratio β (none needed in a quasi-static test)",
                             [](R& r) -> double& { return r.damping_ratio.emplace(); }),
                "0"),
       shown_as(
           range_key<R>("local_damping", "", dem::kLocalDamping, "PFC local damping α of the test",
                        [](R& r) -> double& { return r.local_damping.emplace(); }),
           "the specimen's")}};
  return s;
}

namespace {

// [probe]: the table, then depth required and the cone checked whole.
dem::ProbeSettings read_probe(const TomlFields& f, const toml::node& val) {
  dem::ProbeSettings p;
  const std::vector<std::string> given = read_section(f, val, probe_section(), p);
  if (std::find(given.begin(), given.end(), "depth") == given.end())
    f.fail("probe.depth", "is required (the push below the specimen's top, m)");
  try {
    dem::validate_probe(p);
  } catch (const InvalidInput& e) {
    throw InvalidInput(f.file + ": " + e.what());
  }
  return p;
}

}  // namespace

TestRecipe parse_test_recipe(const std::string& text, const std::string& path) {
  const TomlFields f{path};
  const toml::table root = parse_toml(text, path);
  TestRecipe r;
  r.path = path;
  r.text = text;
  dem::ElementTestSettings& s = r.settings;
  bool have_final = false;
  // The top level: each key's reader, in the order the unknown-key message lists them.
  const TopLevelReaders top{
      {"name", [&](const toml::node& v) { f.string(v, "name"); }},
      {"description", [&](const toml::node& v) { f.string(v, "description"); }},
      {"test",
       [&](const toml::node& v) {
         for (const std::string& given : read_section(f, v, test_section(), r))
           if (given == "final_stress") have_final = true;
       }},
      {"contact", [&](const toml::node& v) { read_section(f, v, contact_override_section(), r); }},
      {"probe", [&](const toml::node& v) { r.probe = read_probe(f, v); }}};
  read_top_level(f, root, top);
  if (r.scaling == dem::StiffnessScaling::linear && !r.d_ref)
    f.fail("contact.d_ref", "is required with stiffness_scaling = \"linear\"");
  if (have_final && !(s.final_stress > s.confining))
    f.fail("test.final_stress", "must exceed test.confining");
  if (!have_final) s.final_stress = 4.0 * s.confining;
  const int bad = dem::first_hold_out_of_order(s.hold_stresses, s.confining, s.final_stress);
  if (bad >= 0)
    f.fail("test.hold_stresses[" + std::to_string(bad) + "]",
           "must rise above test.confining (" + format_number(s.confining) +
               ") to at most test.final_stress (" + format_number(s.final_stress) + "), got " +
               format_number(s.hold_stresses[bad]));
  return r;
}

TestRecipe read_test_recipe(const std::string& path) {
  return parse_test_recipe(read_file(path, "recipe file"), path);
}

}  // namespace clumpkit
