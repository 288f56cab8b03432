// Refinement after the greedy fill: each sphere in turn moved to where it covers the most of the
// shape that no other sphere covers, its radius the largest the overshoot contract allows there.
#pragma once

#include "geom/fill/contract.h"
#include "geom/fill/coverage_grid.h"
#include "geom/progress.h"
#include "geom/sphere.h"

#include <cstdint>
#include <vector>

namespace clumpkit {

/// What a refinement did.
struct RefineStats {
  int sweeps = 0;  ///< sweeps over the spheres made
  int moves = 0;   ///< spheres moved (a sphere moved in two sweeps counts twice)
};

/// Coordinate ascent on the covered volume, after the variational sphere sets of Wang et al.
/// (2006) but under the fill's contract: sphere by sphere in index order, the sphere is taken
/// out of `grid` (and off the ledger), a pattern search over its centre (26 directions; steps 2,
/// 1, ½ and ¼ voxel) finds the centre whose ball, of the largest radius the contract allows there
/// (contract.radius_at of the feature distance, kept only while the ledger holds it), covers the
/// most voxels no other sphere covers, and the sphere placed there by the contract (exact distance)
/// replaces the old one only if it covers strictly more; else the old one goes back. Coverage
/// therefore never falls, the ledger stays within its budget, and every sphere keeps the radius the
/// contract gives its centre. A sweep searches only the spheres that moved or lie near one that
/// moved since their last search (the rest would find the same). Stops after `sweeps` sweeps, or
/// after a sweep that gained less than `min_gain` of the interior, or once the searches have read
/// `max_work` more row spans of the grid (CoverageGrid::work; ≤ 0: no limit) — a time budget that
/// is the same on every machine. `recorded[i]` says whether sphere i is on the contract's ledger;
/// both it and `spheres` are updated. Serial, so the same bytes for any thread count. The
/// interrupter is polled ("fill", 1.0) before each sphere; asked to stop, throws Interrupted.
RefineStats refine_spheres(std::vector<Sphere>& spheres, std::vector<char>& recorded,
                           CoverageGrid& grid, FillContract& contract, double min_radius,
                           int sweeps, double min_gain, std::int64_t max_work,
                           const Interrupter& interrupter = {});

}  // namespace clumpkit
