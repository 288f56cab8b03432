// Gravity-free specimens by homogeneous compression (dem/specimen/compression.h): exact porosity,
// no gradient, the same bytes for any thread count, and exact similarity of a copy at scale 2.
#include "dem/specimen/compression.h"

#include "geom/errors.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

// About 570 spheres of d = 10 mm ± 1 % in an 8 d cube at n = 0.40, compressed from 1.25 times
// the size at 2e-5 strain per step (12,000 steps) to keep the test short.
CompressionSpec small_spec(double lambda = 1.0, double edge = 0.08) {
  CompressionSpec s;
  s.size = Vec3::Constant(edge * lambda);
  s.porosity = 0.40;
  s.classes = {{0.0099 * lambda, 0.0101 * lambda, 100.0, false}};
  s.soil_density = 2650;
  s.contact.kn = 8e7;
  s.contact.ks = 8e5;
  s.contact.friction = 0.8;
  s.contact.scaling = StiffnessScaling::linear;
  s.contact.d_ref = 0.01;
  s.loose_factor = 1.25;
  s.strain_per_step = 2e-5;
  s.relax_max_steps = 2000;
  s.seed = 7;
  return s;
}

CompressionResult build(const CompressionSpec& spec, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return compress_specimen(spec);
}

}  // namespace

TEST(DemCompression, ReachesTheTargetPorosityWithoutGradientAndIsThreadIndependent) {
  const CompressionSpec spec = small_spec();
  const CompressionResult a = build(spec, 1);
  const CompressionResult b = build(spec, 2);
  const auto& bodies = a.world.bodies();
  ASSERT_GT(bodies.size(), 500u);
  // Porosity: the container is sized to the drawn solid volume, so the target holds exactly;
  // the box stays within part of a particle of the requested 0.08 m.
  double solid = 0;
  for (const Body& body : bodies) solid += body.volume;
  const Vec3 edge = a.hi - a.lo;
  EXPECT_NEAR(1.0 - solid / edge.prod(), 0.40, 1e-12);
  EXPECT_NEAR(a.porosity, 0.40, 1e-12);
  EXPECT_NEAR(edge.x(), 0.08, 0.002);
  EXPECT_DOUBLE_EQ(edge.x(), edge.z());
  // Every sphere inside the walls (up to its contact overlap: this porosity is below the
  // frictionless jamming one of an 8 d box, so walls press by up to ~5 % of a radius) and at
  // rest, with the material friction back.
  for (const Body& body : bodies) {
    const double r = body.spheres[0].radius;
    for (int k = 0; k < 3; ++k) {
      EXPECT_GT(body.position[k] - r, a.lo[k] - 0.1 * r);
      EXPECT_LT(body.position[k] + r, a.hi[k] + 0.1 * r);
    }
    EXPECT_EQ(body.velocity.norm(), 0.0);
  }
  EXPECT_EQ(a.world.options().contact.friction, 0.8);
  EXPECT_EQ(a.world.options().gravity.norm(), 0.0);
  // Homogeneous: walls closing on a gas would pile bodies against them; mapping every centre
  // with the walls keeps the halves of the box equally full (within 5 % of the count).
  for (int k = 0; k < 3; ++k) {
    const double mid = 0.5 * (a.lo[k] + a.hi[k]);
    int low = 0;
    for (const Body& body : bodies) low += body.position[k] < mid;
    EXPECT_NEAR(double(low) / bodies.size(), 0.5, 0.05) << "axis " << k;
  }
  // Jammed: contacts carry stress (Z counts body pairs only; over half the bodies touch a wall).
  EXPECT_GT(a.coordination, 3.0);
  EXPECT_GT(a.mean_stress, 0.0);
  // The same bytes on 2 threads.
  ASSERT_EQ(b.world.bodies().size(), bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k)
    ASSERT_EQ(b.world.bodies()[k].position, bodies[k].position) << "body " << k;
  EXPECT_EQ(b.mean_stress, a.mean_stress);
}

