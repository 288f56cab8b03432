// The fill's options (stop rules, resolution, overshoot contract, refinement) and their checks.
#pragma once

#include "geom/fill/distance_field.h"
#include "geom/mesh/mesh.h"
#include "geom/range.h"

namespace clumpkit {

/// A sphere budget, when there is one (FillOptions::spheres; 0 there is none).
inline constexpr Range kSphereBudget = integers_from(1);

/// The fraction of the interior volume whose covering stops a fill (FillOptions::coverage; 0
/// there is none).
inline constexpr Range kCoverage = closed(0, 1);
/// R_lim of Jin et al. 2017 (FillOptions::min_radius; finite, 0 for none), in the mesh's units.
inline constexpr Range kMinRadius = at_least(0);
/// The clump's volume outside the mesh over the mesh's volume (FillOptions::max_overshoot).
inline constexpr Range kMaxOvershoot = closed_open(0, 1);
/// Sweeps of the refinement after the greedy pass (FillOptions::refine_iterations; 0: none).
inline constexpr Range kRefineIterations = integers(0, 1000);

/// Stop rules and resolution. The fill stops at the first rule met; with neither `spheres` nor
/// `coverage` given it stops at 50 spheres.
struct FillOptions {
  int spheres = 0;        ///< sphere budget, in kSphereBudget (0 = none)
  double coverage = 0.0;  ///< stop when this fraction of the interior volume is covered (0 = none)
  double min_radius = 0.0;  ///< R_lim of Jin et al. 2017: smaller spheres are never placed
  FieldOptions field;       ///< resolution of the distance field and coverage grid
  double ridge = 0.8;       ///< medial-candidate slope threshold (see medial_candidates)
  /// The contract: the clump's volume outside the mesh stays at most this fraction of the
  /// mesh's volume (fill --max-overshoot; 0 keeps every sphere inside). A sphere is grown past
  /// the surface (below) only while an overshoot ledger on rows a third of a voxel apart stays
  /// within 0.9 of it, so the midpoint-rule error of the ledger has room.
  double max_overshoot = 0.01;
  /// Internal detail of the contract: how far a sphere may reach past the surface. A sphere
  /// whose centre lies d inside gets radius d·(1 + tolerance_relative) + tolerance (units of
  /// the mesh; negative: tolerance_voxels voxels). A small relative tolerance fills edges and
  /// corners much better for a small overshoot, because a cap of height ε·r holds ∝ ε²r³
  /// outside but the shell adds ∝ ε·r³ inside; it scales with each sphere, so small corner
  /// spheres poke out proportionally little.
  double tolerance = -1.0;
  double tolerance_voxels = 0.0;
  double tolerance_relative = 0.03;
  /// Local refinement of each chosen sphere: a pattern search over its centre (steps h/2, h/4,
  /// h/8; radius = exact distance + tolerance) keeps the move that covers the most still-uncovered
  /// voxels. Off-lattice centres cover more per sphere.
  bool refine = true;
  /// Sweeps of the refinement after the greedy pass (geom/fill/fill_refine.h: every sphere moved
  /// to cover more of what the others leave, within the contract); 0: none. Sweeps stop early
  /// once one gains less than refine_min_gain of the volume, so the default rarely runs them all.
  /// The budget is in sweeps, not seconds, so the clump does not depend on the machine. In
  /// kRefineIterations.
  int refine_iterations = 8;
  double refine_min_gain = 2e-4;
  /// The refinement's time budget, as a multiple of the greedy pass's coverage counts
  /// (CoverageGrid::work): it stops when its searches have read this many times the row spans
  /// the greedy pass read (≤ 0: no limit).
  double refine_work = 1.0;
  /// After the refinement, spend what is left of the overshoot budget by growing spheres past
  /// the surface where that covers most per volume outside (geom/fill/fill_grow.h), so a larger
  /// --max-overshoot never gives less coverage.
  bool spend_budget = true;
  /// Resolution from the count: with a sphere budget, the voxel is made fine enough that the
  /// smallest sphere the budget is expected to need spans kVoxelsPerSmallestRadius voxels
  /// (fill_field_options), within the voxel budget and at most kCountVoxelGrowth times the
  /// voxels of the resolution asked. Off where the user gave the resolution.
  bool voxels_from_count = true;
  /// Coverage: the greedy above (default). Largest: the classic biggest-sphere-first rule (next
  /// sphere = largest candidate whose centre no placed sphere covers), kept as a baseline.
  enum class Strategy { Coverage, Largest };
  Strategy strategy = Strategy::Coverage;
};

/// The smallest sphere radius a fill of N spheres is expected to need, over (V/N)^(1/3) for a
/// mesh of volume V: the greedy fills of a unit cube (the shape that needs the smallest spheres
/// of the bench's, for its corners) gave 0.40–0.57 from 5 to 100 spheres, 0.33 at 200.
inline constexpr double kSmallestSphereOverSpacing = 0.45;
/// Voxels across that radius: a ball of 5.5 voxels' radius is counted on the coverage grid to
/// about 1 %, and the cube's coverage at 100 spheres stops changing there (0.948 at 50 voxels
/// across, 0.950 at 60).
inline constexpr double kVoxelsPerSmallestRadius = 5.5;

/// options.field with FieldOptions::count_voxel set from the sphere budget and the mesh volume
/// when options.voxels_from_count holds (else unchanged).
FieldOptions fill_field_options(const Mesh& mesh, const FillOptions& options);

/// Throws InvalidInput for a sphere budget outside kSphereBudget (0: none), field.voxels outside
/// kFieldVoxels where no voxel_size is given, coverage outside kCoverage, min_radius outside
/// kMinRadius, max_overshoot outside kMaxOvershoot, refine_iterations outside kRefineIterations,
/// or a mesh without interior voxels at this resolution.
void validate(const FillOptions& options);

}  // namespace clumpkit
