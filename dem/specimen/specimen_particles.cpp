#include "dem/specimen/specimen_particles.h"

#include "geom/errors.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace clumpkit::dem {

std::vector<ParticleClass> replace_fines(const std::vector<SieveClass>& gradation,
                                         double fines_below, double fines_min, double fines_max,
                                         double soil_rock_threshold) {
  require(kFinesBelow, fines_below, "fines: below");
  require(kSoilRockThreshold, soil_rock_threshold, "soil-rock threshold");
  std::vector<ParticleClass> classes;
  double fines = 0.0;
  for (const SieveClass& c : gradation) {
    if (c.mass_percent <= 0) continue;
    if (c.max_size <= fines_below + 1e-12) {
      fines += c.mass_percent;
      continue;
    }
    classes.push_back(
        {c.min_size, c.max_size, c.mass_percent, c.min_size >= soil_rock_threshold - 1e-12});
  }
  if (fines > 0) {
    auto it = std::find_if(classes.begin(), classes.end(), [&](const ParticleClass& c) {
      return std::abs(c.min_size - fines_min) < 1e-12 && std::abs(c.max_size - fines_max) < 1e-12;
    });
    if (it != classes.end())
      it->mass_percent += fines;
    else
      classes.push_back({fines_min, fines_max, fines, fines_min >= soil_rock_threshold});
  }
  return classes;
}

std::vector<double> class_volumes(const std::vector<ParticleClass>& classes, double solid_volume,
                                  double soil_density, double rock_density) {
  if (!(solid_volume > 0) || !(soil_density > 0) || !(rock_density > 0))
    throw InvalidInput("class_volumes: volume and densities must be positive");
  double specific = 0.0;  // Σ p_k / ρ_k, volume per unit mass
  for (const ParticleClass& c : classes)
    specific += c.mass_percent / 100.0 / (c.rock ? rock_density : soil_density);
  if (!(specific > 0)) throw InvalidInput("class_volumes: the gradation holds no mass");
  const double mass = solid_volume / specific;
  std::vector<double> out;
  for (const ParticleClass& c : classes)
    out.push_back(c.mass_percent / 100.0 * mass / (c.rock ? rock_density : soil_density));
  return out;
}

LayerParticles layer_particles(const std::vector<ParticleClass>& classes,
                               const std::vector<RockTemplate>& templates, double solid_volume,
                               double soil_density, double rock_density, Rng& rng) {
  const std::vector<double> goal = class_volumes(classes, solid_volume, soil_density, rock_density);
  struct Drawn {
    Body body;
    double bound;
  };
  std::vector<Drawn> drawn;
  LayerParticles out;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const ParticleClass& c = classes[k];
    if (!(c.min_size > 0) || !(c.max_size >= c.min_size))
      throw InvalidInput("layer_particles: class " + std::to_string(k) + " has bad sizes");
    if (c.rock && templates.empty())
      throw InvalidInput("layer_particles: rock class " + std::to_string(k) +
                         " but the library holds no templates");
    double volume = 0.0;
    while (volume < goal[k]) {
      const double size = rng.uniform(c.min_size, c.max_size);
      Drawn d;
      double v = 0.0;
      if (c.rock) {
        const int index = static_cast<int>(rng.below(templates.size()));
        const RockTemplate& t = templates[index];
        const double s = size / t.sieve_size;
        d.body = make_clump_body(t.clump, rock_density, Vec3::Zero(),
                                 Eigen::Quaterniond::Identity(), s, index);
        v = d.body.volume;
      } else {
        d.body = make_sphere_body(Vec3::Zero(), 0.5 * size, soil_density);
        v = M_PI / 6.0 * size * size * size;
      }
      // Keep the last particle only when it brings the class closer to its goal.
      if (volume + v - goal[k] > goal[k] - volume) break;
      d.bound = d.body.bounding_radius();
      volume += v;
      (c.rock ? out.rock_volume : out.soil_volume) += v;
      drawn.push_back(std::move(d));
    }
  }
  // Rocks first, then soil; each largest first (stable, so equal sizes keep draw order).
  std::stable_sort(drawn.begin(), drawn.end(), [](const Drawn& a, const Drawn& b) {
    const bool ra = a.body.kind == BodyKind::rock, rb = b.body.kind == BodyKind::rock;
    if (ra != rb) return ra;
    return a.bound > b.bound;
  });
  for (Drawn& d : drawn) out.bodies.push_back(std::move(d.body));
  return out;
}

std::vector<PlacementItem> placement_items(const std::vector<Body>& bodies) {
  std::vector<PlacementItem> items;
  items.reserve(bodies.size());
  for (const Body& b : bodies) items.push_back({b.spheres, b.bounding_radius()});
  return items;
}

}  // namespace clumpkit::dem
