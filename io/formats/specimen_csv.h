// specimen.csv, the bodies and spheres of a built specimen: written, read back, and turned into
// DEM bodies and back.
#pragma once

#include "dem/core/world.h"
#include "dem/specimen/specimen.h"
#include "geom/sphere.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Format version of specimen.csv, in its first line ("# clumpkit specimen format N"). 2: the
/// body rows gained scale, I1, I2, I3. 3: bodies and spheres are numbered from 1 (0 means "no
/// molecule" in LAMMPS and is no PFC id), so engine exports keep the ids. 4: the body rows end
/// with zone (the region of a zoned specimen, 0 without zones); format 3 is still read (zone 0).
inline constexpr int kSpecimenCsvFormat = 4;

/// One body of a specimen.csv, as read back: its row and its spheres (world frame).
struct SpecimenBody {
  long id = 0;  ///< from 1
  dem::BodyKind kind = dem::BodyKind::soil;
  int template_id = -1;
  Vec3 position = Vec3::Zero();                                     ///< centroid (m)
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body → world
  double mass = 0, volume = 0, scale = 1;
  int zone = 0;                 ///< region of a zoned specimen, 0 without zones
  Vec3 moments = Vec3::Zero();  ///< principal moments about the body axes (kg m²)
  std::vector<Sphere> spheres;  ///< world frame (m)
};

/// The bodies of a built specimen as specimen.csv holds them (ids from 1, spheres in the world
/// frame).
std::vector<SpecimenBody> specimen_bodies(const dem::World& world);
inline std::vector<SpecimenBody> specimen_bodies(const dem::SpecimenResult& result) {
  return specimen_bodies(result.world);
}

/// A body's spheres in its own (principal) frame: q⁻¹(c − x).
std::vector<Sphere> body_frame_spheres(const SpecimenBody& body);

/// The DEM body of a specimen row (the inverse of specimen_bodies for one body), at rest.
dem::Body dem_body(const SpecimenBody& body);

/// specimen.csv: "# bodies" section (body, kind, template, x, y, z, qw, qx, qy, qz, mass,
/// volume, scale, I1, I2, I3: principal moments in kg m² about the body axes, the template's
/// principal frame, which the quaternion rotates into the world; zone) then "# spheres" section
/// (sphere, body, x, y, z, r), world frame, SI, round-trip precision. Bodies and spheres are
/// numbered from 1 in file order; template is the library particle id (-1 for soil).
void write_specimen_csv(const std::string& path, const std::vector<SpecimenBody>& bodies);

/// Reads a specimen.csv of format 4 (or 3, without the zone column). Throws IoError for a missing
/// file and InvalidInput naming the file, line and field for anything malformed (wrong format line,
/// bad or non-finite number, non-positive mass, volume or radius, a sphere of an unknown body, a
/// body without spheres).
std::vector<SpecimenBody> read_specimen_csv(const std::string& path);

}  // namespace clumpkit
