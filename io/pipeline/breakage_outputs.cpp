#include "io/pipeline/breakage_outputs.h"

#include "dem/measure/fragment_sizes.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"
#include "io/formats/specimen_vtp.h"
#include "io/reports/plot.h"

#include <algorithm>
#include <cmath>

namespace clumpkit {

void track_breakage(const dem::World& world, dem::ElementTestSettings& s) {
  s.reference.clear();
  s.particles.clear();
  s.initial_grading.clear();
  s.sieves.clear();
  s.class_bounds.clear();
  if (world.bonds().empty()) return;
  s.reference = world.bodies();
  s.particles = dem::fragments(static_cast<int>(world.bodies().size()), world.bonds());
  s.initial_grading = dem::fragment_pieces(s.reference, world.bonds());
  double largest = 0;
  for (const dem::SievedPiece& p : s.initial_grading) largest = std::max(largest, p.size);
  s.sieves = dem::sieve_series(largest / 64, largest * std::sqrt(2.0), std::sqrt(2.0));
  // Size classes: the particles' volume-equivalent diameters in equal steps from the smallest
  // to the largest (the last bound a hair above it, so the largest falls in the last class).
  double d_lo = 1e300, d_hi = 0;
  for (const dem::SievedPiece& p : s.initial_grading) {
    const double d = std::cbrt(6.0 * p.volume / M_PI);
    d_lo = std::min(d_lo, d), d_hi = std::max(d_hi, d);
  }
  for (int c = 0; c <= dem::kBreakageClasses; ++c)
    s.class_bounds.push_back(d_lo + (d_hi - d_lo) * c / dem::kBreakageClasses);
  s.class_bounds.back() *= 1.0 + 1e-12;
}

std::vector<double> input_work(const std::vector<dem::CurveRow>& curve) {
  std::vector<double> w(curve.size(), 0.0);
  for (std::size_t k = 1; k < curve.size(); ++k) {
    const dem::CurveRow &a = curve[k - 1], &b = curve[k];
    const double radial_a = 0.5 * (a.volumetric_strain - a.axial_strain),
                 radial_b = 0.5 * (b.volumetric_strain - b.axial_strain);
    w[k] = w[k - 1] + 0.5 * (a.axial_stress + b.axial_stress) * (b.axial_strain - a.axial_strain) +
           (a.lateral_stress + b.lateral_stress) * (radial_b - radial_a);
  }
  return w;
}

std::string breakage_header() {
  std::string h =
      ",bonds_broken,bonds_mode_i,bonds_mode_ii,bonds_mixed,fragments,particles_broken,hardin_br,"
      "einav_b,marsal_bg,work";
  for (int c = 1; c <= dem::kBreakageClasses; ++c) h += ",broken_class_" + std::to_string(c);
  return h;
}

namespace {

std::string class_values(const dem::CurveRow& c) {
  std::string v;
  for (double f : c.broken_by_class) v += "," + format_number(f);
  return v;
}

}  // namespace

std::string breakage_values(const dem::CurveRow& c, double work) {
  return "," + format_number(c.bonds_broken) + "," + format_number(c.bonds_mode_i) + "," +
         format_number(c.bonds_mode_ii) + "," + format_number(c.bonds_mixed) + "," +
         format_number(c.fragments) + "," + format_number(c.particles_broken) + "," +
         format_number(c.hardin_br) + "," + format_number(c.einav_b) + "," +
         format_number(c.marsal_bg) + "," + format_number(work) + class_values(c);
}

void write_breakage_outputs(const std::filesystem::path& out, const dem::World& world,
                            const dem::ElementTestSettings& s,
                            const std::vector<dem::CurveRow>& curve,
                            const std::vector<double>& work, nlohmann::ordered_json& report,
                            std::vector<std::string>& files) {
  const std::vector<dem::SievedPiece> final_pieces =
      dem::fragment_pieces(s.reference, world.bonds());
  const std::vector<double> before = dem::passing(s.initial_grading, s.sieves),
                            after = dem::passing(final_pieces, s.sieves);
  write_file_atomically((out / "grading.csv").string(), [&](std::ostream& f) {
    f << csv_header("grading", "sieve,passing_initial,passing_final", si_length()) << "\n";
    for (std::size_t k = 0; k < s.sieves.size(); ++k)
      f << format_number(s.sieves[k]) << "," << format_number(before[k]) << ","
        << format_number(after[k]) << "\n";
  });
  PlotSeries initial, last;
  for (std::size_t k = 0; k < s.sieves.size(); ++k) {
    const double x = std::log10(s.sieves[k] * 1e3);
    initial.points.x.push_back(x), initial.points.y.push_back(100 * before[k]);
    last.points.x.push_back(x), last.points.y.push_back(100 * after[k]);
  }
  initial.label = "before";
  last.label = "after";
  last.rgb = {200, 40, 30};
  write_plot((out / "grading.png").string(), {initial, last}, "log10 sieve size (mm)",
             "percent passing (by volume)", "grading by intermediate dimension");
  PlotSeries by_stress, by_work;
  for (std::size_t k = 0; k < curve.size(); ++k) {
    by_stress.points.x.push_back(curve[k].axial_stress / 1e6);
    by_stress.points.y.push_back(curve[k].hardin_br);
  }
  write_plot((out / "breakage.png").string(), {by_stress}, "axial stress (MPa)",
             "Hardin's relative breakage Br", "breakage against stress");
  for (std::size_t k = 0; k < curve.size(); ++k) {
    by_work.points.x.push_back(work[k] / 1e3);
    by_work.points.y.push_back(curve[k].hardin_br);
  }
  write_plot((out / "breakage_work.png").string(), {by_work}, "input work per volume (kJ/m³)",
             "Hardin's relative breakage Br", "breakage against input work");
  const dem::CurveRow& end = curve.back();
  double solid0 = 0, solid1 = 0;
  for (const dem::SievedPiece& p : s.initial_grading) solid0 += p.volume;
  for (const dem::SievedPiece& p : final_pieces) solid1 += p.volume;
  report["breakage"] = {
      {"bonds", world.bonds().size()},
      {"bonds_broken", end.bonds_broken},
      {"bonds_broken_by_mode",
       {{"mode_i", end.bonds_mode_i}, {"mode_ii", end.bonds_mode_ii}, {"mixed", end.bonds_mixed}}},
      {"particles", s.initial_grading.size()},
      {"particles_broken", end.particles_broken},
      {"fragments", end.fragments},
      {"hardin_br", end.hardin_br},
      {"einav_b", end.einav_b},
      {"marsal_bg", end.marsal_bg},
      {"work", work.back()},
      {"class_bounds", s.class_bounds},
      {"broken_by_class", end.broken_by_class},
      {"solid_volume_initial", solid0},
      {"solid_volume_final", solid1},
      {"sieve_rule",
       "a fragment passes a square sieve of opening s when its intermediate "
       "dimension I (extent along its middle principal axis of inertia) < s"}};
  const int n = static_cast<int>(world.bodies().size());
  write_specimen_vtp((out / "fragments.vtp").string(), specimen_bodies(world),
                     {{"particle", dem::fragment_ordinals(s.particles)},
                      {"fragment", dem::fragment_ordinals(dem::fragments(n, world.bonds()))}});
  for (const char* f :
       {"grading.csv", "grading.png", "breakage.png", "breakage_work.png", "fragments.vtp"})
    files.push_back(f);
}

}  // namespace clumpkit
