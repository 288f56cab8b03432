// Cohesive bonds between two rigid bodies (the faces shared by the Voronoi cells of a crushable
// particle, Hu et al. 2023): integration points fixed in both bodies, the cohesive law at each,
// and the fragments that the intact bonds hold together.
#pragma once

#include "dem/core/body.h"
#include "dem/core/cohesive_law.h"

#include <vector>

namespace clumpkit::dem {

/// One integration point of a bond: the same material point as seen from each body's frame
/// (equal in the world when the bond is made), the face area it stands for, and its damage.
struct BondPoint {
  Vec3 in_a = Vec3::Zero();  ///< body frame of a (m)
  Vec3 in_b = Vec3::Zero();  ///< body frame of b (m)
  double area = 0.0;         ///< m²
  CohesiveState state;
};

/// A bond between bodies a and b across their shared face.
struct Bond {
  int a = 0, b = 0;
  Vec3 normal_in_a = Vec3::UnitZ();  ///< the face's unit normal from a towards b, a's frame
  double factor = 1.0;               ///< factor on the strengths σ_eI and σ_eII of this face
  std::vector<BondPoint> points;
  /// Whether any point still holds (damage below 1).
  bool holds() const;
  /// Whether no point has any damage (damage never heals).
  bool undamaged() const;
};

/// A bond between two bodies at their present poses from the face's integration points given in
/// the world (cell_bonds of geom/cells): each point stored in both body frames; the normal
/// (world, from a towards b) stored in a's frame.
Bond make_bond(const Body& a, const Body& b, int ia, int ib, const Vec3& normal,
               const std::vector<Vec3>& points, const std::vector<double>& areas, double factor);

/// What a bond does to its two bodies: forces (N) and torques about each centroid (N·m), world
/// frame.
struct BondWrench {
  Vec3 force_a = Vec3::Zero(), torque_a = Vec3::Zero();
  Vec3 force_b = Vec3::Zero(), torque_b = Vec3::Zero();
};

/// The bond's wrench at the bodies' poses, updating each point's damage: at each point the
/// displacement jump Δ = x_b − x_a of its two copies, split along the face normal (a's, rotated
/// to the world) into opening and slip, gives the cohesive stresses (cohesive_traction); b feels
/// −area·(σ_n·n + τ) at the midpoint of the two copies and a the opposite. A rigid motion of the
/// two bodies together leaves every Δ zero: no force.
BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Body& a, const Body& b);
/// The same for the poses (centroid, orientation) of a and b.
BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Vec3& pa,
                       const Eigen::Quaterniond& qa, const Vec3& pb, const Eigen::Quaterniond& qb);
/// The same with the orientations as rotation matrices (made once per bond and step).
BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Vec3& pa, const Mat3& ra,
                       const Vec3& pb, const Mat3& rb);

/// What a bond's points are after bond_wrench: whether one still holds (Bond::holds) and whether
/// none has any damage (Bond::undamaged), found in its loop over them.
struct BondPointsAfter {
  bool holds = false;
  bool undamaged = true;
};
/// bond_wrench with the orientations as matrices, and the points' state after it in `after`.
BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Vec3& pa, const Mat3& ra,
                       const Vec3& pb, const Mat3& rb, BondPointsAfter& after);

/// The stiffness the bond adds to a body it joins, for the critical time step: Σ area·max(K_I,
/// K_II) over its points (N/m).
double bond_stiffness(const Bond& bond, const CohesiveParams& law);

/// How a bond failed: intact while a point holds; else by the area-weighted mean s̄² of its
/// points' mode mix at failure (CohesiveState::failure_mix): mode I (opening) for s̄² < 1/4, the
/// jump within 30° of the face normal; mode II (slip) for s̄² > 3/4, within 30° of the face;
/// mixed between.
enum class BondFailure { intact, mode_i, mode_ii, mixed };
BondFailure failure_mode(const Bond& bond);

/// Connected components of `bodies` bodies under the bonds that hold: the label of each body is
/// the smallest body index of its component (a fragment), so labels are the same for any bond
/// order.
std::vector<int> fragments(int bodies, const std::vector<Bond>& bonds);

/// Labels of `fragments` (or any labelling whose label is its smallest member) numbered 1, 2, …
/// in the order of their smallest body, as ParaView and the pages colour integers.
std::vector<int> fragment_ordinals(const std::vector<int>& labels);

}  // namespace clumpkit::dem
