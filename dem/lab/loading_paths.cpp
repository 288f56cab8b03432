// The loading paths of the element tests (LoadingPath, dem/lab/element_loading.h).
#include "dem/lab/element_loading.h"

#include <algorithm>

namespace clumpkit::dem {

namespace {

using Mode = Control::Mode;

double ramp_duration(const ElementTestSettings& s, double stress_rate) {
  return (s.final_stress - s.confining) / stress_rate;
}
double strain_duration(const ElementTestSettings& s, double) {
  return s.max_axial_strain / s.strain_rate;
}
bool strain_reached(const ElementTestSettings& s, const CurveRow& c) {
  return c.axial_strain >= s.max_axial_strain;
}
double strain_progress(const ElementTestSettings& s, const CurveRow& c) {
  return c.axial_strain / s.max_axial_strain;
}

}  // namespace

const LoadingPath kIsotropicPath{
    "isotropic",
    false,
    true,
    false,
    [](const LoadingStep& at, Control& axial, Control& lateral) {
      const ElementTestSettings& s = at.settings;
      const double target = std::min(
          s.final_stress, s.confining + at.stress_rate * at.dt * double(at.state.loading_steps));
      axial = lateral = Control{Mode::stress, target, 0.0};
    },
    [](const ElementTestSettings& s, const CurveRow& c) {
      return c.p >= s.final_stress * (1.0 - s.consolidation_tolerance);
    },
    [](const ElementTestSettings& s, const CurveRow& c) {
      return (c.p - s.confining) / (s.final_stress - s.confining);
    },
    ramp_duration};

const LoadingPath kOedometerPath{
    "oedometer", true, true, true,
    [](const LoadingStep& at, Control& axial, Control& lateral) {
      const ElementTestState& st = at.state;
      axial = st.holding ? Control{Mode::top_stress, at.settings.hold_stresses[st.next_hold], 0.0}
                         : Control{Mode::velocity, 0.0, at.platen_speed};
      lateral = Control{Mode::fixed, 0.0, 0.0};
    },
    [](const ElementTestSettings& s, const CurveRow& c) {
      return c.axial_stress >= s.final_stress;
    },
    [](const ElementTestSettings& s, const CurveRow& c) {
      return (c.axial_stress - s.confining) / (s.final_stress - s.confining);
    },
    // Half the height at the strain rate: a bound, since the platen stops at final_stress.
    [](const ElementTestSettings& s, double) { return 0.5 / s.strain_rate; }};

const LoadingPath kTriaxialPath{"triaxial",
                                true,
                                false,
                                false,
                                [](const LoadingStep& at, Control& axial, Control& lateral) {
                                  axial = Control{Mode::velocity, 0.0, at.platen_speed};
                                  lateral = Control{Mode::stress, at.settings.confining, 0.0};
                                },
                                strain_reached,
                                strain_progress,
                                strain_duration};

const LoadingPath kConstantMeanStressPath{
    "triaxial-p",
    true,
    false,
    false,
    [](const LoadingStep& at, Control& axial, Control& lateral) {
      axial = Control{Mode::velocity, 0.0, at.platen_speed};
      const double sa = axial_stress(at.world, at.cell);
      lateral = Control{Mode::stress, std::max(0.0, 0.5 * (3.0 * at.settings.confining - sa)), 0.0};
    },
    strain_reached,
    strain_progress,
    strain_duration};

}  // namespace clumpkit::dem
