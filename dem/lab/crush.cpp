#include "dem/lab/crush.h"

#include "dem/core/bond.h"
#include "dem/core/timestep.h"
#include "dem/measure/stress.h"
#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace clumpkit::dem {

namespace {

void require(bool ok, const char* field, double value, const char* range) {
  if (!ok)
    throw InvalidInput(std::string("crushing test: ") + field + " must be " + range + ", got " +
                       format_number(value));
}

// The rig's ranges, in the words of geom's `require`, prefixed with the test.
void require(const Range& r, const char* field, double value) {
  clumpkit::require(r, value, std::string("crushing test: ") + field);
}

// The number of fragments and the largest one's mass fraction.
struct FragmentCount {
  int all = 0;
  double largest = 0.0;
};

FragmentCount count_fragments(const World& world) {
  const std::vector<Body>& bodies = world.bodies();
  const std::vector<int> label = fragments(static_cast<int>(bodies.size()), world.bonds());
  std::vector<double> mass(bodies.size(), 0.0);
  double total = 0.0;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    mass[label[k]] += bodies[k].mass;
    total += bodies[k].mass;
  }
  FragmentCount c;
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (label[k] != static_cast<int>(k)) continue;
    ++c.all;
    c.largest = std::max(c.largest, mass[k] / total);
  }
  return c;
}

}  // namespace

void validate(const CrushOptions& o) {
  require(o.axis >= 0 && o.axis <= 2, "axis", o.axis, "0, 1 or 2");
  require(kCrushStrainRate, "strain_rate", o.strain_rate);
  require(kFriction, "platen_friction", o.platen_friction);
  require(kPlatenStiffness, "platen_stiffness", o.platen_stiffness);
  require(kLocalDamping, "local_damping", o.local_damping);
  require(kTimestepSafety, "timestep_safety", o.timestep_safety);
  require(kDensityScaling, "density_scaling", o.density_scaling);
  require(kCrushMaxStrain, "max_strain", o.max_strain);
  require(o.sample_strain > 0 && o.sample_strain < o.max_strain, "sample_strain", o.sample_strain,
          "positive and below max_strain");
  require(kBedDepth, "bed_depth", o.bed_depth);
  require(kIntactFraction, "intact_fraction", o.intact_fraction);
}

CrushResult crush_particle(World& world, double diameter, const CrushOptions& o,
                           const Interrupter& interrupter) {
  validate(o);
  require(diameter > 0 && std::isfinite(diameter), "diameter", diameter, "positive");
  if (!world.walls().empty()) throw InvalidInput("crushing test: the world already has walls");
  const int axis = o.axis;
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Body& b : world.bodies())
    for (const Vec3& v : b.vertices) {
      const double x = (b.position + b.orientation * v)[axis];
      low = std::min(low, x);
      high = std::max(high, x);
    }
  if (!(high > low)) throw InvalidInput("crushing test: the particle has no corners");

  WorldOptions& wo = world.options();
  wo.gravity = Vec3::Zero();
  wo.vertex_stiffness = o.platen_stiffness;
  wo.contact.friction = o.platen_friction;
  wo.contact.local_damping = o.local_damping;
  for (Body& b : world.bodies()) {
    b.mass *= o.density_scaling;
    b.moments *= o.density_scaling;
    b.velocity = b.angular_velocity = Vec3::Zero();
  }
  CrushResult r;
  r.gap = high - low;
  if (o.bed_depth > 0)
    for (Body& b : world.bodies()) {
      double lowest = std::numeric_limits<double>::infinity();
      for (const Vec3& v : b.vertices)
        lowest = std::min(lowest, (b.position + b.orientation * v)[axis]);
      b.rotation_locked = lowest <= low + o.bed_depth * r.gap;
      r.bedded += b.rotation_locked ? 1 : 0;
    }
  const double speed = o.strain_rate * r.gap;  // closing speed, half on each platen
  const Vec3 n = Vec3::Unit(axis);
  Wall bottom = Wall::plane(n * low, n, 0.5 * speed * n);
  Wall top = Wall::plane(n * high, -n, -0.5 * speed * n);
  bottom.friction = top.friction = o.platen_friction;
  const int wb = world.add_wall(bottom), wt = world.add_wall(top);
  r.timestep = o.timestep_safety * critical_timestep(world);
  wo.timestep = r.timestep;

  const double travel_per_sample = o.sample_strain * r.gap;
  const int steps_per_sample =
      std::max(1, static_cast<int>(std::ceil(travel_per_sample / (speed * r.timestep))));
  const double max_travel = o.max_strain * r.gap;
  r.samples.push_back({0.0, 0.0, false, true});
  std::vector<double> difference{0.0};
  for (;;) {
    world.step(steps_per_sample);
    r.steps += steps_per_sample;
    const double travel = speed * world.time();
    const double lower = -wall_force(world, wb).dot(n), upper = wall_force(world, wt).dot(n);
    const double force = 0.5 * (lower + upper);
    difference.push_back(std::abs(lower - upper));
    const FragmentCount f = count_fragments(world);
    r.samples.push_back({travel, force, f.largest < o.intact_fraction, f.all == 1});
    r.peak = crushing_peak(r.samples, diameter, o.rule);
    if (r.peak.found || travel >= max_travel) break;
    if (interrupted(interrupter, "crush", travel / max_travel))
      throw Interrupted("crushing test interrupted");
  }
  const std::size_t last = r.peak.found ? r.peak.index : r.samples.size() - 1;
  double fmax = 0.0, dsum = 0.0;
  for (std::size_t i = 0; i <= last; ++i) {
    fmax = std::max(fmax, r.samples[i].force);
    dsum += difference[i];
  }
  r.imbalance = fmax > 0.0 ? dsum / static_cast<double>(last + 1) / fmax : 0.0;
  const FragmentCount f = count_fragments(world);
  r.fragments = f.all;
  r.largest_fragment = f.largest;
  return r;
}

}  // namespace clumpkit::dem
