// Fragments as sieved pieces: a bonded block of unit spheres measures its own extents, whatever
// its pose, and falls into pieces of one sphere each when its bonds fail.
#include "dem/measure/fragment_sizes.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// 3 × 2 × 1 bodies of one sphere (radius 0.5, unit spacing), turned by q about the origin and
// shifted by t, each bonded to its +x and +y neighbours (a bond holds while one point holds).
struct Block {
  std::vector<Body> bodies;
  std::vector<Bond> bonds;
};

Block block(const Eigen::Quaterniond& q, const Vec3& t) {
  Block b;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      Body body;
      body.spheres = {Sphere{Vec3::Zero(), 0.5}};
      body.mass = 1.0;
      body.volume = M_PI / 6;
      body.moments = Vec3::Constant(0.1);
      body.position = q * Vec3(i, j, 0) + t;
      body.orientation = q;
      b.bodies.push_back(body);
    }
  auto bond = [&](int a, int c) {
    Bond x;
    x.a = a;
    x.b = c;
    x.points.resize(1);
    b.bonds.push_back(x);
  };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i < 2) bond(3 * j + i, 3 * j + i + 1);
      if (j < 1) bond(3 * j + i, 3 * j + i + 3);
    }
  return b;
}

}  // namespace

TEST(FragmentSizes, ABondedBlockMeasuresItsExtentsInAnyPose) {
  for (const Eigen::Quaterniond& q :
       {Eigen::Quaterniond::Identity(),
        Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))}) {
    const Block b = block(q, Vec3(5, -2, 7));
    const Vec3 e = fragment_extents(b.bodies, {0, 1, 2, 3, 4, 5});
    EXPECT_NEAR(e[0], 3.0, 1e-12);
    EXPECT_NEAR(e[1], 2.0, 1e-12);
    EXPECT_NEAR(e[2], 1.0, 1e-12);
    const std::vector<SievedPiece> pieces = fragment_pieces(b.bodies, b.bonds);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_NEAR(pieces[0].volume, M_PI, 1e-14);  // six bodies' volumes: nothing lost
    EXPECT_NEAR(pieces[0].size, 2.0, 1e-12);
  }
}

TEST(FragmentSizes, BrokenBondsLeavePiecesOfOneBodyEach) {
  Block b = block(Eigen::Quaterniond::Identity(), Vec3::Zero());
  // Cut the row j = 1 off: the bonds across y fail.
  for (Bond& x : b.bonds)
    if (x.b - x.a == 3) x.points[0].state.damage = 1.0;
  std::vector<SievedPiece> pieces = fragment_pieces(b.bodies, b.bonds);
  ASSERT_EQ(pieces.size(), 2u);
  for (const SievedPiece& p : pieces) {
    EXPECT_NEAR(p.volume, M_PI / 2, 1e-14);
    EXPECT_NEAR(p.size, 1.0, 1e-12);  // a row of three: 3 × 1 × 1
  }
  for (Bond& x : b.bonds) x.points[0].state.damage = 1.0;
  pieces = fragment_pieces(b.bodies, b.bonds);
  ASSERT_EQ(pieces.size(), 6u);
  double volume = 0;
  for (const SievedPiece& p : pieces) volume += p.volume;
  EXPECT_NEAR(volume, M_PI, 1e-14);
  b.bodies[2].volume = 0;
  EXPECT_THROW(fragment_pieces(b.bodies, b.bonds), InvalidInput);
}
