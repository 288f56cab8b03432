// Rigid DEM bodies (a plain sphere or a clump of spheres in its principal frame) and their state.
#pragma once

#include "geom/range.h"
#include "geom/sphere.h"
#include "geom/template/clump_template.h"

#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit::dem {

/// What a body is made of; explicit, never inferred from its sphere count (a one-sphere
/// template is still a rock).
enum class BodyKind : std::uint8_t { soil, rock };

/// "soil" or "rock", as written in specimen files.
std::string kind_name(BodyKind kind);

/// The density of a body's material (kg/m³; finite) that make_sphere_body, make_clump_body and
/// cell_body take.
inline constexpr Range kDensity = above(0);
/// Mass scaling λ of a run: its bodies' masses and moments × λ, so the time step grows by √λ
/// (finite; 1 is none, below 1 would shrink the step).
inline constexpr Range kDensityScaling = at_least(1);

/// A rigid body: spheres fixed in the body frame (the principal frame: centroid at the origin,
/// inertia axes along x, y, z), its mass and principal moments, and its state in the world.
/// Units SI. Orientation is a Hamilton unit quaternion rotating the body frame into the world
/// frame: x_world = orientation · x_body + position.
/// A rock carries the identity of its library template: `template_id` and the `scale` s by which
/// the template's spheres were multiplied, so its volume is V_t·s³ and its moments ρ·I_t·s⁵,
/// taken from the template once instead of recomputed per body.
struct Body {
  std::vector<Sphere> spheres;  ///< body frame (m); a plain sphere is one sphere at the origin
  double mass = 0.0;            ///< kg
  Vec3 moments = Vec3::Zero();  ///< principal moments of inertia (kg·m²) about body x, y, z
  double volume = 0.0;          ///< exact solid volume of the union of the spheres (m³)
  BodyKind kind = BodyKind::soil;
  // (The small members sit together: a million bodies pay no padding between them.)
  /// A body with locked rotation only translates (its torque is ignored, ω stays as set).
  bool rotation_locked = false;
  int template_id = -1;  ///< index of the template in its library; −1 for a plain soil sphere
  /// Zone of a zoned specimen (dem/specimen/zones.h): the index of its region in the layout; 0
  /// in a specimen without zones. Carried through checkpoints and specimen files.
  int zone = 0;
  double scale = 1.0;  ///< template length scale (body = template × scale); 1 for soil
  /// Volume-equivalent diameter (m) that sizes its contact stiffness under linear scaling;
  /// 0: World::add_body sets the sphere's diameter for a plain sphere, else (6·volume/π)^(1/3)
  /// (left 0 for a clump without a volume, which only a size-scaled law refuses).
  double diameter = 0.0;
  /// Corners of a convex polyhedron in the body frame (m), for a body that meets plane walls
  /// with its corners (a Voronoi cell of a crushable particle between platens); empty for the
  /// rest, whose spheres meet every wall. Its spheres still meet other bodies and other walls.
  std::vector<Vec3> vertices;

  Vec3 position = Vec3::Zero();  ///< centroid in the world (m)
  Vec3 velocity = Vec3::Zero();  ///< m/s (at the half step, leapfrog)
  /// Not integrated for a plain sphere centred on the origin (it changes nothing there): such a
  /// body keeps the orientation it was given.
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Vec3 angular_velocity = Vec3::Zero();  ///< world frame (rad/s)
  /// Net force and torque (world, about the centroid) of the last step: gravity + contacts,
  /// before local damping. N and N·m.
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();

  /// Radius of the smallest centroid-centred ball holding every sphere (m).
  double bounding_radius() const;
  /// Angular momentum about the centroid in the world frame, L = R·diag(I)·Rᵀ·ω (kg·m²/s).
  Vec3 angular_momentum() const;
  /// World angular velocity for a world angular momentum at this orientation,
  /// ω = R·diag(I)⁻¹·Rᵀ·L.
  Vec3 angular_velocity_for(const Vec3& angular_momentum,
                            const Eigen::Quaterniond& orientation) const;
  /// ½·m·|v|² + ½·ω·L (J).
  double kinetic_energy() const;
};

/// Angular momentum R·diag(I)·Rᵀ·ω of a body with principal moments `moments` at orientation q
/// (world frame, kg·m²/s).
Vec3 angular_momentum(const Vec3& moments, const Eigen::Quaterniond& q, const Vec3& omega);
/// World angular velocity R·diag(I)⁻¹·Rᵀ·L for a world angular momentum L at orientation q.
Vec3 angular_velocity_for(const Vec3& moments, const Vec3& momentum, const Eigen::Quaterniond& q);

/// A solid soil sphere of the given radius (m) and density (kg/m³) centred at `center`:
/// V = 4/3·π·r³, m = ρ·V, I = 2/5·m·r² about every axis. Throws InvalidInput for a
/// non-positive or non-finite radius, or a density outside kDensity.
Body make_sphere_body(const Vec3& center, double radius, double density);

/// A rigid rock clump from a clump template (spheres in the principal frame, exact unit-density
/// mass properties) scaled by `scale`: spheres ×s, V = V_t·s³, mass = ρ·V, moments =
/// ρ·I_t·s⁵ (inertia scales with mass × length²). Placed at `position` with `orientation`
/// (body -> world); `template_id` is recorded on the body. Throws InvalidInput for a density
/// outside kDensity, a non-positive scale, or a template without spheres or positive moments.
Body make_clump_body(const ClumpTemplate& clump_template, double density, const Vec3& position,
                     const Eigen::Quaterniond& orientation, double scale = 1.0,
                     int template_id = -1);

/// A rigid clump from spheres in any frame: exact union mass properties (union_properties via
/// make_clump_template), spheres rotated into the principal frame; the body is placed where the
/// clump was (position = centroid, orientation = principal frame -> clump frame), so its
/// spheres land on the given ones. Density in kg/m³, clump in metres. A rock without a library
/// template (template_id −1).
Body make_clump_body(const Clump& clump, double density);

}  // namespace clumpkit::dem
