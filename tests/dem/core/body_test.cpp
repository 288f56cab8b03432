// Tests of DEM bodies made from clump templates: template identity and exact scaling of mass
// properties (V s³, I s⁵) against the per-body union computation they replace.
#include "dem/core/body.h"
#include "geom/errors.h"
#include "geom/random.h"
#include "geom/template/clump_template.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clumpkit::dem {
namespace {

Clump random_clump(Rng& rng, int n) {
  Clump c;
  for (int k = 0; k < n; ++k)
    c.spheres.push_back(
        {rng.uniform(Vec3(-1, -0.6, -0.4), Vec3(1, 0.6, 0.4)), rng.uniform(0.3, 0.7)});
  return c;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

// A body made from a template scaled by s, placed with a rotation and a translation, against
// the old per-body path: the union of its world spheres computed afresh (make_clump_body of a
// Clump). Mass, centroid and principal moments agree to 1e-12 relative.
TEST(DemBody, TemplateScalingMatchesTheUnionOfTheScaledSpheres) {
  Rng rng(2024);
  for (int trial = 0; trial < 6; ++trial) {
    const ClumpTemplate t = make_clump_template(random_clump(rng, 4 + 3 * trial));
    const double scale = 0.004 * (1 + trial);  // a 1-unit template as a 4–24 mm rock
    const double density = 2650.0;
    const Vec3 position = rng.uniform(Vec3(-0.1, -0.1, 0), Vec3(0.1, 0.1, 0.3));
    const Eigen::Quaterniond q = rng.normal_quaternion().normalized();
    const Body body = make_clump_body(t, density, position, q, scale, trial);
    EXPECT_EQ(body.kind, BodyKind::rock);
    EXPECT_EQ(body.template_id, trial);
    EXPECT_EQ(body.scale, scale);

    Clump world;
    for (const Sphere& s : t.spheres)
      world.spheres.push_back({q * (s.center * scale) + position, s.radius * scale});
    const Body fresh = make_clump_body(world, density);

    EXPECT_LT(relative(body.mass, fresh.mass), 1e-12);
    EXPECT_LT(relative(body.volume, fresh.volume), 1e-12);
    EXPECT_LT((body.position - fresh.position).norm(), 1e-12 * scale);
    for (int a = 0; a < 3; ++a) EXPECT_LT(relative(body.moments[a], fresh.moments[a]), 1e-12);
    // V ∝ s³ and I ∝ s⁵ exactly as formulas.
    EXPECT_DOUBLE_EQ(body.volume, t.mass.volume * scale * scale * scale);
    EXPECT_DOUBLE_EQ(body.moments.x(), density * t.principal_moments.x() * std::pow(scale, 5));
  }
}

TEST(DemBody, KindIsExplicitAndBadScalesAreRefused) {
  const ClumpTemplate one = make_clump_template(Clump{{{Vec3::Zero(), 1.0}}});
  const Body rock =
      make_clump_body(one, 2000.0, Vec3::Zero(), Eigen::Quaterniond::Identity(), 0.01);
  EXPECT_EQ(rock.kind, BodyKind::rock);  // a one-sphere template is still a rock
  EXPECT_EQ(kind_name(rock.kind), "rock");
  const Body soil = make_sphere_body(Vec3::Zero(), 0.01, 2000.0);
  EXPECT_EQ(soil.kind, BodyKind::soil);
  EXPECT_EQ(soil.template_id, -1);
  EXPECT_DOUBLE_EQ(soil.volume, rock.volume);
  EXPECT_DOUBLE_EQ(soil.mass, rock.mass);
  for (double bad : {0.0, -1.0, double(NAN), double(INFINITY)})
    EXPECT_THROW(make_clump_body(one, 2000.0, Vec3::Zero(), Eigen::Quaterniond::Identity(), bad),
                 InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
