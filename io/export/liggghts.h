// LIGGGHTS export of a specimen: multisphere templates carrying clumpkit's exact mass and inertia
// (use_density), one insertion per pre-placed body, soil atoms and a runnable deck.
#pragma once

#include "io/export/engine_settings.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Writes into `dir` (which must exist):
///  - templates.liggghts: per distinct (template, scale) pair of the rock bodies a
///    `particletemplate/multisphere` (spheres in the template's principal frame, centroid at
///    the origin, `mass M inertia_tensor I1 0 0 I2 0 I3 use_density`: LIGGGHTS then takes both
///    as given, no Monte Carlo) and its `particledistribution/discrete` (ids pt1, pdd1, ...);
///  - specimen_bodies.liggghts: per rock body a point region and a `fix insert/pack` that puts
///    one body of its template at its centroid with its quaternion (LIGGGHTS-PUBLIC cannot read
///    multisphere bodies at given poses otherwise);
///  - soil.liggghts: per soil body `create_atoms` and `set atom` (diameter, density);
///  - in.clumpkit: Hookean contacts (hooke/stiffness, tangential history), floor and cylinder
///    walls, gravity; fix multisphere for the clumps, nve/sphere for the soil. `-var nsteps N`
///    (default 1000). Dumps atoms.1.txt (after the insertion step) and atoms.END.txt (id type x y
///    z radius), thermo prints ke/multisphere and erotate/multisphere;
///  - bodies_map.csv: body id → LIGGGHTS ids (soil: atom id; rock: multisphere body id and first
///    atom id, as inserted in file order).
/// Random seeds are distinct primes above 10,000 (LIGGGHTS aborts silently otherwise).
/// Returns the paths written.
std::vector<std::string> write_liggghts_export(const std::vector<SpecimenBody>& bodies,
                                               const EngineSettings& settings,
                                               const std::string& dir);

/// The command line that runs the deck in the export directory.
inline std::string liggghts_run_command() {
  return "liggghts -in in.clumpkit";
}

}  // namespace clumpkit
