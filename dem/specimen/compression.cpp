#include "dem/specimen/compression.h"

#include "dem/specimen/container.h"

#include "dem/core/crushable.h"
#include "dem/core/timestep.h"
#include "dem/lab/cell.h"
#include "dem/measure/sampled_porosity.h"
#include "dem/measure/stress.h"
#include "dem/specimen/zoned_packing.h"
#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace clumpkit::dem {

namespace {

enum CompressionStream : std::uint64_t { particles_stream = 11, placement_stream = 12 };

constexpr const char* kCompressionStage = "compression";

// The container of `size` (cuboid edges, or diameter, diameter, height), centred on the z-axis
// and standing on z = 0: its walls' positions.
struct Box {
  Vec3 lo, hi;
  double radius = 0;  // cylinder
};

Box container(const Vec3& size) {
  Box b;
  b.lo = Vec3(-0.5 * size.x(), -0.5 * size.y(), 0.0);
  b.hi = Vec3(0.5 * size.x(), 0.5 * size.y(), size.z());
  b.radius = 0.5 * size.x();
  return b;
}

// Every body at rest (the quench of the closing, and the finished specimen).
void stop_bodies(World& world) {
  for (Body& b : world.bodies()) b.velocity = b.angular_velocity = Vec3::Zero();
}

double container_volume(const CompressionSpec& spec, const Vec3& size) {
  const double disk = spec.shape == CompressionSpec::Shape::segment ? 0.5 * spec.angle : M_PI;
  return spec.shape == CompressionSpec::Shape::cuboid
             ? size.prod()
             : disk * 0.25 * size.x() * size.x() * size.z();
}

Prism prism_of(const CompressionSpec& spec, const Vec3& size) {
  Prism p;
  p.shape = spec.shape == CompressionSpec::Shape::cuboid     ? Prism::Shape::cuboid
            : spec.shape == CompressionSpec::Shape::cylinder ? Prism::Shape::cylinder
                                                             : Prism::Shape::segment;
  p.size = size;
  p.angle = spec.angle;
  return p;
}

bool zoned(const CompressionSpec& spec) {
  return !spec.zones.regions.empty();
}

// The largest class size: the core's largest particle.
double largest_size(const CompressionSpec& spec) {
  double d = 0;
  for (const ParticleClass& c : spec.classes) d = std::max(d, c.max_size);
  return d;
}

// The largest rectangle |y'| ≤ w, x0 ≤ x' ≤ x1 inside the sector |φ'| ≤ angle/2 of the disk of
// `radius` (the sector's bisector along x'): w = x0·tan(angle/2), x1 = sqrt(R² − w²), x0 chosen
// by a fixed search (so the same for every run). A half-disk (angle π) takes its inscribed
// square's half.
std::array<double, 3> sector_box(double radius, double angle) {
  if (angle >= M_PI - 1e-12) return {0.0, radius * M_SQRT1_2, radius * M_SQRT1_2};
  const double t = std::tan(0.5 * angle);
  double best = -1, x0_best = 0;
  for (int k = 1; k < 400; ++k) {
    const double x0 = radius / std::sqrt(1.0 + t * t) * k / 400.0;
    const double w = x0 * t, x1 = std::sqrt(radius * radius - w * w);
    const double area = (x1 - x0) * 2.0 * w;
    if (area > best) best = area, x0_best = x0;
  }
  const double w = x0_best * t;
  return {x0_best, std::sqrt(radius * radius - w * w), w};
}

// Moves the cell's walls to the container `b`.
void set_walls(World& world, const TestCell& cell, const Box& b) {
  std::vector<Wall>& w = world.walls();
  w[cell.bottom].point.z() = b.lo.z();
  w[cell.top].point.z() = b.hi.z();
  if (cell.shape != TestCell::Shape::cuboid) {  // a segment's planes pass through the axis
    w[cell.lateral[0]].radius = b.radius;
  } else {
    w[cell.lateral[0]].point.x() = b.lo.x();
    w[cell.lateral[1]].point.x() = b.hi.x();
    w[cell.lateral[2]].point.y() = b.lo.y();
    w[cell.lateral[3]].point.y() = b.hi.y();
  }
}

void validate(const CompressionSpec& spec) {
  try {
    for (int a = 0; a < 3; ++a) check_container_length(spec.size[a]);
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string("compression: container size: ") + e.what());
  }
  if (spec.shape != CompressionSpec::Shape::cuboid && spec.size.x() != spec.size.y())
    throw InvalidInput("compression: a cylinder's size is (diameter, diameter, height)");
  if (spec.shape == CompressionSpec::Shape::segment)
    require(kSegmentAngleDegrees, spec.angle * 180.0 / M_PI,
            "compression: segment angle (degrees)");
  require(kDensity, spec.soil_density, "compression: soil density");
  require(kDensity, spec.rock_density, "compression: rock density");
  if (!kTargetPorosity.contains(spec.porosity))
    throw InvalidInput("compression: porosity " + outside(kTargetPorosity, spec.porosity) +
                       ", got " + format_number(spec.porosity));
  if (!kFriction.contains(spec.friction))
    throw InvalidInput("compression: friction " + outside(kFriction, spec.friction) + ", got " +
                       format_number(spec.friction));
  if (!(spec.loose_factor > 1.0 && spec.loose_factor <= 10.0))
    throw InvalidInput("compression: loose_factor must be in (1, 10]");
  if (!(spec.strain_per_step > 0.0 && spec.strain_per_step < 0.01))
    throw InvalidInput("compression: strain_per_step must be in (0, 0.01)");
  require(kTimestepSafety, spec.timestep_safety, "compression: timestep_safety");
  if (spec.relax_max_steps < 0 || !(spec.relax_unbalanced >= 0))
    throw InvalidInput("compression: relaxation limits must not be negative");
  if (!(spec.wall_excess >= 0.0 && spec.wall_excess < 1.0))
    throw InvalidInput("compression: wall_excess must be in [0, 1), got " +
                       format_number(spec.wall_excess));
  if (spec.crushable && zoned(spec))
    throw InvalidInput("compression: a crushable specimen cannot be zoned");
  if (spec.crushable) validate(*spec.crushable);
  if (zoned(spec)) {
    validate_zones(spec.zones, largest_size(spec));
    if (spec.mixed_porosity != 0.0 && !kTargetPorosity.contains(spec.mixed_porosity))
      throw InvalidInput("compression: mixed_porosity " +
                         outside(kTargetPorosity, spec.mixed_porosity) +
                         " (or 0: the porosity), got " + format_number(spec.mixed_porosity));
  }
}

