// A crushable specimen by homogeneous compression: each particle's bonded cells move as one piece
// while the container closes, so the packing is made with its particles intact, of their exact
// volume, with the same bytes for any thread count.
#include "dem/specimen/compression.h"

#include "geom/errors.h"
#include "tests/dem/crushable_spec.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

CompressionResult build_crushable(const CompressionSpec& spec, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return compress_specimen(spec);
}

}  // namespace

TEST(CrushableCompression, ParticlesStayWholeAtTheTargetPorosityForAnyThreadCount) {
  const CompressionSpec spec = test::small_crushable_spec(0.5);
  const CompressionResult a = build_crushable(spec, 1);
  const World& w = a.world;
  ASSERT_GT(w.bonds().size(), 20u);
  // Every cell a body with the cells' exact volume: the solid fills the container at the target.
  double solid = 0, mass = 0;
  for (const Body& b : w.bodies()) solid += b.volume, mass += b.mass;
  EXPECT_NEAR(a.porosity, 0.5, 1e-12);
  EXPECT_NEAR(1.0 - solid / (M_PI * a.radius * a.radius * a.height), 0.5, 1e-12);
  EXPECT_NEAR(a.radius, 0.02, 0.004);
  EXPECT_NEAR(mass, 2650 * solid, 1e-12 * mass);
  // The particles came through the closing whole: every bond intact (undamaged), so each
  // particle is one fragment.
  int damaged = 0;
  for (const Bond& b : w.bonds())
    for (const BondPoint& p : b.points) damaged += p.state.damage > 0 ? 1 : 0;
  EXPECT_EQ(damaged, 0);
  // Each fragment is a whole parent: its volume that of a volume-equivalent diameter drawn in
  // the class, 14–18 mm.
  const std::vector<int> label = fragments(static_cast<int>(w.bodies().size()), w.bonds());
  std::vector<double> volume(label.size(), 0.0);
  for (std::size_t k = 0; k < label.size(); ++k) volume[label[k]] += w.bodies()[k].volume;
  int pieces = 0;
  for (std::size_t k = 0; k < label.size(); ++k) {
    if (label[k] != static_cast<int>(k)) continue;
    ++pieces;
    const double d = std::cbrt(6 * volume[k] / M_PI);
    EXPECT_GE(d, 0.014 * (1 - 1e-9));
    EXPECT_LE(d, 0.018 * (1 + 1e-9));
  }
  EXPECT_GE(pieces, 8);
  // The specimen carries the material's law again, its bonds undamaged.
  EXPECT_EQ(w.options().cohesive.sigma_n, spec.cohesive.sigma_n);
  EXPECT_EQ(w.options().cohesive.g_t, spec.cohesive.g_t);
  EXPECT_GT(a.mean_stress, 0.0);  // a packing, not a loose cloud
  const CompressionResult b = build_crushable(spec, 2);
  ASSERT_EQ(b.world.bodies().size(), w.bodies().size());
  for (std::size_t k = 0; k < w.bodies().size(); ++k)
    ASSERT_EQ(b.world.bodies()[k].position, w.bodies()[k].position) << "body " << k;
}

TEST(CrushableCompression, RefusesSoilClassesZonesAndCellsAsLargeAsTheParticles) {
  CompressionSpec s = test::small_crushable_spec(0.5);
  s.classes = {{0.014, 0.018, 100.0, false}};
  EXPECT_THROW(compress_specimen(s), InvalidInput);
  s = test::small_crushable_spec(0.5);
  s.crushable->cells.cell_size = 0.02;
  EXPECT_THROW(compress_specimen(s), InvalidInput);
}
