// An oedometer on a small crushable specimen (bonded cells from a crushable compression): the
// breakage columns count what broke, the fragments keep the particles' volume, and the rows are
// the same bytes for one and two threads. The short sibling of tests/cli/crushable_test.cpp.
#include "dem/core/crushable.h"
#include "dem/lab/element_loading.h"

#include "dem/core/timestep.h"
#include "dem/measure/fragment_sizes.h"
#include "dem/specimen/compression.h"
#include "tests/dem/crushable_spec.h"

#include "../../sanitized.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// The small crushable specimen (tests/dem/crushable_spec.h) at n = 0.45, its bonds weak (the
// granite law's strengths × 0.15, energies × 0.15²).
const CompressionResult& weak_specimen() {
  static const CompressionResult r = [] {
    CompressionSpec s = test::small_crushable_spec(0.45);
    s.contact.local_damping = 0.7;
    s.relax_max_steps = 1000;
    s.cohesive.sigma_n *= 0.15, s.cohesive.sigma_t *= 0.15;
    s.cohesive.g_n *= 0.0225, s.cohesive.g_t *= 0.0225;
    return compress_specimen(s);
  }();
  return r;
}

std::vector<CurveRow> crushable_oedometer(int threads, World* end = nullptr) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const CompressionResult& c = weak_specimen();
  const WorldOptions o =
      cell_packing_options(element_test_world_options(c.world.bodies(), c.world.options().contact),
                           c.world.options().cohesive);
  World w(o);
  for (Body b : c.world.bodies()) {
    b.mass *= 1000, b.moments *= 1000;  // λ = 1000, as the crushing recipes
    w.add_body(std::move(b));
  }
  for (const Bond& b : c.world.bonds()) w.add_bond(b);
  const TestCell cell = add_cylinder_test_cell(w, c.radius, 0.0, c.height);
  w.options().timestep = 0.2 * critical_timestep(w);
  ElementTestSettings s;
  s.path = &kOedometerPath;
  s.confining = 50e3;
  // Under the sanitizers to 0.3 MPa: 21 rows and 4,000 loading steps instead of 102 and 20,200
  // (the specimen broke 67 bonds and 5 particles in its consolidation, 117 and 10 by 0.3 MPa), each
  // run ~3x shorter; the specimen's build, about a quarter of the test, stays. The Release pass
  // loads to 1 MPa.
  s.final_stress = kSanitized ? 0.3e6 : 1e6;
  s.strain_rate = 1;  // fast (a test of the bookkeeping, not of the physics)
  s.record_every = 200;
  s.max_consolidation_steps = 3000;
  s.reference = w.bodies();
  s.particles = fragments(static_cast<int>(w.bodies().size()), w.bonds());
  s.initial_grading = fragment_pieces(s.reference, w.bonds());
  s.sieves = sieve_series(0.001, 0.03, std::sqrt(2.0));
  s.class_bounds = {0.01, 0.015, 0.016, 0.017, 0.02};
  const ElementTestResult r = run_element_test(w, cell, s);
  if (end) *end = w;
  return r.curve;
}

}  // namespace

TEST(CrushableOedometer, CountsWhatBrokeKeepsTheVolumeSameBytesForOneAndTwoThreads) {
  World end;
  const std::vector<CurveRow> one = crushable_oedometer(1, &end);
  ASSERT_GT(one.size(), 3u);
  const CurveRow& first = one.front();
  const CurveRow& last = one.back();
  EXPECT_GT(last.bonds_broken, 0);
  EXPECT_GT(last.fragments, first.fragments);
  EXPECT_GT(last.particles_broken, 0);
  EXPECT_GT(last.hardin_br, 0);
  EXPECT_GE(last.hardin_br, first.hardin_br);
  // Each broken bond failed in one mode; under platens most faces slide or fail mixed.
  EXPECT_GT(last.bonds_mode_ii + last.bonds_mixed, 0);
  for (const CurveRow& c : one) {
    EXPECT_EQ(c.bonds_mode_i + c.bonds_mode_ii + c.bonds_mixed, c.bonds_broken);
  }
  for (const CurveRow& c : one)
    for (double f : c.broken_by_class) {
      EXPECT_GE(f, 0.0);
      EXPECT_LE(f, 1.0);
    }
  // The fragments hold the particles' solid volume.
  double before = 0, after = 0;
  for (const Body& b : weak_specimen().world.bodies()) before += b.volume;
  for (const SievedPiece& p : fragment_pieces(end.bodies(), end.bonds())) after += p.volume;
  EXPECT_NEAR(after / before, 1.0, 1e-12);
  const std::vector<CurveRow> two = crushable_oedometer(2);
  ASSERT_EQ(two.size(), one.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(std::memcmp(&one[k].axial_stress, &two[k].axial_stress, sizeof(double)), 0);
    EXPECT_EQ(one[k].hardin_br, two[k].hardin_br);
    EXPECT_EQ(one[k].fragments, two[k].fragments);
  }
}
