// Neighbour search and contact bookkeeping of dem::World against brute force, and the
// invariance of results under the Verlet skin (a pure performance setting).
#include "dem/core/world.h"
#include "dem/core/state_hash.h"
#include "geom/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <set>
#include <utility>
#include <vector>

namespace clumpkit::dem {
namespace {

// Gravity, μ = 0.5, damping ratio 0.3, kn = ks = `stiffness` (N/m).
WorldOptions cloud_options(double timestep, double stiffness, double skin) {
  WorldOptions o;
  o.timestep = timestep;
  o.skin = skin;
  o.contact.kn = stiffness;
  o.contact.ks = stiffness;
  o.contact.friction = 0.5;
  o.contact.damping_ratio = 0.3;
  return o;
}

// `count` spheres with radii in [r_min, r_max), centres within ±spread of c on each axis.
Clump random_clump(Rng& rng, const Vec3& c, int count, double spread, double r_min, double r_max) {
  Clump clump;
  for (int s = 0; s < count; ++s)
    clump.spheres.push_back(Sphere{c + rng.uniform(Vec3::Constant(-spread), Vec3::Constant(spread)),
                                   rng.uniform(r_min, r_max)});
  return clump;
}

// A polydisperse cloud like a soil–rock mixture: many small spheres, some large ones and a few
// clumps of unequal spheres (radii 0.6–30 mm), packed so that many pairs overlap.
World mixed_cloud(double skin, std::uint64_t seed) {
  World world(cloud_options(2e-6, 1e5, skin));
  Rng rng(seed);
  const double box = 0.12;
  auto point = [&] { return rng.uniform(Vec3::Constant(0.0), Vec3::Constant(box)); };
  for (int k = 0; k < 900; ++k) {
    const double r = k % 30 == 0 ? rng.uniform(0.01, 0.03) : rng.uniform(0.0006, 0.006);
    Body b = make_sphere_body(point(), r, 2650.0);
    b.velocity = rng.uniform(Vec3::Constant(-0.2), Vec3::Constant(0.2));
    world.add_body(b);
  }
  for (int k = 0; k < 40; ++k) {
    const Vec3 c = point();
    const Clump clump = random_clump(rng, c, 5, 0.008, 0.002, 0.009);
    world.add_body(make_clump_body(clump, 2800.0));
  }
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  return world;
}

std::set<std::pair<int, int>> touching_pairs(const World& w) {
  std::vector<Vec3> x;
  std::vector<double> r;
  for (const Body& b : w.bodies())
    for (const Sphere& s : b.spheres) {
      x.push_back(b.position + b.orientation * s.center);
      r.push_back(s.radius);
    }
  std::set<std::pair<int, int>> out;
  for (int i = 0; i < static_cast<int>(x.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(x.size()); ++j)
      if (w.sphere_body(i) != w.sphere_body(j) && (x[j] - x[i]).norm() < r[i] + r[j])
        out.insert({i, j});
  return out;
}

TEST(DemWorld, ContactsAreExactlyTheTouchingPairsOfAPolydisperseCloud) {
  World w = mixed_cloud(0.001, 3);
  // Positions before the step: the contact list reports the pairs touching at that step.
  const std::set<std::pair<int, int>> expected = touching_pairs(w);
  w.step(1);
  std::set<std::pair<int, int>> got;
  for (const PairContact& c : w.contacts()) got.insert({c.i, c.j});
  EXPECT_GT(expected.size(), 200u);
  EXPECT_EQ(got, expected);
  // After many steps, with neighbour rebuilds on the way.
  w.step(400);
  const std::set<std::pair<int, int>> later = touching_pairs(w);  // at the next step's positions
  w.step(1);
  got.clear();
  for (const PairContact& c : w.contacts()) got.insert({c.i, c.j});
  EXPECT_GT(w.neighbour_builds(), 2);
  EXPECT_EQ(got, later);
}

// Spheres (radii 1.5–6 mm, a few of 10–20 mm) and clumps placed without overlap in a box, moving
// at up to 0.5 m/s under gravity: they collide at moderate speeds and settle on the floor.
World gentle_cloud(double skin, std::uint64_t seed) {
  World world(cloud_options(1e-5, 1e4, skin));
  Rng rng(seed);
  std::vector<Sphere> placed;
  auto free = [&](const std::vector<Sphere>& spheres) {
    for (const Sphere& a : spheres) {
      if (a.center.z() < a.radius) return false;
      for (const Sphere& b : placed)
        if ((a.center - b.center).norm() < a.radius + b.radius) return false;
    }
    return true;
  };
  auto velocity = [&] { return rng.uniform(Vec3::Constant(-0.5), Vec3(0.5, 0.5, 0.0)); };
  auto point = [&] { return rng.uniform(Vec3::Constant(0.0), Vec3(0.15, 0.15, 0.06)); };
  for (int k = 0; k < 500;) {
    const double r = k < 12 ? rng.uniform(0.01, 0.02) : rng.uniform(0.0015, 0.006);
    const Sphere s{point(), r};
    if (!free({s})) continue;
    placed.push_back(s);
    Body b = make_sphere_body(s.center, r, 2650.0);
    b.velocity = velocity();
    world.add_body(b);
    ++k;
  }
  for (int k = 0; k < 25;) {
    const Vec3 c = point();
    const Clump clump = random_clump(rng, c, 4, 0.006, 0.003, 0.007);
    if (!free(clump.spheres)) continue;
    placed.insert(placed.end(), clump.spheres.begin(), clump.spheres.end());
    Body b = make_clump_body(clump, 2800.0);
    b.velocity = velocity();
    world.add_body(b);
    ++k;
  }
  world.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  return world;
}

TEST(DemWorld, ResultsDoNotDependOnTheVerletSkin) {
  // Candidates beyond touching never contribute, and every body sums its touching contacts in
  // the same order, so the skin changes only how often the list is rebuilt.
  World thin = gentle_cloud(0.0002, 5);
  World thick = gentle_cloud(0.004, 5);
  thin.step(8000);
  thick.step(8000);
  EXPECT_GT(thin.neighbour_builds(), 2 * thick.neighbour_builds());
  EXPECT_GT(thin.contacts().size(), 20u);
  EXPECT_EQ(state_hash(thin), state_hash(thick));
}

TEST(DemWorld, ResultsDoNotDependOnTheNearList) {
  // The near list keeps the skin-list pairs that can touch before its next filter, so it changes
  // only how many candidates the contact pass scans.
  World one = gentle_cloud(0.004, 5);
  World two = gentle_cloud(0.004, 5);
  one.options().near_skin_fraction = 1.0;
  two.options().near_skin_fraction = 0.05;
  one.step(8000);
  two.step(8000);
  EXPECT_EQ(one.near_filters(), one.neighbour_builds());  // one list: every filter is a build
  EXPECT_GT(two.near_filters(), 4 * two.neighbour_builds());
  EXPECT_GT(two.contacts().size(), 20u);
  EXPECT_EQ(state_hash(one), state_hash(two));
}

// A lattice strained at a constant rate, every sphere moving with the strain (no contacts, no
// gravity): measured from the cell's stretch, nobody moves, so the first search is the only one.
TEST(DemWorld, AnAffinelyStrainedCellIsNotSearchedAgain) {
  auto lattice = [](bool framed) {
    WorldOptions o = cloud_options(1e-4, 1e5, 0.0002);
    o.gravity = Vec3::Zero();
    World world(o);
    const double rate = 0.5, spacing = 0.0025;  // 1/s; 0.5 mm between surfaces
    const Vec3 centre = Vec3::Constant(4.5 * spacing);
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j)
        for (int k = 0; k < 10; ++k) {
          Body b = make_sphere_body(Vec3(i, j, k) * spacing, 0.001, 2650.0);
          b.velocity = -rate * Vec3(0.0, 0.0, b.position.z() - centre.z());
          world.add_body(b);
        }
    const double h0 = 10 * spacing;
    for (int s = 0; s < 1000; ++s) {  // 5 % axial strain
      if (framed) world.set_cell_frame(centre, Vec3(h0, h0, h0 * (1.0 - rate * world.time())));
      world.step(1);
    }
    EXPECT_TRUE(world.contacts().empty());
    return world;
  };
  const World plain = lattice(false), framed = lattice(true);
  EXPECT_GE(plain.neighbour_builds(), 5);
  EXPECT_EQ(framed.neighbour_builds(), 1);
  EXPECT_EQ(state_hash(plain), state_hash(framed));
}

// The cell frame only says when to search again: a top platen closing on a settling cloud gives
// the same run to the bit with no frame, the platens' frame, or a frame that strains the wrong
// way about the wrong centre (the lists' bound holds for any affine map).
TEST(DemWorld, ResultsDoNotDependOnTheCellFrame) {
  auto run = [](int frame) {
    World world = gentle_cloud(0.0005, 5);
    const int top = world.add_wall(Wall::plane(Vec3(0, 0, 0.09), -Vec3::UnitZ()));
    world.walls()[top].velocity = Vec3(0, 0, -0.3);
    for (int s = 0; s < 6000; ++s) {
      const double h = world.walls()[top].point.z();
      if (frame == 1) world.set_cell_frame(Vec3(0.075, 0.075, 0.5 * h), Vec3(0.15, 0.15, h));
      if (frame == 2) world.set_cell_frame(Vec3(0.3, -0.1, h), Vec3(0.15 / h, 0.15, 0.05 + h));
      world.step(1);
    }
    return world;
  };
  const World none = run(0), platens = run(1), wrong = run(2);
  EXPECT_GT(none.wall_contacts().size(), 20u);
  EXPECT_GT(none.contacts().size(), 20u);
  EXPECT_EQ(state_hash(none), state_hash(platens));
  EXPECT_EQ(state_hash(none), state_hash(wrong));
  EXPECT_NE(none.neighbour_builds(), wrong.neighbour_builds());
}

TEST(DemWorld, ContactListsAskedForOrNotChangeNothing) {
  // contacts() writes the lists from the engine's slots when first asked for after a step: asking
  // after every call, or never, gives the same run to the bit.
  World asked = gentle_cloud(0.002, 7);
  World quiet = gentle_cloud(0.002, 7);
  std::size_t seen = 0;
  for (int call = 0; call < 40; ++call) {
    asked.step(200);
    quiet.step(200);
    seen = std::max(seen, asked.contacts().size());
  }
  EXPECT_GT(seen, 20u);
  EXPECT_EQ(state_hash(asked), state_hash(quiet));
}

TEST(DemWorld, EditsBetweenCallsKeepTheContactHistory) {
  // An edit that drops the slots (a body or a bond added, μ rescaled) first hands their history
  // to the lists: the lists read after the edit are those read before it, to the bit.
  World w = gentle_cloud(0.002, 7);
  w.step(4000);
  const std::vector<PairContact> before = w.contacts();
  ASSERT_GT(before.size(), 20u);
  World edited = w;
  edited.add_body(make_sphere_body(Vec3(5.0, 5.0, 5.0), 0.003, 2650.0));  // far from the rest
  ASSERT_EQ(edited.contacts().size(), before.size());
  EXPECT_EQ(
      std::memcmp(edited.contacts().data(), before.data(), before.size() * sizeof(PairContact)), 0);
  World rescaled = w;
  rescaled.rescale_friction(10.0);  // a larger μ clamps nothing
  ASSERT_EQ(rescaled.contacts().size(), before.size());
  EXPECT_EQ(
      std::memcmp(rescaled.contacts().data(), before.data(), before.size() * sizeof(PairContact)),
      0);
  // And the run goes on from them as if nothing had happened to the slots (the same μ set
  // without the clamp, which keeps the slots).
  World carried = w;
  carried.options().contact.friction = 10.0;
  rescaled.step(500);
  carried.step(500);
  EXPECT_EQ(state_hash(rescaled), state_hash(carried));
}

}  // namespace
}  // namespace clumpkit::dem
