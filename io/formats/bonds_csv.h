// bonds.csv, the bonds between the cells of a crushable specimen: the cohesive law, each bond
// with its bodies and normal, each integration point with its damage; written and read back.
#pragma once

#include "dem/core/bond.h"
#include "dem/core/cohesive_law.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Format version of bonds.csv, in its first line ("# clumpkit bonds format N").
inline constexpr int kBondsCsvFormat = 2;

/// The bonds of a specimen and the law they follow.
struct SpecimenBonds {
  dem::CohesiveParams law;
  std::vector<dem::Bond> bonds;
};

/// bonds.csv: a "# law" row (kn, kt, sigma_n, sigma_t, g_n, g_t, friction: the law as used,
/// strengths and energies with the recipe's scale applied), "# bonds" (bond, a, b: body ids of
/// specimen.csv, from 1; nx, ny, nz: the face normal in a's body frame; factor), "# points"
/// (bond, the point in a's and in b's body frame, area, damage, slip x, y, z). SI, round-trip
/// precision: a specimen read back holds the same bonds to the bit.
void write_bonds_csv(const std::string& path, const SpecimenBonds& bonds);

/// Reads bonds.csv for a specimen of `bodies` bodies. Throws IoError for a missing file and
/// InvalidInput naming the file, line and field for anything malformed (another format, a bad or
/// non-finite number, a body outside 1..bodies or a bond joining a body to itself, a point of an
/// unknown bond, a bond without points, damage outside [0, 1], a law dem::validate_values
/// refuses).
SpecimenBonds read_bonds_csv(const std::string& path, std::size_t bodies);

}  // namespace clumpkit
