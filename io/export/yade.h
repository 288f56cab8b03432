// Yade export of a specimen: sphere files, clumpkit's exact per-body table and a script that
// builds the clumps, forces clumpkit's mass and principal moments on them and settles them.
#pragma once

#include "io/export/engine_settings.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Writes into `dir` (which must exist):
///  - clump_members.txt: `x y z r body` per rock sphere (ymport.textClumps' format, bodies in
///    contiguous runs), soil_spheres.txt: `x y z r body` per soil body;
///  - specimen_bodies.txt: `body mass x y z qw qx qy qz I1 I2 I3` per rock body (exact);
///  - run_clumpkit.py, for `yade -n -x run_clumpkit.py [nsteps] [exact]`: FrictMat materials and
///    Cundall–Strack contacts (E chosen so two spheres of the mean radius get the recipe's kn,
///    ks/kn as Poisson's ratio, tan φ = μ), NewtonIntegrator's local damping, a floor and a
///    faceted cylinder, gravity. Each clump is built by appendClumped (Yade's own centroid and
///    axes, from its member spheres), then its state.mass is set to ours and state.inertia to
///    our principal moments, each put on the Yade axis nearest our principal axis. The script
///    writes yade_residuals.txt (per body: Yade's centroid minus ours and the largest angle
///    between matched axes, the part Yade's clump frame keeps) and bodies.STEP.txt (body yade_id
///    mass I1 I2 I3 x y z, as Yade sees them) at step 0 and at the end;
///  - bodies_map.csv: body id → Yade body id (clump id for rock, sphere id for soil).
/// Returns the paths written.
std::vector<std::string> write_yade_export(const std::vector<SpecimenBody>& bodies,
                                           const EngineSettings& settings, const std::string& dir);

/// The command line that runs the script in the export directory.
inline std::string yade_run_command() {
  return "yade -n -x run_clumpkit.py";
}

}  // namespace clumpkit
