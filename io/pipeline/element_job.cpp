#include "io/pipeline/element_job.h"

#include "dem/core/timestep.h"
#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/checkpoint.h"
#include "io/formats/specimen_csv.h"
#include "io/pipeline/breakage_outputs.h"
#include "io/pipeline/consolidated.h"
#include "io/pipeline/lab_setup.h"
#include "io/pipeline/stage_files.h"
#include "io/pipeline/test_kind.h"
#include "io/reports/plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

// curve.csv: one row per record, compression positive; a crushable test adds its breakage
// columns, an oedometer with holds the `held` code.
void write_curve_csv(const fs::path& path, const std::vector<dem::CurveRow>& curve,
                     const std::vector<double>& work, bool crushable, bool holds) {
  write_file_atomically(path.string(), [&](std::ostream& f) {
    std::string names =
        "step,axial_strain,volumetric_strain,axial_stress,radial_stress,p,q,porosity,"
        "coordination_number,unbalanced_force,interior_axial_strain";
    if (crushable) names += breakage_header();
    if (holds) names += ",held";
    f << csv_header("curve", names, si_length()) << "\n";
    for (std::size_t k = 0; k < curve.size(); ++k) {
      const dem::CurveRow& c = curve[k];
      f << c.step << "," << format_number(c.axial_strain) << ","
        << format_number(c.volumetric_strain) << "," << format_number(c.axial_stress) << ","
        << format_number(c.lateral_stress) << "," << format_number(c.p) << "," << format_number(c.q)
        << "," << format_number(c.porosity) << "," << format_number(c.coordination) << ","
        << format_number(c.unbalanced) << "," << format_number(c.interior_axial_strain)
        << (crushable ? breakage_values(c, work[k]) : "")
        << (holds ? "," + std::to_string(static_cast<int>(c.held)) : "") << "\n";
    }
  });
}

// report.json's fields every element test has, before its kind's own.
nlohmann::ordered_json common_report(const TestKind& kind, const std::string& specimen_dir,
                                     const TestRecipe& recipe, const TestSetup& setup,
                                     const dem::ElementTestSettings& s,
                                     const dem::ElementTestResult& r, const dem::World& world) {
  const dem::WorldOptions& o = setup.options;
  nlohmann::ordered_json rep;
  rep["test"] = kind.name;
  rep["specimen"] = specimen_dir;
  rep["recipe"] = recipe.path;
  rep["bodies"] = setup.bodies;
  rep["consolidated"] = r.consolidated;
  rep["consolidation_steps"] = r.consolidation_steps;
  rep["confining_stress"] = s.confining;
  rep["timestep"] = world.options().timestep;
  const double test_friction = s.friction >= 0 ? s.friction : o.contact.friction;
  rep["contact"] = {
      {"stiffness_scaling", o.contact.scaling == dem::StiffnessScaling::linear ? "linear" : "none"},
      {"kn", o.contact.kn},
      {"ks", o.contact.ks},
      {"d_ref", o.contact.d_ref},
      {"friction", test_friction},
      {"consolidation_friction",
       s.consolidation_friction >= 0 ? s.consolidation_friction : test_friction}};
  const dem::CurveRow& first = r.curve.front();
  rep["porosity"] = first.porosity;
  rep["coordination_number"] = first.coordination;
  rep["inertial_number"] = setup.inertial;
  if (s.inertial_number > 0) rep["inertial_number_held"] = s.inertial_number;
  return rep;
}

}  // namespace

LabJobResult run_element_test_job(const TestKind& kind, const std::string& specimen_dir,
                                  const TestRecipe& recipe, const std::string& out_dir,
                                  const LabJobOptions& options, const Interrupter& interrupter) {
  if (!recipe.settings.hold_stresses.empty() && !kind.path->holds)
    throw InvalidInput(recipe.path + ": test.hold_stresses: for the oedometer test only, not the " +
                       std::string(kind.name) + " test");
  TestSetup setup = setup_test(
      kind.name, specimen_dir, recipe, out_dir, options.resume, options.checkpoint_seconds,
      options.allow_dynamic, recipe.settings.strain_rate, "test.strain_rate", interrupter,
      [&](const nlohmann::json& spec_report, const std::string& report_path,
          const dem::CellSpecimen&) {
        if (recipe.probe)
          throw InvalidInput(recipe.path +
                             ": probe: a [probe] section is for `clumpkit test cpt` "
                             "only, not the " +
                             std::string(kind.name) + " test");
        if (options.save_consolidated) check_consolidated_container(spec_report, report_path);
      });
  const fs::path& out = setup.out;
  dem::CellSpecimen& specimen = setup.specimen;

  dem::ElementTestSettings s = recipe.settings;
  s.path = kind.path;
  track_breakage(specimen.world, s);  // a crushable specimen's grading as built
  const bool crushable = !s.initial_grading.empty();
  const auto consolidated = [&](const dem::CellSpecimen& c, const dem::ElementTestState& st) {
    if (options.save_consolidated)
      write_consolidated(out / "consolidated", c.world, c.cell, setup.spec_report,
                         setup.options.contact, st.test_friction, s.confining,
                         recipe.density_scaling);
  };
  dem::ElementTestResult r;
  try {
    r = dem::run_element_test(specimen, s, setup.control, setup.fingerprint, consolidated);
  } catch (const Interrupted& e) {
    throw Interrupted(std::string(e.what()) + "; " + out.string() +
                      " is kept: continue with --resume");
  }
  const dem::World& world = specimen.world;
  fs::remove_all(out / "checkpoints");

  const std::vector<double> work = crushable ? input_work(r.curve) : std::vector<double>{};
  write_curve_csv(out / "curve.csv", r.curve, work, crushable, !s.hold_stresses.empty());
  nlohmann::ordered_json rep = common_report(kind, specimen_dir, recipe, setup, s, r, world);
  kind.report(TestReportInput{r.curve, s, recipe, work, crushable}, rep);
  rep["steps"] = r.curve.back().step;
  PlotCurve plot;
  for (const auto& c : r.curve)
    plot.x.push_back(kind.picture.x(c)), plot.y.push_back(kind.picture.y(c));
  write_line_plot(
      (out / "curve.png").string(), plot, kind.picture.x_label, kind.picture.y_label,
      std::string(kind.name) + " test, " + format_number(s.confining / 1e3, 4) + " kPa");
  std::vector<std::string> files = {"curve.csv", "curve.png", "report.json"};
  if (crushable) write_breakage_outputs(out, world, s, r.curve, work, rep, files);
  if (options.save_consolidated) files.push_back("consolidated/");
  return finish_test_job(setup, out_dir, recipe, kind.name, specimen_dir, rep, files,
                         options.resume, r.resumed);
}

}  // namespace clumpkit
