// Rigid walls for DEM: planes (floor, moving platen), the inside of a vertical cylinder and the
// outside of an axisymmetric probe (a cone penetrometer).
#pragma once

#include "geom/mesh/mesh.h"

#include <vector>

namespace clumpkit::dem {

/// A rigid wall. Plane: the half-space side of `normal` is the inside; it translates with
/// `velocity` (m/s). Cylinder: the inside of an infinite vertical (z) cylinder of `radius`
/// around the axis through `point` (its x, y); its radius grows at `radial_velocity` (m/s,
/// negative: it closes in), which a servo sets for a confining stress. Probe: the outside of a
/// solid of revolution about the vertical axis through `point` (its x, y), `point` its lowest
/// point (the cone's apex); its meridian `profile` lists (ρ, z above `point`) from the apex up,
/// z increasing, and the last radius continues upward for ever (the rod leaves the chamber); it
/// translates with `velocity`. The profile's segments from index `sleeve_from` up, the ray above
/// included, are the sleeve, the ones below the tip.
struct Wall {
  enum class Kind { plane, cylinder, probe };
  Kind kind = Kind::plane;
  Vec3 point = Vec3::Zero();     ///< m
  Vec3 normal = Vec3::UnitZ();   ///< unit, into the domain (plane only)
  double radius = 0.0;           ///< m (cylinder only)
  Vec3 velocity = Vec3::Zero();  ///< m/s (plane only)
  double radial_velocity = 0.0;  ///< dR/dt, m/s (cylinder only)
  /// Coulomb coefficient of sphere–wall contacts; negative: the contact law's μ. Element-test
  /// cells use 0 (frictionless walls, so wall and Love–Weber stresses agree).
  double friction = -1.0;
  std::vector<Eigen::Vector2d> profile;  ///< (ρ, z) in m (probe only)
  int sleeve_from = 0;                   ///< first profile point of the sleeve (probe only)

  /// Throws InvalidInput for a zero or non-finite normal; the normal is normalised.
  static Wall plane(const Vec3& point, const Vec3& normal, const Vec3& velocity = Vec3::Zero());
  /// Throws InvalidInput for a non-positive radius.
  static Wall cylinder(double axis_x, double axis_y, double radius);
  /// A cone penetrometer with its apex at `apex`: a cone of apex angle `apex_deg` (60 for the
  /// standard cone) up to the shaft of diameter `diameter`, whose cylinder is the sleeve. Throws
  /// InvalidInput for a non-positive diameter or an angle outside (0, 180).
  static Wall probe(const Vec3& apex, double diameter, double apex_deg,
                    const Vec3& velocity = Vec3::Zero());
};

/// Throws InvalidInput unless a probe's profile is usable: at least one point, every coordinate
/// finite, radii ≥ 0, heights non-decreasing, `sleeve_from` a point of the profile.
void validate_probe_profile(const Wall& wall);

/// Which part of a probe a contact touches (WallHit::part): the cone or the shaft.
enum class ProbePart { tip = 0, sleeve = 1 };

/// Contact geometry of a sphere with a wall.
struct WallHit {
  bool touching = false;
  double overlap = 0.0;             ///< m
  Vec3 normal = Vec3::UnitZ();      ///< unit, from the wall towards the sphere centre
  Vec3 point = Vec3::Zero();        ///< midpoint of the overlap along the normal
  ProbePart part = ProbePart::tip;  ///< probe: the part holding the closest profile point
};

/// Plane: δ = r − (c − p)·n. Cylinder: δ = ρ + r − R with ρ the distance of the centre from the
/// axis, normal −e_ρ (none for a centre on the axis, where no sphere with r < R can touch).
/// Probe: in the meridian half-plane of the centre, the one closest point q of the profile (the
/// lower segment where two tie, so a contact belongs to one part only); δ = r − |c − q| outside
/// the solid, r + |c − q| inside it, normal from q towards the centre (away from it inside). On
/// the axis the meridian is the x–z plane.
WallHit wall_hit(const Wall& wall, const Vec3& center, double radius);

}  // namespace clumpkit::dem
