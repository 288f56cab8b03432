#include "dem/specimen/specimen.h"

#include "dem/specimen/container.h"

#include "dem/core/timestep.h"
#include "dem/run/run.h"
#include "dem/specimen/deposition.h"
#include "dem/specimen/placement.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/progress.h"
#include "geom/random.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <mutex>
#include <optional>

namespace clumpkit::dem {

namespace {

// Random streams of the stages (Rng::stream(seed, index)).
enum SpecimenStream : std::uint64_t {
  calibration_particles = 1,
  calibration_placement,
  layer_particles_stream,
  layer_placement
};

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double top_height(const World& world) {
  double top = 0.0;
  for (const Body& b : world.bodies())
    for (const Sphere& s : b.spheres)
      top = std::max(top, (b.orientation * s.center + b.position).z() + s.radius);
  return top;
}

/// Central region of a settled pack: margin from the wall, the floor and the top.
CylinderRegion central_region(double radius, double margin, double height) {
  CylinderRegion r;
  r.radius = radius - margin;
  r.z_lo = margin;
  r.z_hi = height - margin;
  if (!(r.radius > 0) || !(r.z_hi > r.z_lo))
    throw InvalidInput("specimen: the measurement margin " + std::to_string(margin) +
                       " m leaves no central region in a pack " + std::to_string(height) +
                       " m high of radius " + std::to_string(radius) + " m");
  return r;
}

DepositionSpec deposition_spec(const SpecimenSpec& s, double friction) {
  DepositionSpec d;
  d.radius = s.radius;
  d.contact = s.contact;
  d.contact.friction = friction;
  d.timestep_safety = s.timestep_safety;
  return d;
}

double smallest_size(const SpecimenSpec& s) {
  double d = INFINITY;
  for (const ParticleClass& c : s.classes) d = std::min(d, c.min_size);
  return d;
}

/// The density scaling λ of the preparation (SpecimenSpec::density_scaling).
double density_scaling(const SpecimenSpec& s) {
  if (s.density_scaling > 0) return s.density_scaling;
  const double d_min = smallest_size(s);
  const double stress =
      std::max(s.rock_density, s.soil_density) * (1.0 - s.porosity_guess) * 9.81 * s.height;
  return std::clamp(0.005 * s.contact.kn / (stress * d_min), 1.0, 1000.0);
}

/// A deposition world with masses scaled by λ and the time step of the scaled bodies.
World scaled_world(const std::vector<Body>& bodies, const std::vector<Placement>& placed,
                   const SpecimenSpec& spec, double friction, double lambda) {
  World world = make_deposition_world(bodies, placed, deposition_spec(spec, friction));
  for (Body& b : world.bodies()) {
    b.mass *= lambda;
    b.moments *= lambda;
  }
  const double dt = critical_timestep(world);
  if (std::isfinite(dt)) world.options().timestep = spec.timestep_safety * dt;
  return world;
}

/// Settles `world` from its current step to equilibrium (SpecimenSpec::equilibrium_ratio or the
/// settled-height rule of run_until) or the step cap, with periodic checkpoints of `stage`
/// carrying the run's state (the height reference), so a resumed run tests its
/// rules as the uninterrupted one. `resumed` is the info of the checkpoint the world came from,
/// or null for a fresh stage. `report(fraction of the stage)` answers whether to stop; then the
/// checkpoint is saved and Interrupted thrown.
RunOutcome settle(World& world, const SpecimenSpec& spec, const std::string& stage,
                  StageStore& store, const StageControl& control,
                  const std::function<bool(double)>& report,
                  const CheckpointInfo* resumed = nullptr) {
  RunLimits limits;
  limits.max_steps = std::max(0L, spec.max_steps - static_cast<long>(world.steps()));
  limits.weight_ratio_below = spec.equilibrium_ratio;
  limits.height_window = spec.settle_window;
  limits.height_tolerance = spec.height_tolerance * smallest_size(spec);
  if (resumed)
    limits.state.height_reference = record_number(resumed->state, "height_reference", stage);
  if (store.keeps_checkpoints()) {
    limits.checkpoint_every_seconds = control.checkpoint_every_seconds;
    limits.checkpoint = [&](const World& w, const RunState& state) {
      CheckpointInfo info;
      info.stage = stage;
      put_number(info.state, "height_reference", state.height_reference);
      store.checkpoint(stage, w, info);
    };
  }
  RunOutcome out = run_until(world, limits, [&](std::string_view, double) {
    return report &&
           report(static_cast<double>(world.steps()) / static_cast<double>(spec.max_steps));
  });
  out.steps = static_cast<long>(world.steps());
  if (out.stopped_by == "interrupted")
    throw Interrupted("specimen: stopped on request in stage " + stage + " at step " +
                      std::to_string(out.steps) +
                      (store.keeps_checkpoints() ? " (checkpoint kept)" : ""));
  return out;
}

/// A settling stage of the layer or the specimen: the world it ended with when the store has it
/// finished, else settled from the store's running checkpoint or from `start()`; after settling,
/// `finish` (if any) edits the world before the store keeps it.
World settled_stage(const std::string& name, StageStore& store, const SpecimenSpec& spec,
                    const StageControl& control, const std::function<World()>& start,
                    const std::function<bool(double)>& report,
                    const std::function<void(World&)>& finish = {}) {
  if (store.finished(name)) return store.finished_world(name);
  CheckpointInfo info;
  std::optional<World> resumed = store.running(name, info);
  World world = resumed ? std::move(*resumed) : start();
  settle(world, spec, name, store, control, report, resumed ? &info : nullptr);
  if (finish) finish(world);
  store.finish(name, {{"steps", std::to_string(world.steps())}}, &world);
  return world;
}

void check_spec(const SpecimenSpec& s) {
  auto bad = [](const std::string& what) { throw InvalidInput("specimen: " + what); };
  try {
    check_container_length(s.radius);
    check_container_length(s.height);
  } catch (const InvalidInput& e) {
    bad(std::string("container radius and height: ") + e.what());
  }
  require(kSpecimenLayers, s.layers, "specimen: layers");
  require(kDensity, s.soil_density, "specimen: soil density");
  require(kDensity, s.rock_density, "specimen: rock density");
  if (s.correction_rounds < 0 || !(s.relative_density_tolerance >= 0))
    bad("correction rounds and tolerance must be non-negative");
  if (s.classes.empty()) bad("the gradation has no classes");
  if (!kTargetRelativeDensity.contains(s.target_relative_density))
    bad("target relative density " + outside(kTargetRelativeDensity, s.target_relative_density) +
        ", got " + format_number(s.target_relative_density));
  if (s.calibration_frictions.size() < static_cast<std::size_t>(kMinCalibrationFrictions))
    bad("need at least " + std::to_string(kMinCalibrationFrictions) +
        " calibration frictions, got " + std::to_string(s.calibration_frictions.size()));
  for (double f : s.calibration_frictions)
    if (!kFriction.contains(f))
      bad("calibration frictions " + outside(kFriction, f) + ", got " + format_number(f));
  if (!(s.porosity_guess > 0 && s.porosity_guess < 1)) bad("porosity guess must lie in (0, 1)");
  if (!(s.equilibrium_ratio > 0) || s.max_steps < 1) bad("settling limits must be positive");
  if (s.settle_window < 0 || !(s.height_tolerance >= 0))
    bad("settle window and height tolerance must be non-negative");
  if (!(s.density_scaling >= 0) || !std::isfinite(s.density_scaling))
    bad("density scaling must be non-negative");
}

}  // namespace

double relative_density(double porosity, double porosity_max, double porosity_min) {
  const auto e = [](double n) { return n / (1.0 - n); };
  return (e(porosity_max) - e(porosity)) / (e(porosity_max) - e(porosity_min));
}

double interpolate_friction(const std::vector<CalibrationPoint>& c, double target) {
  if (c.size() < 2) throw InvalidInput("interpolate_friction: need at least two points");
  for (std::size_t k = 0; k + 1 < c.size(); ++k) {
    const double e0 = c[k].void_ratio, e1 = c[k + 1].void_ratio;
    if ((e0 <= target && target <= e1) || (e1 <= target && target <= e0)) {
      if (e1 == e0) return c[k].friction;
      return c[k].friction + (target - e0) / (e1 - e0) * (c[k + 1].friction - c[k].friction);
    }
  }
  // Outside the measured range: the nearer end.
  return std::abs(target - c.front().void_ratio) < std::abs(target - c.back().void_ratio)
             ? c.front().friction
             : c.back().friction;
}

World stack_layers(const World& layer, int layers, double layer_height) {
  World stacked(layer.options());
  stacked.reserve(
      static_cast<std::size_t>(layers) * layer.bodies().size(),
      static_cast<std::size_t>(layers) * static_cast<std::size_t>(layer.sphere_count()));
  for (int copy = 0; copy < layers; ++copy)
    for (const Body& b : layer.bodies()) {
      Body c = b;
      c.position.z() += copy * layer_height;
      c.velocity.setZero();
      c.angular_velocity.setZero();
      stacked.add_body(std::move(c));
    }
  for (const Wall& w : layer.walls()) stacked.add_wall(w);
  return stacked;
}

namespace {

/// What every stage of one build shares.
struct Build {
  const SpecimenSpec& spec;
  const StageControl& control;
  StageStore& store;
  double lambda;  ///< density scaling of the preparation
  double margin;  ///< of the measurement regions (m)
  /// Tells the interrupter the stage and the fraction of the whole job (clamped to 0..1).
  bool report(const std::string& stage, double fraction) const {
    return interrupted(control.interrupter, stage, std::clamp(fraction, 0.0, 1.0));
  }
};

/// Stage 1: n(μ) by depositing the same placed sample at each calibration friction (in
/// parallel, one stage per friction), porosity of the central region; sorted by friction.
std::vector<CalibrationPoint> calibrate(const Build& build, double layer_volume) {
  const SpecimenSpec& spec = build.spec;
  std::vector<double> frictions = spec.calibration_frictions;
  std::sort(frictions.begin(), frictions.end());
  frictions.erase(std::unique(frictions.begin(), frictions.end()), frictions.end());
  if (frictions.size() < 2) throw InvalidInput("specimen: need two distinct calibration frictions");
  std::vector<CalibrationPoint> cal(frictions.size());
  Rng particle_rng = Rng::stream(spec.seed, calibration_particles);
  const LayerParticles sample =
      layer_particles(spec.classes, spec.templates, (1.0 - spec.porosity_guess) * layer_volume,
                      spec.soil_density, spec.rock_density, particle_rng);
  Rng place_rng = Rng::stream(spec.seed, calibration_placement);
  const std::vector<Placement> placed =
      place_in_cylinder(placement_items(sample.bodies), spec.radius, place_rng);
  std::vector<double> fraction(frictions.size(), 0.0);
  std::mutex mutex;   // guards fraction, stop and error
  bool stop = false;  // sticky: once asked (or a run failed), every run stops at its next check
  std::exception_ptr error;  // the first failure (or interruption) of a run
  const auto run_one = [&](std::size_t k) {
    const std::string name = "calibration-" + std::to_string(k);
    StageStore& store = build.store;
    if (const std::optional<StageRecord> r = store.finished(name)) {
      const auto stopped = r->find("stopped_by");
      cal[k] = {record_number(*r, "friction", name), record_number(*r, "porosity", name), 0.0,
                static_cast<long>(record_integer(*r, "steps", name)),
                stopped == r->end() ? std::string() : stopped->second};
      cal[k].void_ratio = cal[k].porosity / (1.0 - cal[k].porosity);
      return;
    }
    CheckpointInfo info;
    std::optional<World> resumed = store.running(name, info);
    World world = resumed ? std::move(*resumed)
                          : scaled_world(sample.bodies, placed, spec, frictions[k], build.lambda);
    const auto report = [&](double f) {
      std::lock_guard<std::mutex> lock(mutex);
      fraction[k] = f;
      double sum = 0;
      for (double v : fraction) sum += v;
      stop = build.report("calibration", 0.5 * sum / static_cast<double>(fraction.size())) || stop;
      return stop;
    };
    const RunOutcome out =
        settle(world, spec, name, store, build.control, report, resumed ? &info : nullptr);
    CalibrationPoint& p = cal[k];
    p.friction = frictions[k];
    p.porosity = region_porosity(world, body_volumes(world),
                                 central_region(spec.radius, build.margin, column_height(world)));
    p.void_ratio = p.porosity / (1.0 - p.porosity);
    p.steps = out.steps;
    p.stopped_by = out.stopped_by;
    store.finish(name,
                 {{"friction", format_number(p.friction)},
                  {"porosity", format_number(p.porosity)},
                  {"steps", std::to_string(p.steps)},
                  {"stopped_by", p.stopped_by}},
                 nullptr);
  };
  // No exception may leave this loop while other runs step: TBB would cancel the task group,
  // and with it the parallel loops inside their World::step, which would then silently skip
  // work (and a checkpoint would save the damage). A failing or interrupted run records its
  // exception and makes the others stop at their next check (each saving a checkpoint first);
  // the first exception is rethrown once all have returned.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, frictions.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t k = range.begin(); k != range.end(); ++k) {
                        {
                          std::lock_guard<std::mutex> lock(mutex);
                          if (stop) return;  // asked to stop: start no further run
                        }
                        try {
                          run_one(k);
                        } catch (...) {
                          std::lock_guard<std::mutex> lock(mutex);
                          if (!error) error = std::current_exception();
                          stop = true;
                        }
                      }
                    });
  if (error) std::rethrow_exception(error);
  return cal;
}

