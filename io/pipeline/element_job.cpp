#include "io/pipeline/element_job.h"

#include "dem/core/timestep.h"
#include "dem/measure/compressibility.h"
#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/hash.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/formats/checkpoint.h"
#include "io/formats/specimen_csv.h"
#include "io/pipeline/breakage_outputs.h"
#include "io/pipeline/consolidated.h"
#include "io/pipeline/lab_setup.h"
#include "io/pipeline/stage_files.h"
#include "io/reports/plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace clumpkit {

namespace fs = std::filesystem;

dem::TestKind test_kind(const std::string& name) {
  if (name == "isotropic") return dem::TestKind::isotropic;
  if (name == "oedometer") return dem::TestKind::oedometer;
  if (name == "triaxial") return dem::TestKind::triaxial;
  throw InvalidInput("test: unknown test '" + name +
                     "' (known: isotropic, oedometer, triaxial, cpt)");
}

namespace {

const char* kind_name(dem::TestKind k) {
  switch (k) {
    case dem::TestKind::isotropic:
      return "isotropic";
    case dem::TestKind::oedometer:
      return "oedometer";
    case dem::TestKind::triaxial:
      return "triaxial";
  }
  return "";
}

double axial(const dem::CurveRow& c) {
  return c.axial_stress;
}
double axial_strain(const dem::CurveRow& c) {
  return c.axial_strain;
}
double interior_strain(const dem::CurveRow& c) {
  return c.interior_axial_strain;
}
double mean_p(const dem::CurveRow& c) {
  return c.p;
}
double vol_strain(const dem::CurveRow& c) {
  return c.volumetric_strain;
}

// A measured value, or null when the curve could not give it (too few rows in the range).
nlohmann::ordered_json measured(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

// The compression index over the last decade of the stresses `sv` and the knee of e–log σv
// (dem/measure/compressibility.h), as report.json's `compression_index` and `yield_stress` with
// `suffix`.
void report_compressibility(const std::vector<double>& e, const std::vector<double>& sv,
                            const std::string& suffix, nlohmann::ordered_json& rep) {
  const double top = *std::max_element(sv.begin(), sv.end());
  rep["compression_index" + suffix] = measured(dem::compression_index(e, sv, 0.1 * top, top));
  rep["yield_stress" + suffix] = measured(dem::yield_stress(e, sv));
}

// The oedometer's holds: the state at the end of each (and its breakage), and e–log σv of the
// consolidated state and those ends, where the platen was at rest: the compression index over
// the last decade and the knee without the rate part of a continuous curve's stresses.
void report_holds(const std::vector<dem::CurveRow>& curve, const std::vector<double>& work,
                  bool crushable, nlohmann::ordered_json& rep) {
  std::vector<double> e = {curve.front().porosity / (1 - curve.front().porosity)},
                      sv = {curve.front().axial_stress};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t k = 1; k < curve.size(); ++k) {
    const dem::CurveRow& c = curve[k];
    if (c.held < 2) continue;
    e.push_back(c.porosity / (1 - c.porosity));
    sv.push_back(c.axial_stress);
    nlohmann::ordered_json h = {{"axial_stress", c.axial_stress},
                                {"axial_strain", c.axial_strain},
                                {"void_ratio", e.back()},
                                {"equilibrium", c.held == 2},
                                {"step", c.step}};
    if (crushable) {
      h["hardin_br"] = c.hardin_br;
      h["einav_b"] = c.einav_b;
      h["marsal_bg"] = c.marsal_bg;
      h["particles_broken"] = c.particles_broken;
      h["bonds_broken"] = c.bonds_broken;
      h["work"] = work[k];
    }
    list.push_back(h);
  }
  rep["holds"] = list;
  report_compressibility(e, sv, "_held", rep);
}

}  // namespace

