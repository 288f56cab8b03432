// Golden state hashes: pin the bits of short falling-spheres, falling-clumps and settling runs,
// so a change that alters the engine's arithmetic fails here instead of being compared by hand.
//
// Re-baselining: a change that alters bits on purpose (a new contact law, another summation
// order, template mass properties) replaces the constants below in the same commit and says
// why in its message. Any other failure here is a regression.
#include "dem/core/pair_kernel.h"
#include "dem/core/state_hash.h"
#include "dem/core/world.h"
#include "geom/random.h"
#include "simd_off.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

constexpr double kD = 0.010;  // sphere diameter (m)

WorldOptions options() {
  WorldOptions o;
  o.timestep = 5e-6;
  o.skin = 0.002;
  o.contact.kn = 1e6;
  o.contact.ks = 1e6;
  o.contact.friction = 0.5;
  o.contact.damping_ratio = 0.3;
  o.contact.local_damping = 0.1;
  return o;
}

// A floor and a cylinder of radius 0.06 m; lattice points of spacing a inside r < 0.06 − a/2,
// z in [a/2, a/2 + layers·a], in lattice order.
World container() {
  World w(options());
  w.add_wall(Wall::plane(Vec3::Zero(), Vec3::UnitZ()));
  w.add_wall(Wall::cylinder(0.0, 0.0, 0.06));
  return w;
}

std::vector<Vec3> lattice(double a, int layers) {
  std::vector<Vec3> out;
  const double rc = 0.06 - 0.6 * a;
  for (int k = 0; k < layers; ++k)
    for (int j = -8; j <= 8; ++j)
      for (int i = -8; i <= 8; ++i) {
        const Vec3 p(i * a, j * a, (k + 0.5) * a + 0.001);
        if (p.x() * p.x() + p.y() * p.y() < rc * rc) out.push_back(p);
      }
  return out;
}

Vec3 jitter(Rng& rng, double speed) {
  return rng.uniform(Vec3::Constant(-speed), Vec3::Constant(speed));
}

World spheres(double spacing, int layers) {
  World w = container();
  Rng rng(11);
  for (const Vec3& p : lattice(spacing * kD, layers)) {
    Body b = make_sphere_body(p, 0.5 * kD * rng.uniform(0.8, 1.0), 2700.0);
    b.velocity = jitter(rng, 0.05);
    w.add_body(std::move(b));
  }
  return w;
}

// A fixed four-sphere clump in its principal frame with fixed mass properties (the engine's bits
// only, not the mass-property computation, are pinned here).
Body clump_prototype() {
  Body b;
  b.spheres = {{Vec3(-0.006, 0.0, 0.0), 0.004},
               {Vec3(0.005, 0.001, 0.0), 0.0045},
               {Vec3(0.0, -0.002, 0.003), 0.0035},
               {Vec3(0.001, 0.002, -0.002), 0.003}};
  b.mass = 1.1e-3;
  b.moments = Vec3(1.2e-8, 2.3e-8, 2.6e-8);
  return b;
}

World falling_clumps() {
  World w = container();
  Rng rng(12);
  const Body proto = clump_prototype();
  for (const Vec3& p : lattice(2.2 * kD, 8)) {
    Body b = proto;
    b.position = p;
    Eigen::Quaterniond q = rng.normal_quaternion();
    b.orientation = q.normalized();
    b.velocity = jitter(rng, 0.05);
    b.angular_velocity = jitter(rng, 5.0);
    w.add_body(std::move(b));
  }
  return w;
}

std::string hex(std::uint64_t h) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%016" PRIx64, h);
  return buf;
}

std::uint64_t run(World w, int steps, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  w.step(steps);
  return state_hash(w);
}

// The golden hashes of the short cases, which the SIMD checks below share.
constexpr const char* kFallingSpheres = "0xe569e55e0e76812c";
constexpr const char* kFallingClumps = "0x2c8f7b9e2b917e5f";
constexpr const char* kSmallSettlingSorted = "0x30140a5abf83cc3f";

// The small sorted settling packing of DemGolden.SmallSettlingPackingSorted, settled.
World small_settled_packing() {
  World w = spheres(1.02, 4);
  w.options().timestep = 1e-5;
  w.options().sort_every = 1000;
  w.step(25000);
  return w;
}

}  // namespace

TEST(DemGolden, FallingSpheres) {
  const World w = spheres(1.2, 20);
  ASSERT_GT(w.sphere_count(), 1000);
  const std::uint64_t one = run(w, 3000, 1);
  EXPECT_EQ(one, run(w, 3000, 2)) << "thread count changed the bits";
  EXPECT_EQ(hex(one), kFallingSpheres) << "golden hash of the falling spheres changed";
}

TEST(DemGolden, FallingClumps) {
  const World w = falling_clumps();
  ASSERT_GT(w.bodies().size(), 100u);
  const std::uint64_t one = run(w, 3000, 1);
  EXPECT_EQ(one, run(w, 3000, 2)) << "thread count changed the bits";
  EXPECT_EQ(hex(one), kFallingClumps) << "golden hash of the falling clumps changed";
}

