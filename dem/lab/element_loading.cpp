#include "dem/lab/element_loading.h"

#include "dem/measure/fragment_sizes.h"
#include "dem/measure/strain_rate.h"
#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace clumpkit::dem {

namespace {

// Starts, checks and ends the oedometer's holds (ElementTestSettings::hold_stresses) after a
// step: a hold starts at the step whose axial stress reaches its target and is checked every
// 100 of its steps, as the consolidation is. Returns the CurveRow::held code of a hold that
// ended at this step (2 at equilibrium, 3 at the step limit), else 0.
int advance_hold(const World& world, const TestCell& cell, const ElementTestSettings& s,
                 ElementTestState& st) {
  const int holds = static_cast<int>(s.hold_stresses.size());
  if (!st.holding) {
    if (st.next_hold < holds && axial_stress(world, cell) >= s.hold_stresses[st.next_hold]) {
      st.holding = true;
      st.hold_steps = 0;
    }
    return 0;
  }
  if (++st.hold_steps % 100 != 0) return 0;
  const double target = s.hold_stresses[st.next_hold];
  const bool equilibrium =
      std::abs(axial_stress(world, cell) / target - 1.0) <= s.consolidation_tolerance &&
      mean_unbalanced_force_ratio(world) <= s.consolidation_unbalanced;
  if (!equilibrium && st.hold_steps < s.max_hold_steps) return 0;
  st.holding = false;
  ++st.next_hold;
  return equilibrium ? 2 : 3;
}

void check_holds(const ElementTestSettings& s) {
  if (s.hold_stresses.empty()) return;
  if (!s.path->holds)
    throw InvalidInput(std::string("element test: hold stresses are for the oedometer test only, "
                                   "not the ") +
                       s.path->name + " test");
  require(kMaxHoldSteps, static_cast<double>(s.max_hold_steps), "element test: max_hold_steps");
  const int bad = first_hold_out_of_order(s.hold_stresses, s.confining, s.final_stress);
  if (bad >= 0)
    throw InvalidInput(
        "element test: hold stresses must rise above the confining stress to "
        "at most the final stress, got " +
        format_number(s.hold_stresses[bad]));
}

}  // namespace

int first_hold_out_of_order(const std::vector<double>& holds, double confining,
                            double final_stress) {
  double last = confining;
  for (std::size_t i = 0; i < holds.size(); ++i) {
    if (!(holds[i] > last) || !(holds[i] <= final_stress)) return static_cast<int>(i);
    last = holds[i];
  }
  return -1;
}

WorldOptions element_test_world_options(const std::vector<Body>& bodies,
                                        const ContactParams& contact) {
  if (bodies.empty()) throw InvalidInput("element test: the specimen has no bodies");
  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.sort_every = 1000;
  o.contact = contact;
  double r_min = std::numeric_limits<double>::max();
  for (const Body& b : bodies)
    for (const Sphere& s : b.spheres) r_min = std::min(r_min, s.radius);
  o.skin = 0.2 * r_min;
  return o;
}

double crushable_skin(const std::vector<Body>& bodies) {
  std::vector<double> radius;
  for (const Body& b : bodies)
    for (const Sphere& s : b.spheres) radius.push_back(s.radius);
  if (radius.empty()) throw InvalidInput("element test: the specimen has no spheres");
  const auto middle = radius.begin() + static_cast<std::ptrdiff_t>(radius.size() / 2);
  std::nth_element(radius.begin(), middle, radius.end());
  return 0.75 * *middle;
}

double inertial_number(const std::vector<Body>& bodies, double strain_rate, double confining) {
  const GrainScale g = grain_scale(bodies);
  return strain_rate * g.diameter * std::sqrt(g.density / confining);
}

GrainScale grain_scale(const std::vector<Body>& bodies, const std::vector<int>& particles) {
  if (bodies.empty()) throw InvalidInput("grain scale: no bodies");
  if (!particles.empty() && particles.size() != bodies.size())
    throw InvalidInput("grain scale: one particle per body needed");
  double mass = 0, volume = 0;
  // The volume of each grain: a body's own, or its particle's sum.
  std::vector<double> grain(particles.empty() ? bodies.size() : 0, 0.0);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    mass += bodies[k].mass;
    volume += bodies[k].volume;
    const std::size_t g = particles.empty() ? k : std::size_t(particles[k]);
    if (g >= grain.size()) grain.resize(g + 1, 0.0);
    grain[g] += bodies[k].volume;
  }
  double d_sum = 0;
  int count = 0;
  for (double v : grain)
    if (v > 0) d_sum += std::cbrt(6.0 * v / kPi), ++count;
  return GrainScale{d_sum / count, mass / volume};
}

