// LAMMPS molecule templates of clump templates (for fix deposit/pour ... mol) and a deck that
// deposits them into a container with clumpkit's exact mass properties.
#pragma once

#include "io/export/engine_settings.h"
#include "io/formats/specimen_csv.h"

#include <string>
#include <vector>

namespace clumpkit {

/// The molecule file name of a template: clump_NNNNN.mol (NNNNN its template id).
std::string lammps_molecule_name(int template_id);

/// Writes into `dir` (which must exist), for bodies that are one per template (an export of a
/// library or clump CSV, export_source.h):
///  - clump_NNNNN.mol per body: the molecule template in the body's principal frame, with the
///    header lines "M mass", "0 0 0 com" and "I1 I2 I3 0 0 0 inertia" (clumpkit's exact values:
///    LAMMPS uses them for every body fix deposit or pour creates), then Coords, Types (all
///    atoms of the k-th body have type k, so an atom's type names its template), Diameters and
///    Masses (each atom's density M/Σ(4/3·π·r³), so Σ m_i = M);
///  - molecules.csv: type, template id, molecule file, mass, I1, I2, I3, spheres;
///  - in.deposit: the deck. One fix rigid/small on the molecule set (gravity through it), one
///    fix deposit per template (`-var count N` bodies of each, default 1, one every
///    `-var every S` steps, default 100; random orientation; `near` keeps new spheres clear of
///    the others), the container and contact law of in.clumpkit; after `-var nsteps N` (default
///    1000) steps it dumps deposit_bodies.N.txt (compute rigid/local: id mol mass x y z
///    inertiax inertiay inertiaz, as LAMMPS sees them) and deposit_atoms.N.txt (id mol type x y
///    z radius), also at step 0 (empty).
/// Returns the paths written.
std::vector<std::string> write_lammps_molecules(const std::vector<SpecimenBody>& bodies,
                                                const EngineSettings& settings,
                                                const std::string& dir);

}  // namespace clumpkit
