// The closed form of an undamaged bond: the same wrench as the sum over its points, for any
// pose of a face of irregular points, and no answer where a point may be damaged.
#include "dem/core/bond_moments.h"

#include "dem/core/integrator.h"
#include "geom/random.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// Two cells of 6.5 mm in random poses bonded on a face of seven points of unequal areas (a
// Voronoi face's fan of triangles), made in the bodies' present poses.
struct FacePair {
  Body a, b;
  Bond bond;
};
FacePair random_face_pair(Rng& rng) {
  FacePair p;
  p.a = make_sphere_body(rng.uniform(Vec3(-0.1, -0.1, -0.1), Vec3(0.1, 0.1, 0.1)), 0.003, 2650);
  p.a.orientation = rng.normal_quaternion().normalized();
  const Vec3 n = rng.unit_vector();
  p.b = make_sphere_body(p.a.position + 0.0065 * n, 0.003, 2650);
  p.b.orientation = rng.normal_quaternion().normalized();
  const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  std::vector<Vec3> points;
  std::vector<double> areas;
  for (int i = 0; i < 7; ++i) {
    const double x = rng.uniform(-0.003, 0.003), y = rng.uniform(-0.003, 0.003);
    points.push_back(p.a.position + 0.00325 * n + x * e1 + y * e2);
    areas.push_back(rng.uniform(1e-6, 8e-6));
  }
  p.bond = make_bond(p.a, p.b, 0, 1, n, points, areas, rng.uniform(0.75, 1.25));
  return p;
}

void expect_same_wrench(const BondWrench& got, const BondWrench& want) {
  const double f = want.force_b.norm(), t = want.torque_b.norm() + want.torque_a.norm();
  EXPECT_LT((got.force_b - want.force_b).norm(), 1e-9 * f);
  EXPECT_LT((got.force_a - want.force_a).norm(), 1e-9 * f);
  EXPECT_LT((got.torque_b - want.torque_b).norm(), 1e-9 * t);
  EXPECT_LT((got.torque_a - want.torque_a).norm(), 1e-9 * t);
}

}  // namespace

TEST(BondMoments, ClosedFormIsTheSumOverThePointsInAnyPose) {
  const CohesiveParams law;
  Rng rng(5);
  int closed = 0;
  for (int k = 0; k < 200; ++k) {
    FacePair p = random_face_pair(rng);
    const BondMoments m = bond_moments(p.bond);
    EXPECT_LT(m.misfit, 1e-15);
    // Move b by a few micrometres and turn it by up to 1e-3 rad: below the onset (0.11 mm × 0.75).
    p.b.position += rng.uniform(Vec3(-3e-6, -3e-6, -3e-6), Vec3(3e-6, 3e-6, 3e-6));
    p.b.orientation =
        (rotation_quaternion(rng.uniform(Vec3(-1e-3, -1e-3, -1e-3), Vec3(1e-3, 1e-3, 1e-3))) *
         p.b.orientation)
            .normalized();
    BondWrench w;
    Bond copy = p.bond;
    const BondWrench want = bond_wrench(copy, law, p.a, p.b);
    if (elastic_bond_wrench(m, p.bond, law, p.a.position, p.a.orientation.toRotationMatrix(),
                            p.b.position, p.b.orientation.toRotationMatrix(), w)) {
      ++closed;
      expect_same_wrench(w, want);
    }
    for (const BondPoint& q : copy.points) EXPECT_EQ(q.state.damage, 0.0);
  }
  EXPECT_GT(closed, 150);  // the bound is not so loose that it rarely serves
}

TEST(BondMoments, NoClosedFormNearTheOnsetOrOnceDamaged) {
  const CohesiveParams law;
  Rng rng(9);
  FacePair p = random_face_pair(rng);
  BondWrench w;
  const auto closed = [&](const BondMoments& m) {
    return elastic_bond_wrench(m, p.bond, law, p.a.position, p.a.orientation.toRotationMatrix(),
                               p.b.position, p.b.orientation.toRotationMatrix(), w);
  };
  EXPECT_TRUE(closed(bond_moments(p.bond)));
  // Opened to 60 % of the smallest onset opening: a point may be damaged, the points decide.
  const double onset = p.bond.factor * std::min(law.sigma_n / law.kn, law.sigma_t / law.kt);
  const Vec3 n = p.a.orientation * p.bond.normal_in_a;
  p.b.position += 0.6 * onset * n;
  EXPECT_FALSE(closed(bond_moments(p.bond)));
  p.b.position -= 0.6 * onset * n;
  // A point damaged at all: never again in closed form.
  p.bond.points[3].state.damage = 1e-9;
  const BondMoments m = bond_moments(p.bond);
  EXPECT_FALSE(m.pristine);
  EXPECT_FALSE(closed(m));
  // A turn of the whole pair leaves the bound where it was.
  p.bond.points[3].state.damage = 0.0;
  const Eigen::Quaterniond q = rng.normal_quaternion().normalized();
  for (Body* body : {&p.a, &p.b}) {
    body->position = q * body->position;
    body->orientation = q * body->orientation;
  }
  EXPECT_TRUE(closed(bond_moments(p.bond)));
  EXPECT_LT(w.force_b.norm(), 1e-6);  // moved together: no force to rounding (N)
}
