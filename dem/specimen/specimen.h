// Building a DEM specimen to a target relative density: calibration by quasi-vibration
// compaction, one compacted layer, layered duplication and measurement (Jin et al. 2017 §4).
#pragma once

#include "dem/core/world.h"
#include "dem/measure/region_volume.h"
#include "dem/run/stage_store.h"
#include "dem/specimen/specimen_particles.h"
#include "geom/progress.h"
#include "geom/range.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// The layers a deposited specimen is stacked from (SpecimenSpec::layers; measure_specimen's).
inline constexpr Range kSpecimenLayers = integers(1, 100);
/// The relative density Dr a deposited specimen is built to (SpecimenSpec).
inline constexpr Range kTargetRelativeDensity = closed(0, 1);

/// The fewest calibration frictions a deposition takes: the two ends of n(μ) (0 gives n_min, the
/// largest n_max) and at least four between them to read the target from. Each is in kFriction.
inline constexpr int kMinCalibrationFrictions = 6;

/// What to build (SI units).
struct SpecimenSpec {
  double radius = 0.15, height = 0.6;  ///< container cylinder (m)
  int layers = 3;                      ///< in kSpecimenLayers
  std::vector<ParticleClass> classes;  ///< after fines replacement
  std::vector<RockTemplate> templates;
  double soil_density = 2700, rock_density = 2870;  ///< kg/m³, each in kDensity
  /// Contact law; `friction` is the material friction (deposition, final state). Damping as in
  /// deposition_contact() unless set otherwise.
  ContactParams contact;
  double target_relative_density = 0.5;  ///< in kTargetRelativeDensity
  /// Frictions of the calibration (the largest gives n_max, 0 gives n_min): at least
  /// kMinCalibrationFrictions, each in kFriction.
  std::vector<double> calibration_frictions = {0.0, 0.05, 0.1, 0.2, 0.4, 0.8};
  std::uint64_t seed = 1;
  /// Porosity assumed when sizing the calibration sample (its solid volume fills one layer at
  /// this porosity); the measured n(μ) does not depend on it much.
  double porosity_guess = 0.4;
  /// Time step = safety × min body_critical_timestep, in kTimestepSafety (the deposition checks
  /// it). 0.35 measured stable on the srm40 calibration sample (μ = 0.8: porosity 0.4465 against
  /// 0.4456 at 0.2, in half the steps).
  double timestep_safety = 0.35;
  /// Equilibrium: Σ|F_net| / Σ weight (unbalanced_to_weight_ratio) below this, or the settled
  /// height rule below.
  double equilibrium_ratio = 0.01;
  /// Settled height: every `settle_window` steps of a settling run the column height (twice the
  /// volume-weighted mean body height) is compared with the previous window's; the run stops once
  /// it changed by less than height_tolerance × the smallest sieve size while the unbalanced
  /// force is below the total weight (ratio < 1, so a pack still falling or rebounding never
  /// stops). Measured on the srm40 calibration sample (16,937 bodies): μ = 0.8 keeps its porosity
  /// to 1e-4 from about 23k steps on, yet needs ~41k steps to reach ratio 0.01, and a frictionless
  /// pack creeps for 200k steps with its ratio near 0.3 (porosity 0.3408 at 40k steps, 0.3373 at
  /// the cap). 0 disables the rule.
  long settle_window = 2000;
  double height_tolerance = 0.02;
  long max_steps = 200000;  ///< step cap of each settling run
  /// Correction rounds: while the stacked specimen misses the target relative density by more
  /// than the tolerance, layer and specimen are rebuilt (at most this many more times) with a
  /// new μ* from every build so far (next_compaction_friction): interpolated between builds that
  /// bracket the target, else on the line through the builds, else read from the calibration at
  /// the porosity shifted by the miss.
  int correction_rounds = 3;
  double relative_density_tolerance = 0.015;
  /// Density scaling λ of the preparation (masses and moments ×λ, so the time step grows by
  /// √λ; gravity and inertia scale together, so static equilibria keep their geometry while
  /// contact overlaps grow by λ). 0 = automatic: the largest λ ≤ 1000 keeping the overlap under
  /// the full column's weight below 0.5 % of the smallest diameter,
  /// λ = 0.005·kn / (σ_v·d_min), σ_v = ρ_rock·(1 − porosity_guess)·g·height. The finished
  /// specimen has the true masses.
  double density_scaling = 0.0;
  /// Margin of the measurement regions from the wall, floor and top (m); 0 = the largest
  /// sieve size of the gradation.
  double margin = 0.0;
};

/// One point of the n(μ) calibration.
struct CalibrationPoint {
  double friction = 0.0, porosity = 0.0, void_ratio = 0.0;
  long steps = 0;  ///< steps the deposition took
  std::string stopped_by;
};

/// One build of layer and specimen: the compaction friction and what the specimen reached.
struct SpecimenRound {
  double friction = 0, porosity = 0, relative_density = 0;
};

