// Greedy maximal-inscribed-sphere fill (Zhang & Zhou 2015 §2.3, ODEC): a mesh becomes a clump of
// overlapping spheres chosen by how much uncovered volume each one adds.
#pragma once

#include "geom/fill/distance_field.h"
#include "geom/fill/fill_options.h"
#include "geom/progress.h"
#include "geom/sphere.h"

#include <vector>

namespace clumpkit {

struct FillResult {
  Clump clump;
  double voxel = 0.0;  ///< the coverage lattice's (finer than the field's where the budget asks)
  int candidates = 0;  ///< medial candidates considered (a looser ridge adds some late)
  /// Covered fraction of the interior voxels after each sphere of the greedy pass (same length
  /// as the clump); the refined clump's coverage is the fidelity report's.
  std::vector<double> coverage_curve;
  /// The ledger's outside volume over the mesh's volume (≤ 0.9 max_overshoot).
  double overshoot = 0.0;
  /// The greedy pass's clump, before the refinement (the result's when no refinement ran), and
  /// what the refinement did.
  Clump greedy;
  int refine_sweeps = 0, refine_moves = 0;
  /// Radius steps of the pass that spent the rest of the overshoot budget (fill_grow.h).
  int grow_steps = 0;
  /// "spheres" (the budget), "coverage" (the target), "min-radius" (the candidates left are
  /// smaller) or "candidates" (no medial candidate left adds coverage).
  std::string stopped_by;
};

/// Fill on a precomputed field of the index's mesh. Candidate centres come from the field's
/// ridges; each candidate's radius is the exact distance from its centre to the mesh (the
/// index's nearest-triangle query), since the swept interior of the field runs high by up to
/// about a voxel.
/// Greedy: the largest inscribed sphere first, then repeatedly the
/// medial candidate whose ball covers the most still-uncovered interior voxels. Coverage gains
/// only decrease as spheres are added, so a lazy priority queue (re-evaluate the top, accept if
/// still the best) picks exactly the greedy choice. Ties go to the lower candidate index.
/// Coarse to fine: where the sphere budget asks for a finer voxel than the field's
/// (fill_field_options, field_voxel_size), the candidates come from a lattice of that voxel whose
/// distances are the field's features (make_finer_field), the greedy pass ranks them by what they
/// cover on the field's own voxels, and the chosen spheres' search, the refinement and the growth
/// pass count coverage on the finer lattice, whose voxel the result reports.
/// The interrupter is told ("fill", the fraction of the budget or coverage target reached) before
/// each sphere; asked to stop, the fill throws Interrupted.
FillResult fill(const MeshIndex& index, const DistanceField& field, const FillOptions& options,
                const Interrupter& interrupter = {});

/// Index + field + fill.
FillResult fill(const Mesh& mesh, const FillOptions& options, const Interrupter& interrupter = {});

}  // namespace clumpkit
