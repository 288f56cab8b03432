// Polyhedral bodies on plane walls: a corner spring per corner below the plane, friction with
// history, the wrench about the centroid; spheres of such a body leave plane walls alone.
#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

constexpr double kEdge = 0.01;  // m: cube edge

// A cube of edge a with its inscribed sphere for contacts with bodies and its eight corners for
// plane walls, centred at `at`.
Body cube(const Vec3& at) {
  Body b;
  b.spheres = {Sphere{Vec3::Zero(), 0.5 * kEdge}};
  b.volume = kEdge * kEdge * kEdge;
  b.mass = 2650 * b.volume;
  b.moments = Vec3::Constant(b.mass * kEdge * kEdge / 6.0);
  for (int i = 0; i < 8; ++i)
    b.vertices.emplace_back(i & 1 ? 0.5 * kEdge : -0.5 * kEdge, i & 2 ? 0.5 * kEdge : -0.5 * kEdge,
                            i & 4 ? 0.5 * kEdge : -0.5 * kEdge);
  b.position = at;
  return b;
}

WorldOptions vertex_options() {
  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.vertex_stiffness = 1e8;
  o.contact.friction = 0.3;
  o.timestep = 1e-8;
  return o;
}

}  // namespace

TEST(VertexContacts, FlatFaceOnAPlatenCarriesFourCornerSprings) {
  World w(vertex_options());
  const double delta = 1e-6;
  w.add_body(cube(Vec3(0, 0, 0.5 * kEdge - delta)));
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  w.step(1);
  ASSERT_EQ(w.vertex_contacts().size(), 4u);  // the bottom face's corners
  EXPECT_TRUE(w.wall_contacts().empty());     // not the sphere (it touches the floor too)
  const Body& b = w.bodies()[0];
  EXPECT_NEAR(b.force.z() / (4 * 1e8 * delta), 1.0, 1e-6);
  EXPECT_LT(b.force.head<2>().norm(), 1e-9);
  EXPECT_LT(b.torque.norm(), 1e-12);
  for (const VertexContact& c : w.vertex_contacts()) EXPECT_EQ(c.wall, 0);
}

TEST(VertexContacts, ACornerPushesAtTheCornerAndSlidesAtCoulomb) {
  // Tilted 45° about x and about y: one corner lowest; pressed into the floor by δ.
  World w(vertex_options());
  Body b = cube(Vec3::Zero());
  b.orientation = Eigen::AngleAxisd(0.3, Vec3::UnitX()) * Eigen::AngleAxisd(0.4, Vec3::UnitY());
  double lowest = 0;
  Vec3 corner;
  for (const Vec3& v : b.vertices)
    if ((b.orientation * v).z() < lowest)
      lowest = (b.orientation * v).z(), corner = b.orientation * v;
  const double delta = 2e-6;
  b.position = Vec3(0, 0, -lowest - delta);
  b.velocity = Vec3(0.1, 0, 0);  // sliding along x
  b.mass *= 1e9;                 // heavy: it keeps its pose while the springs load
  b.moments *= 1e9;
  w.add_body(b);
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  w.step(1);
  ASSERT_EQ(w.vertex_contacts().size(), 1u);
  const Body& out = w.bodies()[0];
  const double fn = 1e8 * delta;
  EXPECT_NEAR(out.force.z() / fn, 1.0, 1e-3);
  // After some sliding the shear spring reaches the Coulomb limit μ·Fn, against the motion.
  w.bodies()[0].velocity = Vec3(0.1, 0, 0);
  w.step(5000);
  const VertexContact& c = w.vertex_contacts()[0];
  EXPECT_NEAR(c.state.shear.norm() / (0.3 * c.state.normal_force), 1.0, 1e-9);
  EXPECT_LT(c.state.shear.x(), 0.0);
  // The wrench acts at the corner: torque = (corner − centroid) × F (the centroid of that step).
  const Body& now = w.bodies()[0];
  const Vec3 f = c.state.force();
  const Vec3 before = now.position - now.velocity * w.options().timestep;
  EXPECT_LT((now.torque - (c.state.point - before).cross(f)).norm(), 1e-9 * f.norm() * kEdge);
  // A corner that leaves the wall leaves the list.
  w.bodies()[0].position.z() += 1e-3;
  w.step(1);
  EXPECT_TRUE(w.vertex_contacts().empty());
  EXPECT_EQ(w.bodies()[0].force, Vec3::Zero());
}

TEST(VertexContacts, CornersEnterTheTimeStepAndLeverArm) {
  World w(vertex_options());
  w.add_body(cube(Vec3::Zero()));
  const Body& b = w.bodies()[0];
  // Rotation about x: the corner arm √2·a/2 beyond the sphere's a/2, and 2 corner springs.
  const double k = w.options().contact.kn + 2e8;
  const double arm = std::sqrt(2.0) * 0.5 * kEdge;
  EXPECT_NEAR(critical_timestep(w), std::sqrt(b.moments.x() / (k * arm * arm)), 1e-15);
  std::vector<VertexContact> bad(1);
  bad[0].vertex = 8;
  EXPECT_THROW(w.restore_vertex_contacts(bad), InvalidInput);
}
