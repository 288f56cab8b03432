// The CPT curve file: curve.csv of `clumpkit test cpt` and cpt.csv of the LAMMPS CPT deck,
// step,depth,tip_force,sleeve_force,qc,fs (SI, units in the header cells: "depth[m]").
#pragma once

#include "dem/lab/cpt.h"

#include <string>
#include <vector>

namespace clumpkit {

/// The columns, without their units (cpt_curve_header() adds them).
inline constexpr const char* kCptCurveColumns = "step,depth,tip_force,sleeve_force,qc,fs";

/// The header line: "step[1],depth[m],tip_force[N],sleeve_force[N],qc[Pa],fs[Pa]".
std::string cpt_curve_header();

/// Writes the rows (each number the shortest decimal that reads back exactly), atomically.
void write_cpt_curve(const std::string& path, const std::vector<dem::CptRow>& rows);

/// Reads such a file, its header with units or without (step,depth_m,tip_force_n,... of files
/// written before units). Throws IoError for a missing file and InvalidInput naming the file and
/// line for another header, a row that is not six finite numbers, or no rows.
std::vector<dem::CptRow> read_cpt_curve(const std::string& path);

}  // namespace clumpkit