/// Stage 4: porosity of the central region of the settled specimen, its relative density from
/// the calibration's extremes, the column height (into `result`).
void measure(const World& world, double radius, double margin, SpecimenResult& result) {
  result.height = column_height(world);
  result.region = central_region(radius, margin, result.height);
  result.porosity = region_porosity(world, body_volumes(world), result.region);
  result.relative_density =
      relative_density(result.porosity, result.porosity_max, result.porosity_min);
}

/// The per-layer and per-band porosities and the coordination number of the finished specimen.
void measure_profiles(const World& world, int layers, SpecimenResult& result) {
  // Layers and bands share the region's radius: one pass, each body integrated once.
  const double layer_span = result.height / layers;
  std::vector<CylinderRegion> regions;
  std::vector<int> layer_region(layers, -1);  // -1: the layer misses the central region
  for (int k = 0; k < layers; ++k) {
    CylinderRegion r = result.region;
    r.z_lo = std::max(result.region.z_lo, k * layer_span);
    r.z_hi = std::min(result.region.z_hi, (k + 1) * layer_span);
    if (!(r.z_hi > r.z_lo)) continue;
    layer_region[k] = static_cast<int>(regions.size());
    regions.push_back(r);
  }
  const int bands = 2 * layers;
  const double band = (result.region.z_hi - result.region.z_lo) / bands;
  for (int k = 0; k < bands; ++k) {
    CylinderRegion r = result.region;
    r.z_lo = result.region.z_lo + k * band;
    r.z_hi = k + 1 == bands ? result.region.z_hi : r.z_lo + band;
    regions.push_back(r);
  }
  const std::vector<double> porosity = region_porosities(world, body_volumes(world), regions);
  for (int k = 0; k < layers; ++k)
    result.layer_porosity.push_back(layer_region[k] >= 0 ? porosity[layer_region[k]]
                                                         : std::nan(""));
  result.band_porosity.assign(porosity.end() - bands, porosity.end());
  result.coordination = coordination_number(world, result.region);
}

}  // namespace

