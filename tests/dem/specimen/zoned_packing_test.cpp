// Zoned specimens' particles (dem/specimen/zoned_packing.h): prisms, zone volumes against closed
// forms, per-zone draws at the zone's λ and porosity, and a loose placement that keeps every
// centre in its zone's pre-image.
#include "dem/specimen/zoned_packing.h"

#include "geom/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clumpkit;
using namespace clumpkit::dem;

namespace {

Prism segment(double diameter, double height, double angle_deg) {
  Prism p;
  p.shape = Prism::Shape::segment;
  p.size = Vec3(diameter, diameter, height);
  p.angle = angle_deg * M_PI / 180.0;
  return p;
}

// Core to 0.03 m (λ 1), a mixed layer to 0.05 m with a small fraction going 0.8 → 0.2, λ 2 beyond.
ZoneLayout three_zones() {
  ZoneLayout z;
  z.coordinate = ZoneCoordinate::radial;
  z.regions = {{false, 0.03, 1.0, 0.5, 0.5}, {true, 0.05, 1.0, 0.8, 0.2}, {false, 1.0, 2.0, 0, 0}};
  return z;
}

TEST(ZonedPacking, SegmentPrismHoldsBoundsAndMeasures) {
  const Prism p = segment(0.2, 0.1, 90);
  Vec3 lo, hi;
  p.bounds(lo, hi);
  EXPECT_NEAR((lo - Vec3(0, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((hi - Vec3(0.1, 0.1, 0.1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(p.volume(), 0.25 * M_PI * 0.01 * 0.1, 1e-15);
  EXPECT_TRUE(p.holds(Vec3(0.02, 0.02, 0.05), 0.01));
  EXPECT_FALSE(p.holds(Vec3(0.02, 0.005, 0.05), 0.01));  // through the plane φ = 0
  EXPECT_FALSE(p.holds(Vec3(0.005, 0.02, 0.05), 0.01));  // through the plane φ = 90°
  EXPECT_FALSE(p.holds(Vec3(0.07, 0.07, 0.05), 0.01));   // through the cylinder
  EXPECT_NEAR(p.wall_distance(Vec3(0.02, 0.03, 0.05)), 0.02, 1e-15);
  EXPECT_NEAR(p.wall_distance(Vec3(0.03, 0.03, 0.005)), 0.005, 1e-15);
  const Prism half = segment(0.2, 0.1, 180);
  half.bounds(lo, hi);
  EXPECT_NEAR(lo.x(), -0.1, 1e-15);
  EXPECT_NEAR(hi.y(), 0.1, 1e-15);
  EXPECT_NEAR(lo.y(), 0.0, 1e-15);
  EXPECT_NEAR(p.scaled(2).volume(), 8 * p.volume(), 1e-15);
}

// Annuli of a 90° segment: θ/2·(b² − a²)·h; the mixed layer's ∫ f dV with f linear in r from f0
// at a to f1 at b: θ h ∫ f(r) r dr.
TEST(ZonedPacking, RadialZoneVolumesMatchTheAnnuli) {
  const Prism p = segment(0.12, 0.04, 90);
  const double t = 0.5 * M_PI, h = 0.04;
  const ZoneVolumes v = zone_volumes(three_zones(), p);
  ASSERT_EQ(v.volume.size(), 3u);
  EXPECT_NEAR(v.volume[0] / (0.5 * t * 0.03 * 0.03 * h), 1.0, 1e-4);
  EXPECT_NEAR(v.volume[1] / (0.5 * t * (0.05 * 0.05 - 0.03 * 0.03) * h), 1.0, 1e-4);
  EXPECT_NEAR(v.volume[2] / (0.5 * t * (0.06 * 0.06 - 0.05 * 0.05) * h), 1.0, 1e-4);
  // Walls: floor and top (θ r² per zone), the two planes (h per metre of radius), the arc θ R h.
  EXPECT_NEAR(v.wall_area[0] / (t * 0.03 * 0.03 + 2 * 0.03 * h), 1.0, 2e-4);
  EXPECT_NEAR(v.wall_area[1] / (t * (0.05 * 0.05 - 0.03 * 0.03) + 2 * 0.02 * h), 1.0, 2e-4);
  EXPECT_NEAR(v.wall_area[2] / (t * (0.06 * 0.06 - 0.05 * 0.05) + 2 * 0.01 * h + t * 0.06 * h), 1.0,
              2e-4);
  const double a = 0.03, b = 0.05, f0 = 0.8, f1 = 0.2;
  const double slope = (f1 - f0) / (b - a);  // ∫ (f0 + slope (r − a)) r dr from a to b
  const double integral =
      (f0 - slope * a) * (b * b - a * a) / 2 + slope * (b * b * b - a * a * a) / 3;
  EXPECT_NEAR(v.small_volume[1] / (t * h * integral), 1.0, 1e-4);
  EXPECT_EQ(v.small_volume[0], 0.0);
}

TEST(ZonedPacking, DepthAndSphericalZoneVolumes) {
  Prism box;
  box.size = Vec3(0.1, 0.08, 0.2);
  ZoneLayout depth;
  depth.coordinate = ZoneCoordinate::depth;
  depth.origin = Vec3(0, 0, 0.2);
  depth.regions = {{false, 0.05, 1, 0, 0}, {false, 1, 2, 0, 0}};
  const ZoneVolumes d = zone_volumes(depth, box);
  EXPECT_NEAR(d.volume[0], 0.1 * 0.08 * 0.05, 1e-9);
  EXPECT_NEAR(d.volume[1], 0.1 * 0.08 * 0.15, 1e-9);
  EXPECT_NEAR(d.wall_area[0], 0.1 * 0.08 + 2 * (0.1 + 0.08) * 0.05, 1e-6);  // top and sides
  EXPECT_NEAR(d.wall_area[1], 0.1 * 0.08 + 2 * (0.1 + 0.08) * 0.15, 1e-6);
  ZoneLayout ball;
  ball.coordinate = ZoneCoordinate::spherical;
  ball.origin = Vec3(0, 0, 0.1);
  ball.regions = {{false, 0.03, 1, 0, 0}, {false, 1, 2, 0, 0}};
  const ZoneVolumes s = zone_volumes(ball, box);
  EXPECT_NEAR(s.volume[0] / (4.0 / 3.0 * M_PI * 0.03 * 0.03 * 0.03), 1.0, 5e-3);
  EXPECT_NEAR((s.volume[0] + s.volume[1]) / box.volume(), 1.0, 1e-9);
}

std::vector<ParticleClass> three_mm() {
  return {{0.0029, 0.0031, 100.0, false}};
}

TEST(ZonedPacking, EachZoneDrawsItsScaledGradationToItsGoal) {
  const Prism p = segment(0.12, 0.04, 90);
  const ZoneLayout z = three_zones();
  const ZoneVolumes v = zone_volumes(z, p);
  const ZonedParticles a =
      zoned_particles(z, v, three_mm(), {}, 0.38, 0.33, 0.0, 2650, 2650, /*seed=*/3);
  ASSERT_EQ(a.bodies.size(), a.small.size());
  std::vector<double> solid(3, 0.0), small(3, 0.0);
  double previous = 1.0;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const Body& b = a.bodies[i];
    const double d = 2 * b.spheres[0].radius;
    EXPECT_LE(d, previous);  // largest first
    previous = d;
    solid[b.zone] += b.volume;
    if (a.small[i]) small[b.zone] += b.volume;
    const bool is_small = d < 0.0035;
    if (b.zone == 0) {
      EXPECT_TRUE(is_small);
    }
    if (b.zone == 2) {
      EXPECT_FALSE(is_small);
    }
    EXPECT_EQ(a.small[i] != 0, b.zone == 1 && is_small);
  }
  const double big = M_PI / 6 * std::pow(0.0062, 3);
  EXPECT_NEAR(a.goal[0], 0.62 * v.volume[0], 1e-15);
  EXPECT_NEAR(a.goal[1], 0.67 * v.volume[1], 1e-15);
  // With a wall excess the goals shrink by excess × mean diameter × wall area (3 mm in the core,
  // (3·∫f + 6·(V − ∫f))/V mm in the mixed layer).
  const ZonedParticles w =
      zoned_particles(z, v, three_mm(), {}, 0.38, 0.33, 0.1, 2650, 2650, /*seed=*/3);
  EXPECT_NEAR(w.goal[0], 0.62 * (v.volume[0] - 0.1 * 0.003 * v.wall_area[0]), 1e-15);
  const double d1 =
      (0.003 * v.small_volume[1] + 0.006 * (v.volume[1] - v.small_volume[1])) / v.volume[1];
  EXPECT_NEAR(w.goal[1], 0.67 * (v.volume[1] - 0.1 * d1 * v.wall_area[1]), 1e-15);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(solid[k], a.goal[k], big) << k;
  // The mixed layer's small particles fill ∫ f dV at its porosity.
  EXPECT_NEAR(small[1], 0.67 * v.small_volume[1], big);
  // The same seed draws the same particles; another seed others.
  const ZonedParticles again =
      zoned_particles(z, v, three_mm(), {}, 0.38, 0.33, 0.0, 2650, 2650, 3);
  ASSERT_EQ(again.bodies.size(), a.bodies.size());
  EXPECT_EQ(again.bodies.back().spheres[0].radius, a.bodies.back().spheres[0].radius);
  const ZonedParticles other =
      zoned_particles(z, v, three_mm(), {}, 0.38, 0.33, 0.0, 2650, 2650, 4);
  EXPECT_NE(other.bodies.back().spheres[0].radius, a.bodies.back().spheres[0].radius);
}

TEST(ZonedPacking, LoosePlacementKeepsEveryCentreInItsZonesPreImage) {
  const Prism p = segment(0.12, 0.04, 90);
  const ZoneLayout z = three_zones();
  const ZonedParticles a =
      zoned_particles(z, zone_volumes(z, p), three_mm(), {}, 0.38, 0.33, 0.0, 2650, 2650, 3);
  Rng rng(9);
  const double factor = 1.4;
  const std::vector<Placement> placed = place_zoned(a, z, p, factor, rng);
  ASSERT_EQ(placed.size(), a.bodies.size());
  const Prism loose = p.scaled(factor);
  // Small particles of the mixed layer lean inwards (f falls from 0.8 to 0.2), large outwards.
  double small_r = 0, large_r = 0;
  int small_n = 0, large_n = 0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Vec3 x = placed[i].position;
    const double r = a.bodies[i].spheres[0].radius;
    EXPECT_TRUE(loose.holds(x, r * (1 - 1e-9))) << i;
    EXPECT_EQ(region_of(z, zone_coordinate(z, x / factor)), a.bodies[i].zone) << i;
    for (std::size_t j = 0; j < i; j += 7)
      EXPECT_GE((placed[j].position - x).norm(), r + a.bodies[j].spheres[0].radius - 1e-12);
    if (a.bodies[i].zone == 1) {
      (a.small[i] ? small_r : large_r) += zone_coordinate(z, x / factor);
      ++(a.small[i] ? small_n : large_n);
    }
  }
  ASSERT_GT(small_n, 50);
  ASSERT_GT(large_n, 3);
  EXPECT_LT(small_r / small_n, 0.04);  // the layer's middle
  EXPECT_GT(large_r / large_n, 0.04);
}

TEST(ZonedPacking, ARegionOutsideTheContainerIsRefused) {
  const Prism p = segment(0.12, 0.04, 90);
  ZoneLayout z = three_zones();
  z.origin = Vec3(-0.5, 0, 0);  // every point is beyond 0.05 m from this axis
  try {
    zoned_particles(z, zone_volumes(z, p), three_mm(), {}, 0.38, 0.38, 0.0, 2650, 2650, 1);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("region 1: holds no volume"), std::string::npos)
        << e.what();
  }
}

}  // namespace
