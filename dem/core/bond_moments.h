// The closed form of an undamaged bond's wrench: its points' area moments turn the elastic sum
// over the face into a few 3×3 products, with a bound on the points' jumps that says when it holds.
#pragma once

#include "dem/core/bond.h"

namespace clumpkit::dem {

/// What the closed form needs of a bond's points, made once (the points never move in the bodies'
/// frames). Moments are about the points' area centroid in each frame: u = in_a − centroid_a,
/// v = in_b − centroid_b.
struct BondMoments {
  double area = 0.0;               ///< Σ a (m²)
  Vec3 centroid_a = Vec3::Zero();  ///< Σ a·in_a / Σ a
  Vec3 centroid_b = Vec3::Zero();  ///< Σ a·in_b / Σ a
  Mat3 uu = Mat3::Zero();          ///< Σ a·u·uᵀ
  Mat3 uv = Mat3::Zero();          ///< Σ a·u·vᵀ
  Mat3 vv = Mat3::Zero();          ///< Σ a·v·vᵀ
  Mat3 made = Mat3::Identity();    ///< the rotation P with P·v ≈ u (b's frame to a's, as made)
  double reach = 0.0;              ///< max |v|
  double misfit = 0.0;             ///< max |P·v − u|: how far the copies were apart, as made
  bool pristine = true;            ///< no point has any damage (damage never heals)
  bool holding = true;             ///< a point still holds (Bond::holds; never again once false)
};

/// The moments of `bond`'s points, and whether every point is undamaged.
BondMoments bond_moments(const Bond& bond);

/// The wrench of a bond whose points are all undamaged and provably below the onset of damage, in
/// closed form. With Δ̄ the area-mean jump (the centroids' copies apart), K = K_II·I + (K_I −
/// K_II)·n·nᵀ and the centred moments: force on b −A·K·Δ̄; torque on b −A·(m − p_b)×K·Δ̄ − t with m
/// the midpoint of the centroids' copies and t the axial vector of C·K, C = Σ a·p·qᵀ over the
/// points' offsets p (midpoint) and q (jump) — the sum bond_wrench makes point by point, with no
/// state to update. Returns false, touching nothing, when a point may be damaged or may reach the
/// smaller pure-mode onset opening (|Δ| ≤ |Δ̄| + ‖RaᵀRb − P‖_F·reach + misfit bounds every
/// point's jump): then bond_wrench must run.
bool elastic_bond_wrench(const BondMoments& m, const Bond& bond, const CohesiveParams& law,
                         const Vec3& pa, const Mat3& ra, const Vec3& pb, const Mat3& rb,
                         BondWrench& w);

}  // namespace clumpkit::dem
