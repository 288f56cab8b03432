// Tests of the gravity deposition of a placed assembly in a cylinder (issue 5, specimen stage 2).
#include "dem/deposition.h"
#include "geom/errors.h"
#include "geom/random.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clumpkit::dem {
namespace {

constexpr double kCylinder = 0.05;  // m

/// 150 soil spheres of radius 4–8 mm, largest first.
std::vector<PlacementItem> soil_items() {
  Rng rng(31);
  std::vector<double> radii;
  for (int i = 0; i < 150; ++i) radii.push_back(rng.uniform(0.004, 0.008));
  std::sort(radii.rbegin(), radii.rend());
  std::vector<PlacementItem> items;
  for (double r : radii) items.push_back({{{Vec3::Zero(), r}}, r});
  return items;
}

double top_of(const World& world) {
  double top = 0.0;
  for (const Body& b : world.bodies())
    for (const Sphere& s : b.spheres)
      top = std::max(top, (b.orientation * s.center + b.position).z() + s.radius);
  return top;
}

TEST(Deposition, SettlesInsideTheCylinderToARandomPackBitIdenticalForThreads) {
  const auto items = soil_items();
  Rng rng(5);
  double placed_height = 0.0;
  const auto placements = place_in_cylinder(items, kCylinder, rng, 200, &placed_height);
  DepositionSpec spec;
  spec.radius = kCylinder;

  std::vector<World> runs;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    World world = make_deposition_world(items, placements, spec);
    const RunOutcome outcome = deposit(world, spec);
    EXPECT_EQ(outcome.stopped_by, "unbalanced_ratio");
    EXPECT_LT(outcome.steps, spec.max_steps);
    EXPECT_LT(mean_unbalanced_force_ratio(world), spec.unbalanced_ratio);
    runs.push_back(std::move(world));
  }
  const World& a = runs[0];
  const World& b = runs[1];
  ASSERT_EQ(a.bodies().size(), items.size());
  EXPECT_EQ(a.walls().size(), 2u);

  // Inside the cylinder and above the floor up to a small contact overlap.
  for (const Body& body : a.bodies()) {
    ASSERT_EQ(body.spheres.size(), 1u);
    const Sphere& s = body.spheres[0];
    const Vec3 c = body.position + body.orientation * s.center;
    EXPECT_LT(std::hypot(c.x(), c.y()) + s.radius, kCylinder + 0.02 * s.radius);
    EXPECT_GT(c.z() - s.radius, -0.02 * s.radius);
  }
  const double top = top_of(a);
  EXPECT_LT(top, placed_height);

  // Central region one largest diameter (16 mm) away from the wall, the floor and the top.
  const double d = 0.016;
  const double porosity = lattice_porosity(a, kCylinder - d, d, top - d, 2.5e-4);
  std::printf("placed height %.4f m, deposited top %.4f m, steps %lld, porosity %.4f\n",
              placed_height, top, static_cast<long long>(a.steps()), porosity);
  EXPECT_GT(porosity, 0.3);
  EXPECT_LT(porosity, 0.5);

  ASSERT_EQ(a.contacts().size(), b.contacts().size());
  EXPECT_EQ(a.steps(), b.steps());
  for (std::size_t k = 0; k < a.bodies().size(); ++k) {
    const Body& p = a.bodies()[k];
    const Body& q = b.bodies()[k];
    EXPECT_EQ(std::memcmp(p.position.data(), q.position.data(), sizeof(double) * 3), 0);
    EXPECT_EQ(std::memcmp(p.velocity.data(), q.velocity.data(), sizeof(double) * 3), 0);
    EXPECT_EQ(std::memcmp(p.orientation.coeffs().data(), q.orientation.coeffs().data(),
                          sizeof(double) * 4),
              0);
  }
}

TEST(Deposition, WorldHasBodiesOfTheRightDensityAndStableTimestep) {
  std::vector<PlacementItem> items = {
      {{{Vec3::Zero(), 0.01}}, 0.01},
      {{{Vec3(-0.005, 0, 0), 0.008}, {Vec3(0.005, 0, 0), 0.008}}, 0.013}};
  std::vector<Placement> placements(2);
  placements[0].position = Vec3(0.0, 0.0, 0.01);
  placements[1].position = Vec3(0.0, 0.0, 0.04);
  placements[1].orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3::UnitY()));
  DepositionSpec spec;
  spec.radius = 0.05;
  const World world = make_deposition_world(items, placements, spec);
  ASSERT_EQ(world.bodies().size(), 2u);
  const double sphere_mass = 4.0 / 3.0 * M_PI * std::pow(0.01, 3) * spec.soil_density;
  EXPECT_NEAR(world.bodies()[0].mass, sphere_mass, 1e-12 * sphere_mass);
  EXPECT_EQ(world.bodies()[1].spheres.size(), 2u);
  // The clump's spheres land where the placement put them.
  const Body& clump = world.bodies()[1];
  for (const Sphere& s : items[1].spheres) {
    const Vec3 want = placements[1].orientation * s.center + placements[1].position;
    double best = 1.0;
    for (const Sphere& t : clump.spheres)
      best = std::min(best, (clump.orientation * t.center + clump.position - want).norm());
    EXPECT_LT(best, 1e-12);
  }
  EXPECT_GT(clump.mass / spec.rock_density, 0.0);
  EXPECT_DOUBLE_EQ(world.options().timestep, spec.timestep_safety * critical_timestep(world));
  EXPECT_EQ(world.options().contact.local_damping, 0.1);
  EXPECT_EQ(world.options().contact.damping_ratio, 0.5);
  EXPECT_THROW(make_deposition_world(items, {}, spec), InvalidInput);
}

TEST(Deposition, LatticePorosityOfOneSphereMatchesItsVolume) {
  World world;
  world.add_body(make_sphere_body(Vec3(0.0, 0.0, 0.05), 0.02, 1000.0));
  // Region: cylinder r < 0.03, z in [0.02, 0.08] holds the whole sphere.
  const double region = M_PI * 0.03 * 0.03 * 0.06;
  const double sphere = 4.0 / 3.0 * M_PI * std::pow(0.02, 3);
  EXPECT_NEAR(lattice_porosity(world, 0.03, 0.02, 0.08, 2.5e-4), 1.0 - sphere / region, 2e-3);
  EXPECT_THROW(lattice_porosity(world, 0.03, 0.08, 0.02, 1e-3), InvalidInput);
  EXPECT_THROW(lattice_porosity(world, 0.03, 0.02, 0.08, 0.0), InvalidInput);
}

}  // namespace
}  // namespace clumpkit::dem
