// The CPT curve file: curve.csv of `clumpkit test cpt` and cpt.csv of the LAMMPS CPT deck,
// step,depth_m,tip_force_n,sleeve_force_n,qc_pa,fs_pa.
#pragma once

#include "dem/lab/cpt.h"

#include <string>
#include <vector>

namespace clumpkit {

inline constexpr const char* kCptCurveHeader =
    "step,depth_m,tip_force_n,sleeve_force_n,qc_pa,fs_pa";

/// Writes the rows (each number the shortest decimal that reads back exactly), atomically.
void write_cpt_curve(const std::string& path, const std::vector<dem::CptRow>& rows);

/// Reads such a file. Throws IoError for a missing file and InvalidInput naming the file and
/// line for another header, a row that is not six finite numbers, or no rows.
std::vector<dem::CptRow> read_cpt_curve(const std::string& path);

}  // namespace clumpkit