// The loose packing of `bodies` in the container of `size` enlarged by `factor` (more while too
// crowded; the same stream goes on, so the result stays fixed by the seed): the world with the
// cell's walls there and its time step; `factor` and `cell` as built.
// A zoned specimen (`in_zones` not null) places each body in its zone's pre-image (place_zoned),
// so its bodies are not turned by the segment's bisector rotation.
World loose_packing(const CompressionSpec& spec, std::vector<Body> bodies,
                    const std::vector<CrushableBodies>& crushable, const ZonedParticles* in_zones,
                    const Vec3& size, double& factor, TestCell& cell) {
  const bool cuboid = spec.shape == CompressionSpec::Shape::cuboid;
  const bool segment = spec.shape == CompressionSpec::Shape::segment;
  Rng place_rng = Rng::stream(spec.seed, placement_stream);
  std::vector<PlacementItem> items = placement_items(bodies);
  for (const CrushableBodies& p : crushable) items.push_back(placement_item(p));
  std::vector<Placement> placed;
  for (int tries = 0; placed.empty(); ++tries) {
    if (tries == 40) throw InvalidInput("compression: no room for the loose packing");
    if (in_zones) {
      placed = place_zoned(*in_zones, spec.zones, prism_of(spec, size), factor, place_rng);
      if (placed.empty()) factor *= 1.1;
      continue;
    }
    const Box loose = container(size * factor);
    Vec3 lo = loose.lo, hi = loose.hi;
    if (segment) {  // a box inside the sector, about its bisector (turned onto it below)
      const std::array<double, 3> b = sector_box(loose.radius, spec.angle);
      lo.head<2>() = Eigen::Vector2d(b[0], -b[2]);
      hi.head<2>() = Eigen::Vector2d(b[1], b[2]);
    } else if (!cuboid) {  // the cylinder's inscribed square prism: every body inside it
      lo.head<2>() *= M_SQRT1_2;
      hi.head<2>() *= M_SQRT1_2;
    }
    placed = place_in_box(items, lo, hi, place_rng, 1000);
    if (placed.empty()) factor *= 1.1;
  }

  WorldOptions o;
  o.gravity = Vec3::Zero();
  o.sort_every = 1000;  // placement order is random: sort for locality (as LAMMPS)
  o.contact = spec.contact;
  o.contact.friction = spec.friction;
  // Strong local damping while closing (PFC's default 0.7): mapping the centres creates overlaps
  // whose springs would otherwise pump energy into the packing (measured: with α = 0.1 the
  // kinetic energy of 1,100 spheres grew to 600 J, ~30 m/s). The specimen keeps the spec's.
  o.contact.local_damping = std::max(spec.contact.local_damping, 0.7);
  double r_min = 1e300;
  for (const Body& b : bodies)
    for (const Sphere& s : b.spheres) r_min = std::min(r_min, s.radius);
  for (const CrushableBodies& p : crushable)
    for (const Body& b : p.cells)
      for (const Sphere& s : b.spheres) r_min = std::min(r_min, s.radius);
  if (!crushable.empty()) {
    // Intact bonds while the specimen is made: the closing's map and its quenches load the
    // contacts far above the final stress (a mean stress of 0.8 MPa while closing at 1e-4 per
    // step to n = 0.65, 0.17 MPa at 1e-5, against kPa once relaxed), which would break bonds
    // that the specimen at rest never loads: the same stiffness, bonds that cannot fail
    // (dem::unbreakable). finish_specimen restores the material's law. Bodies keep their
    // indices: the closing moves each particle's cells together (groups).
    o = cell_packing_options(o, unbreakable(spec.cohesive));
  }
  o.skin = 0.2 * r_min;  // a length of the specimen: similar specimens scale exactly
  World world(o);
  world.reserve(bodies);
  // From the bisector's frame into the sector (zoned segments' bodies are placed in it already;
  // crushable specimens have no zones).
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(segment ? 0.5 * spec.angle : 0.0, Vec3::UnitZ()));
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    Body b = std::move(bodies[k]);
    b.position = placed[k].position;
    b.orientation = placed[k].orientation;
    if (segment && !in_zones) b.position = turn * b.position, b.orientation = turn * b.orientation;
    world.add_body(std::move(b));
  }
  for (std::size_t k = 0; k < crushable.size(); ++k) {
    const Placement& p = placed[bodies.size() + k];
    add_crushable(world, crushable[k], turn * p.orientation, turn * p.position);
  }
  const Box start = container(size * factor);
  cell = cuboid ? add_cuboid_test_cell(world, start.lo, start.hi)
         : segment
             ? add_segment_test_cell(world, start.radius, spec.angle, start.lo.z(), start.hi.z())
             : add_cylinder_test_cell(world, start.radius, start.lo.z(), start.hi.z());
  world.options().timestep = spec.timestep_safety * critical_timestep(world);
  return world;
}