// Dropped onto the floor and left to settle: a dense packing with thousands of sliding and
// rolling contacts, the regime of specimen building.
TEST(DemGolden, SettlingPacking) {
  World w = spheres(1.02, 16);
  w.options().timestep = 1e-5;
  w.step(40000);
  ASSERT_GT(w.contacts().size(), w.bodies().size());  // a packing, not a cloud
  const std::uint64_t one = run(w, 2000, 1);
  EXPECT_EQ(one, run(w, 2000, 2)) << "thread count changed the bits";
  EXPECT_EQ(hex(one), "0x974e4ad875cc4d47") << "golden hash of the settled packing changed";
}

// The same packing sorted spatially every 1,000 steps, as the specimen, compression and element
// test drivers run it (WorldOptions::sort_every): the bodies are summed in another order, so its
// bits are its own.
TEST(DemGolden, SettlingPackingSortedEvery1000Steps) {
  World w = spheres(1.02, 16);
  w.options().timestep = 1e-5;
  w.options().sort_every = 1000;
  w.step(40000);
  ASSERT_GT(w.contacts().size(), w.bodies().size());
  const std::uint64_t one = run(w, 2000, 1);
  EXPECT_EQ(one, run(w, 2000, 2)) << "thread count changed the bits";
  EXPECT_EQ(hex(one), "0x7c250dc5b7a4025b") << "golden hash of the sorted settled packing changed";
}

// The sorted settling packing in small (4 layers of the same container: a quarter of the bodies,
// 27,000 steps): the dense-contact kernels, sorting and the 2-thread split in seconds,
// for the sanitizer pass, which leaves the two above out (label long, tests/long_tests.cmake).
TEST(DemGolden, SmallSettlingPackingSorted) {
  const World w = small_settled_packing();
  ASSERT_GT(w.contacts().size(), w.bodies().size());
  const std::uint64_t one = run(w, 2000, 1);
  EXPECT_EQ(one, run(w, 2000, 2)) << "thread count changed the bits";
  EXPECT_EQ(hex(one), kSmallSettlingSorted) << "golden hash of the small sorted packing changed";
}

// The small packing with its bodies in a random order: the contact pass runs in several chunks
// of bodies with most pairs deferred (j beyond the next chunk, World's StepCache::pair_wrench_),
// so each body's sum mixes the kernel's additions and the deferred ones; the bits must still be
// the same for 1 and 2 threads and with SIMD off, and the forces those of the sorted order.
TEST(DemGolden, ShuffledPackingSumsTheSameOnAnyThreadsAndWithSimdOff) {
  const World settled = small_settled_packing();
  World w(settled.options());
  w.options().sort_every = 0;
  for (const Wall& wall : settled.walls()) w.add_wall(wall);
  std::vector<std::size_t> order(settled.bodies().size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  Rng rng(11);
  for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[rng.below(k)]);
  for (std::size_t k : order) w.add_body(settled.bodies()[k]);
  ASSERT_GE(w.sphere_count(), 256);  // at least two chunks of 128 spheres
  const std::uint64_t one = run(w, 300, 1);
  EXPECT_EQ(one, run(w, 300, 2)) << "thread count changed the bits";
  {
    SimdOff off;
    EXPECT_EQ(one, run(w, 300, 1)) << "SIMD changed the bits";
  }
  // The order changes the sums' rounding only: one step of either order gives every body the
  // same force and torque to rounding (the shear histories, dropped by add_body, start from
  // zero in both).
  World a(settled.options()), b = w;
  a.options().sort_every = 0;
  for (const Wall& wall : settled.walls()) a.add_wall(wall);
  for (const Body& body : settled.bodies()) a.add_body(body);
  a.step(1);
  b.step(1);
  double scale = 0.0;
  for (const Body& body : a.bodies()) scale = std::max(scale, body.force.norm());
  ASSERT_GT(scale, 0.0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Body& x = a.bodies()[order[k]];
    const Body& y = b.bodies()[k];
    EXPECT_LT((x.force - y.force).norm(), 1e-12 * scale) << "body " << order[k];
    EXPECT_LT((x.torque - y.torque).norm(), 1e-12 * scale * kD) << "body " << order[k];
  }
}

// The cases above run the pair kernel in SIMD (on this CPU's best instruction set); its scalar
// reference gives the same bits (dem/core/pair_kernel.h).
TEST(DemGolden, ShortCasesWithSimdOffGiveTheSameBits) {
  SimdOff off;
  EXPECT_EQ(hex(run(spheres(1.2, 20), 3000, 1)), kFallingSpheres);
  EXPECT_EQ(hex(run(falling_clumps(), 3000, 1)), kFallingClumps);
  EXPECT_EQ(hex(run(small_settled_packing(), 2000, 2)), kSmallSettlingSorted);
}

// Every instruction set compiled and supported here (AVX-512, AVX2, SSE4 and Highway's portable
// fallback on an AVX-512 machine), from the settle on.
TEST(DemGolden, SmallSettlingPackingOnEveryInstructionSet) {
  int sets = 0;
  for_each_simd_target([&](const char* name) {
    EXPECT_EQ(hex(run(small_settled_packing(), 2000, 2)), kSmallSettlingSorted) << name;
    ++sets;
  });
  EXPECT_GE(sets, 1);
}
