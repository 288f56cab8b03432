// Bilinear mixed-mode cohesive law of a bonded face point (Hu et al. 2023 eqs. 5–11): elastic to
// a quadratic onset, linear softening to a linear energy criterion, irreversible damage.
#pragma once

#include "geom/mesh/mesh.h"
#include "geom/range.h"

namespace clumpkit::dem {

/// A bond's stiffnesses per unit area K_I and K_II (N/m³; finite).
inline constexpr Range kBondStiffness = above(0);
/// A bond's strengths σ_eI and σ_eII (Pa; finite).
inline constexpr Range kBondStrength = above(0);
/// A bond's fracture energies G_I and G_II (J/m²; finite); validate asks more of them: above the
/// elastic energy at onset.
inline constexpr Range kFractureEnergy = above(0);
/// Hu et al. 2023's calibration factor s on a law: strengths × s, energies × s² (finite; the
/// recipes apply it, and validate checks the law it gives).
inline constexpr Range kBondScale = above(0);

/// Per unit area (SI). Hu et al. 2023 calibrate granite at K_I = 8e10 N/m³, K_II = 1.2e11 N/m³,
/// σ_eI = 9 MPa, σ_eII = 11.5 MPa, G_I = 900 J/m², G_II = 1125 J/m² (the paper prints "mJ/mm²";
/// only J/m² gives a finite opening at failure: δ_uI = 2·G_I/σ_eI = 0.2 mm, not 0.2 m).
struct CohesiveParams {
  double kn = 8e10;         ///< K_I: normal stiffness per unit area (N/m³), in kBondStiffness
  double kt = 1.2e11;       ///< K_II: shear stiffness per unit area (N/m³), in kBondStiffness
  double sigma_n = 9e6;     ///< σ_eI: tensile strength (Pa), in kBondStrength
  double sigma_t = 11.5e6;  ///< σ_eII: shear strength (Pa), in kBondStrength
  double g_n = 900.0;       ///< G_I: mode I fracture energy (J/m²), in kFractureEnergy
  double g_t = 1125.0;      ///< G_II: mode II fracture energy (J/m²), in kFractureEnergy
  /// Coulomb coefficient of the damaged part of a face in compression (the paper's "ν = 0.3",
  /// read as the friction between cells: a crack that closes slides with friction).
  double friction = 0.3;
};

/// The law with the same stiffness whose bonds cannot fail: strengths × 1e6 and energies × 1e12
/// (openings at onset and failure × 1e6, far beyond any contact's reach): elastic throughout.
CohesiveParams unbreakable(const CohesiveParams& p);

/// Throws InvalidInput "cohesive law: FIELD: must be > 0, got V" for a stiffness outside
/// kBondStiffness, a strength outside kBondStrength or a fracture energy outside kFractureEnergy
/// (friction: outside dem::kFriction). The one check of each value (recipes call it on their
/// [bond] table as read, validate on the law as used).
void validate_values(const CohesiveParams& p);

/// validate_values, and InvalidInput for a fracture energy below the elastic energy at onset
/// (G < σ²/(2K) at `max_factor` times the strengths: the softening branch would run backwards).
void validate(const CohesiveParams& p, double max_factor = 1.0);

/// Onset and failure of one mode mix, for the strengths × `factor` (the bond's heterogeneity).
struct MixedMode {
  double onset = 0.0;    ///< δ_em: effective opening where damage starts (eq. 7)
  double failure = 0.0;  ///< δ_um: effective opening where the bond is broken (eq. 11)
};

/// δ_em and δ_um for the mode mix given by the opening Δn⁺ = max(Δn, 0) and the slip |Δt|
/// through c² = Δn⁺²/δ² and s² = |Δt|²/δ² (δ² = Δn⁺² + |Δt|², so β² = s²/c²; pure shear, and
/// any compression, is β = ∞): eq. 7 as δ_em = (c²/δ_eI² + s²/δ_eII²)^(−1/2) (the quadratic
/// onset of eq. 6), eq. 11 as δ_um = 2 / (δ_em·(c²·K_I/G_I + s²·K_II/G_II)) (the linear energy
/// criterion of eq. 10, G_mI/G_I + G_mII/G_II = 1). Pure modes give δ_e = σ_e/K and δ_u = 2G/σ_e.
MixedMode mixed_mode(const CohesiveParams& p, double factor, double c2, double s2);

/// The smaller pure-mode onset opening, min(factor·σ_eI/K_I, factor·σ_eII/K_II) (m): the onset of
/// any mode mix is at least this (eq. 7), so a jump below it damages nothing.
double onset_floor(const CohesiveParams& p, double factor);

/// State of a bond point: its damage D in [0, 1], which never decreases (1: broken), the
/// slip of its crack: the part of the tangential jump Δt that friction no longer resists (in
/// the frame Δt is given in), and the mode mix it failed in: the slip's share s² = |Δt|²/δ² of
/// the effective opening when D reached 1 (0: pure opening, 1: pure slip or compression; 0
/// while the point holds).
struct CohesiveState {
  double damage = 0.0;
  Vec3 slip = Vec3::Zero();
  double failure_mix = 0.0;
};

/// Stresses of a bond point for the displacement jump Δ = Δn·n + Δt of one side relative to
/// the other (Δn opening positive, Δt tangential): damage D = δ_um(δ − δ_em)/(δ(δ_um − δ_em))
/// once the effective opening δ = sqrt(Δn⁺² + |Δt|²) passes δ_em (eq. 5 generalised to the mode
/// mix), kept as the largest reached; normal stress (1 − D)·K_I·Δn in tension and K_I·Δn in
/// compression (compression never damages and is never lost), shear stress (1 − D)·K_II·Δt plus,
/// on the damaged part, friction: D·τ_f with τ_f = K_II·(Δt − slip) held to |τ_f| ≤ μ·K_I·|Δn|
/// in compression (the slip follows when it is exceeded; an open crack carries none and slips
/// freely). The side displaced by Δ feels −(normal·n + shear)·area. Updates `state` (the
/// failure mix on the step D reaches 1).
struct CohesiveTraction {
  double normal = 0.0;        ///< Pa, positive in tension
  Vec3 shear = Vec3::Zero();  ///< Pa, along Δt
};
CohesiveTraction cohesive_traction(const CohesiveParams& p, double factor, double dn,
                                   const Vec3& dt, CohesiveState& state);

}  // namespace clumpkit::dem