// The bodies that move together while the container closes: each crushable particle's cells
// (bodies joined by a bond, broken or not: a resumed closing groups them as a fresh one did),
// as runs of consecutive indices (a particle's cells are added together and the world is not
// sorted); a body of its own is a run of one. Empty without bonds: every body maps alone.
struct Groups {
  std::vector<int> first;  // start of each run, then the body count
};

Groups bonded_groups(const World& world) {
  Groups g;
  if (world.bonds().empty()) return g;
  const int n = static_cast<int>(world.bodies().size());
  std::vector<Bond> joined = world.bonds();
  for (Bond& b : joined)
    for (BondPoint& p : b.points) p.state = CohesiveState{};
  const std::vector<int> label = fragments(n, joined);
  for (int k = 0; k < n; ++k)
    if (k == 0 || label[k] != label[k - 1]) g.first.push_back(k);
  g.first.push_back(n);
  return g;
}

// The closing's map x → c_new + ratio·(x − c_old): of every body's centroid, or of each group's
// mass centroid with its bodies translated along (a bonded particle moves as one piece).
void map_positions(World& world, const Groups& groups, const Vec3& c_old, const Vec3& c_new,
                   double ratio) {
  std::vector<Body>& bodies = world.bodies();
  if (groups.first.empty()) {
    for (Body& b : bodies) b.position = c_new + ratio * (b.position - c_old);
    return;
  }
  for (std::size_t g = 0; g + 1 < groups.first.size(); ++g) {
    double mass = 0;
    Vec3 c = Vec3::Zero();
    for (int k = groups.first[g]; k < groups.first[g + 1]; ++k) {
      mass += bodies[k].mass;
      c += bodies[k].mass * bodies[k].position;
    }
    c /= mass;
    const Vec3 shift = c_new + ratio * (c - c_old) - c;
    for (int k = groups.first[g]; k < groups.first[g + 1]; ++k) bodies[k].position += shift;
  }
}

