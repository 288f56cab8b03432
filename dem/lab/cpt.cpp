#include "dem/lab/cpt.h"

#include "dem/measure/stress.h"
#include "dem/run/single_stage.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace clumpkit::dem {

namespace {
constexpr const char* kCptStage = "cpt";
constexpr int kCptRowFields = 8;

// The cell's vertical axis (x, y): the cylinder's (a segment's apex), or the middle of the
// cuboid's side walls.
Vec3 cell_axis(const World& world, const TestCell& cell) {
  const std::vector<Wall>& w = world.walls();
  if (cell.shape != TestCell::Shape::cuboid)
    return Vec3(w[cell.lateral[0]].point.x(), w[cell.lateral[0]].point.y(), 0.0);
  return Vec3(0.5 * (w[cell.lateral[0]].point.x() + w[cell.lateral[1]].point.x()),
              0.5 * (w[cell.lateral[2]].point.y() + w[cell.lateral[3]].point.y()), 0.0);
}

std::array<double*, kCptRowFields - 1> row_fields(CptRow& c) {
  return {&c.depth, &c.tip_force,    &c.sleeve_force,  &c.qc,
          &c.fs,    &c.axial_stress, &c.lateral_stress};
}

double fraction_done(const CptState& st, const CptSettings& s) {
  if (st.phase != CptState::Phase::push || st.curve.empty())
    return 0.1 * std::min(1.0, double(st.consolidation_steps) /
                                   double(std::max(1LL, s.cell.max_consolidation_steps)));
  return 0.1 + 0.9 * std::clamp(st.curve.back().depth / s.probe.depth, 0.0, 1.0);
}

}  // namespace

void validate_probe(const ProbeSettings& p) {
  auto check = [](const Range& r, double v, const char* what, const char* unit) {
    if (!r.contains(v))
      throw InvalidInput(std::string("probe.") + what + " " + outside(r, v) + unit + ", got " +
                         format_number(v));
  };
  check(kProbeDiameter, p.diameter, "diameter", "");
  check(kProbeVelocity, p.velocity, "velocity", "");
  check(kProbeDepth, p.depth, "depth", "");
  check(kProbeApex, p.apex_deg, "apex_deg", " degrees");
}

void check_probe_width(const ProbeSettings& p, double width) {
  if (!(p.diameter <= 0.5 * width))
    throw InvalidInput("probe.diameter " + format_number(p.diameter) +
                       " m is wider than half the cell (width " + format_number(width) + " m)");
}

void check_probe_core(const ProbeSettings& p, double core_radius) {
  if (core_radius > 0.0 && p.diameter > 2.0 * core_radius)
    throw InvalidInput("cpt: probe.diameter " + format_number(p.diameter) +
                       " m is wider than the specimen's core of small particles (radius " +
                       format_number(core_radius) + " m)");
  if (core_radius > 0.0 && core_radius < 4.0 * p.diameter)
    throw InvalidInput("cpt: probe.diameter: the specimen's core of small particles (" +
                       format_number(core_radius) + " m) is smaller than 4 probe diameters (" +
                       format_number(4.0 * p.diameter) + " m)");
}

void check_segment_reach(const std::vector<Body>& bodies, const Vec3& axis, double angle,
                         const ProbeSettings& p) {
  // A sphere of diameter d between the segment's radial walls keeps its centre at least
  // (d/2)/sin(θ/2) from the axis, its surface (d/2)/sin(θ/2) − d/2: the probe must reach at
  // least one diameter past that into the packing around it (the largest particle within two
  // probe diameters of its shaft), or it barely touches the particles (a 30° segment of 6 mm
  // spheres keeps them 8.6 mm from the axis, an 18 mm cone's radius 9 mm).
  double d = 0.0;
  for (const Body& b : bodies)
    if (std::hypot(b.position.x() - axis.x(), b.position.y() - axis.y()) <
        0.5 * p.diameter + 2.0 * p.diameter)
      for (const Sphere& sp : b.spheres) d = std::max(d, 2.0 * sp.radius);
  const double gap = 0.5 * d / std::sin(0.5 * angle) - 0.5 * d;
  if (d > 0.0 && 0.5 * p.diameter - gap < d)
    throw InvalidInput("cpt: the segment's walls keep particles of " + format_number(d) + " m " +
                       format_number(gap) + " m from the axis: a probe of radius " +
                       format_number(0.5 * p.diameter) + " m reaches less than one particle " +
                       "past that (widen the segment or the probe)");
}

