// Tests of the gravity deposition of a placed assembly in a cylinder (specimen stage 1).
#include "dem/specimen/deposition.h"
#include "dem/core/timestep.h"
#include "dem/run/run.h"
#include "dem/specimen/specimen_particles.h"
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

/// `count` soil spheres of radius 4–8 mm and density 2700 kg/m³, largest first.
std::vector<Body> soil_bodies(int count = 150) {
  Rng rng(31);
  std::vector<double> radii;
  for (int i = 0; i < count; ++i) radii.push_back(rng.uniform(0.004, 0.008));
  std::sort(radii.rbegin(), radii.rend());
  std::vector<Body> bodies;
  for (double r : radii) bodies.push_back(make_sphere_body(Vec3::Zero(), r, 2700.0));
  return bodies;
}

/// Settles until the mean unbalanced-force ratio is below 1e-3 (at most 200,000 steps).
RunOutcome deposit(World& world) {
  RunLimits limits;
  limits.max_steps = 200000;
  limits.unbalanced_ratio_below = 1e-3;
  return run_until(world, limits);
}

/// Porosity estimate of the cylindrical sub-region r < radius (around the z-axis),
/// z in [z_lo, z_hi]: the fraction of the points of a cubic lattice of the given spacing inside
/// the region that lie in no sphere of any body; an estimate independent of the exact
/// sphere–region volumes of dem/measure/region_volume.h.
double lattice_porosity(const World& world, double radius, double z_lo, double z_hi,
                        double spacing) {
  if (!(radius > 0) || !(spacing > 0) || !(z_hi > z_lo) || !std::isfinite(radius) ||
      !std::isfinite(z_lo) || !std::isfinite(z_hi))
    throw InvalidInput("lattice_porosity: need radius > 0, spacing > 0 and z_hi > z_lo");
  const long nxy = static_cast<long>(std::ceil(2.0 * radius / spacing));
  const long nz = static_cast<long>(std::ceil((z_hi - z_lo) / spacing));
  const auto coord = [&](long i, double lo) {
    return lo + (static_cast<double>(i) + 0.5) * spacing;
  };
  // Point (i, j, k) is in the region when its centre is inside the disc and below z_hi.
  const auto in_region = [&](long i, long j, long k) {
    const double x = coord(i, -radius), y = coord(j, -radius), z = coord(k, z_lo);
    return x * x + y * y < radius * radius && z <= z_hi;
  };
  std::vector<char> solid(static_cast<std::size_t>(nxy * nxy * nz), 0);
  const auto clamp_index = [&](double v, double lo, long n) {
    return std::clamp(static_cast<long>(std::floor((v - lo) / spacing - 0.5)), 0L, n - 1);
  };
  for (const Body& body : world.bodies()) {
    for (const Sphere& s : body.spheres) {
      const Vec3 c = body.orientation * s.center + body.position;
      const double r = s.radius;
      if (c.z() + r < z_lo || c.z() - r > z_hi || std::hypot(c.x(), c.y()) - r > radius) continue;
      const long i0 = clamp_index(c.x() - r, -radius, nxy),
                 i1 = clamp_index(c.x() + r, -radius, nxy) + 1;
      const long j0 = clamp_index(c.y() - r, -radius, nxy),
                 j1 = clamp_index(c.y() + r, -radius, nxy) + 1;
      const long k0 = clamp_index(c.z() - r, z_lo, nz), k1 = clamp_index(c.z() + r, z_lo, nz) + 1;
      for (long k = k0; k <= std::min(k1, nz - 1); ++k)
        for (long j = j0; j <= std::min(j1, nxy - 1); ++j)
          for (long i = i0; i <= std::min(i1, nxy - 1); ++i) {
            const Vec3 p(coord(i, -radius), coord(j, -radius), coord(k, z_lo));
            if ((p - c).squaredNorm() <= r * r)
              solid[static_cast<std::size_t>((k * nxy + j) * nxy + i)] = 1;
          }
    }
  }
  long total = 0, filled = 0;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < nxy; ++j)
      for (long i = 0; i < nxy; ++i)
        if (in_region(i, j, k)) {
          ++total;
          filled += solid[static_cast<std::size_t>((k * nxy + j) * nxy + i)];
        }
  if (total == 0) throw InvalidInput("lattice_porosity: the region holds no lattice point");
  return 1.0 - static_cast<double>(filled) / static_cast<double>(total);
}

double top_of(const World& world) {
  double top = 0.0;
  for (const Body& b : world.bodies())
    for (const Sphere& s : b.spheres)
      top = std::max(top, (b.orientation * s.center + b.position).z() + s.radius);
  return top;
}