// Re-tags every body by the zone of its final centre, counting those that left the zone they
// were placed in, the migrated ones among them (more than their own diameter beyond it) and the
// mis-zoned ones (into a zone drawn without their size, by more than the largest diameter of
// either zone: a small sphere of a mixed layer that drifts into a core of the same spheres, or
// into a pocket of the large spheres' first layer, is not out of place), and measures each
// zone's porosity one of its largest diameters from the walls.
void measure_zones(const CompressionSpec& spec, const Prism& prism, World& world,
                   CompressionResult& r) {
  const ZoneLayout& layout = spec.zones;
  const int n = static_cast<int>(layout.regions.size());
  // The bounding diameters drawn for each zone (bodies still carry the zone they were placed in).
  std::vector<double> d_lo(n, std::numeric_limits<double>::infinity()), d_hi(n, 0.0);
  for (const Body& b : world.bodies()) {
    d_lo[b.zone] = std::min(d_lo[b.zone], 2.0 * b.bounding_radius());
    d_hi[b.zone] = std::max(d_hi[b.zone], 2.0 * b.bounding_radius());
  }
  double r_min = std::numeric_limits<double>::infinity();
  for (Body& b : world.bodies()) {
    const double c = zone_coordinate(layout, b.position);
    const int k = region_of(layout, c);
    if (k != b.zone) {
      ZoneResult& placed = r.zones[b.zone];
      ++placed.left_zone, ++r.left_zone;
      const double beyond =
          std::max(b.zone > 0 ? placed.inner - c : 0.0, b.zone + 1 < n ? c - placed.outer : 0.0);
      const double d = 2.0 * b.bounding_radius();
      if (beyond > d) {
        ++placed.migrated, ++r.migrated;
        if (mis_zoned(d, beyond, d_hi[b.zone], d_lo[k], d_hi[k])) ++placed.mis_zoned, ++r.mis_zoned;
      }
    }
    b.zone = k;
    ++r.zones[k].count;
    r.zones[k].margin = std::max(r.zones[k].margin, 2.0 * b.bounding_radius());
    for (const Sphere& s : b.spheres) r_min = std::min(r_min, s.radius);
  }
  Vec3 lo, hi;
  prism.bounds(lo, hi);
  const std::vector<SampledRegion> sampled =
      sampled_regions(world, lo, hi, 0.2 * r_min, n, [&](const Vec3& p) {
        if (!prism.holds(p)) return -1;
        const int k = region_of(layout, zone_coordinate(layout, p));
        return prism.wall_distance(p) >= r.zones[k].margin ? k : -1;
      });
  for (int k = 0; k < n; ++k) r.zones[k].porosity = sampled[k].porosity();
}

