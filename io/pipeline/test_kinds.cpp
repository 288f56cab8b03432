#include "io/pipeline/test_kinds.h"

#include "dem/measure/compressibility.h"
#include "geom/errors.h"
#include "io/pipeline/cpt.h"
#include "io/pipeline/element_job.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clumpkit {

namespace {

double axial(const dem::CurveRow& c) {
  return c.axial_stress;
}
double axial_kpa(const dem::CurveRow& c) {
  return c.axial_stress / 1e3;
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
double mean_p_kpa(const dem::CurveRow& c) {
  return c.p / 1e3;
}
double deviator_kpa(const dem::CurveRow& c) {
  return c.q / 1e3;
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

// The stress range of a tangent modulus: the recipe's, else the loading's.
std::pair<double, double> modulus_range(const TestReportInput& in) {
  return in.recipe.modulus_range.value_or(
      std::make_pair(in.settings.confining, in.settings.final_stress));
}

void report_isotropic(const TestReportInput& in, nlohmann::ordered_json& rep) {
  const auto range = modulus_range(in);
  rep["bulk_modulus"] =
      measured(dem::tangent_modulus(in.curve, mean_p, vol_strain, range.first, range.second));
  rep["modulus_range"] = {range.first, range.second};
}

void report_oedometer(const TestReportInput& in, nlohmann::ordered_json& rep) {
  const auto range = modulus_range(in);
  rep["constrained_modulus"] =
      measured(dem::tangent_modulus(in.curve, axial, axial_strain, range.first, range.second));
  // From the strain of the middle half of the height: without the platens' boundary layers,
  // whose share of the compliance grows with d/H (CurveRow::interior_axial_strain).
  rep["constrained_modulus_interior"] =
      measured(dem::tangent_modulus(in.curve, axial, interior_strain, range.first, range.second));
  rep["modulus_range"] = {range.first, range.second};
  const dem::CurveRow& last = in.curve.back();
  rep["k0"] = last.lateral_stress / last.axial_stress;
  // e–log σv: the compression index over the last decade of stress and the yield stress at
  // the knee (dem/measure/compressibility.h).
  std::vector<double> e, sv;
  for (const auto& c : in.curve)
    e.push_back(c.porosity / (1 - c.porosity)), sv.push_back(c.axial_stress);
  report_compressibility(e, sv, "", rep);
  if (!in.settings.hold_stresses.empty()) report_holds(in.curve, in.work, in.crushable, rep);
}

void report_triaxial(const TestReportInput& in, nlohmann::ordered_json& rep) {
  const std::vector<dem::CurveRow>& curve = in.curve;
  const dem::CurveRow& first = curve.front();
  const dem::CurveRow& last = curve.back();
  // Secant Young's modulus at ε_a = 1e-4: q interpolated there over the strain.
  double e_young = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 1; k < curve.size(); ++k)
    if (curve[k].axial_strain >= 1e-4) {
      const auto& a = curve[k - 1];
      const auto& b = curve[k];
      const double t = (1e-4 - a.axial_strain) / (b.axial_strain - a.axial_strain);
      const double q = (a.q - first.q) + t * (b.q - a.q);
      e_young = q / 1e-4;
      break;
    }
  double peak = -90, q_peak = 0, peak_strain = 0;
  for (const auto& c : curve)
    if (dem::friction_angle(c) > peak) {
      peak = dem::friction_angle(c);
      q_peak = c.q;
      peak_strain = c.axial_strain;
    }
  const double from = last.axial_strain * (1.0 - in.recipe.critical_fraction);
  double sum = 0;
  int n = 0;
  for (const auto& c : curve)
    if (c.axial_strain >= from) sum += dem::friction_angle(c), ++n;
  rep["young_modulus"] = measured(e_young);
  rep["peak_friction_angle"] = peak;
  rep["peak_deviator_stress"] = q_peak;
  rep["peak_axial_strain"] = peak_strain;
  rep["critical_friction_angle"] = n ? sum / n : 0.0;
  rep["final_axial_strain"] = last.axial_strain;
  rep["final_volumetric_strain"] = last.volumetric_strain;
}

// The triaxial's fields, and how far the mean stress strayed from the one held: the largest
// |p/p′ − 1| over the loading's rows (the servo follows σa with a lag).
void report_constant_p(const TestReportInput& in, nlohmann::ordered_json& rep) {
  report_triaxial(in, rep);
  double drift = 0;
  for (std::size_t k = 1; k < in.curve.size(); ++k)
    drift = std::max(drift, std::abs(in.curve[k].p / in.settings.confining - 1.0));
  rep["mean_stress_drift"] = drift;
}

LabJobResult cpt_job(const TestKind&, const std::string& specimen_dir, const TestRecipe& recipe,
                     const std::string& out_dir, const LabJobOptions& options,
                     const Interrupter& interrupter) {
  return run_cpt_job(specimen_dir, recipe, out_dir, options, interrupter);
}

const PagePlot kDeviatorPlot{
    "deviator stress", "axial strain", "q (kPa)", "axial_strain", "q", 1, 1e-3};
const PagePlot kVolumePlot{"volumetric strain", "axial strain", "volumetric strain", "axial_strain",
                           "volumetric_strain"};
const CurvePicture kDeviatorPicture{"axial strain (-)", "deviator stress q (kPa)", axial_strain,
                                    deviator_kpa};

}  // namespace

const std::vector<TestKind>& test_kinds() {
  static const std::vector<TestKind> kinds = {
      {"isotropic",
       "all walls follow a stress ramp to final_stress (report: bulk_modulus, tangent over "
       "modulus_range)",
       &dem::kIsotropicPath,
       run_element_test_job,
       report_isotropic,
       {"volumetric strain (-)", "mean stress p (kPa)", vol_strain, mean_p_kpa},
       {{"isotropic compression", "volumetric strain", "p (kPa)", "volumetric_strain", "p", 1,
         1e-3}}},
      {"oedometer",
       "radial wall fixed, platen at strain_rate to final_stress, holding at hold_stresses "
       "(report: constrained_modulus, constrained_modulus_interior from the strain of the middle "
       "half of the height, k0, compression_index over the last decade, yield_stress at the knee "
       "of e-log sv; with holds, the same of the held states)",
       &dem::kOedometerPath,
       run_element_test_job,
       report_oedometer,
       {"axial strain (-)", "axial stress (kPa)", axial_strain, axial_kpa},
       {{"vertical stress", "axial strain", "axial stress (MPa)", "axial_strain", "axial_stress", 1,
         1e-6},
        {"compression", "log10 axial stress (MPa)", "porosity", "axial_stress", "porosity", 1e-6, 1,
         true}}},
      {"triaxial",
       "radial stress held, platen at strain_rate to max_axial_strain (report: young_modulus at "
       "1e-4, peak_friction_angle, critical_friction_angle)",
       &dem::kTriaxialPath,
       run_element_test_job,
       report_triaxial,
       kDeviatorPicture,
       {kDeviatorPlot, kVolumePlot}},
      {"triaxial-p",
       "mean stress p' held at confining (radial stress (3p' - sa)/2), platen at strain_rate to "
       "max_axial_strain (report: the triaxial's, and mean_stress_drift)",
       &dem::kConstantMeanStressPath,
       run_element_test_job,
       report_constant_p,
       kDeviatorPicture,
       {kDeviatorPlot, kVolumePlot}},
      {"cpt",
       "the [probe] cone pushed down the cell's axis from the top platen at its velocity to its "
       "depth, the cell's stresses held: curve.csv step,depth,tip_force,sleeve_force,qc,fs",
       nullptr,
       cpt_job,
       nullptr,
       {},
       {{"cone resistance", "depth (m)", "qc (MPa)", "depth", "qc", 1, 1e-6},
        {"sleeve friction", "depth (m)", "fs (kPa)", "depth", "fs", 1, 1e-3}}},
  };
  return kinds;
}

const TestKind& find_test_kind(const std::string& name) {
  for (const TestKind& k : test_kinds())
    if (name == k.name) return k;
  throw InvalidInput("test: unknown test '" + name + "' (known: " + test_kind_names() + ")");
}

std::string test_kind_names() {
  std::string names;
  const auto& kinds = test_kinds();
  for (std::size_t k = 0; k < kinds.size(); ++k)
    names += std::string(k == 0 ? "" : k + 1 == kinds.size() ? " or " : ", ") + kinds[k].name;
  return names;
}

}  // namespace clumpkit
