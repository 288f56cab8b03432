// The pair-contact kernel: its scalar reference against the contact law of dem/core/contact.h
// (update_contact_force) evaluated one contact at a time, with the wrenches it adds to the
// bodies in candidate order (some pairs deferred), and every SIMD instruction set this CPU runs
// against the reference, bit for bit, on contacts that start, stick, slip, part, share a centre,
// carry size-scaled stiffness and excuse part of their overlap (a bond that broke).
#include "dem/core/pair_kernel.h"

#include "dem/core/contact.h"
#include "geom/random.h"
#include "simd_off.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace clumpkit;
using namespace clumpkit::dem;
using namespace clumpkit::dem::detail;

namespace {

// A cloud of spheres in a small box (two per body, so a body meets several others), every pair
// within reach a candidate, and slots in every state: new, carried with a shear inside the
// Coulomb limit, carried with one far beyond it (slip), and inactive.
struct Scene {
  std::vector<std::pair<int, int>> candidates;
  std::vector<Vec3> world;
  std::vector<double> radius;
  std::vector<int> body;
  std::vector<std::int64_t> body64;
  std::vector<Kinematics> kinematics;
  std::vector<double> damping, stiffness;
  std::vector<SlotForce> force;
  std::vector<double> excused;
  std::vector<std::uint8_t> active;
  std::vector<Wrench> wrench;  // per body
  std::vector<std::size_t> deferred_candidates;
  std::vector<Wrench> deferred;
  bool scaled = false;
  bool excusing = false;

