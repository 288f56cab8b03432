// LAMMPS export of a specimen: data file, exact rigid-body table (fix rigid/small infile) and a
// runnable deck (settle under gravity in the recipe's container; any number of MPI ranks).
#pragma once

#include "io/export/engine_settings.h"
#include "io/export/lammps_cpt.h"
#include "io/export/lammps_deck.h"
#include "io/formats/specimen_csv.h"

#include <optional>
#include <string>
#include <vector>

namespace clumpkit {

/// What the deck adds to the settle: an element test, or tiling for scale-out runs.
struct LammpsDeck {
  bool oedometer = false;    ///< a top platen moving down at a constant strain rate
  double max_strain = 0.05;  ///< strain of H0 it stops at (seating on the rough top included)
  double strain_rate = 1.0;  ///< 1/s
  /// Copies of the specimen side by side (tile_bodies); more than one replaces the cylinder
  /// wall by the side planes of the box around all copies.
  int tiles_x = 1, tiles_y = 1;
  /// A cone penetration test instead of the settle (write_lammps_cpt_deck).
  std::optional<LammpsCpt> cpt;
};

/// Writes into `dir` (which must exist):
///  - data.specimen: atom_style hybrid sphere molecular, one atom per sphere (id = the sphere id
///    of specimen.csv), type 1 rock / 2 soil, mol = the body id for rock spheres and 0 for soil;
///    a rock sphere's density is M/Σ(4/3·π·r³) of its body, so Σ m_i = M (only for per-atom
///    quantities; the rigid fix takes M from bodies.infile);
///  - bodies.infile: per rock body (id = body id) M, centroid and the inertia tensor in the box
///    frame, R·diag(I1, I2, I3)·Rᵀ with R from the body's quaternion (LAMMPS's infile frame);
///  - bodies_map.csv: body id → LAMMPS id (molecule id for rock, atom id for soil);
///  - in.clumpkit: the deck. Rock bodies integrate by fix rigid/small with the infile (and
///    gravity through it, M·g at the centroid), soil by nve/sphere, Hookean contacts with
///    history (gran/hooke/history), floor and cylinder walls (wall/gran). `-var nsteps N`
///    (default 1000) and `-var exact 0` (LAMMPS's own mass properties, to compare) change it. It
///    dumps every body's mass and principal moments as LAMMPS sees them (bodies.0.txt,
///    bodies.N.txt: id mol mass x y z inertiax inertiay inertiaz) and every atom (atoms.0.txt,
///    atoms.N.txt: id mol x y z radius), sorted by id.
///    With `deck.oedometer`, after the settle a plane platen (fix wall/gran/region, the same
///    contact law) starts at the specimen's top H0 (highest sphere surface) and moves down at
///    strain_rate·H0 until max_strain; every 100 steps the deck appends strain and vertical
///    stress (the platen's force over the container's area, compression positive) to
///    oedometer.csv, and it dumps atoms.final.txt at the end.
/// Returns the paths written.
std::vector<std::string> write_lammps_export(const std::vector<SpecimenBody>& bodies,
                                             const EngineSettings& settings, const std::string& dir,
                                             const LammpsDeck& deck = {});

}  // namespace clumpkit