/// The finished specimen and its measurements.
struct SpecimenResult {
  World world;  ///< bodies carry kind, template id, scale and exact volume
  std::vector<CalibrationPoint> calibration;  ///< sorted by friction
  double porosity_max = 0, porosity_min = 0;  ///< from the calibration
  double target_porosity = 0, friction_compaction = 0;
  double layer_height = 0;              ///< shift between duplicated layers (m)
  double layer_porosity_compacted = 0;  ///< central porosity of the compacted layer at μ*
  double porosity = 0, relative_density = 0, height = 0;
  CylinderRegion region;               ///< where `porosity` was measured
  std::vector<double> layer_porosity;  ///< per layer (central region of each)
  std::vector<double> band_porosity;   ///< 2·layers equal height bands of the central region
  double coordination = 0;             ///< mean coordination number in the central region
  std::vector<std::pair<std::string, double>> seconds;  ///< wall-clock seconds per stage
  std::vector<std::pair<std::string, long>> steps;      ///< steps per stage
  double density_scaling = 1.0;                         ///< λ used in the preparation
  std::vector<SpecimenRound> rounds;                    ///< every build, the last one is the result
};

/// Relative density Dr = (e_max − e)/(e_max − e_min) from porosities (e = n/(1 − n)).
double relative_density(double porosity, double porosity_max, double porosity_min);

/// The friction μ* at which the calibration gives the void ratio of the target relative density:
/// e* = e_max − Dr·(e_max − e_min), linear interpolation of e(μ) between the two calibration
/// points that bracket e* (the first bracket from μ = 0 upward). Throws InvalidInput for fewer
/// than two points.
double interpolate_friction(const std::vector<CalibrationPoint>& calibration,
                            double target_void_ratio);

/// The compaction friction of the next round after builds that missed the target porosity
/// (Jin et al. 2017's μ* corrected on the stacked specimens themselves): between the two closest
/// builds that bracket the target, linearly (regula falsi on the measured n(μ*)); with every
/// build on one side, the least-squares line n(μ*) through all of them followed to the target
/// (clamped to the calibrated frictions) when it rises with μ*; after a single build, or a line
/// that does not rise, the calibration curve at the porosity shifted by the misses so far
/// (accumulated in `porosity_for_friction`, which starts at the target). Throws InvalidInput
/// without a build.
double next_compaction_friction(const std::vector<SpecimenRound>& rounds,
                                const std::vector<CalibrationPoint>& calibration,
                                double target_porosity, double& porosity_for_friction);

/// Every field of the spec as text, one "key value" line each, doubles in hexadecimal (exact),
/// templates with all their spheres and mass properties: two specs that differ in any field
/// have different texts.
std::string canonical_text(const SpecimenSpec& spec);

/// The resume fingerprint: FNV-1a 64 (16 hex digits) of the program version and
/// canonical_text(spec), so checkpoints are reused only by the same program on the same spec.
std::string spec_fingerprint(const SpecimenSpec& spec);

/// Stage 4 of build_specimen on any settled world: the column height, the central region
/// (`margin` from the wall of a container of `radius`, the floor and the top), its porosity, the
/// relative density from result.porosity_max and porosity_min (set them first), the per-layer
/// and per-band porosities and the coordination number (from world.contacts(): step the world
/// once first). Throws InvalidInput for a margin that leaves no region or layers outside
/// kSpecimenLayers.
void measure_specimen(const World& world, double radius, double margin, int layers,
                      SpecimenResult& result);

/// Stage 3 of build_specimen: `layers` copies of the layer's bodies (and its walls), copy k
/// shifted up by k·layer_height and at rest; the copies keep kind, template, scale and mass.
World stack_layers(const World& layer, int layers, double layer_height);

/// Runs the stages:
///  1. calibration: the particles of one layer at spec.porosity_guess, placed loose and
///     overlap-free in a tall cylinder (rocks first, then soil in the pores), deposited under
///     gravity at each calibration friction (quasi-vibration compaction, Huang et al. 2015; runs
///     in parallel), porosity measured in the central region → n(μ), n_max, n_min, μ*;
///  2. layer: particles whose solid volume fills one layer (height/layers) at the target
///     porosity (Jin et al. 2017 §4.2), placed and compacted at μ*, then μ restored to the material
///     friction (shear history rescaled);
///  3. specimen: the layer copied `layers` times, each shifted up by the layer's top height
///     (clumps whole, new ids), and settled to equilibrium at the material friction
///     (Jin et al. 2017 §4.2 steps 1–3: "cycle to equilibrium");
///     stages 2–3 are repeated (correction_rounds) while the relative density misses;
///  4. measurement: porosity of the central region (exact sphere–region volumes), Dr, height,
///     per-layer and per-band porosity, coordination number.
/// Random streams derive from spec.seed only, and the DEM is deterministic, so the result is
/// bit-identical for any thread count and after a resume from the store. Throws InvalidInput for
/// a bad spec; the store's open() throws for stored stages of another spec. The interrupter is
/// told "calibration", "layer compaction", "layered specimen", "measurement" or "done" and the
/// fraction of the whole build; when it asks to stop, the running stages save a checkpoint and
/// Interrupted is thrown.
SpecimenResult build_specimen(const SpecimenSpec& spec, const StageControl& control = {});

}  // namespace clumpkit::dem