// `count` soil spheres placed in the cylinder and deposited on 1 and 2 threads (in that order),
// each stopped by the unbalanced-force rule; `placed_height` the top of the placed assembly.
std::vector<World> deposit_on_one_and_two_threads(int count, double& placed_height) {
  const auto items = soil_bodies(count);
  Rng rng(5);
  const auto placements =
      place_in_cylinder(placement_items(items), kCylinder, rng, 200, &placed_height);
  DepositionSpec spec;
  spec.radius = kCylinder;
  std::vector<World> runs;
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    World world = make_deposition_world(items, placements, spec);
    const RunOutcome outcome = deposit(world);
    EXPECT_EQ(outcome.stopped_by, "unbalanced_ratio");
    EXPECT_LT(outcome.steps, 200000);
    EXPECT_LT(mean_unbalanced_force_ratio(world), 1e-3);
    runs.push_back(std::move(world));
  }
  return runs;
}

TEST(Deposition, SettlesInsideTheCylinderToARandomPackBitIdenticalForThreads) {
  const auto items = soil_bodies();
  double placed_height = 0.0;
  const std::vector<World> runs = deposit_on_one_and_two_threads(150, placed_height);
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

TEST(Deposition, WorldKeepsBodiesAndTheirTemplatesAndHasAStableTimestep) {
  const ClumpTemplate pair =
      make_clump_template(Clump{{{Vec3(-0.5, 0, 0), 0.8}, {Vec3(0.5, 0, 0), 0.8}}});
  std::vector<Body> items = {
      make_sphere_body(Vec3::Zero(), 0.01, 2700.0),
      make_clump_body(pair, 2870.0, Vec3::Zero(), Eigen::Quaterniond::Identity(), 0.01, 4)};
  std::vector<Placement> placements(2);
  placements[0].position = Vec3(0.0, 0.0, 0.01);
  placements[1].position = Vec3(0.0, 0.0, 0.04);
  placements[1].orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vec3::UnitY()));
  DepositionSpec spec;
  spec.radius = 0.05;
  const World world = make_deposition_world(items, placements, spec);
  ASSERT_EQ(world.bodies().size(), 2u);
  const double sphere_mass = 4.0 / 3.0 * M_PI * std::pow(0.01, 3) * 2700.0;
  EXPECT_NEAR(world.bodies()[0].mass, sphere_mass, 1e-12 * sphere_mass);
  EXPECT_EQ(world.bodies()[1].spheres.size(), 2u);
  // The clump keeps its template identity and mass, and its spheres land where the placement
  // put them.
  const Body& clump = world.bodies()[1];
  EXPECT_EQ(clump.kind, BodyKind::rock);
  EXPECT_EQ(clump.template_id, 4);
  EXPECT_EQ(clump.scale, 0.01);
  EXPECT_EQ(clump.mass, items[1].mass);
  EXPECT_EQ(world.bodies()[0].kind, BodyKind::soil);
  for (const Sphere& s : items[1].spheres) {
    const Vec3 want = placements[1].orientation * s.center + placements[1].position;
    double best = 1.0;
    for (const Sphere& t : clump.spheres)
      best = std::min(best, (clump.orientation * t.center + clump.position - want).norm());
    EXPECT_LT(best, 1e-12);
  }
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
TEST(Deposition, ThirtySpheresSettleBitIdenticalForThreads) {
  // The deposition above with 30 spheres, for the sanitizer pass (the 150-sphere test is
  // labelled long there): settled by the unbalanced-force rule, inside the walls, the same bytes
  // on 1 and 2 threads.
  const auto items = soil_bodies(30);
  double placed_height = 0.0;
  const std::vector<World> runs = deposit_on_one_and_two_threads(30, placed_height);
  const World& a = runs[0];
  const World& b = runs[1];
  ASSERT_EQ(a.bodies().size(), items.size());
  for (const Body& body : a.bodies()) {
    const Sphere& s = body.spheres[0];
    const Vec3 c = body.position + body.orientation * s.center;
    EXPECT_LT(std::hypot(c.x(), c.y()) + s.radius, kCylinder + 0.02 * s.radius);
    EXPECT_GT(c.z() - s.radius, -0.02 * s.radius);
  }
  EXPECT_LT(top_of(a), placed_height);
  std::printf("settled in %lld steps\n", static_cast<long long>(a.steps()));
  EXPECT_EQ(a.steps(), b.steps());
  for (std::size_t k = 0; k < a.bodies().size(); ++k)
    EXPECT_EQ(std::memcmp(a.bodies()[k].position.data(), b.bodies()[k].position.data(),
                          sizeof(double) * 3),
              0);
}

}  // namespace clumpkit::dem
