// The cone penetration test as a LAMMPS deck: the probe of `clumpkit test cpt` pushed into an
// exported chamber, tip and sleeve forces apart, on any number of MPI ranks.
#pragma once

#include "dem/lab/cpt.h"
#include "io/export/engine_settings.h"
#include "io/export/lammps_deck.h"
#include "io/export/lammps_stiffness.h"

#include <ostream>

namespace clumpkit {

/// What the CPT deck needs besides the specimen's files.
struct LammpsCpt {
  dem::ProbeSettings probe;  ///< friction resolved (≥ 0)
  double confining = 0;      ///< the lateral and top stress BC1 holds (Pa)
  int record_every = 200;    ///< steps between rows of cpt.csv (the test's record_every)
  /// Linear stiffness scaling (stiffness_classes): class k is soil atom type 2 + k, each pair
  /// of types and each wall its own law. Empty: one law, gran/hooke/history.
  std::vector<StiffnessClass> classes;
};

/// Throws InvalidInput (naming `where`) for a probe the deck cannot push: validate_probe's
/// cases, a friction outside dem::kFriction, a probe wider than half the container
/// (dem::check_probe_width).
void check_lammps_cpt(const LammpsCpt& cpt, const EngineSettings& settings,
                      const std::string& where);

/// Writes in.clumpkit of the CPT. LAMMPS (29 Sep 2021) cannot move a region made of two (`region
/// intersect` is static), and two separate wall regions for cone and shaft count the rim twice,
/// so the test runs in the probe's frame: the probe is one static region, the intersection of
/// the outside of a cone (apex_deg, apex at the specimen's top H0 — its highest sphere surface,
/// or the container's height when lower, as for a consolidated state whose top platen the
/// spheres press on — or `-var apex Z`) and the outside of the shaft above it; the lid (top platen)
/// starts at H0 too, as `clumpkit test cpt` starts the apex at its top platen; every body starts
/// moving up at the probe's speed (soil by `velocity`, rock bodies by the vz column of
/// bodies.infile, which write_lammps_export fills), and the floor and lid planes rise at it (the
/// lateral cylinder is frictionless, so its axial motion changes nothing); a segment's radial
/// planes stay, and its forces count for the whole chamber (× 2π / angle). A frame moving at
/// constant speed changes no force (contacts depend on relative positions and velocities, gravity
/// is the same), so this is the push in the laboratory's frame. A contact's point (column 7 of the
/// probe fix's per-atom contacts) below the shoulder is the tip's, else the sleeve's: each contact
/// on one part. Every `-var every N` steps (default the test's record_every) a row of cpt.csv:
/// step,depth[m],tip_force[N],sleeve_force[N],qc[Pa],fs[Pa] as `clumpkit test cpt`'s curve.csv
/// (forces on the probe, upwards positive; fs over the shaft below the lid); the push ends at the
/// recipe's depth; atoms.final.txt (id mol x y z radius fx fy fz) at the end. With stiffness
/// classes the pairs run pair_style granular (hooke, linear_history, mass_velocity damping: the
/// same law) and every wall is one fix per class, their forces summed.
void write_lammps_cpt_deck(std::ostream& o, const LammpsCpt& cpt, const EngineSettings& settings,
                           const LammpsContact& contact, bool rocks, bool soils);

}  // namespace clumpkit
