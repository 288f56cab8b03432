#include "io/pipeline/cpt.h"

#include "dem/lab/cpt.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/formats/cpt_curve.h"
#include "io/pipeline/consolidated.h"
#include "io/pipeline/lab_setup.h"
#include "io/reports/cpt_report.h"

#include <algorithm>
#include <filesystem>

namespace clumpkit {

namespace fs = std::filesystem;

LabJobResult run_cpt_job(const std::string& specimen_dir, const TestRecipe& recipe,
                         const std::string& out_dir, const LabJobOptions& options,
                         const Interrupter& interrupter) {
  if (!recipe.probe)
    throw InvalidInput(recipe.path +
                       ": probe: `clumpkit test cpt` needs a [probe] section (diameter, "
                       "apex_deg, velocity, depth)");
  dem::CptSettings s;
  s.cell = recipe.settings;
  s.probe = *recipe.probe;
  TestSetup setup = setup_test("cpt", specimen_dir, recipe, out_dir, options.resume,
                               options.checkpoint_seconds, options.allow_dynamic,
                               s.probe.velocity / s.probe.diameter, "probe.velocity", interrupter,
                               [&](const nlohmann::json& report, const std::string& report_path,
                                   const dem::CellSpecimen& specimen) {
                                 if (options.save_consolidated)
                                   check_consolidated_container(report, report_path);
                                 const double core = radial_core_radius(report, report_path);
                                 try {
                                   dem::validate_cpt(specimen.world, specimen.cell, s, core);
                                 } catch (const InvalidInput& e) {
                                   throw InvalidInput(recipe.path + ": " + e.what() +
                                                      (core > 0.0 ? " (" + report_path + ")" : ""));
                                 }
                               });
  const fs::path& out = setup.out;
  dem::CptResult r;
  try {
    r = dem::run_cpt(setup.specimen, s, setup.control, setup.fingerprint,
                     [&](const dem::CellSpecimen& c, const dem::CptState& st) {
                       if (options.save_consolidated)
                         write_consolidated(out / "consolidated", c.world, c.cell,
                                            setup.spec_report, setup.options.contact,
                                            st.test_friction, s.cell.confining,
                                            recipe.density_scaling);
                     });
  } catch (const Interrupted& e) {
    throw Interrupted(std::string(e.what()) + "; " + out.string() +
                      " is kept: continue with --resume");
  }
  fs::remove_all(out / "checkpoints");

  write_cpt_curve((out / "curve.csv").string(), r.curve);

  const dem::ContactParams& law = setup.options.contact;
  const double test_friction = s.cell.friction >= 0 ? s.cell.friction : law.friction;
  nlohmann::ordered_json rep;
  rep["test"] = "cpt";
  rep["specimen"] = specimen_dir;
  rep["recipe"] = recipe.path;
  rep["bodies"] = setup.bodies;
  rep["consolidated"] = r.consolidated;
  rep["consolidation_steps"] = r.consolidation_steps;
  rep["confining_stress"] = s.cell.confining;
  rep["timestep"] = setup.specimen.world.options().timestep;
  rep["contact"] = {
      {"stiffness_scaling", law.scaling == dem::StiffnessScaling::linear ? "linear" : "none"},
      {"kn", law.kn},
      {"ks", law.ks},
      {"d_ref", law.d_ref},
      {"friction", test_friction},
      {"consolidation_friction",
       s.cell.consolidation_friction >= 0 ? s.cell.consolidation_friction : test_friction}};
  rep["probe"] = {{"diameter", s.probe.diameter},
                  {"apex_deg", s.probe.apex_deg},
                  {"velocity", s.probe.velocity},
                  {"depth", s.probe.depth},
                  {"friction", s.probe.friction >= 0 ? s.probe.friction : test_friction}};
  rep["inertial_number"] = setup.inertial;
  const dem::CptRow& last = r.curve.back();
  rep["steps"] = last.step;
  rep["final_depth"] = last.depth;
  rep["reached_bottom"] = r.reached_bottom;
  add_cpt_summary(rep, r.curve);
  write_cpt_plot((out / "curve.png").string(), r.curve,
                 "CPT, " + format_number(s.cell.confining / 1e3, 4) + " kPa");
  return finish_test_job(
      setup, out_dir, recipe, "cpt", specimen_dir, rep,
      options.save_consolidated
          ? std::vector<std::string>{"curve.csv", "curve.png", "report.json", "consolidated/"}
          : std::vector<std::string>{"curve.csv", "curve.png", "report.json"},
      options.resume, r.resumed);
}

}  // namespace clumpkit
