// Linear spring contact law: normal spring + dashpot, incremental Coulomb shear spring, PFC
// local damping, and friction rescaling that keeps the shear history.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/range.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace clumpkit::dem {

/// How contact stiffness depends on particle size.
enum class StiffnessScaling {
  none,   ///< every contact has kn and ks
  linear  ///< kn ∝ d (CTGU 2017; Thakur et al. 2016): see pair_stiffness_factor
};

/// Contact parameters (SI). Defaults follow Jin et al. 2017 §4.1 (kn = ks = 1e6 N/m, μ = 0.8).
struct ContactParams {
  /// Normal stiffness (N/m), in kNormalStiffness; with linear scaling kn_ref, at d = d_ref.
  double kn = 1e6;
  /// Shear stiffness (N/m), in kShearStiffness; with linear scaling ks at d = d_ref.
  double ks = 1e6;
  StiffnessScaling scaling = StiffnessScaling::none;
  double d_ref = 0.0;     ///< reference diameter of linear scaling (m), in kReferenceDiameter
  double friction = 0.8;  ///< Coulomb coefficient μ, in kFriction
  /// Viscous normal damping ratio β (0 = none), in kDampingRatio: dashpot c = 2·β·sqrt(m_eff·kn).
  /// Use damping_ratio_from_restitution(e) to ask for a restitution coefficient instead.
  double damping_ratio = 0.0;
  /// PFC local damping coefficient α (0 = none), in kLocalDamping, applied per body by the world:
  /// F_k -= α·|F_k|·sign(v_k) for each force and torque component (local_damping()).
  double local_damping = 0.0;
};

/// The Coulomb coefficients μ a contact law, a test or a recipe takes (finite: +∞ is no value).
inline constexpr Range kFriction = at_least(0);
/// The normal stiffness kn of a contact law (N/m; finite).
inline constexpr Range kNormalStiffness = above(0);
/// The shear stiffness ks of a contact law (N/m; finite): 0 is a law without a shear spring.
inline constexpr Range kShearStiffness = at_least(0);
/// ks/kn, as a test sets a specimen's shear stiffness from its normal one (finite): ks is then
/// in kShearStiffness for any kn in kNormalStiffness.
inline constexpr Range kStiffnessRatio = at_least(0);
/// The diameter d_ref at which a linearly scaled law's kn and ks hold (m; finite).
inline constexpr Range kReferenceDiameter = above(0);
/// The viscous normal damping ratio β: 1 is the critically damped dashpot, beyond which
/// restitution_from_damping_ratio has no value.
inline constexpr Range kDampingRatio = closed_open(0, 1);
/// PFC local damping α: 1 would remove every unbalanced force.
inline constexpr Range kLocalDamping = closed_open(0, 1);

/// Factor f on kn and ks for a contact of bodies of volume-equivalent diameters d_i and d_j
/// (every sphere of a clump has its body's d): 1 without scaling; with linear scaling the two
/// particle springs k_i = 2·kn_ref·d_i/d_ref in series, kn_ij = 2·(kn_ref/d_ref)·d_i·d_j /
/// (d_i + d_j), so f = 2·d_i·d_j / ((d_i + d_j)·d_ref) (equal sizes: d/d_ref). Written so that
/// scaling both diameters by a power of two scales f exactly (the similarity copy,
/// dem/core/scale.h).
inline double pair_stiffness_factor(const ContactParams& p, double d_i, double d_j) {
  if (p.scaling == StiffnessScaling::none) return 1.0;
  return (2.0 * d_i) * d_j / ((d_i + d_j) * p.d_ref);
}

/// The factor for a body of diameter d on a rigid wall: the series limit d_j → ∞ of
/// pair_stiffness_factor, 2·d/d_ref.
inline double wall_stiffness_factor(const ContactParams& p, double d) {
  if (p.scaling == StiffnessScaling::none) return 1.0;
  return 2.0 * d / p.d_ref;
}

/// p with kn and ks multiplied by `factor` (the rest unchanged).
inline ContactParams scaled_stiffness(ContactParams p, double factor) {
  p.kn *= factor;
  p.ks *= factor;
  return p;
}

/// Throws InvalidInput for kn outside kNormalStiffness, ks outside kShearStiffness, d_ref outside
/// kReferenceDiameter under linear scaling, friction outside kFriction, damping_ratio outside
/// kDampingRatio or local_damping outside kLocalDamping.
void validate(const ContactParams& p);

/// Damping ratio giving restitution e in a head-on collision of the linear spring-dashpot:
/// β = −ln e / sqrt(π² + ln² e) (from e = exp(−β·π / sqrt(1 − β²)); the classical result for
/// an unclamped dashpot, e.g. Tsuji et al. 1992). e in (0, 1]; throws InvalidInput otherwise.
double damping_ratio_from_restitution(double restitution);