double next_compaction_friction(const std::vector<SpecimenRound>& rounds,
                                const std::vector<CalibrationPoint>& calibration,
                                double target_porosity, double& porosity_for_friction) {
  if (rounds.empty()) throw InvalidInput("specimen: no build to correct μ* from");
  const SpecimenRound* below = nullptr;  // densest-side build closest to the target
  const SpecimenRound* above = nullptr;
  for (const SpecimenRound& x : rounds) {
    if (x.porosity <= target_porosity && (!below || x.porosity > below->porosity)) below = &x;
    if (x.porosity > target_porosity && (!above || x.porosity < above->porosity)) above = &x;
  }
  if (below && above && above->porosity > below->porosity)
    return below->friction + (target_porosity - below->porosity) /
                                 (above->porosity - below->porosity) *
                                 (above->friction - below->friction);
  // One side only: the least-squares line n = a + b·μ through every build, when it rises with μ
  // as the calibration does, is followed to the target within the calibrated range.
  double sum_f = 0, sum_n = 0;
  for (const SpecimenRound& x : rounds) sum_f += x.friction, sum_n += x.porosity;
  const double count = static_cast<double>(rounds.size());
  const double mean_f = sum_f / count, mean_n = sum_n / count;
  double sff = 0, sfn = 0;
  for (const SpecimenRound& x : rounds) {
    sff += (x.friction - mean_f) * (x.friction - mean_f);
    sfn += (x.friction - mean_f) * (x.porosity - mean_n);
  }
  if (rounds.size() >= 2 && sff > 0 && sfn > 0)
    return std::clamp(mean_f + (target_porosity - mean_n) * sff / sfn, calibration.front().friction,
                      calibration.back().friction);
  porosity_for_friction += target_porosity - rounds.back().porosity;
  return interpolate_friction(calibration, porosity_for_friction / (1.0 - porosity_for_friction));
}

