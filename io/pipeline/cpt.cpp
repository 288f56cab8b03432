#include "io/pipeline/cpt.h"

#include "dem/lab/cpt.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/pipeline/consolidated.h"
#include "io/pipeline/lab_setup.h"
#include "io/reports/plot.h"

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

  write_file_atomically((out / "curve.csv").string(), [&](std::ostream& f) {
    f << "step,depth_m,tip_force_n,sleeve_force_n,qc_pa,fs_pa\n";
    for (const dem::CptRow& c : r.curve)
      f << c.step << "," << format_number(c.depth) << "," << format_number(c.tip_force) << ","
        << format_number(c.sleeve_force) << "," << format_number(c.qc) << "," << format_number(c.fs)
        << "\n";
  });

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
  // qc and fs at their largest, and averaged over the push's second half (the steady part once
  // the cone is buried).
  double qc_max = 0, qc_sum = 0, fs_sum = 0;
  int n = 0;
  for (const dem::CptRow& c : r.curve) {
    qc_max = std::max(qc_max, c.qc);
    if (c.depth >= 0.5 * last.depth) qc_sum += c.qc, fs_sum += c.fs, ++n;
  }
  rep["qc_max"] = qc_max;
  rep["qc_mean_second_half"] = n ? qc_sum / n : 0.0;
  rep["fs_mean_second_half"] = n ? fs_sum / n : 0.0;
  PlotCurve plot;
  for (const dem::CptRow& c : r.curve) plot.x.push_back(c.depth), plot.y.push_back(c.qc / 1e6);
  write_line_plot((out / "curve.png").string(), plot, "depth (m)", "cone resistance qc (MPa)",
                  "CPT, " + format_number(s.cell.confining / 1e3, 4) + " kPa");
  return finish_test_job(
      setup, out_dir, recipe, "cpt", specimen_dir, rep,
      options.save_consolidated
          ? std::vector<std::string>{"curve.csv", "curve.png", "report.json", "consolidated/"}
          : std::vector<std::string>{"curve.csv", "curve.png", "report.json"},
      options.resume, r.resumed);
}

}  // namespace clumpkit