TEST(DemCompression, ACopyAtTwiceTheSizeIsTheSameSpecimenScaledExactly) {
  // CTGU 2017 eqs. 1–3 through the preparation: sizes ×2 with kn ∝ d (linear law, same kn_ref
  // and d_ref) and every length of the algorithm relative to the specimen's, so the copy's
  // positions are 2× the original's bit for bit, and its stresses equal.
  const CompressionResult a = build(small_spec(1.0), 2);
  const CompressionResult b = build(small_spec(2.0), 2);
  ASSERT_EQ(a.world.bodies().size(), b.world.bodies().size());
  for (std::size_t k = 0; k < a.world.bodies().size(); ++k)
    ASSERT_EQ(2.0 * a.world.bodies()[k].position, b.world.bodies()[k].position) << "body " << k;
  EXPECT_EQ(2.0 * a.hi, b.hi);
  EXPECT_EQ(a.mean_stress, b.mean_stress);
  EXPECT_EQ(a.porosity, b.porosity);
  EXPECT_EQ(a.relax_steps, b.relax_steps);
}

TEST(DemCompression, BadSpecsAreRefused) {
  CompressionSpec s = small_spec();
  s.porosity = 1.0;
  EXPECT_THROW(compress_specimen(s), InvalidInput);
  s = small_spec();
  s.size.x() = -1;
  EXPECT_THROW(compress_specimen(s), InvalidInput);
  s = small_spec();
  s.friction = NAN;
  EXPECT_THROW(compress_specimen(s), InvalidInput);
  s = small_spec();
  s.shape = CompressionSpec::Shape::cylinder;  // size must be (diameter, diameter, height)
  s.size = Vec3(0.08, 0.06, 0.08);
  EXPECT_THROW(compress_specimen(s), InvalidInput);
}

TEST(DemCompression, FiveDiameterCubeIsExactForAnyThreadsAndAtTwiceTheSize) {
  // The two tests above on a 5 d cube (about 140 spheres) in one, for the sanitizer pass (they
  // are labelled long there): exact porosity, the same bytes on 2 threads, a copy at λ = 2.
  const CompressionResult a = build(small_spec(1.0, 0.05), 1);
  const CompressionResult b = build(small_spec(1.0, 0.05), 2);
  const CompressionResult c = build(small_spec(2.0, 0.05), 2);
  ASSERT_GT(a.world.bodies().size(), 100u);
  EXPECT_NEAR(a.porosity, 0.40, 1e-12);
  EXPECT_GT(a.mean_stress, 0.0);
  ASSERT_EQ(b.world.bodies().size(), a.world.bodies().size());
  ASSERT_EQ(c.world.bodies().size(), a.world.bodies().size());
  for (std::size_t k = 0; k < a.world.bodies().size(); ++k) {
    ASSERT_EQ(b.world.bodies()[k].position, a.world.bodies()[k].position) << "body " << k;
    ASSERT_EQ(c.world.bodies()[k].position, 2.0 * a.world.bodies()[k].position) << "body " << k;
  }
  EXPECT_EQ(b.mean_stress, a.mean_stress);
  EXPECT_EQ(c.mean_stress, a.mean_stress);
  EXPECT_EQ(c.relax_steps, a.relax_steps);
}

