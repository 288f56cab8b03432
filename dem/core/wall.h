// Rigid walls for DEM: planes (floor, moving platen) and the inside of a vertical cylinder.
#pragma once

#include "geom/mesh/mesh.h"

namespace clumpkit::dem {

/// A rigid wall. Plane: the half-space side of `normal` is the inside; it translates with
/// `velocity` (m/s). Cylinder: the inside of an infinite vertical (z) cylinder of `radius`
/// around the axis through `point` (its x, y); its radius grows at `radial_velocity` (m/s,
/// negative: it closes in), which a servo sets for a confining stress.
struct Wall {
  enum class Kind { plane, cylinder };
  Kind kind = Kind::plane;
  Vec3 point = Vec3::Zero();     ///< m
  Vec3 normal = Vec3::UnitZ();   ///< unit, into the domain (plane only)
  double radius = 0.0;           ///< m (cylinder only)
  Vec3 velocity = Vec3::Zero();  ///< m/s (plane only)
  double radial_velocity = 0.0;  ///< dR/dt, m/s (cylinder only)
  /// Coulomb coefficient of sphere–wall contacts; negative: the contact law's μ. Element-test
  /// cells use 0 (frictionless walls, so wall and Love–Weber stresses agree).
  double friction = -1.0;

  /// Throws InvalidInput for a zero or non-finite normal; the normal is normalised.
  static Wall plane(const Vec3& point, const Vec3& normal, const Vec3& velocity = Vec3::Zero());
  /// Throws InvalidInput for a non-positive radius.
  static Wall cylinder(double axis_x, double axis_y, double radius);
};

/// Contact geometry of a sphere with a wall.
struct WallHit {
  bool touching = false;
  double overlap = 0.0;         ///< m
  Vec3 normal = Vec3::UnitZ();  ///< unit, from the wall towards the sphere centre
  Vec3 point = Vec3::Zero();    ///< midpoint of the overlap along the normal
};

/// Plane: δ = r − (c − p)·n. Cylinder: δ = ρ + r − R with ρ the distance of the centre from the
/// axis, normal −e_ρ (none for a centre on the axis, where no sphere with r < R can touch).
WallHit wall_hit(const Wall& wall, const Vec3& center, double radius);

}  // namespace clumpkit::dem
