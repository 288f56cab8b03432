// Tests of the specimen building blocks: gradation volumes, layer particle sets, relative
// density and μ* interpolation, the resume fingerprint.
#include "dem/specimen/specimen.h"
#include "dem/specimen/specimen_particles.h"
#include "geom/errors.h"
#include "geom/template/clump_template.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <set>
#include <string>

namespace clumpkit::dem {
namespace {

TEST(SpecimenParticles, ClassVolumesFollowMassAndDensity) {
  // 40 % rock at 2870, 60 % soil at 2700 kg/m³: M = V / (0.4/2870 + 0.6/2700).
  const std::vector<ParticleClass> classes = {{0.02, 0.04, 40.0, true}, {0.005, 0.01, 60.0, false}};
  const auto v = class_volumes(classes, 1.0, 2700, 2870);
  const double mass = 1.0 / (0.4 / 2870 + 0.6 / 2700);
  EXPECT_NEAR(v[0], 0.4 * mass / 2870, 1e-15);
  EXPECT_NEAR(v[1], 0.6 * mass / 2700, 1e-15);
  EXPECT_NEAR(v[0] + v[1], 1.0, 1e-14);
  EXPECT_THROW(class_volumes(classes, -1.0, 2700, 2870), InvalidInput);
}

// Jin et al. 2017 §4.1: soil finer than 5 mm is replaced by the same mass of 5–10 mm.
TEST(SpecimenParticles, FinesMoveByMassIntoTheReplacementClass) {
  const std::vector<SieveClass> gradation = {
      {0.0, 0.001, 4.0},  {0.001, 0.005, 11.0}, {0.005, 0.01, 20.0}, {0.01, 0.02, 25.0},
      {0.02, 0.04, 30.0}, {0.04, 0.06, 10.0},   {0.06, 0.08, 0.0}};
  const auto c = replace_fines(gradation, 0.005, 0.005, 0.010, 0.02);
  ASSERT_EQ(c.size(), 4u);  // two fines classes merged, the empty class dropped
  EXPECT_EQ(c[0].min_size, 0.005);
  EXPECT_DOUBLE_EQ(c[0].mass_percent, 20.0 + 4.0 + 11.0);
  EXPECT_FALSE(c[0].rock);
  EXPECT_FALSE(c[1].rock);  // 10–20 mm: soil, below the 20 mm threshold
  EXPECT_TRUE(c[2].rock);   // 20–40 mm
  EXPECT_TRUE(c[3].rock);
  double total = 0;
  for (const ParticleClass& k : c) total += k.mass_percent;
  EXPECT_DOUBLE_EQ(total, 100.0);  // mass kept
  // No 5–10 mm class in the gradation: the replacement class is added at the end.
  const auto added =
      replace_fines({{0.0, 0.005, 15.0}, {0.02, 0.04, 85.0}}, 0.005, 0.005, 0.01, 0.02);
  ASSERT_EQ(added.size(), 2u);
  EXPECT_EQ(added[1].min_size, 0.005);
  EXPECT_EQ(added[1].max_size, 0.01);
  EXPECT_EQ(added[1].mass_percent, 15.0);
  EXPECT_FALSE(added[1].rock);
  // Nothing finer than fines_below: the gradation passes unchanged.
  const auto same =
      replace_fines({{0.005, 0.01, 40.0}, {0.02, 0.04, 60.0}}, 0.005, 0.005, 0.01, 0.02);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[0].mass_percent, 40.0);
  EXPECT_TRUE(same[1].rock);
}

TEST(SpecimenParticles, LayerFillsEachClassToWithinOneParticle) {
  RockTemplate t;  // two unit balls one apart: W measured as 2, exact union mass properties
  t.clump = make_clump_template(Clump{{{Vec3(-0.5, 0, 0), 1.0}, {Vec3(0.5, 0, 0), 1.0}}});
  t.sieve_size = 2.0;
  const std::vector<ParticleClass> classes = {{0.02, 0.03, 40.0, true}, {0.005, 0.01, 60.0, false}};
  Rng rng(9);
  const double solid = 2e-4;
  const LayerParticles p = layer_particles(classes, {t}, solid, 2700, 2870, rng);
  const auto goal = class_volumes(classes, solid, 2700, 2870);
  const double rock_max = t.clump.mass.volume * std::pow(0.03 / 2.0, 3);
  const double soil_max = M_PI / 6 * std::pow(0.01, 3);
  EXPECT_NEAR(p.rock_volume, goal[0], 0.5 * rock_max);
  EXPECT_NEAR(p.soil_volume, goal[1], 0.5 * soil_max);
  // Rocks first, each group largest first, sizes inside their class; every rock knows its
  // template and scale, and its mass properties are the template's scaled (V s³, I s⁵).
  bool soil_seen = false;
  double last = INFINITY;
  int rocks = 0;
  for (const Body& b : p.bodies) {
    const bool rock = b.kind == BodyKind::rock;
    if (!rock && !soil_seen) soil_seen = true, last = INFINITY;
    EXPECT_FALSE(rock && soil_seen);
    EXPECT_LE(b.bounding_radius(), last);
    last = b.bounding_radius();
    if (rock) {
      ++rocks;
      EXPECT_EQ(b.template_id, 0);
      EXPECT_EQ(b.spheres[0].radius, b.scale);  // template radius 1
      EXPECT_GE(2.0 * b.scale, 0.02 - 1e-15);
      EXPECT_LE(2.0 * b.scale, 0.03 + 1e-15);
      const double s3 = b.scale * b.scale * b.scale;
      EXPECT_NEAR(b.volume, t.clump.mass.volume * s3, 1e-15 * b.volume);
      EXPECT_NEAR(b.mass, 2870 * t.clump.mass.volume * s3, 1e-12 * b.mass);
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(b.moments[a], 2870 * t.clump.principal_moments[a] * s3 * b.scale * b.scale,
                    1e-12 * b.moments[a]);
    } else {
      EXPECT_EQ(b.template_id, -1);
      EXPECT_GE(2.0 * b.spheres[0].radius, 0.005 - 1e-15);
      EXPECT_LE(2.0 * b.spheres[0].radius, 0.01 + 1e-15);
      EXPECT_NEAR(b.mass, 2700 * b.volume, 1e-12 * b.mass);
    }
  }
  EXPECT_GT(rocks, 0);
  EXPECT_TRUE(soil_seen);
}

TEST(Specimen, RelativeDensityAndFrictionInterpolation) {
  // e_max = 0.8/0.2... use n_max 0.45, n_min 0.35: Dr(n_max) = 0, Dr(n_min) = 1.
  EXPECT_NEAR(relative_density(0.45, 0.45, 0.35), 0.0, 1e-15);
  EXPECT_NEAR(relative_density(0.35, 0.45, 0.35), 1.0, 1e-15);
  const double e_max = 0.45 / 0.55, e_min = 0.35 / 0.65, e = 0.5 * (e_max + e_min);
  EXPECT_NEAR(relative_density(e / (1 + e), 0.45, 0.35), 0.5, 1e-14);
  std::vector<CalibrationPoint> c = {
      {0.0, 0, 0.5, 0, ""}, {0.2, 0, 0.6, 0, ""}, {0.4, 0, 0.7, 0, ""}, {0.8, 0, 0.8, 0, ""}};
  EXPECT_NEAR(interpolate_friction(c, 0.65), 0.3, 1e-14);
  EXPECT_NEAR(interpolate_friction(c, 0.75), 0.6, 1e-14);
  EXPECT_EQ(interpolate_friction(c, 0.3), 0.0);  // beyond the densest point
  EXPECT_EQ(interpolate_friction(c, 0.9), 0.8);
  EXPECT_THROW(interpolate_friction({c[0]}, 0.5), InvalidInput);
}

// The μ* search between rounds, on a specimen whose porosity is n(μ) = 0.30 + 0.25·μ: after
// one build the calibration, read at the porosity shifted by the miss; the line through two builds
// on one side lands on the target exactly; a bracket is closed by regula falsi; a line that does
// not rise with μ (noise) falls back on the shifted calibration.
TEST(Specimen, NextCompactionFrictionUsesEveryBuild) {
  const std::vector<CalibrationPoint> c = {{0.0, 0.32, 0.32 / 0.68, 0, ""},
                                           {0.4, 0.42, 0.42 / 0.58, 0, ""},
                                           {0.8, 0.52, 0.52 / 0.48, 0, ""}};
  auto specimen = [](double mu) { return SpecimenRound{mu, 0.30 + 0.25 * mu, 0.0}; };
  const double target = 0.36;  // μ = 0.24 on the specimen, 0.16 on the calibration
  double shifted = target;
  std::vector<SpecimenRound> rounds{specimen(0.16)};
  // One build: the calibration at the porosity shifted by the miss (0.36 + 0.02).
  const double first = next_compaction_friction(rounds, c, target, shifted);
  EXPECT_NEAR(shifted, 0.38, 1e-15);
  EXPECT_EQ(first, interpolate_friction(c, shifted / (1.0 - shifted)));
  // Two builds below the target: the line through them reaches it.
  rounds.push_back(specimen(0.20));
  double unused = target;
  EXPECT_NEAR(next_compaction_friction(rounds, c, target, unused), 0.24, 1e-12);
  EXPECT_EQ(unused, target);
  // A bracket: regula falsi between the closest builds on either side.
  rounds.push_back(specimen(0.30));
  EXPECT_NEAR(next_compaction_friction(rounds, c, target, unused), 0.24, 1e-12);
  // Clamped to the calibrated range when the line points beyond it.
  EXPECT_EQ(next_compaction_friction({specimen(0.0), specimen(0.01)}, c, 0.9, unused), 0.8);
  // Builds that grow denser with μ (noise): back to the shifted calibration.
  double noisy = target;
  const std::vector<SpecimenRound> falling{{0.16, 0.35, 0}, {0.20, 0.34, 0}};
  const double fallback = next_compaction_friction(falling, c, target, noisy);
  EXPECT_NEAR(noisy, 0.38, 1e-15);
  EXPECT_EQ(fallback, interpolate_friction(c, noisy / (1.0 - noisy)));
  EXPECT_THROW(next_compaction_friction({}, c, target, noisy), InvalidInput);
}

// The resume fingerprint: a spec changed in any one field (every field of the spec, its contact
// law, its gradation classes and its templates) gets another fingerprint; equal specs agree.
TEST(Specimen, FingerprintChangesWithEveryField) {
  SpecimenSpec base;
  base.classes = {{0.005, 0.01, 60.0, false}, {0.01, 0.02, 40.0, true}};
  RockTemplate t;
  t.clump = make_clump_template(Clump{{{Vec3(-0.5, 0, 0), 1.0}, {Vec3(0.5, 0, 0), 1.0}}});
  t.sieve_size = 2.0;
  base.templates = {t};
  using Edit = void (*)(SpecimenSpec&);
  const Edit edits[] = {
      [](SpecimenSpec& s) { s.radius *= 1.0000001; },
      [](SpecimenSpec& s) { s.height += 1e-9; },
      [](SpecimenSpec& s) { s.layers += 1; },
      [](SpecimenSpec& s) { s.soil_density += 1; },
      [](SpecimenSpec& s) { s.rock_density += 1; },
      [](SpecimenSpec& s) { s.contact.kn *= 2; },
      [](SpecimenSpec& s) { s.contact.ks *= 2; },
      [](SpecimenSpec& s) { s.contact.friction += 0.01; },
      [](SpecimenSpec& s) { s.contact.damping_ratio += 0.01; },
      [](SpecimenSpec& s) { s.contact.local_damping += 0.01; },
      [](SpecimenSpec& s) { s.target_relative_density += 0.01; },
      [](SpecimenSpec& s) { s.calibration_frictions.back() = 0.7; },
      [](SpecimenSpec& s) { s.calibration_frictions.push_back(1.0); },
      [](SpecimenSpec& s) { s.seed += 1; },
      [](SpecimenSpec& s) { s.porosity_guess += 0.01; },
      [](SpecimenSpec& s) { s.timestep_safety += 0.01; },
      [](SpecimenSpec& s) { s.equilibrium_ratio *= 2; },
      [](SpecimenSpec& s) { s.settle_window += 1; },
      [](SpecimenSpec& s) { s.height_tolerance += 0.01; },
      [](SpecimenSpec& s) { s.max_steps += 1; },
      [](SpecimenSpec& s) { s.correction_rounds += 1; },
      [](SpecimenSpec& s) { s.relative_density_tolerance += 0.001; },
      [](SpecimenSpec& s) { s.density_scaling = 10; },
      [](SpecimenSpec& s) { s.margin = 0.01; },
      [](SpecimenSpec& s) { s.classes[0].min_size *= 1.01; },
      [](SpecimenSpec& s) { s.classes[0].max_size *= 1.01; },
      [](SpecimenSpec& s) { s.classes[0].mass_percent += 1; },
      [](SpecimenSpec& s) { s.classes[1].rock = false; },
      [](SpecimenSpec& s) { s.classes.pop_back(); },
      [](SpecimenSpec& s) { s.templates[0].sieve_size *= 1.01; },
      [](SpecimenSpec& s) { s.templates[0].clump.mass.volume *= 1.01; },
      [](SpecimenSpec& s) { s.templates[0].clump.mass.centroid.x() = 1e-9; },
      [](SpecimenSpec& s) { s.templates[0].clump.mass.inertia(0, 1) = 1e-9; },
      [](SpecimenSpec& s) { s.templates[0].clump.principal_moments.z() *= 1.01; },
      [](SpecimenSpec& s) { s.templates[0].clump.orientation.x() = 1e-9; },
      [](SpecimenSpec& s) { s.templates[0].clump.position.y() = 1e-9; },
      [](SpecimenSpec& s) { s.templates[0].clump.density_factor = 1.2; },
      [](SpecimenSpec& s) { s.templates[0].clump.spheres[1].radius *= 1.01; },
      [](SpecimenSpec& s) { s.templates[0].clump.spheres[0].center.z() = 1e-9; },
      [](SpecimenSpec& s) { s.templates[0].clump.spheres.pop_back(); },
      [](SpecimenSpec& s) { s.templates.push_back(s.templates[0]); },
  };
  const std::string print = spec_fingerprint(base);
  EXPECT_EQ(print.size(), 16u);
  EXPECT_EQ(spec_fingerprint(SpecimenSpec(base)), print);
  std::set<std::string> seen = {print};
  for (std::size_t k = 0; k < std::size(edits); ++k) {
    SpecimenSpec changed = base;
    edits[k](changed);
    const std::string other = spec_fingerprint(changed);
    EXPECT_NE(other, print) << "edit " << k << " kept the fingerprint";
    EXPECT_TRUE(seen.insert(other).second) << "edit " << k << " collides with another";
  }
}

}  // namespace
}  // namespace clumpkit::dem