double inertial_strain_rate(const GrainScale& grains, double inertial, double stress) {
  return inertial * std::sqrt(stress / grains.density) / grains.diameter;
}

ElementTestResult run_element_test(World& world, const TestCell& cell, const ElementTestSettings& s,
                                   const std::function<bool()>& stop) {
  ElementTestState state;
  return run_element_test(world, cell, s, state, stop);
}

namespace {

// Rejects settings and a resumed state the test cannot run with, before anything moves.
void check_element_test(const ElementTestSettings& s, const ElementTestState& state) {
  if (s.path == nullptr) throw InvalidInput("element test: no loading path");
  require(kConfiningStress, s.confining, "element test: confining stress");
  require(kTestStrainRate, s.strain_rate, "element test: strain rate");
  require(kStressRate, s.stress_rate, "element test: stress rate");
  require(kHeldInertialNumber, s.inertial_number, "element test: inertial number");
  if (s.path->ends_at_final_stress && !(s.final_stress > s.confining))
    throw InvalidInput("element test: final stress must exceed the confining stress");
  if (!s.path->ends_at_final_stress)
    require(kMaxAxialStrain, s.max_axial_strain, "element test: maximum axial strain");
  require(kConsolidationTolerance, s.consolidation_tolerance,
          "element test: consolidation tolerance");
  require(kServoStrainRate, s.servo_strain_rate, "element test: servo strain rate");
  require(kRecordEvery, s.record_every, "element test: record_every");
  check_holds(s);
  const int holds = static_cast<int>(s.hold_stresses.size());
  if (state.next_hold < 0 || state.next_hold > holds || (state.holding && state.next_hold == holds))
    throw InvalidInput("element test: the state's hold " + std::to_string(state.next_hold) +
                       " is not one of the test's " + std::to_string(holds));
}

// The state of a new test: the loading friction, the consolidation's, and the specimen's
// starting height and solid volume.
void start_element_test(World& world, const TestCell& cell, const ElementTestSettings& s,
                        ElementTestState& st) {
  st.test_friction = s.friction >= 0.0 ? s.friction : world.options().contact.friction;
  world.rescale_friction(s.consolidation_friction >= 0.0 ? s.consolidation_friction
                                                         : st.test_friction);
  st.start_height = cell_height(world, cell);
  st.solid_volume = 0;
  for (const Body& b : world.bodies()) st.solid_volume += b.volume;
  st.phase = ElementTestState::Phase::consolidation;
}

// The result of the test so far, from its state.
ElementTestResult element_test_result(const ElementTestState& st, bool stopped) {
  ElementTestResult r;
  r.consolidation_steps = st.consolidation_steps;
  r.consolidated = st.consolidated;
  r.curve = st.curve;
  r.solid_volume = st.solid_volume;
  r.stopped = stopped;
  return r;
}

// The curve's row at loading step `step`: strains from the consolidated state.
CurveRow loading_row(const World& world, const TestCell& cell, const ElementTestSettings& s,
                     const ElementTestState& st, long long step) {
  const double h0 = st.height0, v0 = st.volume0;
  CurveRow c;
  c.step = step;
  c.axial_strain = (h0 - cell_height(world, cell)) / h0;
  const double v = cell_volume(world, cell);
  c.volumetric_strain = (v0 - v) / v0;
  c.axial_stress = axial_stress(world, cell);
  c.lateral_stress = lateral_stress(world, cell);
  c.p = (c.axial_stress + 2.0 * c.lateral_stress) / 3.0;
  c.q = c.axial_stress - c.lateral_stress;
  c.porosity = 1.0 - st.solid_volume / v;
  c.coordination = coordination_number(world);
  c.unbalanced = mean_unbalanced_force_ratio(world);
  // The rate integrates to the gauge's logarithmic strain; as the others, engineering.
  c.interior_axial_strain = -std::expm1(-st.interior_strain);
  if (!s.initial_grading.empty()) measure_breakage(world, s, c);
  return c;
}

// A bound on the loading steps: the planned duration four times over.
long long loading_step_bound(const ElementTestSettings& s, double rate, double dt) {
  const double duration = s.path->duration(s, rate);
  return static_cast<long long>(std::ceil(4.0 * duration / dt)) + 1000 +
         static_cast<long long>(s.hold_stresses.size()) * s.max_hold_steps;
}

// The steps of one record (record_every, or fewer when a hold ends): returns the
// CurveRow::held code of a hold that ended, else 0.
int loading_record(World& world, const TestCell& cell, const ElementTestSettings& s,
                   ElementTestState& st, const ServoGain& gain, double rate, double dt,
                   double platen_speed) {
  long long& step = st.loading_steps;
  int ended = 0;  // CurveRow::held of a hold that ended
  for (int k = 0; k < s.record_every && !ended; ++k) {
    Control axial, lateral;
    s.path->controls(LoadingStep{world, cell, s, st, rate, dt, platen_speed}, axial, lateral);
    drive_cell(world, cell, axial, lateral, gain, 1);
    const double base = world.walls()[cell.bottom].point.z(),
                 quarter = 0.25 * cell_height(world, cell);
    st.interior_strain +=
        interior_axial_strain_rate(world, base + quarter, base + 3.0 * quarter) * dt;
    ++step;
    if (!s.hold_stresses.empty()) ended = advance_hold(world, cell, s, st);
  }
  return ended;
}

// Whether the loading has ended at the recorded row `c`.
bool loading_done(const ElementTestSettings& s, const ElementTestState& st, const CurveRow& c,
                  bool final_held) {
  // With holds: once the last has ended, and at its end when it holds the final stress.
  const bool holds_done = !st.holding && st.next_hold == static_cast<int>(s.hold_stresses.size());
  return holds_done && (final_held || s.path->done(s, c));
}

// The loading phase, from the consolidated state (or a resumed one) to its end, recording a
// row every record_every steps; the walls stop at its end. Returns whether `stop` ended it.
bool run_loading(World& world, const TestCell& cell, const ElementTestSettings& s,
                 ElementTestState& st, const ServoGain& gain, double dt,
                 const std::function<bool()>& stop) {
  const double h0 = st.height0;
  if (st.curve.empty()) {
    st.curve.push_back(loading_row(world, cell, s, st, 0));
    // Asked once at the consolidated state too: a caller may save it (or stop there).
    if (stop && stop()) return true;
  }
  const double rate =
      s.stress_rate > 0.0 ? s.stress_rate : 20.0 * s.confining * s.strain_rate;  // Pa/s
  const double base_speed = s.strain_rate * h0;
  const bool held_inertial = s.inertial_number > 0.0 && s.path->strain_driven;
  const GrainScale grains = held_inertial ? grain_scale(world.bodies(), s.particles) : GrainScale{};
  const long long max_steps = loading_step_bound(s, rate, dt);
  const bool final_held = !s.hold_stresses.empty() && s.hold_stresses.back() >= s.final_stress;
  const long long& step = st.loading_steps;
  while (step < max_steps) {
    // The rate of the next record's steps, from the last row's stress (so a resumed test
    // continues at the same speed).
    const double platen_speed =
        held_inertial
            ? std::max(base_speed, h0 * inertial_strain_rate(
                                            grains, s.inertial_number,
                                            std::max(st.curve.back().axial_stress, s.confining)))
            : base_speed;
    const int ended = loading_record(world, cell, s, st, gain, rate, dt, platen_speed);
    CurveRow c = loading_row(world, cell, s, st, step);
    c.held = ended ? ended : st.holding ? 1 : 0;
    st.curve.push_back(c);
    if (loading_done(s, st, c, final_held)) break;
    if (stop && stop()) return true;
  }
  for (int w : cell.lateral) set_wall_speed(world, w, 0.0);
  set_wall_speed(world, cell.bottom, 0.0);
  set_wall_speed(world, cell.top, 0.0);
  st.phase = ElementTestState::Phase::done;
  return false;
}

}  // namespace

