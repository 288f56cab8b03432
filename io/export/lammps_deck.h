// What every LAMMPS deck shares: the contact law's arguments, time step and ghost cutoff, the
// opening lines, the atoms' density of a clump, and the command that runs a deck.
#pragma once

#include "io/export/engine_settings.h"
#include "io/export/lammps_stiffness.h"
#include "io/formats/specimen_csv.h"

#include <string>

namespace clumpkit {

/// What every LAMMPS deck of these bodies shares: the pair and wall arguments of the contact law
/// ("kn kt gamma_n gamma_t mu 1" of gran/hooke/history), the time step, the neighbour skin and
/// the ghost cutoff of fix rigid/small (the largest body must fit).
struct LammpsContact {
  double kn = 0, kt = 0;  ///< N/m
  double gamma_n = 0;     ///< pairs' normal dashpot (1/s; γt = 0)
  double friction = 0;    ///< the specimen's μ
  /// γn of a wall contact: a wall's m_eff is the body's mass m, so the dashpot 2β·sqrt(m·kn)
  /// is γn·m with γn = 2β·sqrt(kn/m) at the median body's m (twice the pairs' m_eff).
  double wall_gamma_n = 0;
  double dt = 0, skin = 0, cutoff = 0;
};
LammpsContact lammps_contact(const SpecimenExtents& extents, const EngineSettings& settings);

/// The pairs' contact law with friction μ: "kn kt γn 0 μ 1" (lammps_hooke_args); μ = 0 for the
/// walls of an element test.
std::string lammps_contact_args(const LammpsContact& contact, double mu);
/// The same with the specimen's μ.
std::string lammps_contact_args(const LammpsContact& contact);

/// The atom density of a body's spheres that makes their masses sum to the body's mass M:
/// M / Σ(4/3·π·r³) (the spheres overlap, so it is not the material density).
double lammps_atom_density(const SpecimenBody& body);

/// The deck lines both LAMMPS decks open with: SI units, spheres with molecule ids, fixed
/// boundaries, newton off, ghost velocities and fix rigid/small's ghost cutoff.
std::string lammps_preamble(const LammpsContact& contact);

/// The command line that runs the deck in `dir` on `ranks` MPI ranks (1: plain lmp).
std::string lammps_run_command(int ranks);

}  // namespace clumpkit
