#include "dem/specimen/crushable_particles.h"

#include "geom/cells/cell_bonds.h"
#include "geom/errors.h"
#include "geom/format.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace clumpkit::dem {

namespace {

// The random streams of particle i: kFirstStream + 3i its shape, + 1 its cells' seeds, + 2 its
// faces' strength factors — above the specimen's own streams (the draw of the diameters and the
// placement use small indices), so no particle shares one with them.
constexpr std::uint64_t kFirstStream = std::uint64_t(1) << 32;

CrushableBodies make_particle(double diameter, const CrushableMaterial& m, std::uint64_t seed,
                              std::uint64_t i) {
  PolyhedronParams shape = m.shape;
  shape.diameter = diameter;
  const std::uint64_t first = kFirstStream + 3 * i;
  Rng shape_rng = Rng::stream(seed, first), cell_rng = Rng::stream(seed, first + 1),
      bond_rng = Rng::stream(seed, first + 2);
  const Mesh parent = make_polyhedron(shape, shape_rng);
  const Tessellation cells = voronoi_cells(parent, m.cells, cell_rng);
  const std::vector<CellBond> bonds = cell_bonds(cells, m.strength, bond_rng, m.face_subdivision);
  return crushable_bodies(cells, bonds, m.density, &m.fill);
}

}  // namespace

void validate(const CrushableMaterial& m) {
  validate(m.shape);
  validate(m.cells);
  validate(m.strength, "crushable.strength_factor");
  validate(m.fill);
  require(kCellSpheres, m.fill.spheres, "crushable particles: fill.spheres");
  require(kCellVoxels, m.fill.field.voxels, "crushable particles: fill.field.voxels");
  if (!(m.density > 0 && std::isfinite(m.density)))
    throw InvalidInput("crushable particles: density must be positive, got " +
                       format_number(m.density));
  if (m.face_subdivision < 0 || m.face_subdivision > 3)
    throw InvalidInput("crushable particles: face_subdivision must be in [0, 3], got " +
                       std::to_string(m.face_subdivision));
}

std::vector<CrushableBodies> crushable_particles(const std::vector<ParticleClass>& classes,
                                                 double solid_volume,
                                                 const CrushableMaterial& material,
                                                 std::uint64_t seed, Rng& rng) {
  validate(material);
  const std::vector<double> goal =
      class_volumes(classes, solid_volume, material.density, material.density);
  std::vector<double> diameters;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const ParticleClass& c = classes[k];
    if (!c.rock)
      throw InvalidInput("crushable particles: class " + std::to_string(k) + " (" +
                         format_number(c.min_size) + "–" + format_number(c.max_size) +
                         " m) is soil; a crushable specimen holds rock particles only");
    if (!(c.min_size > 0) || !(c.max_size >= c.min_size))
      throw InvalidInput("crushable particles: class " + std::to_string(k) + " has bad sizes");
    double volume = 0;
    while (volume < goal[k]) {
      const double d = rng.uniform(c.min_size, c.max_size);
      const double v = M_PI / 6 * d * d * d;
      if (volume + v - goal[k] > goal[k] - volume) break;
      volume += v;
      diameters.push_back(d);
    }
  }
  // Every parent's cell count first: a cell size at or above a particle is refused before any
  // work (cell_count names the sizes).
  for (double d : diameters) cell_count(material.cells, M_PI / 6 * d * d * d);
  std::vector<CrushableBodies> particles(diameters.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, diameters.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        particles[i] = make_particle(diameters[i], material, seed, i);
                    });
  // Largest first (stable: equal sizes keep the draw order).
  std::vector<std::size_t> order(particles.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return diameters[a] > diameters[b]; });
  std::vector<CrushableBodies> sorted;
  sorted.reserve(particles.size());
  for (std::size_t i : order) sorted.push_back(std::move(particles[i]));
  return sorted;
}

PlacementItem placement_item(const CrushableBodies& particle) {
  PlacementItem item;
  for (const Body& b : particle.cells)
    for (const Sphere& s : b.spheres) {
      item.spheres.push_back(Sphere{b.position + b.orientation * s.center, s.radius});
      item.bounding_radius =
          std::max(item.bounding_radius, item.spheres.back().center.norm() + s.radius);
    }
  return item;
}

double particle_volume(const CrushableBodies& particle) {
  double v = 0;
  for (const Body& b : particle.cells) v += b.volume;
  return v;
}

}  // namespace clumpkit::dem