ElementTestResult run_element_test(World& world, const TestCell& cell, const ElementTestSettings& s,
                                   ElementTestState& state, const std::function<bool()>& stop) {
  using Phase = ElementTestState::Phase;
  check_element_test(s, state);

  ElementTestState& st = state;
  if (st.phase == Phase::start) start_element_test(world, cell, s, st);
  const double dt = world.options().timestep;
  const ServoGain gain =
      test_servo_gain(s.gain, s.servo_strain_rate, s.strain_rate, st.start_height, dt);

  // 1. Isotropic consolidation to the confining stress.
  if (st.phase == Phase::consolidation) {
    const Consolidation c = consolidate_cell(world, cell, s.confining, s.consolidation_tolerance,
                                             s.consolidation_unbalanced, s.max_consolidation_steps,
                                             gain, st.consolidation_steps, stop);
    if (c == Consolidation::stopped) return element_test_result(st, true);
    st.consolidated = c == Consolidation::equilibrium;
    st.height0 = cell_height(world, cell);
    st.volume0 = cell_volume(world, cell);
    if (world.options().contact.friction != st.test_friction)
      world.rescale_friction(st.test_friction);
    st.phase = Phase::loading;
  }

  // 2. Loading, from the consolidated state.
  if (st.phase == Phase::loading && run_loading(world, cell, s, st, gain, dt, stop))
    return element_test_result(st, true);
  return element_test_result(st, false);
}

