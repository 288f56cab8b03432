// Shells of a mesh (geom/mesh/shells.h): components, winding numbers, nesting depth, and the
// orientation rules of one solid.
#include "geom/mesh/shells.h"

#include "geom/errors.h"
#include "geom/shapes/primitives.h"

#include <gtest/gtest.h>

using namespace clumpkit;

namespace {

// The shells of a and b in one mesh.
Mesh joined(Mesh a, const Mesh& b) {
  append_mesh(a, b);
  return a;
}

Mesh box_at(const Vec3& centre, double edge) {
  Mesh m = make_box(Vec3::Constant(edge));
  transform(m, Mat3::Identity(), centre);
  return m;
}

}  // namespace

TEST(Shells, WindingNumberIsOneInsideZeroOutsideAndSignedByOrientation) {
  Mesh ball = make_icosphere(2);
  std::vector<int> all(ball.triangles.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  EXPECT_NEAR(winding_number(ball, all, Vec3(0.1, -0.2, 0.3)), 1.0, 1e-9);
  EXPECT_NEAR(winding_number(ball, all, Vec3(1.5, 0, 0)), 0.0, 1e-9);
  flip_orientation(ball);
  EXPECT_NEAR(winding_number(ball, all, Vec3::Zero()), -1.0, 1e-9);
}

TEST(Shells, DepthAndParentOfNestedBoxes) {
  // Boxes of edge 6, 4 and 2 about the origin, and one of edge 1 far away; listed out of order.
  const Mesh m = joined(joined(box_at(Vec3::Zero(), 2), box_at(Vec3::Zero(), 6)),
                        joined(box_at(Vec3(10, 0, 0), 1), box_at(Vec3::Zero(), 4)));
  const std::vector<Shell> s = mesh_shells(m);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].depth, 2);  // edge 2: inside 4 and 6
  EXPECT_EQ(s[0].parent, 3);
  EXPECT_EQ(s[1].depth, 0);
  EXPECT_EQ(s[1].parent, -1);
  EXPECT_EQ(s[2].depth, 0);
  EXPECT_EQ(s[3].depth, 1);
  EXPECT_EQ(s[3].parent, 1);
  EXPECT_NEAR(s[1].volume, 216.0, 1e-9);
}

TEST(Shells, OrientationAlternatesWithDepthAndAnInwardOuterShellIsFlipped) {
  Mesh cavity = box_at(Vec3::Zero(), 2);
  flip_orientation(cavity);
  Mesh inward_outer = box_at(Vec3(10, 0, 0), 1);
  flip_orientation(inward_outer);
  Mesh m = joined(joined(box_at(Vec3::Zero(), 4), cavity), inward_outer);
  std::size_t count = 0;
  EXPECT_TRUE(orient_shells(m, &count));
  EXPECT_EQ(count, 3u);
  EXPECT_NEAR(signed_volume(m), 64.0 - 8.0 + 1.0, 1e-9);
  // An island in the cavity, facing outward, is a solid again.
  Mesh island = joined(m, box_at(Vec3::Zero(), 1));
  EXPECT_FALSE(orient_shells(island));
  EXPECT_NEAR(signed_volume(island), 64.0 - 8.0 + 1.0 + 1.0, 1e-9);
  // Facing inward, it is a void in a void: refused.
  Mesh wrong = box_at(Vec3::Zero(), 1);
  flip_orientation(wrong);
  Mesh bad = joined(m, wrong);
  EXPECT_THROW(orient_shells(bad), InvalidInput);
}