void validate_cpt(const World& world, const TestCell& cell, const CptSettings& s,
                  double core_radius) {
  const ProbeSettings& p = s.probe;
  try {
    validate_probe(p);
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string("cpt: ") + e.what());
  }
  check_probe_core(p, core_radius);
  const Vec3 l = cell_lengths(world, cell);
  try {
    check_probe_width(p, std::min(l.x(), l.y()));
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string("cpt: ") + e.what());
  }
  if (cell.shape == TestCell::Shape::segment)
    check_segment_reach(world.bodies(), cell_axis(world, cell), cell.angle, p);
  if (s.cell.record_every < 1) throw InvalidInput("cpt: record_every must be at least 1");
  if (!(s.cell.confining > 0.0)) throw InvalidInput("cpt: the confining stress must be positive");
}

CptResult run_cpt(World& world, const TestCell& cell, const CptSettings& s, CptState& st,
                  const std::function<bool()>& stop) {
  using Phase = CptState::Phase;
  validate_cpt(world, cell, s);
  const ProbeSettings& p = s.probe;
  if (st.phase == Phase::start) {
    st.test_friction = s.cell.friction >= 0.0 ? s.cell.friction : world.options().contact.friction;
    world.rescale_friction(s.cell.consolidation_friction >= 0.0 ? s.cell.consolidation_friction
                                                                : st.test_friction);
    st.start_height = cell_height(world, cell);
    st.phase = Phase::consolidation;
  }
  const double dt = world.options().timestep;
  // The push's strain rate, for the servo's default speed limit: the probe's speed over its
  // diameter.
  const ServoGain gain = test_servo_gain(s.cell.gain, s.cell.servo_strain_rate,
                                         p.velocity / p.diameter, st.start_height, dt);
  auto result = [&](bool stopped) {
    CptResult r;
    r.consolidation_steps = st.consolidation_steps;
    r.consolidated = st.consolidated;
    r.reached_bottom = st.reached_bottom;
    r.curve = st.curve;
    r.stopped = stopped;
    return r;
  };

  // 1. Isotropic consolidation to the confining stress.
  if (st.phase == Phase::consolidation) {
    const Consolidation c =
        consolidate_cell(world, cell, s.cell.confining, s.cell.consolidation_tolerance,
                         s.cell.consolidation_unbalanced, s.cell.max_consolidation_steps, gain,
                         st.consolidation_steps, stop);
    if (c == Consolidation::stopped) return result(true);
    st.consolidated = c == Consolidation::equilibrium;
    if (world.options().contact.friction != st.test_friction)
      world.rescale_friction(st.test_friction);
    // The probe, apex at the top platen on the cell's axis, pushed down.
    const Vec3 axis = cell_axis(world, cell);
    st.apex0 = world.walls()[cell.top].point.z();
    Wall probe = Wall::probe(Vec3(axis.x(), axis.y(), st.apex0), p.diameter, p.apex_deg,
                             Vec3(0.0, 0.0, -p.velocity));
    probe.friction = p.friction >= 0.0 ? p.friction : st.test_friction;
    st.probe = world.add_wall(probe);
    st.phase = Phase::push;
  }

  // 2. The push, with the cell's stresses held.
  if (st.phase == Phase::push) {
    const Wall& probe = world.walls()[st.probe];
    const double radius = 0.5 * p.diameter;
    const double shoulder = probe.profile[probe.sleeve_from].y();
    auto row = [&](long long step) {
      CptRow c;
      c.step = step;
      const double apex = world.walls()[st.probe].point.z();
      c.depth = st.apex0 - apex;
      // A segment holds angle/2π of the chamber and of the probe: forces for the whole one.
      const ProbeForces f = probe_forces(world, st.probe);
      const double whole = 1.0 / cell_fraction(cell);
      c.tip_force = whole * f.tip.z();
      c.sleeve_force = whole * f.sleeve.z();
      c.qc = c.tip_force / (kPi * radius * radius);
      const double embedded = world.walls()[cell.top].point.z() - (apex + shoulder);
      c.fs = embedded > 0.0 ? c.sleeve_force / (2.0 * kPi * radius * embedded) : 0.0;
      c.axial_stress = axial_stress(world, cell);
      c.lateral_stress = lateral_stress(world, cell);
      return c;
    };
    if (st.curve.empty()) {
      st.curve.push_back(row(0));
      if (stop && stop()) return result(true);
    }
    // The base fixed (with both platens under stress control the probe carried the whole
    // specimen down with it), the top platen and the lateral walls at the confining stress.
    const Control top{Control::Mode::top_stress, s.cell.confining, 0.0};
    const Control hold{Control::Mode::stress, s.cell.confining, 0.0};
    const long long max_steps = static_cast<long long>(std::ceil(p.depth / p.velocity / dt)) + 1;
    long long& step = st.push_steps;
    while (step < max_steps) {
      for (int k = 0; k < s.cell.record_every && step < max_steps; ++k, ++step)
        drive_cell(world, cell, top, hold, gain, 1);
      st.curve.push_back(row(step));
      const double apex = world.walls()[st.probe].point.z();
      if (apex - world.walls()[cell.bottom].point.z() < p.diameter) {
        st.reached_bottom = true;
        break;
      }
      if (st.curve.back().depth >= p.depth) break;
      if (stop && stop()) return result(true);
    }
    world.walls()[st.probe].velocity = Vec3::Zero();
    for (int w : cell_walls(cell)) set_wall_speed(world, w, 0.0);
    st.phase = Phase::done;
  }
  return result(false);
}

