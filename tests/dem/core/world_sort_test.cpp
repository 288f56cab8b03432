// World::sort_bodies and WorldOptions::sort_every: the spatial order is a renumbering only —
// every body, contact and force travels with it — and a sorting run is still the same on any
// number of threads.
#include "dem/core/state_hash.h"
#include "dem/core/world.h"
#include "geom/errors.h"
#include "geom/random.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <tuple>
#include <vector>

namespace clumpkit::dem {
namespace {

// 700 spheres (radii 2–5 mm) and 20 three-sphere clumps dropped in random order into a box of
// 8 cm with a floor, under gravity with friction and damping: after 10,000 steps a heap with
// hundreds of contacts carrying shear history, its bodies far from any spatial order.
World heap(int sort_every) {
  WorldOptions o;
  o.timestep = 4e-5;  // 0.3 of the smallest sphere's critical step
  o.skin = 0.001;
  o.sort_every = sort_every;
  o.contact.kn = o.contact.ks = 2e4;
  o.contact.friction = 0.5;
  o.contact.damping_ratio = 0.3;
  World w(o);
  Rng rng(77);
  auto point = [&] { return rng.uniform(Vec3(0.0, 0.0, 0.005), Vec3(0.08, 0.08, 0.10)); };
  for (int k = 0; k < 720; ++k) {
    if (k % 36 == 0) {
      const Vec3 c = point();
      Clump clump{{Sphere{c, 0.004}, Sphere{c + Vec3(0.004, 0, 0), 0.003},
                   Sphere{c + Vec3(0, 0.003, 0.002), 0.0035}}};
      w.add_body(make_clump_body(clump, 2650.0));
    } else {
      Body b = make_sphere_body(point(), rng.uniform(0.002, 0.005), 2650.0);
      const double vy = rng.uniform(-0.2, 0.2);  // y before x, as GCC drew them (Rng::uniform)
      b.velocity = Vec3(rng.uniform(-0.2, 0.2), vy, -0.5);
      w.add_body(std::move(b));
    }
  }
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  w.add_wall(Wall::plane(Vec3(-0.01, 0, 0), Vec3::UnitX()));
  w.add_wall(Wall::plane(Vec3(0.09, 0, 0), -Vec3::UnitX()));
  w.add_wall(Wall::plane(Vec3(0, -0.01, 0), Vec3::UnitY()));
  w.add_wall(Wall::plane(Vec3(0, 0.09, 0), -Vec3::UnitY()));
  return w;
}

// Bodies are identified across a renumbering by their exact position (all distinct here).
using Key = std::tuple<double, double, double>;
Key key_of(const Body& b) {
  return {b.position.x(), b.position.y(), b.position.z()};
}

double max_force(const World& w) {
  double m = 0;
  for (const Body& b : w.bodies()) m = std::max(m, b.force.norm());
  return m;
}

TEST(DemWorldSort, RenumbersBodiesContactsAndHistoriesWithoutChangingAnyForce) {
  World w = heap(0);
  // Under the sanitizers the heap of 5,000 steps (390 contacts; 797 after 10,000, 297 after
  // 4,000): the same checks in half the steps. The Release pass steps 10,000.
  w.step(kSanitized ? 5000 : 10000);
  ASSERT_GT(w.contacts().size(), 300u);
  ASSERT_GT(w.wall_contacts().size(), 50u);
  World sorted = w;
  ASSERT_TRUE(sorted.sort_bodies());
  EXPECT_FALSE(sorted.sort_bodies()) << "a sorted world sorts to itself";

  // The same bodies, in bins of the largest diameter: z, then y, then x, non-decreasing.
  ASSERT_EQ(sorted.bodies().size(), w.bodies().size());
  std::map<Key, int> old_index;
  for (std::size_t k = 0; k < w.bodies().size(); ++k) old_index[key_of(w.bodies()[k])] = int(k);
  ASSERT_EQ(old_index.size(), w.bodies().size());
  Vec3 lo = Vec3::Constant(1e300);
  for (const Body& b : w.bodies()) lo = lo.cwiseMin(b.position);
  double r_max = 0;
  for (const Body& b : w.bodies())
    for (const Sphere& s : b.spheres) r_max = std::max(r_max, s.radius);
  const double bin = 2 * r_max;
  std::vector<int> to_old;
  std::tuple<long, long, long> previous{-1, -1, -1};
  int moved = 0;
  for (std::size_t k = 0; k < sorted.bodies().size(); ++k) {
    const Body& b = sorted.bodies()[k];
    const auto found = old_index.find(key_of(b));
    ASSERT_NE(found, old_index.end());
    to_old.push_back(found->second);
    moved += found->second != int(k);
    EXPECT_TRUE(std::memcmp(&b.velocity, &w.bodies()[found->second].velocity, sizeof(Vec3)) == 0);
    const Vec3 d = (b.position - lo) / bin;
    const std::tuple<long, long, long> cell{long(std::floor(d.z())), long(std::floor(d.y())),
                                            long(std::floor(d.x()))};
    EXPECT_LE(previous, cell) << "body " << k;
    previous = cell;
  }
  EXPECT_GT(moved, 600);

  // Every contact is there, between the same bodies, with its history (the sign follows i < j).
  ASSERT_EQ(sorted.contacts().size(), w.contacts().size());
  // A sphere is (old body index, its place in the body): spheres are numbered body by body.
  auto first_spheres = [](const World& x) {
    std::vector<int> first(x.bodies().size(), -1);
    for (int s = x.sphere_count() - 1; s >= 0; --s) first[x.sphere_body(s)] = s;
    return first;
  };
  const std::vector<int> first_w = first_spheres(w), first_s = first_spheres(sorted);
  using SphereId = std::pair<int, int>;
  auto id_w = [&](int s) { return SphereId{w.sphere_body(s), s - first_w[w.sphere_body(s)]}; };
  auto id_s = [&](int s) {
    const int b = sorted.sphere_body(s);
    return SphereId{to_old[b], s - first_s[b]};
  };
  std::map<std::pair<SphereId, SphereId>, const PairContact*> by_spheres;
  for (const PairContact& c : w.contacts()) by_spheres[{id_w(c.i), id_w(c.j)}] = &c;
  ASSERT_EQ(by_spheres.size(), w.contacts().size());
  int swapped = 0;
  for (const PairContact& c : sorted.contacts()) {
    ASSERT_LT(c.i, c.j);
    auto it = by_spheres.find({id_s(c.i), id_s(c.j)});
    double sign = 1;
    if (it == by_spheres.end()) it = by_spheres.find({id_s(c.j), id_s(c.i)}), sign = -1, ++swapped;
    ASSERT_NE(it, by_spheres.end());
    EXPECT_EQ(c.state.normal_force, it->second->state.normal_force);
    EXPECT_EQ(c.state.shear, sign * it->second->state.shear);
    EXPECT_EQ(c.state.normal, sign * it->second->state.normal);
  }
  EXPECT_GT(swapped, 10);
  ASSERT_EQ(sorted.wall_contacts().size(), w.wall_contacts().size());

  // One step on: each body feels the same force, up to the rounding of summing its contacts in
  // another order.
  World plain = w;
  plain.step(1);
  sorted.step(1);
  const double scale = max_force(plain);
  ASSERT_GT(scale, 0);
  ASSERT_EQ(sorted.contacts().size(), plain.contacts().size());
  for (std::size_t k = 0; k < sorted.bodies().size(); ++k) {
    const Body& a = sorted.bodies()[k];
    const Body& b = plain.bodies()[to_old[k]];
    EXPECT_LT((a.force - b.force).norm(), 1e-12 * scale) << "body " << k;
    EXPECT_LT((a.position - b.position).norm(), 1e-15) << "body " << k;
  }
}

std::uint64_t run(World w, int steps, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  w.step(steps);
  return state_hash(w);
}

TEST(DemWorldSort, SortingEveryFewStepsIsTheSameOnOneAndTwoThreadsAndAcrossCalls) {
  const World w = heap(250);
  const std::uint64_t one = run(w, 1200, 1);
  EXPECT_EQ(one, run(w, 1200, 2));
  // Sorting happens at steps that are multiples of sort_every, whatever the call boundaries.
  World pieces = w;
  for (int k = 0; k < 12; ++k) pieces.step(k % 2 ? 130 : 70);
  EXPECT_EQ(pieces.steps(), 1200);
  EXPECT_EQ(state_hash(pieces), one);
  // And it did reorder: the unsorted run ends with the bodies in another order.
  World unsorted = heap(0);
  unsorted.step(1200);
  int differ = 0;
  World sorted_run = w;
  sorted_run.step(1200);
  for (std::size_t k = 0; k < w.bodies().size(); ++k)
    differ += sorted_run.bodies()[k].mass != unsorted.bodies()[k].mass;
  EXPECT_GT(differ, 100);
}

TEST(DemWorldSort, NegativeIntervalIsRefused) {
  WorldOptions o;
  o.sort_every = -1;
  EXPECT_THROW(World{o}, InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