LabJobResult run_element_test_job(dem::TestKind kind, const std::string& specimen_dir,
                                  const TestRecipe& recipe, const std::string& out_dir,
                                  const LabJobOptions& options, const Interrupter& interrupter) {
  if (!recipe.settings.hold_stresses.empty() && kind != dem::TestKind::oedometer)
    throw InvalidInput(recipe.path + ": test.hold_stresses: for the oedometer test only, not the " +
                       std::string(kind_name(kind)) + " test");
  TestSetup setup = setup_test(
      kind_name(kind), specimen_dir, recipe, out_dir, options.resume, options.checkpoint_seconds,
      options.allow_dynamic, recipe.settings.strain_rate, "test.strain_rate", interrupter,
      [&](const nlohmann::json& spec_report, const std::string& report_path,
          const dem::CellSpecimen&) {
        if (recipe.probe)
          throw InvalidInput(recipe.path +
                             ": probe: a [probe] section is for `clumpkit test cpt` "
                             "only, not the " +
                             std::string(kind_name(kind)) + " test");
        if (options.save_consolidated) check_consolidated_container(spec_report, report_path);
      });
  const nlohmann::json& spec_report = setup.spec_report;
  const dem::WorldOptions& o = setup.options;
  const double inertial = setup.inertial;
  const fs::path& out = setup.out;
  const std::string fingerprint = setup.fingerprint;
  const dem::StageControl& control = setup.control;
  dem::CellSpecimen& specimen = setup.specimen;

  dem::ElementTestSettings s = recipe.settings;
  s.kind = kind;
  track_breakage(specimen.world, s);  // a crushable specimen's grading as built
  const bool crushable = !s.initial_grading.empty();
  const auto consolidated = [&](const dem::CellSpecimen& c, const dem::ElementTestState& st) {
    if (options.save_consolidated)
      write_consolidated(out / "consolidated", c.world, c.cell, spec_report, o.contact,
                         st.test_friction, s.confining, recipe.density_scaling);
  };
  dem::ElementTestResult r;
  try {
    r = dem::run_element_test(specimen, s, control, fingerprint, consolidated);
  } catch (const Interrupted& e) {
    throw Interrupted(std::string(e.what()) + "; " + out.string() +
                      " is kept: continue with --resume");
  }
  const dem::World& world = specimen.world;
  fs::remove_all(out / "checkpoints");

  const std::vector<double> work = crushable ? input_work(r.curve) : std::vector<double>{};
  const bool holds = !s.hold_stresses.empty();
  write_file_atomically((out / "curve.csv").string(), [&](std::ostream& f) {
    f << "step,axial_strain,volumetric_strain,axial_stress_pa,radial_stress_pa,p_pa,q_pa,"
         "porosity,coordination_number,unbalanced_force,interior_axial_strain"
      << (crushable ? breakage_header() : "") << (holds ? ",held" : "") << "\n";
    for (std::size_t k = 0; k < r.curve.size(); ++k) {
      const dem::CurveRow& c = r.curve[k];
      f << c.step << "," << format_number(c.axial_strain) << ","
        << format_number(c.volumetric_strain) << "," << format_number(c.axial_stress) << ","
        << format_number(c.lateral_stress) << "," << format_number(c.p) << "," << format_number(c.q)
        << "," << format_number(c.porosity) << "," << format_number(c.coordination) << ","
        << format_number(c.unbalanced) << "," << format_number(c.interior_axial_strain)
        << (crushable ? breakage_values(c, work[k]) : "")
        << (holds ? "," + std::to_string(static_cast<int>(c.held)) : "") << "\n";
    }
  });

  nlohmann::ordered_json rep;
  rep["test"] = kind_name(kind);
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
  const dem::CurveRow& last = r.curve.back();
  rep["porosity"] = first.porosity;
  rep["coordination_number"] = first.coordination;
  rep["inertial_number"] = inertial;
  if (s.inertial_number > 0) rep["inertial_number_held"] = s.inertial_number;
  PlotCurve plot;
  std::string x_label, y_label;
  if (kind == dem::TestKind::isotropic) {
    const auto range = recipe.modulus_range.value_or(std::make_pair(s.confining, s.final_stress));
    rep["bulk_modulus"] =
        measured(dem::tangent_modulus(r.curve, mean_p, vol_strain, range.first, range.second));
    rep["modulus_range"] = {range.first, range.second};
    for (const auto& c : r.curve)
      plot.x.push_back(c.volumetric_strain), plot.y.push_back(c.p / 1e3);
    x_label = "volumetric strain (-)";
    y_label = "mean stress p (kPa)";
  } else if (kind == dem::TestKind::oedometer) {
    const auto range = recipe.modulus_range.value_or(std::make_pair(s.confining, s.final_stress));
    rep["constrained_modulus"] =
        measured(dem::tangent_modulus(r.curve, axial, axial_strain, range.first, range.second));
    // From the strain of the middle half of the height: without the platens' boundary layers,
    // whose share of the compliance grows with d/H (CurveRow::interior_axial_strain).
    rep["constrained_modulus_interior"] =
        measured(dem::tangent_modulus(r.curve, axial, interior_strain, range.first, range.second));
    rep["modulus_range"] = {range.first, range.second};
    rep["k0"] = last.lateral_stress / last.axial_stress;
    // e–log σv: the compression index over the last decade of stress and the yield stress at
    // the knee (dem/measure/compressibility.h).
    std::vector<double> e, sv;
    for (const auto& c : r.curve)
      e.push_back(c.porosity / (1 - c.porosity)), sv.push_back(c.axial_stress);
    report_compressibility(e, sv, "", rep);
    if (holds) report_holds(r.curve, work, crushable, rep);
    for (const auto& c : r.curve)
      plot.x.push_back(c.axial_strain), plot.y.push_back(c.axial_stress / 1e3);
    x_label = "axial strain (-)";
    y_label = "axial stress (kPa)";
  } else {
    // Secant Young's modulus at ε_a = 1e-4: q interpolated there over the strain.
    double e_young = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = 1; k < r.curve.size(); ++k)
      if (r.curve[k].axial_strain >= 1e-4) {
        const auto& a = r.curve[k - 1];
        const auto& b = r.curve[k];
        const double t = (1e-4 - a.axial_strain) / (b.axial_strain - a.axial_strain);
        const double q = (a.q - first.q) + t * (b.q - a.q);
        e_young = q / 1e-4;
        break;
      }
    double peak = -90, q_peak = 0, peak_strain = 0;
    for (const auto& c : r.curve)
      if (dem::friction_angle(c) > peak) {
        peak = dem::friction_angle(c);
        q_peak = c.q;
        peak_strain = c.axial_strain;
      }
    const double from = last.axial_strain * (1.0 - recipe.critical_fraction);
    double sum = 0;
    int n = 0;
    for (const auto& c : r.curve)
      if (c.axial_strain >= from) sum += dem::friction_angle(c), ++n;
    rep["young_modulus"] = measured(e_young);
    rep["peak_friction_angle"] = peak;
    rep["peak_deviator_stress"] = q_peak;
    rep["peak_axial_strain"] = peak_strain;
    rep["critical_friction_angle"] = n ? sum / n : 0.0;
    rep["final_axial_strain"] = last.axial_strain;
    rep["final_volumetric_strain"] = last.volumetric_strain;
    for (const auto& c : r.curve) plot.x.push_back(c.axial_strain), plot.y.push_back(c.q / 1e3);
    x_label = "axial strain (-)";
    y_label = "deviator stress q (kPa)";
  }
  rep["steps"] = last.step;
  write_line_plot(
      (out / "curve.png").string(), plot, x_label, y_label,
      std::string(kind_name(kind)) + " test, " + format_number(s.confining / 1e3, 4) + " kPa");
  std::vector<std::string> files = {"curve.csv", "curve.png", "report.json"};
  if (crushable) write_breakage_outputs(out, world, s, r.curve, work, rep, files);
  if (options.save_consolidated) files.push_back("consolidated/");
  return finish_test_job(setup, out_dir, recipe, kind_name(kind), specimen_dir, rep, files,
                         options.resume, r.resumed);
}

}  // namespace clumpkit