// The particles of the requested container: zoned, each region's for its own volume and
// porosity (zoned_particles, `zones` filled with what each was to hold, `goal` their solid
// volume); crushable, into `crushable`; else one draw of the classes for `goal`.
ZonedParticles draw_particles(const CompressionSpec& spec, Rng& particle_rng, double& goal,
                              std::vector<ZoneResult>& zones,
                              std::vector<CrushableBodies>& crushable) {
  ZonedParticles in_zones;
  if (spec.crushable) {
    crushable = crushable_particles(spec.classes, goal, *spec.crushable, spec.seed, particle_rng);
    return in_zones;
  }
  if (zoned(spec)) {
    const ZoneVolumes v = zone_volumes(spec.zones, prism_of(spec, spec.size));
    const double n_mixed = spec.mixed_porosity > 0.0 ? spec.mixed_porosity : spec.porosity;
    in_zones = zoned_particles(spec.zones, v, spec.classes, spec.templates, spec.porosity, n_mixed,
                               spec.wall_excess, spec.soil_density, spec.rock_density, spec.seed);
    goal = 0;
    zones.resize(spec.zones.regions.size());
    for (std::size_t k = 0; k < zones.size(); ++k) {
      ZoneResult& z = zones[k];
      z.inner = inner_bound(spec.zones, int(k));
      z.outer = spec.zones.regions[k].outer;
      z.volume = v.volume[k];
      z.target_porosity = spec.zones.regions[k].mixed ? n_mixed : spec.porosity;
      z.solid_goal = in_zones.goal[k];
      goal += in_zones.goal[k];
    }
    for (const Body& b : in_zones.bodies) zones[b.zone].solid_drawn += b.volume;
  } else {
    in_zones.bodies = layer_particles(spec.classes, spec.templates, goal, spec.soil_density,
                                      spec.rock_density, particle_rng)
                          .bodies;
  }
  return in_zones;
}

// The specimen: at rest, with the material friction (shear history rescaled), measured in its
// container of `size`.
void finish_specimen(const CompressionSpec& spec, const Vec3& size, double solid,
                     std::vector<ZoneResult>& zones, CompressionResult& r) {
  World& world = r.world;
  const bool cuboid = spec.shape == CompressionSpec::Shape::cuboid;
  stop_bodies(world);
  if (spec.crushable) world.options().cohesive = spec.cohesive;
  world.rescale_friction(spec.contact.friction);
  world.options().contact.local_damping = spec.contact.local_damping;
  const Box end = container(size);
  r.lo = end.lo;
  r.hi = end.hi;
  r.radius = cuboid ? 0.0 : end.radius;
  r.angle = spec.shape == CompressionSpec::Shape::segment ? spec.angle : 0.0;
  r.height = size.z();
  const double volume = container_volume(spec, size);
  r.porosity = 1.0 - solid / volume;
  r.coordination = coordination_number(world);
  r.mean_stress = mean_stress(love_weber_stress(
      world, [](const Vec3&) { return true; }, volume));
  if (zoned(spec)) {
    r.zones = std::move(zones);
    measure_zones(spec, prism_of(spec, size), world, r);
  }
}

}  // namespace