/// Inverse of damping_ratio_from_restitution: e = exp(−β·π / sqrt(1 − β²)) for β in kDampingRatio.
double restitution_from_damping_ratio(double damping_ratio);

/// State of one contact: the normal points towards the side that receives force
/// normal_force·normal + shear (the other side receives the opposite).
struct ContactState {
  Vec3 normal = Vec3::UnitZ();  ///< unit contact normal (world)
  Vec3 point = Vec3::Zero();    ///< contact point (world, m)
  double overlap = 0.0;         ///< m
  double normal_force = 0.0;    ///< kn·(δ − excused) − c·vn (N); may be slightly tensile
  /// Overlap the normal spring ignores (m): zero but for a pair of spheres of two bodies whose
  /// bond broke while the spheres overlapped (the fill lets each cell's spheres cross its faces;
  /// pushing them apart at full overlap would release energy the bond never held). It starts at
  /// the overlap at the break and follows the overlap down, never up (excused = min(excused, δ)),
  /// so the pair resists being pressed further in at once and is an ordinary contact once it
  /// has parted. Pair contacts only.
  double excused = 0.0;
  Vec3 shear = Vec3::Zero();  ///< incremental shear force (N), kept between steps (history)
  /// Total force on the receiving side (N).
  Vec3 force() const { return normal_force * normal + shear; }
};

/// Advances a contact by one step of dt (s):
///  1. the previous shear force is rotated into the new contact plane (its normal component is
///     removed and its magnitude restored, as LAMMPS gran/hooke/history does);
///  2. normal force Fn = kn·δ − c·(v·n) with c = 2·β·sqrt(m_eff·kn) (no tension clamp, so the
///     restitution formula above is exact for the continuous law);
///  3. shear increment Fs -= ks·v_t·dt, v_t the tangential part of v;
///  4. Coulomb limit |Fs| ≤ μ·max(Fn, 0) (slip: Fs scaled back onto the limit).
/// `relative_velocity` is the velocity of the receiving side minus the other side at the contact
/// point (m/s); m_eff the effective mass (kg) m1·m2/(m1 + m2), or m for a wall.
void update_contact(ContactState& state, const Vec3& normal, double overlap, const Vec3& point,
                    const Vec3& relative_velocity, double effective_mass,
                    const ContactParams& params, double dt);

/// The normal dashpot coefficient c = 2·β·sqrt(m_eff·kn) of update_contact (N·s/m).
inline double normal_dashpot(double effective_mass, const ContactParams& params) {
  return 2.0 * params.damping_ratio * std::sqrt(effective_mass * params.kn);
}

/// Steps 1–4 of update_contact on the two quantities a contact carries from step to step, the
/// shear force and the normal force, with the normal dashpot coefficient c = 2·β·sqrt(m_eff·kn)
/// (N·s/m) given instead of the effective mass (the world computes it once per pair). Inline:
/// the world's contact kernel calls it once per contact and step.
inline void update_contact_force(Vec3& shear, double& normal_force, const Vec3& normal,
                                 double overlap, const Vec3& v, double c, const ContactParams& p,
                                 double dt) {
  // 1. Rotate the stored shear into the new tangent plane, keeping its magnitude (one square
  // root: the scale is sqrt(|old|² / |projected|²)).
  const double old_squared = shear.squaredNorm();
  if (old_squared > 0.0) {
    const Vec3 projected = shear - normal * normal.dot(shear);
    const double m2 = projected.squaredNorm();
    shear = m2 > 0.0 ? Vec3(projected * std::sqrt(old_squared / m2)) : Vec3(Vec3::Zero());
  }

  // 2. Normal spring + dashpot.
  const double vn = v.dot(normal);
  normal_force = p.kn * overlap - c * vn;

  // 3. Incremental shear spring.
  const Vec3 vt = v - vn * normal;
  shear -= p.ks * dt * vt;

  // 4. Coulomb limit (squared comparison first: a sticking contact needs no square root).
  const double limit = p.friction * std::max(normal_force, 0.0);
  const double squared = shear.squaredNorm();
  if (squared > limit * limit) {
    const double magnitude = std::sqrt(squared);
    shear *= limit / magnitude;
  }
}

/// Keeps the shear history under a new friction coefficient: |Fs| is clamped to
/// μ_new·max(Fn, 0) (direction kept); a shear already inside the new limit is unchanged.
void rescale_friction(ContactState& state, double new_friction);

/// PFC local damping of one vector quantity (force against velocity, or torque against angular
/// velocity): returns F − α·|F_k|·sign(v_k) per component k (Itasca PFC "local damping").
Vec3 local_damping(const Vec3& force, const Vec3& velocity, double alpha);

}  // namespace clumpkit::dem