// A 90° segment of a 12 d cylinder, 3 d high (about 80 spheres, n = 0.48: below that the
// walls of so small a specimen jam it hard): the porosity of the sector's volume exactly, every
// sphere inside the sector (the radial walls through the axis hold it; overlaps within 5 % of a
// radius). The thread invariance of the compression is the tests' above.
TEST(DemCompression, SegmentIsFilledInsideItsSectorAtTheTargetPorosity) {
  CompressionSpec s = small_spec(1.0, 0.16);
  s.shape = CompressionSpec::Shape::segment;
  s.angle = 0.5 * M_PI;
  s.size = Vec3(0.12, 0.12, 0.03);
  s.porosity = 0.48;
  const CompressionResult a = build(s, 1);
  ASSERT_GT(a.world.bodies().size(), 60u);
  EXPECT_NEAR(a.porosity, 0.48, 1e-12);
  EXPECT_GT(a.mean_stress, 0.0);
  EXPECT_EQ(a.angle, 0.5 * M_PI);
  double solid = 0;
  for (const Body& b : a.world.bodies()) {
    solid += b.volume;
    const double r = b.spheres.front().radius;
    const Vec3& x = b.position;
    // Inside up to a contact overlap.
    EXPECT_GT(x.y(), r * 0.95) << "below the plane φ = 0";
    EXPECT_GT(x.x(), r * 0.95) << "beyond the plane φ = 90°";
    EXPECT_LT(std::hypot(x.x(), x.y()) + r, a.radius + 0.05 * r);
  }
  EXPECT_NEAR(solid / (0.25 * M_PI * a.radius * a.radius * a.height), 0.52, 1e-12);
  ASSERT_EQ(a.world.walls().size(), 5u);  // cylinder, platens, two radial planes
  s.angle = 1.1 * M_PI;
  EXPECT_THROW(compress_specimen(s), InvalidInput);
  s.angle = 0.0;
  EXPECT_THROW(compress_specimen(s), InvalidInput);
}

// A zoned cylinder (CTGU 2017): a 5 mm core to r = 15 mm, 10 mm spheres (λ 2) to the 30 mm wall,
// about 300 spheres. Each body ends tagged with the zone of its final centre, each zone's solid
// is its own goal, its porosity away from the walls near the target, few bodies migrate, and
// the bytes do not depend on the thread count.
TEST(DemCompression, ZonedCylinderKeepsItsZonesForAnyThreads) {
  CompressionSpec spec = small_spec(0.5, 0.06);
  spec.shape = CompressionSpec::Shape::cylinder;
  spec.size = Vec3(0.06, 0.06, 0.03);
  spec.porosity = 0.36;
  spec.zones.coordinate = ZoneCoordinate::radial;
  spec.zones.regions = {{false, 0.015, 1.0, 0, 0}, {false, 0.03, 2.0, 0, 0}};
  const CompressionResult a = build(spec, 1);
  const CompressionResult b = build(spec, 2);
  ASSERT_EQ(a.world.bodies().size(), b.world.bodies().size());
  ASSERT_EQ(a.zones.size(), 2u);
  long count[2] = {0, 0};
  for (std::size_t i = 0; i < a.world.bodies().size(); ++i) {
    const Body& body = a.world.bodies()[i];
    EXPECT_EQ(body.position, b.world.bodies()[i].position);
    EXPECT_EQ(body.zone, region_of(spec.zones, zone_coordinate(spec.zones, body.position)));
    EXPECT_EQ(body.zone, b.world.bodies()[i].zone);
    ++count[body.zone];
  }
  const double large = M_PI / 6 * std::pow(0.0101, 3);
  for (int k = 0; k < 2; ++k) {
    const ZoneResult& z = a.zones[k];
    EXPECT_EQ(z.count, count[k]);
    EXPECT_EQ(z.porosity, b.zones[k].porosity);
    EXPECT_NEAR(z.solid_drawn, z.solid_goal, large);
    EXPECT_EQ(z.target_porosity, 0.36);
  }
  EXPECT_GT(count[0], 150);
  EXPECT_GT(count[1], 40);
  // The core, the larger region away from walls: within 0.02 of its target in so small a cell.
  EXPECT_NEAR(a.zones[0].porosity, 0.36, 0.02);
  EXPECT_LT(double(a.migrated) / double(a.world.bodies().size()), 0.03);
  EXPECT_LE(a.migrated, a.left_zone);
  EXPECT_LE(a.mis_zoned, a.migrated);
  long migrated = 0;
  for (const ZoneResult& z : a.zones) migrated += z.migrated;
  EXPECT_EQ(migrated, a.migrated);
}