void measure_breakage(const World& world, const ElementTestSettings& s, CurveRow& row) {
  const std::vector<Body>& bodies = world.bodies();
  const int n = static_cast<int>(bodies.size());
  const std::vector<Bond>& bonds = world.bonds();
  if (s.particles.size() != bodies.size())
    throw InvalidInput("element test: breakage needs the particle of every body");
  const std::vector<int>& particle = s.particles;
  const std::vector<int> piece = fragments(n, bonds);
  // A particle is broken when one of its bodies lies in another fragment than its first body.
  std::vector<int> first_piece(n, -1);
  std::vector<char> broken(n, 0);
  for (int k = 0; k < n; ++k) {
    int& f = first_piece[particle[k]];
    if (f < 0) f = piece[k];
    if (piece[k] != f) broken[particle[k]] = 1;
  }
  row.bonds_broken = row.bonds_mode_i = row.bonds_mode_ii = row.bonds_mixed = 0;
  for (const Bond& b : bonds) switch (failure_mode(b)) {
      case BondFailure::intact:
        break;
      case BondFailure::mode_i:
        row.bonds_broken += 1, row.bonds_mode_i += 1;
        break;
      case BondFailure::mode_ii:
        row.bonds_broken += 1, row.bonds_mode_ii += 1;
        break;
      case BondFailure::mixed:
        row.bonds_broken += 1, row.bonds_mixed += 1;
        break;
    }
  row.fragments = row.particles_broken = 0;
  std::vector<double> volume(n, 0.0);
  for (int k = 0; k < n; ++k) volume[particle[k]] += bodies[k].volume;
  std::array<double, kBreakageClasses> in_class{};
  row.broken_by_class.fill(0.0);
  for (int k = 0; k < n; ++k) {
    row.fragments += piece[k] == k ? 1 : 0;
    row.particles_broken += broken[k];
    if (particle[k] != k || s.class_bounds.size() != kBreakageClasses + 1) continue;
    const double d = std::cbrt(6.0 * volume[k] / M_PI);
    int c = 0;
    while (c + 1 < kBreakageClasses && d >= s.class_bounds[c + 1]) ++c;
    in_class[c] += 1;
    row.broken_by_class[c] += broken[k];
  }
  for (int c = 0; c < kBreakageClasses; ++c)
    row.broken_by_class[c] = in_class[c] > 0 ? row.broken_by_class[c] / in_class[c] : 0.0;
  const std::vector<SievedPiece> now = fragment_pieces(s.reference, bonds);
  row.hardin_br = hardin_breakage(s.initial_grading, now, s.breakage_limits);
  row.einav_b = einav_breakage(s.initial_grading, now, s.breakage_limits);
  row.marsal_bg = marsal_breakage(s.initial_grading, now, s.sieves);
}

double tangent_modulus(const std::vector<CurveRow>& curve, double (*stress)(const CurveRow&),
                       double (*strain)(const CurveRow&), double lo, double hi) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const CurveRow& c : curve) {
    const double y = stress(c), x = strain(c);
    if (!(y >= lo && y <= hi)) continue;
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  if (n < 3) return std::numeric_limits<double>::quiet_NaN();
  const double den = n * sxx - sx * sx;
  if (!(den > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / den;
}

double friction_angle(const CurveRow& row) {
  const double sum = row.axial_stress + row.lateral_stress;
  if (!(sum > 0)) return std::numeric_limits<double>::quiet_NaN();
  return std::asin(std::clamp((row.axial_stress - row.lateral_stress) / sum, -1.0, 1.0)) * 180.0 /
         kPi;
}

}  // namespace clumpkit::dem
