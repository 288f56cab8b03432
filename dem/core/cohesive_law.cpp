#include "dem/core/cohesive_law.h"

#include "dem/core/contact.h"
#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace clumpkit::dem {

CohesiveParams unbreakable(const CohesiveParams& p) {
  CohesiveParams u = p;
  u.sigma_n *= 1e6, u.sigma_t *= 1e6;
  u.g_n *= 1e12, u.g_t *= 1e12;
  return u;
}

void validate_values(const CohesiveParams& p) {
  require(kBondStiffness, p.kn, "cohesive law: kn");
  require(kBondStiffness, p.kt, "cohesive law: kt");
  require(kBondStrength, p.sigma_n, "cohesive law: sigma_n");
  require(kBondStrength, p.sigma_t, "cohesive law: sigma_t");
  require(kFractureEnergy, p.g_n, "cohesive law: g_n");
  require(kFractureEnergy, p.g_t, "cohesive law: g_t");
  require(kFriction, p.friction, "cohesive law: friction");
}

void validate(const CohesiveParams& p, double max_factor) {
  validate_values(p);
  const double en = 0.5 * std::pow(max_factor * p.sigma_n, 2) / p.kn;
  const double et = 0.5 * std::pow(max_factor * p.sigma_t, 2) / p.kt;
  if (p.g_n <= en)
    throw InvalidInput("cohesive law: g_n " + format_number(p.g_n) +
                       " is not above the elastic energy at onset σ²/(2K) = " + format_number(en) +
                       " (strengths × " + format_number(max_factor) + ")");
  if (p.g_t <= et)
    throw InvalidInput("cohesive law: g_t " + format_number(p.g_t) +
                       " is not above the elastic energy at onset σ²/(2K) = " + format_number(et) +
                       " (strengths × " + format_number(max_factor) + ")");
}

MixedMode mixed_mode(const CohesiveParams& p, double factor, double c2, double s2) {
  const double de_n = factor * p.sigma_n / p.kn, de_t = factor * p.sigma_t / p.kt;
  MixedMode m;
  m.onset = 1.0 / std::sqrt(c2 / (de_n * de_n) + s2 / (de_t * de_t));
  m.failure = 2.0 / (m.onset * (c2 * p.kn / p.g_n + s2 * p.kt / p.g_t));
  return m;
}

double onset_floor(const CohesiveParams& p, double factor) {
  return std::min(factor * p.sigma_n / p.kn, factor * p.sigma_t / p.kt);
}

CohesiveTraction cohesive_traction(const CohesiveParams& p, double factor, double dn,
                                   const Vec3& dt, CohesiveState& state) {
  const double open = std::max(dn, 0.0);
  const double slip2 = dt.squaredNorm();
  const double d2 = open * open + slip2;
  // Below the onset floor nothing is damaged and the mix need not be worked out (most points,
  // most steps).
  const double floor = onset_floor(p, factor);
  if (d2 > floor * floor && state.damage < 1.0) {
    const double d = std::sqrt(d2);
    const MixedMode m = mixed_mode(p, factor, open * open / d2, slip2 / d2);
    if (d > m.onset) {
      const double damage =
          d >= m.failure ? 1.0 : m.failure * (d - m.onset) / (d * (m.failure - m.onset));
      state.damage = std::max(state.damage, std::min(damage, 1.0));
      if (state.damage >= 1.0) state.failure_mix = slip2 / d2;
    }
  }
  const double keep = 1.0 - state.damage;
  CohesiveTraction t;
  t.normal = dn > 0.0 ? keep * p.kn * dn : p.kn * dn;
  t.shear = keep * p.kt * dt;
  if (state.damage > 0.0) {
    // The crack's faces: Coulomb friction in compression, elastic up to the limit (Hu et al.
    // 2023: broken contacts become frictional); open, they slide freely.
    const double limit = dn < 0.0 ? p.friction * p.kn * -dn : 0.0;
    Vec3 tf = p.kt * (dt - state.slip);
    const double norm = tf.norm();
    if (norm > limit) {
      tf *= norm > 0.0 ? limit / norm : 0.0;
      state.slip = dt - tf / p.kt;
    }
    t.shear += state.damage * tf;
  }
  return t;
}

}  // namespace clumpkit::dem
