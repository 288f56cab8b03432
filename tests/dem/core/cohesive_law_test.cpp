// The cohesive law of bonded cells (Hu et al. 2023 eqs. 5–11): the energy a point dissipates in
// pure and mixed modes, the onset and failure limits, irreversibility, compression.
#include "dem/core/cohesive_law.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// Work done on a point of area a opened along the fixed direction (cos φ normal, sin φ
// tangential) from 0 to 1.2·δ_um in `steps` steps (trapezoids), split into its normal and
// tangential parts. Once broken the point carries nothing, so all of it was dissipated.
struct Work {
  double normal = 0, tangential = 0;
};
Work open_along(const CohesiveParams& p, double factor, double phi, double a, int steps = 200000) {
  const double c = std::cos(phi), s = std::sin(phi);
  const MixedMode m = mixed_mode(p, factor, c * c, s * s);
  const double end = 1.2 * m.failure;
  CohesiveState state;
  Work w;
  double tn0 = 0, tt0 = 0;
  for (int k = 1; k <= steps; ++k) {
    const double d = end * k / steps, h = end / steps;
    const CohesiveTraction t = cohesive_traction(p, factor, d * c, Vec3(d * s, 0, 0), state);
    w.normal += 0.5 * (tn0 + t.normal) * h * c * a;
    w.tangential += 0.5 * (tt0 + t.shear.x()) * h * s * a;
    tn0 = t.normal;
    tt0 = t.shear.x();
  }
  EXPECT_EQ(state.damage, 1.0);
  EXPECT_EQ(tn0, 0.0);
  return w;
}

}  // namespace

TEST(CohesiveLaw, PureModesDissipateTheirFractureEnergies) {
  const CohesiveParams p;  // granite, Hu et al. 2023 (G in J/m²)
  const double a = 2e-6;   // m²: one integration point
  for (double factor : {0.75, 1.0, 1.25}) {
    SCOPED_TRACE(factor);
    const Work one = open_along(p, factor, 0.0, a);
    EXPECT_NEAR(one.normal / (p.g_n * a), 1.0, 5e-3);
    EXPECT_NEAR(one.tangential, 0.0, 1e-12);
    const Work two = open_along(p, factor, M_PI / 2, a);
    EXPECT_NEAR(two.tangential / (p.g_t * a), 1.0, 5e-3);
  }
  // Pure-mode limits of eqs. 7 and 11: δ_e = σ_e/K, δ_u = 2G/σ_e (0.1125 and 0.2 mm in mode I).
  const MixedMode n = mixed_mode(p, 1.0, 1.0, 0.0), t = mixed_mode(p, 1.0, 0.0, 1.0);
  EXPECT_NEAR(n.onset, 9e6 / 8e10, 1e-15);
  EXPECT_NEAR(n.failure, 2 * 900 / 9e6, 1e-15);
  EXPECT_NEAR(t.onset, 11.5e6 / 1.2e11, 1e-15);
  EXPECT_NEAR(t.failure, 2 * 1125 / 11.5e6, 1e-15);
}

TEST(CohesiveLaw, MixedModesMeetTheLinearEnergyCriterion) {
  const CohesiveParams p;
  const double a = 1.0;
  for (double phi_deg : {15.0, 30.0, 45.0, 60.0, 80.0}) {
    SCOPED_TRACE(phi_deg);
    const double phi = phi_deg * M_PI / 180.0;
    const Work w = open_along(p, 1.0, phi, a);
    // Eq. 10: G_mI/G_I + G_mII/G_II = 1.
    EXPECT_NEAR(w.normal / p.g_n + w.tangential / p.g_t, 1.0, 5e-3);
    // Eq. 7 against the quadratic onset of eq. 6, eq. 11 against its printed form.
    const double beta = std::tan(phi), c = std::cos(phi), s = std::sin(phi);
    const MixedMode m = mixed_mode(p, 1.0, c * c, s * s);
    const double deI = p.sigma_n / p.kn, deII = p.sigma_t / p.kt;
    const double duI = 2 * p.g_n / p.sigma_n, duII = 2 * p.g_t / p.sigma_t;
    EXPECT_NEAR(std::pow(m.onset * c / deI, 2) + std::pow(m.onset * s / deII, 2), 1.0, 1e-12);
    EXPECT_NEAR(m.onset / (deI * deII *
                           std::sqrt((1 + beta * beta) / (deII * deII + std::pow(deI * beta, 2)))),
                1.0, 1e-12);
    const double eq11 = (1 + beta * beta) / m.onset * deI * duI * deII * duII /
                        (deII * duII + beta * beta * deI * duI);
    EXPECT_NEAR(m.failure / eq11, 1.0, 1e-12);
  }
}

