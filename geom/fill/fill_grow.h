// The overshoot budget spent after the refinement: spheres grown past the surface a step at a
// time, the step that covers the most per volume it puts outside first, until the budget is used.
#pragma once

#include "geom/fill/contract.h"
#include "geom/fill/coverage_grid.h"
#include "geom/progress.h"
#include "geom/sphere.h"

#include <vector>

namespace clumpkit {

/// What a growth pass did.
struct GrowStats {
  int steps = 0;  ///< radius steps taken (a sphere grown twice counts twice)
};

/// Spends what the greedy pass and the refinement left of the contract's budget. Every sphere
/// has one candidate step: its radius grown by a quarter voxel about the same centre, whose gain
/// is the uncovered voxels the larger ball adds (exact: the old ball lies inside the new one) and
/// whose cost the outside volume it adds to the ledger. The step of the highest gain per cost is
/// taken (ties: lower index) while the ledger holds it; the pass stops at the first best step the
/// budget cannot hold, or when no step gains. A cap of height ε on a sphere of radius r holds
/// ≈ π r ε² outside against ≈ 2π r² ε of shell inside, so the first steps are cheap wherever a
/// sphere touches the surface at points (corners, edges), and dear where it hugs the surface (an
/// ellipsoid's waist): the budget goes where it buys most. Since the steps are chosen without
/// regard to the budget's size and the pass stops at the first that does not fit, a larger budget
/// takes the same steps and then more: coverage never falls as the budget grows. Serial, so the
/// same bytes for any thread count; the interrupter is polled ("fill", 1.0) before each step.
GrowStats grow_spheres(std::vector<Sphere>& spheres, std::vector<char>& recorded,
                       CoverageGrid& grid, FillContract& contract,
                       const Interrupter& interrupter = {});

}  // namespace clumpkit
