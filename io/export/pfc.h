// PFC3D export of a specimen: one data file (clumpkit.p3dat) that defines every clump template
// with clumpkit's exact unit-density volume and inertia, replicates the bodies, creates the soil
// balls, the container and the contact law, and settles under gravity.
#pragma once

#include "io/export/engine_settings.h"

#include <string>
#include <vector>

namespace clumpkit {

/// PFC's orientation of a body: right-hand rotation by `degrees` about the unit `axis`.
struct AxisAngle {
  Vec3 axis = Vec3::UnitZ();
  double degrees = 0;
};

/// The rotation of a unit quaternion as axis and angle in degrees, angle in [0, 180] (the
/// quaternion's sign chosen so w ≥ 0); the identity gives axis z, angle 0.
AxisAngle axis_angle(const Eigen::Quaterniond& q);

/// Writes into `dir` (which must exist):
///  - clumpkit.p3dat: PFC 7 syntax (not run here: no licence; see its header). One
///    `clump template create` per distinct (template, scale) pair of the rock bodies, pebbles in
///    the template's principal frame, `volume` = the exact clump volume and `inertia` = the
///    exact unit-density tensor (PFC's templates are of unit density; order I11 I22 I33 I12 I13
///    I23, so diag(I1, I2, I3)/ρ); one `clump replicate id ID` per rock body with its centroid,
///    axis–angle and `density`; one `ball create id ID` per soil body; the linear contact model
///    with the recipe's kn, ks, friction, normal damping ratio and local damping; floor and
///    cylinder walls; gravity; a settle of `cycles` steps; a FISH function that prints every
///    clump's id, mass and principal moments.
///  - bodies_map.csv: body id → PFC clump id or ball id (the same number).
/// Returns the paths written.
std::vector<std::string> write_pfc_export(const std::vector<SpecimenBody>& bodies,
                                          const EngineSettings& settings, const std::string& dir);

/// How to run it: PFC3D's console.
inline std::string pfc_run_command() {
  return "pfc3d: program call 'clumpkit.p3dat'";
}

}  // namespace clumpkit
