// Specimen input and output: recipe → build spec, rock templates from a clump library, and the
// files of `clumpkit specimen` (CSV, VTP, report, calibration plot, slice images).
#pragma once

#include "dem/compression.h"
#include "dem/specimen.h"
#include "io/specimen_recipe.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

/// Rock templates of a `clumpkit library` directory: each particle's template spheres
/// (particles/NNNNN.template.csv, principal frame), its measured sieve size W, exact clump
/// volume and unit-density principal moments I1, I2, I3 (library.csv), so bodies take their
/// mass properties from the library instead of recomputing them. Throws IoError/InvalidInput naming
/// the file for a missing or bad file.
std::vector<dem::RockTemplate> read_rock_templates(const std::string& library_dir);

/// One numeric column of a library's library.csv (e.g. "density_factor", V_mesh/V_clump), in
/// row order, as read_rock_templates orders the templates. Throws InvalidInput naming the file,
/// line and value for a missing column or a number that is not finite and positive.
std::vector<double> read_library_column(const std::string& library_dir, const std::string& name);

/// The build spec of a recipe: gradation classes with the fines (classes finer than fines_below)
/// moved, by mass, into the class [fines_min, fines_max] (Jin et al. 2017 §4.1); classes at or
/// above the soil/rock threshold are rock. Contact damping as in deposition_contact().
dem::SpecimenSpec specimen_spec(const SpecimenRecipe& recipe,
                                std::vector<dem::RockTemplate> templates);

/// Format version of specimen.csv, in its first line ("# clumpkit specimen format N"). 2: the
/// body rows gained scale, I1, I2, I3. 3: bodies and spheres are numbered from 1 (0 means "no
/// molecule" in LAMMPS and is no PFC id), so engine exports keep the ids.
inline constexpr int kSpecimenCsvFormat = 3;

/// One body of a specimen.csv, as read back: its row and its spheres (world frame).
struct SpecimenBody {
  long id = 0;  ///< from 1
  dem::BodyKind kind = dem::BodyKind::soil;
  int template_id = -1;
  Vec3 position = Vec3::Zero();                                     ///< centroid (m)
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body → world
  double mass = 0, volume = 0, scale = 1;
  Vec3 moments = Vec3::Zero();  ///< principal moments about the body axes (kg m²)
  std::vector<Sphere> spheres;  ///< world frame (m)
};

/// The bodies of a built specimen as specimen.csv holds them (ids from 1, spheres in the world
/// frame).
std::vector<SpecimenBody> specimen_bodies(const dem::World& world);
inline std::vector<SpecimenBody> specimen_bodies(const dem::SpecimenResult& result) {
  return specimen_bodies(result.world);
}

/// The spec of a recipe with preparation.method = "compression" (gravity-free cuboid or
/// cylinder at a target porosity), classes as specimen_spec makes them.
dem::CompressionSpec compression_spec(const SpecimenRecipe& recipe,
                                      std::vector<dem::RockTemplate> templates);

/// A body's spheres in its own (principal) frame: q⁻¹(c − x).
std::vector<Sphere> body_frame_spheres(const SpecimenBody& body);

/// The DEM body of a specimen row (the inverse of specimen_bodies for one body), at rest.
dem::Body dem_body(const SpecimenBody& body);

/// specimen.csv: "# bodies" section (body, kind, template, x, y, z, qw, qx, qy, qz, mass,
/// volume, scale, I1, I2, I3: principal moments in kg m² about the body axes, the template's
/// principal frame, which the quaternion rotates into the world) then "# spheres" section
/// (sphere, body, x, y, z, r), world frame, SI, round-trip precision. Bodies and spheres are
/// numbered from 1 in file order; template is the library particle id (-1 for soil).
void write_specimen_csv(const std::string& path, const std::vector<SpecimenBody>& bodies);

/// Reads a specimen.csv of format 3. Throws IoError for a missing file and InvalidInput naming
/// the file, line and field for anything malformed (wrong format line, bad or non-finite
/// number, non-positive mass, volume or radius, a sphere of an unknown body, a body without
/// spheres).
std::vector<SpecimenBody> read_specimen_csv(const std::string& path);

/// specimen.vtp: VTK XML PolyData, one point per sphere with point data radius, body (the id of
/// specimen.csv, from 1) and kind (0 soil, 1 rock); in ParaView use a Glyph filter (sphere, scale
/// by radius, factor 2).
void write_specimen_vtp(const std::string& path, const std::vector<SpecimenBody>& bodies);

/// calibration.csv: friction, porosity, void_ratio, relative_density, steps, stopped_by.
void write_calibration_csv(const std::string& path, const dem::SpecimenResult& result);

/// calibration.png: porosity against friction with the target porosity and μ* marked.
void write_calibration_plot(const std::string& path, const dem::SpecimenResult& result,
                            double target_relative_density);

/// Horizontal slice images at the given heights: rock red, soil blue (Jin et al. 2017 Fig. 10), the
/// container grey; `pixels` across the container diameter. Returns the file names written.
std::vector<std::string> write_slices(const std::string& dir, const dem::SpecimenResult& result,
                                      double radius, const std::vector<double>& heights,
                                      int pixels = 600);

/// report.json content (see `clumpkit specimen --help`), with the container, densities and
/// contact law the exports put into the engines' decks.
nlohmann::ordered_json specimen_report(const SpecimenRecipe& recipe,
                                       const dem::SpecimenResult& result);

/// report.json of a compression specimen: method, container (shape; cuboid: size, lo, hi;
/// cylinder: diameter, height), porosity, coordination number, mean stress, the contact law
/// (with stiffness_scaling and d_ref), densities, counts, steps and time step.
nlohmann::ordered_json compression_report(const SpecimenRecipe& recipe,
                                          const dem::CompressionResult& result);

}  // namespace clumpkit