TEST(CohesiveLaw, DamageNeverHealsAndCompressionNeverDamages) {
  const CohesiveParams p;
  CohesiveState s;
  const MixedMode n = mixed_mode(p, 1.0, 1.0, 0.0);
  // Elastic below onset: no damage, stress K·Δn.
  CohesiveTraction t = cohesive_traction(p, 1.0, 0.5 * n.onset, Vec3::Zero(), s);
  EXPECT_EQ(s.damage, 0.0);
  EXPECT_DOUBLE_EQ(t.normal, p.kn * 0.5 * n.onset);
  // Half-way down the softening branch, then unloaded: the damage stays, the stiffness is
  // (1 − D)·K, and reloading to the same opening gives the same stress.
  const double mid = 0.5 * (n.onset + n.failure);
  const CohesiveTraction peak = cohesive_traction(p, 1.0, mid, Vec3::Zero(), s);
  const double damage = s.damage;
  EXPECT_GT(damage, 0.0);
  EXPECT_LT(damage, 1.0);
  EXPECT_NEAR(peak.normal, p.sigma_n * (n.failure - mid) / (n.failure - n.onset), 1e-6);
  t = cohesive_traction(p, 1.0, 0.2 * mid, Vec3::Zero(), s);
  EXPECT_EQ(s.damage, damage);
  EXPECT_DOUBLE_EQ(t.normal, (1 - damage) * p.kn * 0.2 * mid);
  t = cohesive_traction(p, 1.0, mid, Vec3::Zero(), s);
  EXPECT_EQ(s.damage, damage);
  EXPECT_DOUBLE_EQ(t.normal, peak.normal);
  // Compression: full stiffness whatever the damage, and no damage from it.
  t = cohesive_traction(p, 1.0, -3 * n.failure, Vec3::Zero(), s);
  EXPECT_EQ(s.damage, damage);
  EXPECT_DOUBLE_EQ(t.normal, -3 * p.kn * n.failure);
  CohesiveState fresh;
  cohesive_traction(p, 1.0, -10 * n.failure, Vec3::Zero(), fresh);
  EXPECT_EQ(fresh.damage, 0.0);
  // Broken: no tension, no shear; compression still pushes.
  cohesive_traction(p, 1.0, 2 * n.failure, Vec3::Zero(), s);
  EXPECT_EQ(s.damage, 1.0);
  t = cohesive_traction(p, 1.0, 0.5 * n.onset, Vec3(1e-5, 0, 0), s);
  EXPECT_EQ(t.normal, 0.0);
  EXPECT_EQ(t.shear.norm(), 0.0);
  EXPECT_LT(cohesive_traction(p, 1.0, -1e-6, Vec3::Zero(), s).normal, 0.0);
  // A weaker face (factor 0.75) starts to soften at 0.75·σ_eI.
  CohesiveState weak;
  const MixedMode w = mixed_mode(p, 0.75, 1.0, 0.0);
  EXPECT_NEAR(cohesive_traction(p, 0.75, w.onset, Vec3::Zero(), weak).normal, 0.75 * p.sigma_n,
              1e-6);
  EXPECT_EQ(weak.damage, 0.0);
}

TEST(CohesiveLaw, BadParametersAreRefused) {
  CohesiveParams p;
  EXPECT_NO_THROW(validate(p, 1.25));  // 791 ≤ 900 and 861 ≤ 1125 J/m² (Hu et al. 2023)
  p.g_n = 900e3 * 1e-3 * 1e-3;         // "900 mJ/mm²" read as mJ/m²: below σ²/(2K)
  EXPECT_THROW(validate(p), InvalidInput);
  for (double CohesiveParams::*f :
       {&CohesiveParams::kn, &CohesiveParams::kt, &CohesiveParams::sigma_n,
        &CohesiveParams::sigma_t, &CohesiveParams::g_n, &CohesiveParams::g_t})
    for (double bad : {0.0, -1.0, std::nan("")}) {
      CohesiveParams q;
      q.*f = bad;
      EXPECT_THROW(validate(q), InvalidInput);
    }
}

TEST(CohesiveLaw, ACrackSlidesWithCoulombFrictionInCompressionAndFreelyWhenOpen) {
  CohesiveParams p;
  p.friction = 0.3;
  const MixedMode n = mixed_mode(p, 1.0, 1.0, 0.0);
  CohesiveState s;
  cohesive_traction(p, 1.0, 2 * n.failure, Vec3::Zero(), s);  // broken in tension
  ASSERT_EQ(s.damage, 1.0);
  // Closed by dn = −1 µm: a small slip is held elastically (K_II·Δt), a large one at
  // μ·K_I·|Δn|, and the crack keeps the slip it made.
  const double dn = -1e-6, limit = p.friction * p.kn * 1e-6;
  const double small = 0.5 * limit / p.kt;
  CohesiveTraction t = cohesive_traction(p, 1.0, dn, Vec3(small, 0, 0), s);
  EXPECT_NEAR(t.shear.x(), p.kt * small, 1e-9 * limit);
  EXPECT_DOUBLE_EQ(t.normal, p.kn * dn);
  t = cohesive_traction(p, 1.0, dn, Vec3(10 * small, 0, 0), s);
  EXPECT_NEAR(t.shear.x(), limit, 1e-9 * limit);
  EXPECT_NEAR(s.slip.x(), 10 * small - limit / p.kt, 1e-12 * small);
  // Back by 2·small: elastic unloading from the slipped state, the other way.
  t = cohesive_traction(p, 1.0, dn, Vec3(8 * small, 0, 0), s);
  EXPECT_NEAR(t.shear.x(), limit - 2 * p.kt * small, 1e-9 * limit);
  // Opened: no friction, and the crack slides with the faces.
  t = cohesive_traction(p, 1.0, 1e-6, Vec3(3 * small, 0, 0), s);
  EXPECT_EQ(t.shear.norm(), 0.0);
  EXPECT_EQ(t.normal, 0.0);
  t = cohesive_traction(p, 1.0, dn, Vec3(3 * small, 0, 0), s);
  EXPECT_NEAR(t.shear.norm(), 0.0, 1e-9 * limit);
  // An intact point carries no friction term: its shear is K_II·Δt alone.
  CohesiveState intact;
  t = cohesive_traction(p, 1.0, dn, Vec3(small, 0, 0), intact);
  EXPECT_DOUBLE_EQ(t.shear.x(), p.kt * small);
  p.friction = -0.1;
  EXPECT_THROW(validate(p), InvalidInput);
}