  PairKernelArgs args() {
    return PairKernelArgs{candidates.data(),
                          world.data(),
                          radius.data(),
                          body.data(),
                          body64.data(),
                          kinematics.data(),
                          damping.data(),
                          scaled ? stiffness.data() : nullptr,
                          2e5,
                          1.5e5,
                          0.4,
                          1e-5,
                          force.data(),
                          excusing ? excused.data() : nullptr,
                          active.data(),
                          wrench.data(),
                          deferred_candidates.data(),
                          deferred_candidates.size(),
                          deferred.data()};
  }
};

Scene scene(std::uint64_t seed, bool scaled, bool excusing = false) {
  Scene s;
  s.scaled = scaled;
  s.excusing = excusing;
  Rng rng(seed);
  const int n = 150;
  for (int k = 0; k < n; ++k) {
    s.world.push_back(rng.uniform(Vec3::Zero(), Vec3::Constant(3.0)));
    s.radius.push_back(rng.uniform(0.3, 0.6));
    s.body.push_back(k / 2);
    s.body64.push_back(k / 2);
  }
  s.world[1] = s.world[0];  // two centres at one point: the normal falls back to +z
  for (int b = 0; b < n / 2; ++b)
    s.kinematics.push_back(Kinematics{rng.uniform(Vec3::Zero(), Vec3::Constant(3.0)),
                                      rng.uniform(Vec3::Constant(-1.0), Vec3::Constant(1.0)),
                                      rng.uniform(Vec3::Constant(-5.0), Vec3::Constant(5.0)),
                                      rng.uniform(0.5, 2.0)});
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if ((s.world[j] - s.world[i]).norm() < s.radius[i] + s.radius[j] + 0.2)
        s.candidates.emplace_back(i, j);
  const std::size_t m = s.candidates.size();
  for (std::size_t k = 0; k < m; ++k) {
    s.damping.push_back(rng.uniform(0.0, 50.0));
    s.stiffness.push_back(rng.uniform(0.5, 2.0));
    // Shears up to 3e4 N against normal forces of order kn·δ ≈ 2e4 N·μ: some slots slip.
    const double size = rng.below(4) == 0 ? 0.0 : rng.uniform(0.0, 3e4);
    s.force.push_back(SlotForce{size * rng.uniform(Vec3::Constant(-1.0), Vec3::Constant(1.0)),
                                rng.uniform(0.0, 1e4)});
    s.active.push_back(rng.below(2) ? 1 : 0);
    if (rng.below(5) == 0) {  // a fifth of the pairs deferred, their slots holding old values
      s.deferred_candidates.push_back(k);
      s.deferred.push_back(Wrench{rng.uniform(Vec3::Zero(), Vec3::Ones()), Vec3::Ones()});
    }
  }
  // Excused overlaps from their own stream (the scenes above stay as they were): a third none,
  // the rest up to 0.3 (overlaps here reach 1.2), so that some lie above this step's overlap.
  Rng excuses(seed + 1000);
  for (std::size_t k = 0; k < m; ++k)
    s.excused.push_back(excuses.below(3) == 0 ? 0.0 : excuses.uniform(0.0, 0.3));
  for (int b = 0; b < n / 2; ++b)  // gravity, say, and a torque left from elsewhere
    s.wrench.push_back(Wrench{rng.uniform(Vec3::Constant(-1.0), Vec3::Constant(1.0)),
                              rng.uniform(Vec3::Constant(-1.0), Vec3::Constant(1.0))});
  return s;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_same(const Scene& a, const Scene& b, const std::string& what) {
  EXPECT_TRUE(same_bytes(a.force, b.force)) << what << ": contact law state differs";
  EXPECT_TRUE(same_bytes(a.excused, b.excused)) << what << ": excused overlaps differ";
  EXPECT_TRUE(same_bytes(a.active, b.active)) << what << ": touching flags differ";
  EXPECT_TRUE(same_bytes(a.wrench, b.wrench)) << what << ": bodies' wrenches differ";
  EXPECT_TRUE(same_bytes(a.deferred, b.deferred)) << what << ": deferred wrenches differ";
}

// The whole candidate list, cut into uneven ranges so that batches start at every offset and
// every range has a scalar tail.
void run_in_ranges(Scene& s) {
  const PairKernelArgs args = s.args();
  const std::size_t m = s.candidates.size();
  std::size_t begin = 0;
  for (std::size_t len = 1; begin < m; len = len % 23 + 4) {
    const std::size_t end = std::min(m, begin + len);
    pair_contacts(args, begin, end);
    begin = end;
  }
}

}  // namespace

// The reference is the contact law of contact.h (update_contact_force) with the geometry of the
// world's former per-contact loop, one candidate at a time.
TEST(PairKernel, ReferenceIsTheContactLawOfContactH) {
  for (const bool scaled : {false, true})
    for (const bool excusing : {false, true}) {
      Scene s = scene(7, scaled, excusing);
      const Scene before = s;
      {
        SimdOff off;
        run_in_ranges(s);
      }
      int touching = 0, slipping = 0, released = 0, deferred = 0, excused = 0;
      ContactParams p;
      p.kn = 2e5;
      p.ks = 1.5e5;
      p.friction = 0.4;
      std::vector<Wrench> wrench = before.wrench;  // the sums as the kernel must make them
      std::size_t next_deferred = 0;
      for (std::size_t k = 0; k < s.candidates.size(); ++k) {
        const auto [i, j] = s.candidates[k];
        const bool is_deferred = next_deferred < s.deferred_candidates.size() &&
                                 s.deferred_candidates[next_deferred] == k;
        const std::size_t d = next_deferred;
        if (is_deferred) ++next_deferred;
        const Vec3 dx = s.world[j] - s.world[i];
        const double dist = dx.norm();
        const double delta = s.radius[i] + s.radius[j] - dist;
        if (!(delta > 0.0)) {
          EXPECT_EQ(s.active[k], 0);
          if (before.active[k]) ++released;
          if (is_deferred) {
            EXPECT_EQ(s.deferred[d].force, before.deferred[d].force);  // untouched
          }
          continue;
        }
        ++touching;
        const Vec3 n = dist > 0.0 ? Vec3(dx / dist) : Vec3(Vec3::UnitZ());
        const Vec3 point = s.world[i] + (s.radius[i] - 0.5 * delta) * n;
        auto at = [&](int sphere) {
          const Kinematics& q = s.kinematics[s.body[sphere]];
          return Vec3(q.velocity + q.angular_velocity.cross(point - q.position));
        };
        Vec3 shear = before.active[k] ? before.force[k].shear : Vec3::Zero();
        // The excused overlap follows the overlap down (ContactState::excused); none for a new
        // contact or without the array.
        const double carried = excusing && before.active[k] ? before.excused[k] : 0.0;
        const double excuse = std::min(carried, delta);
        if (excusing) {
          EXPECT_EQ(s.excused[k], excuse) << "candidate " << k;
        } else {
          EXPECT_EQ(s.excused[k], before.excused[k]) << "candidate " << k;  // untouched
        }
        if (excuse > 0.0) ++excused;
        double fn = 0.0;
        const ContactParams q = scaled ? scaled_stiffness(p, s.stiffness[k]) : p;
        update_contact_force(shear, fn, n, delta - excuse, at(j) - at(i), s.damping[k], q, 1e-5);
        EXPECT_EQ(s.force[k].normal_force, fn) << "candidate " << k;
        EXPECT_EQ(s.force[k].shear, shear) << "candidate " << k;
        const double scale = std::abs(fn) + shear.norm() + 1.0;
        // The frame the contact lists report is the kernel's.
        Vec3 frame_n, frame_point;
        double frame_overlap = 0.0;
        pair_contact_frame(s.world[i], s.world[j], s.radius[i], s.radius[j], frame_n, frame_point,
                           frame_overlap);
        EXPECT_EQ(frame_n, n);
        EXPECT_EQ(frame_point, point);
        EXPECT_EQ(frame_overlap, delta);
        EXPECT_EQ(s.active[k], 1);
        // −F and its moment on i's body, +F and its moment on j's (or its deferred slot).
        const Vec3 f = fn * n + shear;
        const Kinematics& a = s.kinematics[s.body[i]];
        const Kinematics& b = s.kinematics[s.body[j]];
        wrench[s.body[i]].force -= f;
        wrench[s.body[i]].torque -= (point - a.position).cross(f);
        const Vec3 torque_b = (point - b.position).cross(f);
        if (is_deferred) {
          ++deferred;
          EXPECT_EQ(s.deferred[d].force, f) << "candidate " << k;
          EXPECT_EQ(s.deferred[d].torque, torque_b) << "candidate " << k;
        } else {
          wrench[s.body[j]].force += f;
          wrench[s.body[j]].torque += torque_b;
        }
        if (shear.norm() > 0.0 && std::abs(shear.norm() - 0.4 * std::max(fn, 0.0)) < 1e-9 * scale)
          ++slipping;
      }
      for (std::size_t b = 0; b < wrench.size(); ++b) {
        EXPECT_EQ(s.wrench[b].force, wrench[b].force) << "body " << b;
        EXPECT_EQ(s.wrench[b].torque, wrench[b].torque) << "body " << b;
      }
      // The scene exercises what it claims to.
      EXPECT_GT(touching, 50) << "scaled " << scaled;
      EXPECT_GT(slipping, 5) << "scaled " << scaled;
      EXPECT_GT(released, 5) << "scaled " << scaled;
      EXPECT_GT(deferred, 5) << "scaled " << scaled;
      if (excusing) {
        EXPECT_GT(excused, 10) << "scaled " << scaled;
      }
    }
}

TEST(PairKernel, EveryInstructionSetGivesTheReferenceBits) {
  int targets = 0;
  for (const bool scaled : {false, true})
    for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
      const bool excusing = seed % 2 == 0;
      Scene reference = scene(seed, scaled, excusing);
      {
        SimdOff off;
        run_in_ranges(reference);
      }
      for_each_simd_target([&](const char* name) {
        EXPECT_STREQ(simd_target(), name) << "the kernel did not dispatch to " << name;
        Scene s = scene(seed, scaled, excusing);
        run_in_ranges(s);
        expect_same(reference, s,
                    std::string(name) + ", seed " + std::to_string(seed) +
                        (scaled ? ", scaled" : "") + (excusing ? ", excusing" : ""));
        ++targets;
      });
    }
  EXPECT_GE(targets, 12);  // at least one instruction set besides the reference, every scene
}
