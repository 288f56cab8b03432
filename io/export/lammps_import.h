// The way back from LAMMPS: the exported deck's final atom dump read into specimen bodies, each
// clump's pose refitted to its atoms.
#pragma once

#include "io/formats/specimen_csv.h"

#include <string>
#include <vector>

namespace clumpkit {

/// One atom of a dump of the exported deck (columns id mol x y z radius).
struct LammpsAtom {
  long id = 0, mol = 0;
  Vec3 position = Vec3::Zero();
  double radius = 0;
};

/// The final atom dump of a run of the exported deck: atoms.final.txt when present (decks with
/// a test), otherwise atoms.N.txt with the largest N. Throws InvalidInput naming the directory
/// when there is none.
std::string final_lammps_dump(const std::string& run_dir);

/// The atoms of a dump (the last snapshot when it holds several). Throws IoError for a missing
/// file and InvalidInput naming the file and line for anything malformed.
std::vector<LammpsAtom> read_lammps_dump(const std::string& path);

/// The specimen's bodies where the dump has them. Atom k is the k-th sphere of specimen.csv (the
/// export's numbering); a soil body takes its atom's centre; a rock body's rotation and centroid
/// are the least-squares rigid fit (Eigen::umeyama, no scaling) of its body-frame spheres to its
/// atoms, and its spheres are then placed by that fit, so it stays rigid. Bodies with an atom
/// missing from the dump (lost by the engine) are left out and counted in `lost`; `residual` is
/// the largest distance between a fitted sphere and its atom (m). Throws InvalidInput naming
/// `path` when an atom's radius or molecule differs from the specimen's (a dump of another
/// specimen).
std::vector<SpecimenBody> bodies_from_lammps_atoms(const std::vector<SpecimenBody>& specimen,
                                                   const std::vector<LammpsAtom>& atoms,
                                                   const std::string& path, std::size_t& lost,
                                                   double& residual);

}  // namespace clumpkit
