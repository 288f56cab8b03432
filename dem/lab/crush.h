// Single-particle crushing between two rigid platens (Hu et al. 2023 §3.2): constant strain
// rate, the force–travel curve, the crushing peak and the fragments.
#pragma once

#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "dem/lab/crush_peak.h"
#include "geom/progress.h"
#include "geom/range.h"

#include <vector>

namespace clumpkit::dem {

/// The rig's settings (SI). The defaults are the paper's rig (platen friction 0.3, 0.4 /s) and
/// this engine's numerical choices, each checked by halving or doubling it.
struct CrushOptions {
  int axis = 2;              ///< loading axis of the particle's frame (0 x, 1 y, 2 z)
  double strain_rate = 0.4;  ///< closing speed over the initial gap (1/s)
  double platen_friction = 0.3;
  /// Normal and shear stiffness of a corner on a platen (N/m); WorldOptions::vertex_stiffness.
  double platen_stiffness = 1e7;
  /// PFC local damping α of every cell (quasi-static loading of an explicit model), in
  /// kLocalDamping.
  double local_damping = 0.35;
  /// dt = safety × critical_timestep(world), in kTimestepSafety.
  double timestep_safety = 0.2;
  /// Mass scaling λ, in kDensityScaling: every cell's mass and moments × λ (dt × √λ).
  /// Quasi-static while the platen speed stays far below the particle's wave speed; reported
  /// with the results.
  double density_scaling = 1.0;
  double max_strain = 0.3;      ///< travel at which the test stops without a failure (× gap)
  double sample_strain = 2e-4;  ///< travel between samples (× gap)
  /// The particle counts as split once no fragment (cells joined by intact bonds) holds this
  /// fraction of its mass (Huillca et al. 2021's rule: no component of ≥ 90 % of the volume).
  double intact_fraction = 0.9;
  /// The seat: cells with a corner within bed_depth × gap of the lower platen are bedded, their
  /// rotation locked (Body::rotation_locked), as a particle's end set in a plaster or putty bed
  /// is held square to the platen. An elongated or platy particle stood on its end then cannot
  /// tip over between the platens (it must break first), while every bond, the bed's included,
  /// can still fail. 0: no seat (the particle rests on the platen, Hu et al. 2023's rig as
  /// drawn).
  double bed_depth = 0.0;
  PeakRule rule;
};

/// The rig's closing strain rate (1/s) and platen stiffness (N/m) a test takes.
inline constexpr Range kCrushStrainRate = above(0);
inline constexpr Range kPlatenStiffness = above(0);
/// Platen travel over the gap at which a test stops without a failure.
inline constexpr Range kCrushMaxStrain = open(0, 1);
/// The mass fraction a fragment must hold for the particle to count as intact: above one half,
/// so that at most one fragment can hold it.
inline constexpr Range kIntactFraction = open(0.5, 1);
/// The seat's depth over the gap: below one half, so that the bed holds the lower end only.
inline constexpr Range kBedDepth = closed_open(0, 0.5);

/// Throws InvalidInput naming the field for a value outside its range.
void validate(const CrushOptions& options);

/// The outcome of one test.
struct CrushResult {
  std::vector<CrushSample> samples;  ///< travel (m) and mean platen force (N) along the axis
  CrushPeak peak;
  double gap = 0.0;       ///< initial platen gap: the particle's extent along the axis (m)
  double timestep = 0.0;  ///< s
  std::int64_t steps = 0;
  int bedded = 0;                 ///< cells held by the seat (bed_depth)
  int fragments = 0;              ///< fragments at the end (connected by intact bonds)
  double largest_fragment = 0.0;  ///< its mass fraction
  /// Mean difference of the two platens' forces over the samples up to the peak, over the peak
  /// force: how far from quasi-static the loading was (0 in equilibrium; the brief waves of a
  /// cell breaking off count, averaged).
  double imbalance = 0.0;
};

/// Crushes the particle held by `world` (its cells' bodies and bonds, e.g. crushable_particle):
/// gravity off, two plane walls touching its extreme corners along `axis`, closing at
/// strain_rate × gap, each moving half of it, the lowest cells bedded (bed_depth), until the peak
/// rule is met (crushing_peak with `diameter`, the volume-equivalent diameter) or max_strain. The
/// world's walls, contact friction (the platens', also between fragments' spheres), corner
/// stiffness, damping, masses and time step are set here. The interrupter hears stage "crush" with
/// travel/max travel and may stop the test (Interrupted). Throws InvalidInput for bad options, a
/// world without corners or with walls.
CrushResult crush_particle(World& world, double diameter, const CrushOptions& options,
                           const Interrupter& interrupter = {});

}  // namespace clumpkit::dem