CompressionResult compress_specimen(const CompressionSpec& spec, const StageControl& control) {
  validate(spec);
  StageStore& store = store_of(control);
  store.open(compression_fingerprint(spec));

  // The particles for the requested container, then the container resized so that they fill it
  // at exactly the target porosity (the drawn volume misses the goal by part of a particle).
  // Drawn on a resume too: the size follows from them.
  // Zoned: each region drawn for its own volume and porosity (zoned_particles).
  Rng particle_rng = Rng::stream(spec.seed, particles_stream);
  double goal = (1.0 - spec.porosity) * container_volume(spec, spec.size);
  std::vector<ZoneResult> zones;
  std::vector<CrushableBodies> crushable;
  const ZonedParticles in_zones = draw_particles(spec, particle_rng, goal, zones, crushable);
  if (in_zones.bodies.empty() && crushable.empty())
    throw InvalidInput("compression: the container holds no particle");
  double solid = 0;
  for (const Body& b : in_zones.bodies) solid += b.volume;
  for (const CrushableBodies& p : crushable) solid += particle_volume(p);
  const Vec3 size = zoned(spec) ? Vec3(spec.size * std::cbrt(solid / goal))
                                : Vec3(spec.size * std::cbrt(solid / (1.0 - spec.porosity) /
                                                             container_volume(spec, spec.size)));

  CompressionResult r;
  r.target_porosity = spec.porosity;
  World& world = r.world;
  TestCell cell;
  double factor = spec.loose_factor;  // of the loose packing's container
  long first_step = 1;                // of the closing
  double s = 0;                       // the container's scale before first_step
  long relax = 0;                     // relaxation steps done
  r.relaxed_by = "step_cap";
  bool relaxed = false;  // the relaxation ended (the stage finished)
  CheckpointInfo info;
  if (const std::optional<StageRecord> done = store.finished(kCompressionStage)) {
    world = store.finished_world(kCompressionStage);
    cell = read_cell(*done, kCompressionStage);
    factor = record_number(*done, "factor", kCompressionStage);
    relax = static_cast<long>(record_integer(*done, "relax_steps", kCompressionStage));
    const auto by = done->find("relaxed_by");
    if (by != done->end()) r.relaxed_by = by->second;
    relaxed = true;
  } else if (std::optional<World> running = store.running(kCompressionStage, info)) {
    world = std::move(*running);
    cell = read_cell(info.state, kCompressionStage);
    factor = record_number(info.state, "factor", kCompressionStage);
    first_step =
        static_cast<long>(record_integer(info.state, "closing_step", kCompressionStage)) + 1;
    s = record_number(info.state, "scale", kCompressionStage);
    relax = static_cast<long>(record_integer(info.state, "relax_steps", kCompressionStage));
  } else {
    world = loose_packing(spec, in_zones.bodies, crushable, zoned(spec) ? &in_zones : nullptr, size,
                          factor, cell);
    s = factor;
  }
  // The checkpointed state: where the closing and the relaxation are.
  long k = first_step - 1;
  StageCheckpoints checkpoints(store, control, kCompressionStage);
  const auto state = [&] {
    StageRecord st;
    put_cell(st, cell);
    put_number(st, "factor", factor);
    st["closing_step"] = std::to_string(k);
    put_number(st, "scale", s);
    st["relax_steps"] = std::to_string(relax);
    return st;
  };
  const auto stop = [&](double fraction) {
    if (checkpoints.check(world, state, "compression", fraction))
      throw Interrupted(std::string("compression: stopped on request") +
                        (store.keeps_checkpoints() ? " (checkpoint kept)" : ""));
  };

  // Closing: the container's scale s goes from `factor` to 1 by strain_per_step of the current
  // size each step; every body centre is mapped by the same ratio about the container's centre
  // (x, y about the axis, z about mid-height), so the packing densifies evenly.
  const long steps =
      static_cast<long>(std::ceil(std::log(factor) / -std::log1p(-spec.strain_per_step)));
  const Vec3 centre(0.0, 0.0, 0.5 * size.z());
  const Groups groups = bonded_groups(world);
  if (!relaxed)
    for (k = first_step; k <= steps; ++k) {
      const double next =
          k == steps ? 1.0 : factor * std::pow(1.0 - spec.strain_per_step, double(k));
      const Vec3 c_old = centre * s, c_new = centre * next;
      const double ratio = next / s;
      map_positions(world, groups, c_old, c_new, ratio);
      s = next;
      set_walls(world, cell, container(size * s));
      // Quench: every 100 steps all bodies stop (a steepest-descent relaxation between small
      // affine steps, as in jamming studies), so no kinetic energy builds up while the
      // container closes (with α = 0.7 alone it still reached 28 J).
      if (k % 100 == 0) stop_bodies(world);
      world.step(1);
      if (k % 1000 == 0) stop(0.9 * double(k) / double(steps));
    }
  k = steps;
  r.compression_steps = steps;

  // Relaxation at the final size.
  while (!relaxed && relax < spec.relax_max_steps) {
    world.step(100);
    relax += 100;
    if (mean_unbalanced_force_ratio(world) < spec.relax_unbalanced) {
      r.relaxed_by = "unbalanced_ratio";
      break;
    }
    if (relax % 1000 == 0) stop(0.9 + 0.1 * double(relax) / double(spec.relax_max_steps));
  }
  r.relax_steps = relax;
  r.timestep = world.options().timestep;
  if (!relaxed) {
    StageRecord record = state();
    record["relaxed_by"] = r.relaxed_by;
    store.finish(kCompressionStage, record, &world);
  }

  finish_specimen(spec, size, solid, zones, r);
  return r;
}

}  // namespace clumpkit::dem