SpecimenResult build_specimen(const SpecimenSpec& spec, const StageControl& control) {
  check_spec(spec);
  SpecimenResult result;
  StageStore& store = store_of(control);
  store.open(spec_fingerprint(spec));

  const double layer_volume = M_PI * spec.radius * spec.radius * spec.height / spec.layers;
  double margin = spec.margin;
  if (margin <= 0)
    for (const ParticleClass& c : spec.classes) margin = std::max(margin, c.max_size);
  result.density_scaling = density_scaling(spec);
  const Build build{spec, control, store, result.density_scaling, margin};

  // Stage 1: calibration n(μ).
  auto t0 = Clock::now();
  result.calibration = calibrate(build, layer_volume);
  const std::vector<CalibrationPoint>& cal = result.calibration;
  result.porosity_min = cal.front().porosity;  // μ = smallest (0): densest
  result.porosity_max = cal.back().porosity;   // μ = largest: loosest
  const double e_max = result.porosity_max / (1.0 - result.porosity_max);
  const double e_min = result.porosity_min / (1.0 - result.porosity_min);
  const double e_target = e_max - spec.target_relative_density * (e_max - e_min);
  result.target_porosity = e_target / (1.0 + e_target);
  long cal_steps = 0;
  for (const CalibrationPoint& p : cal) cal_steps += p.steps;
  result.seconds.emplace_back("calibration", since(t0));
  result.steps.emplace_back("calibration", cal_steps);

  // Stages 2 and 3, repeated (at most spec.correction_rounds more times) while the specimen
  // misses the target relative density by more than spec.relative_density_tolerance (the layer
  // interfaces and the overburden make the stacked specimen differ from the single calibration
  // sample at the same μ). Particle volumes always follow the true target porosity, so the
  // height stays right; only μ* changes between rounds.
  // The layer's particles and their loose placement depend on the target porosity only, so
  // every round compacts the same placed layer (placed on first use: a resumed run may not
  // need it).
  Rng particle_rng = Rng::stream(spec.seed, layer_particles_stream);
  const LayerParticles layer =
      layer_particles(spec.classes, spec.templates, (1.0 - result.target_porosity) * layer_volume,
                      spec.soil_density, spec.rock_density, particle_rng);
  std::vector<Placement> layer_placed;
  double porosity_for_friction = result.target_porosity;
  double next_friction = interpolate_friction(cal, e_target);
  World& world = result.world;
  const double round_share = 0.45 / (1 + spec.correction_rounds);
  for (int round = 0;; ++round) {
    const std::string tag = "-" + std::to_string(round);
    const double base = 0.5 + round * round_share;
    const double friction = next_friction;
    result.rounds.push_back({friction, 0.0, 0.0});

    // Stage 2: one layer at the target porosity, compacted at μ*, then μ back to the material
    // friction for stage 3 (shear history rescaled).
    t0 = Clock::now();
    const World layer_world = settled_stage(
        "layer" + tag, store, spec, control,
        [&] {
          if (layer_placed.empty()) {
            Rng place_rng = Rng::stream(spec.seed, layer_placement);
            layer_placed = place_in_cylinder(placement_items(layer.bodies), spec.radius, place_rng);
          }
          return scaled_world(layer.bodies, layer_placed, spec, friction, build.lambda);
        },
        [&](double f) { return build.report("layer compaction", base + 0.4 * round_share * f); },
        [&](World& w) { w.rescale_friction(spec.contact.friction); });
    result.layer_porosity_compacted =
        region_porosity(layer_world, body_volumes(layer_world),
                        central_region(spec.radius, margin, column_height(layer_world)));
    result.layer_height = top_height(layer_world);
    result.steps.emplace_back("layer" + tag, static_cast<long>(layer_world.steps()));
    result.seconds.emplace_back("layer" + tag, since(t0));

    // Stage 3: layered duplication of the layer (already at the material friction): each copy
    // shifted up by the layer's top, so nothing overlaps, then settled to equilibrium.
    t0 = Clock::now();
    world = settled_stage(
        "specimen" + tag, store, spec, control,
        [&] { return stack_layers(layer_world, spec.layers, result.layer_height); },
        [&](double f) {
          return build.report("layered specimen", base + round_share * (0.4 + 0.6 * f));
        });
    result.steps.emplace_back("specimen" + tag, static_cast<long>(world.steps()));

    // Stage 4: measurement (masses do not enter it).
    measure(world, spec.radius, build.margin, result);
    result.friction_compaction = friction;
    result.rounds.back().porosity = result.porosity;
    result.rounds.back().relative_density = result.relative_density;
    result.seconds.emplace_back("specimen" + tag, since(t0));
    if (std::abs(result.relative_density - spec.target_relative_density) <=
            spec.relative_density_tolerance ||
        round >= spec.correction_rounds)
      break;
    next_friction =
        next_compaction_friction(result.rounds, cal, result.target_porosity, porosity_for_friction);
  }

  // True masses in the finished specimen.
  for (Body& b : world.bodies()) {
    b.mass /= build.lambda;
    b.moments /= build.lambda;
  }

  t0 = Clock::now();
  build.report("measurement", 0.95);
  measure_profiles(world, spec.layers, result);
  result.seconds.emplace_back("measurement", since(t0));
  build.report("done", 1.0);
  return result;
}

void measure_specimen(const World& world, double radius, double margin, int layers,
                      SpecimenResult& result) {
  if (!(margin >= 0) || !(radius > margin))
    throw InvalidInput("specimen: the measurement margin " + format_number(margin) +
                       " leaves no region in a container of radius " + format_number(radius));
  require(kSpecimenLayers, layers, "specimen: layers");
  result.layer_porosity.clear();
  result.band_porosity.clear();
  measure(world, radius, margin, result);
  measure_profiles(world, layers, result);
}

}  // namespace clumpkit::dem
