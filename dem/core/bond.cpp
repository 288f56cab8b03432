#include "dem/core/bond.h"

#include "geom/errors.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace clumpkit::dem {

bool Bond::holds() const {
  for (const BondPoint& p : points)
    if (p.state.damage < 1.0) return true;
  return false;
}

bool Bond::undamaged() const {
  for (const BondPoint& p : points)
    if (p.state.damage > 0.0) return false;
  return true;
}

BondFailure failure_mode(const Bond& bond) {
  if (bond.holds()) return BondFailure::intact;
  double area = 0, mix = 0, plain = 0;
  for (const BondPoint& p : bond.points) {
    area += p.area, mix += p.area * p.state.failure_mix, plain += p.state.failure_mix;
  }
  // Points of zero area (none are made, but a file may hold them) count alike.
  const double s2 = area > 0 ? mix / area : plain / static_cast<double>(bond.points.size());
  return s2 < 0.25 ? BondFailure::mode_i : s2 > 0.75 ? BondFailure::mode_ii : BondFailure::mixed;
}

Bond make_bond(const Body& a, const Body& b, int ia, int ib, const Vec3& normal,
               const std::vector<Vec3>& points, const std::vector<double>& areas, double factor) {
  if (points.size() != areas.size() || points.empty())
    throw InvalidInput("bond: needs one area per point and at least one point, got " +
                       std::to_string(points.size()) + " points and " +
                       std::to_string(areas.size()) + " areas");
  Bond bond;
  bond.a = ia;
  bond.b = ib;
  bond.factor = factor;
  bond.normal_in_a = (a.orientation.conjugate() * normal).normalized();
  for (std::size_t k = 0; k < points.size(); ++k) {
    BondPoint p;
    p.in_a = a.orientation.conjugate() * (points[k] - a.position);
    p.in_b = b.orientation.conjugate() * (points[k] - b.position);
    p.area = areas[k];
    bond.points.push_back(p);
  }
  return bond;
}

BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Body& a, const Body& b) {
  return bond_wrench(bond, law, a.position, a.orientation, b.position, b.orientation);
}

BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Vec3& pa,
                       const Eigen::Quaterniond& qa, const Vec3& pb, const Eigen::Quaterniond& qb) {
  // Rotation matrices once per bond: cheaper than a quaternion rotation per point and vector.
  return bond_wrench(bond, law, pa, qa.toRotationMatrix(), pb, qb.toRotationMatrix());
}

BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Vec3& pa, const Mat3& ra,
                       const Vec3& pb, const Mat3& rb) {
  BondPointsAfter after;
  return bond_wrench(bond, law, pa, ra, pb, rb, after);
}

BondWrench bond_wrench(Bond& bond, const CohesiveParams& law, const Vec3& pa, const Mat3& ra,
                       const Vec3& pb, const Mat3& rb, BondPointsAfter& after) {
  after = BondPointsAfter{};
  BondWrench w;
  const Vec3 n = ra * bond.normal_in_a;
  for (BondPoint& p : bond.points) {
    const Vec3 xa = pa + ra * p.in_a;
    const Vec3 xb = pb + rb * p.in_b;
    const Vec3 jump = xb - xa;
    const double dn = jump.dot(n);
    // The slip of a crack is kept in a's frame, so that the pair turning together moves it along.
    const Vec3 dt = ra.transpose() * (jump - dn * n);
    const CohesiveTraction t = cohesive_traction(law, bond.factor, dn, dt, p.state);
    after.holds = after.holds || p.state.damage < 1.0;             // Bond::holds
    after.undamaged = after.undamaged && !(p.state.damage > 0.0);  // Bond::undamaged
    const Vec3 f = -p.area * (t.normal * n + ra * t.shear);        // on b
    const Vec3 at = 0.5 * (xa + xb);
    w.force_b += f;
    w.torque_b += (at - pb).cross(f);
    w.force_a -= f;
    w.torque_a -= (at - pa).cross(f);
  }
  return w;
}

double bond_stiffness(const Bond& bond, const CohesiveParams& law) {
  double area = 0.0;
  for (const BondPoint& p : bond.points) area += p.area;
  return area * std::max(law.kn, law.kt);
}

std::vector<int> fragments(int bodies, const std::vector<Bond>& bonds) {
  std::vector<int> parent(bodies);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Bond& bond : bonds) {
    if (!bond.holds()) continue;
    const int ra = find(bond.a), rb = find(bond.b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);  // the root is the smallest index
  }
  std::vector<int> label(bodies);
  for (int i = 0; i < bodies; ++i) label[i] = find(i);
  return label;
}

std::vector<int> fragment_ordinals(const std::vector<int>& labels) {
  std::vector<int> rank(labels.size(), 0), out(labels.size());
  int next = 0;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    int& r = rank[static_cast<std::size_t>(labels[k])];
    if (r == 0) r = ++next;
    out[k] = r;
  }
  return out;
}

}  // namespace clumpkit::dem
