// The table of a clump library (library.csv): written from the particle records, read back as
// rock templates with their exact mass properties, or as any one numeric column.
#pragma once

#include "dem/specimen/specimen_particles.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

/// The fidelity columns of library.csv, in order (the keys of each record's "fidelity").
const std::vector<std::string>& library_fidelity_columns();

/// library.csv from the particle records of `clumpkit library` (id order): id, fraction, method,
/// mesh and clump paths, attempts, the parameters (p_NAME, union over the particles in order of
/// first appearance), the descriptors, the fidelity, then the template (density_factor, I1..I3,
/// the pose qw..qz and cx..cz); each numeric column's header cell with its SI unit ("W[m]").
void write_library_table(const std::string& path,
                         const std::vector<nlohmann::ordered_json>& records);

/// Rock templates of a `clumpkit library` directory: each particle's template spheres
/// (particles/NNNNN.template.csv, principal frame), its measured sieve size W, exact clump
/// volume and unit-density principal moments I1, I2, I3 (library.csv), so bodies take their
/// mass properties from the library instead of recomputing them. Throws IoError/InvalidInput naming
/// the file for a missing or bad file.
std::vector<dem::RockTemplate> read_rock_templates(const std::string& library_dir);

/// One numeric column of a library's library.csv (e.g. "density_factor", V_mesh/V_clump; header
/// cells compared without their units, so tables written before units were read too), in row order,
/// as read_rock_templates orders the templates. Throws InvalidInput naming the file, line and value
/// for a missing column or a number that is not finite and positive.
std::vector<double> read_library_column(const std::string& library_dir, const std::string& name);

}  // namespace clumpkit