StageRecord cpt_record(const CptState& st, const TestCell& cell) {
  StageRecord r;
  r["phase"] = std::to_string(static_cast<int>(st.phase));
  r["consolidation_steps"] = std::to_string(st.consolidation_steps);
  r["consolidated"] = st.consolidated ? "1" : "0";
  r["push_steps"] = std::to_string(st.push_steps);
  put_number(r, "start_height", st.start_height);
  put_number(r, "test_friction", st.test_friction);
  put_number(r, "apex0", st.apex0);
  r["probe"] = std::to_string(st.probe);
  r["reached_bottom"] = st.reached_bottom ? "1" : "0";
  put_cell(r, cell);
  put_test_curve(r, st.curve, [](CptRow& c) { return row_fields(c); });
  return r;
}

void read_cpt_record(const StageRecord& r, const std::string& where, CptState& st, TestCell& cell) {
  st.phase = static_cast<CptState::Phase>(record_phase(r, where, 4));
  st.consolidation_steps = record_integer(r, "consolidation_steps", where);
  st.consolidated = record_integer(r, "consolidated", where) != 0;
  st.push_steps = record_integer(r, "push_steps", where);
  st.start_height = record_number(r, "start_height", where);
  st.test_friction = record_number(r, "test_friction", where);
  st.apex0 = record_number(r, "apex0", where);
  st.probe = static_cast<int>(record_integer(r, "probe", where));
  st.reached_bottom = record_integer(r, "reached_bottom", where) != 0;
  cell = read_cell(r, where);
  st.curve =
      read_test_curve<CptRow>(r, kCptRowFields, where, [](CptRow& c) { return row_fields(c); });
}

CptResult run_cpt(CellSpecimen& specimen, const CptSettings& settings, const StageControl& control,
                  const std::string& fingerprint,
                  const std::function<void(const CellSpecimen&, const CptState&)>& consolidated) {
  CptState state;
  SingleStage stage;
  stage.stage = kCptStage;
  stage.what = "cpt";
  stage.resume = [&](const StageRecord& record, const World& world) {
    read_cpt_record(record, std::string("cpt checkpoint"), state, specimen.cell);
    std::vector<int> walls = cell_walls(specimen.cell);
    if (state.probe >= 0) walls.push_back(state.probe);
    for (int w : walls)
      if (w >= static_cast<int>(world.walls().size()))
        throw InvalidInput("cpt checkpoint: wall " + std::to_string(w) +
                           " is not a wall of its world");
    if (state.probe >= 0 && world.walls()[state.probe].kind != Wall::Kind::probe)
      throw InvalidInput("cpt checkpoint: wall " + std::to_string(state.probe) + " is not a probe");
  };
  stage.record = [&] { return cpt_record(state, specimen.cell); };
  stage.fraction = [&] { return fraction_done(state, settings); };
  CptResult r;
  r.resumed = run_single_stage(
      specimen.world, control, fingerprint, stage,
      [&](const std::function<bool()>& stop) {
        r = run_cpt(specimen.world, specimen.cell, settings, state, [&] {
          if (consolidated && state.phase == CptState::Phase::push && state.push_steps == 0 &&
              state.curve.size() == 1)
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
