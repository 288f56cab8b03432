// The element test as a resumable stage (dem/lab/element_loading.h): its state as a stage record,
// and the run that checkpoints it into a StageStore and continues from one.
#include "dem/lab/element_loading.h"

#include "dem/run/single_stage.h"
#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace clumpkit::dem {

namespace {

constexpr const char* kStage = "test";
constexpr int kRowFields = 21 + kBreakageClasses;

// The curve row's numbers in file order (the step is the first, written as a double: exact up
// to 2^53 steps).
std::array<double*, kRowFields - 1> row_fields(CurveRow& c) {
  return {&c.axial_strain,
          &c.volumetric_strain,
          &c.axial_stress,
          &c.lateral_stress,
          &c.p,
          &c.q,
          &c.porosity,
          &c.coordination,
          &c.unbalanced,
          &c.interior_axial_strain,
          &c.bonds_broken,
          &c.fragments,
          &c.particles_broken,
          &c.bonds_mode_i,
          &c.bonds_mode_ii,
          &c.bonds_mixed,
          &c.hardin_br,
          &c.einav_b,
          &c.marsal_bg,
          &c.broken_by_class[0],
          &c.broken_by_class[1],
          &c.broken_by_class[2],
          &c.broken_by_class[3],
          &c.held};
}

// How far the test is (0..1): the consolidation is the first tenth (by its step cap), the
// loading the rest by its end criterion.
double fraction_done(const ElementTestState& st, const ElementTestSettings& s) {
  if (st.phase != ElementTestState::Phase::loading || st.curve.empty())
    return 0.1 * std::min(1.0, double(st.consolidation_steps) /
                                   double(std::max(1LL, s.max_consolidation_steps)));
  const CurveRow& c = st.curve.back();
  const double f = s.path->progress(s, c);
  return 0.1 + 0.9 * std::clamp(std::isfinite(f) ? f : 0.0, 0.0, 1.0);
}

}  // namespace

StageRecord element_test_record(const ElementTestState& st, const TestCell& cell) {
  StageRecord r;
  r["phase"] = std::to_string(static_cast<int>(st.phase));
  r["consolidation_steps"] = std::to_string(st.consolidation_steps);
  r["consolidated"] = st.consolidated ? "1" : "0";
  r["loading_steps"] = std::to_string(st.loading_steps);
  put_number(r, "start_height", st.start_height);
  put_number(r, "height0", st.height0);
  put_number(r, "volume0", st.volume0);
  put_number(r, "solid_volume", st.solid_volume);
  put_number(r, "test_friction", st.test_friction);
  put_number(r, "interior_strain", st.interior_strain);
  r["next_hold"] = std::to_string(st.next_hold);
  r["holding"] = st.holding ? "1" : "0";
  r["hold_steps"] = std::to_string(st.hold_steps);
  put_cell(r, cell);
  put_test_curve(r, st.curve, [](CurveRow& c) { return row_fields(c); });
  return r;
}

void read_element_test_record(const StageRecord& r, const std::string& where, ElementTestState& st,
                              TestCell& cell) {
  st.phase = static_cast<ElementTestState::Phase>(record_phase(r, where, 4));
  st.consolidation_steps = record_integer(r, "consolidation_steps", where);
  st.consolidated = record_integer(r, "consolidated", where) != 0;
  st.loading_steps = record_integer(r, "loading_steps", where);
  st.start_height = record_number(r, "start_height", where);
  st.height0 = record_number(r, "height0", where);
  st.volume0 = record_number(r, "volume0", where);
  st.solid_volume = record_number(r, "solid_volume", where);
  st.test_friction = record_number(r, "test_friction", where);
  st.interior_strain = record_number(r, "interior_strain", where);
  st.next_hold = static_cast<int>(record_integer(r, "next_hold", where));
  st.holding = record_integer(r, "holding", where) != 0;
  st.hold_steps = record_integer(r, "hold_steps", where);
  cell = read_cell(r, where);
  st.curve =
      read_test_curve<CurveRow>(r, kRowFields, where, [](CurveRow& c) { return row_fields(c); });
}

ElementTestResult run_element_test(
    CellSpecimen& specimen, const ElementTestSettings& settings, const StageControl& control,
    const std::string& fingerprint,
    const std::function<void(const CellSpecimen&, const ElementTestState&)>& consolidated) {
  ElementTestState state;
  SingleStage stage;
  stage.stage = kStage;
  stage.what = "test";
  stage.resume = [&](const StageRecord& record, const World& world) {
    read_element_test_record(record, std::string("element test checkpoint"), state, specimen.cell);
    for (int w : cell_walls(specimen.cell))
      if (w >= static_cast<int>(world.walls().size()))
        throw InvalidInput("element test checkpoint: the cell's wall " + std::to_string(w) +
                           " is not a wall of its world");
  };
  stage.record = [&] { return element_test_record(state, specimen.cell); };
  stage.fraction = [&] { return fraction_done(state, settings); };
  ElementTestResult r;
  r.resumed = run_single_stage(
      specimen.world, control, fingerprint, stage,
      [&](const std::function<bool()>& stop) {
        r = run_element_test(specimen.world, specimen.cell, settings, state, [&] {
          if (consolidated && state.phase == ElementTestState::Phase::loading &&
              state.loading_steps == 0 && state.curve.size() == 1)
            consolidated(specimen, state);
          return stop();
        });
        return r.stopped;
      },
      [&] {
        return StageRecord{{"steps", std::to_string(state.curve.back().step)}};
      });
  return r;
}

}  // namespace clumpkit::dem
