#include "dem/core/bond_moments.h"

#include <Eigen/SVD>

#include <algorithm>

namespace clumpkit::dem {

BondMoments bond_moments(const Bond& bond) {
  BondMoments m;
  for (const BondPoint& p : bond.points) {
    m.area += p.area;
    m.centroid_a += p.area * p.in_a;
    m.centroid_b += p.area * p.in_b;
  }
  m.pristine = bond.undamaged();
  m.holding = bond.holds();
  if (m.area > 0.0) {
    m.centroid_a /= m.area;
    m.centroid_b /= m.area;
  } else {  // points of zero area carry no force; their plain mean serves the bound
    for (const BondPoint& p : bond.points) m.centroid_a += p.in_a, m.centroid_b += p.in_b;
    m.centroid_a /= static_cast<double>(std::max<std::size_t>(1, bond.points.size()));
    m.centroid_b /= static_cast<double>(std::max<std::size_t>(1, bond.points.size()));
  }
  Mat3 h = Mat3::Zero();  // Σ v·uᵀ (unweighted: the rotation must fit every point)
  for (const BondPoint& p : bond.points) {
    const Vec3 u = p.in_a - m.centroid_a, v = p.in_b - m.centroid_b;
    m.uu += p.area * u * u.transpose();
    m.uv += p.area * u * v.transpose();
    m.vv += p.area * v * v.transpose();
    h += v * u.transpose();
    m.reach = std::max(m.reach, v.norm());
  }
  // The rotation that took b's frame to a's when the bond was made (Kabsch: P = U·diag(1, 1, d)
  // ·Vᵀ of the SVD of Σ u·vᵀ); a face's points are coplanar, which the sign d keeps proper.
  const Eigen::JacobiSVD<Mat3> svd(h.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 d = Mat3::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  m.made = svd.matrixU() * d * svd.matrixV().transpose();
  for (const BondPoint& p : bond.points)
    m.misfit =
        std::max(m.misfit, (m.made * (p.in_b - m.centroid_b) - (p.in_a - m.centroid_a)).norm());
  return m;
}

bool elastic_bond_wrench(const BondMoments& m, const Bond& bond, const CohesiveParams& law,
                         const Vec3& pa, const Mat3& ra, const Vec3& pb, const Mat3& rb,
                         BondWrench& w) {
  if (!m.pristine) return false;
  // Below the smaller pure-mode onset no point's state changes (cohesive_traction's floor); half
  // of it leaves room for rounding in the bound.
  const double floor = onset_floor(law, bond.factor);
  const Vec3 xa = pa + ra * m.centroid_a, xb = pb + rb * m.centroid_b;
  const Vec3 jump = xb - xa;  // Δ̄
  const Mat3 rel = ra.transpose() * rb;
  const double reach = (rel - m.made).norm() * m.reach + m.misfit;
  if (!(jump.norm() + reach < 0.5 * floor)) return false;
  // In a's frame, with M = RaᵀRb the turn of b relative to a: C = Ra·Cₐ·Raᵀ, Cₐ = ½(U·Mᵀ − uu +
  // M·vv·Mᵀ − M·Uᵀ), U = uv, and K = Ra·Kₐ·Raᵀ, Kₐ = K_II·I + (K_I − K_II)·nₐ·nₐᵀ; so t = Ra·tₐ
  // with tₐ = K_II·axial(Cₐ) + (K_I − K_II)·(Cₐ·nₐ) × nₐ, where axial(w·nᵀ) = w × n, and the
  // symmetric terms of Cₐ drop from axial(Cₐ) = axial(U·Mᵀ).
  const Vec3& na = bond.normal_in_a;
  const Mat3 um = m.uv * rel.transpose();
  const Vec3 axial(um(1, 2) - um(2, 1), um(2, 0) - um(0, 2), um(0, 1) - um(1, 0));
  const Vec3 mn = rel.transpose() * na;
  const Vec3 cn = 0.5 * (m.uv * mn - m.uu * na + rel * (m.vv * mn) - rel * (m.uv.transpose() * na));
  const Vec3 t = ra * (law.kt * axial + (law.kn - law.kt) * cn.cross(na));
  const Vec3 n = ra * na;
  const Vec3 f = -m.area * (law.kt * jump + (law.kn - law.kt) * n.dot(jump) * n);  // on b
  const Vec3 mid = 0.5 * (xa + xb);
  w.force_b = f;
  w.torque_b = (mid - pb).cross(f) - t;
  w.force_a = -f;
  w.torque_a = -(mid - pa).cross(f) + t;
  return true;
}

}  // namespace clumpkit::dem
