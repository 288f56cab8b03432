// Test fixture: a 2 × 2 × 4 column of bonded cubic cells (geom/cells) with driven end layers,
// shared by the bond tests of the World and of checkpoints.
#pragma once

#include "dem/core/crushable.h"
#include "dem/core/timestep.h"
#include "dem/core/world.h"
#include "geom/cells/cell_bonds.h"
#include "geom/shapes/primitives.h"

namespace clumpkit::dem::test {

constexpr double kCellEdge = 0.0065;  // m: Hu et al. 2023's cell size

// The body of a cubic cell of edge a at its centroid: one sphere of radius `radius` on it, the
// cube's mass and moments at density rho.
inline Body cube_cell_body(const Cell& cell, double a, double radius, double rho) {
  Body b;
  b.spheres = {Sphere{Vec3::Zero(), radius}};
  b.volume = a * a * a;
  b.mass = rho * b.volume;
  b.moments = Vec3::Constant(b.mass * a * a / 6.0);
  b.position = cell.mass.centroid;
  return b;
}

// A 2 × 2 × 4 column of cubic cells of edge a (Voronoi cells of grid seeds in a box), each body
// a sphere inscribed in its cube with the cube's mass and moments, bonded on every shared face.
// The bottom and top layers are driven (huge mass, no rotation): the top at `velocity` along z.
// With `octants` each body is eight spheres on the centres of its octants instead (several
// spheres a cell, as the fill makes them). `overlap` (× a) widens the spheres so that those of
// neighbouring cells overlap by that much across their face, as the fill's spheres reach across.
inline World bonded_column(double velocity, bool octants = false, double overlap = 0.0) {
  const double a = kCellEdge, rho = 2650;
  std::vector<Vec3> seeds;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) seeds.emplace_back((i - 0.5) * a, (j - 0.5) * a, (k - 1.5) * a);
  const Tessellation cells = voronoi_cells(make_box(Vec3(2 * a, 2 * a, 4 * a)), seeds);
  Rng rng(1);
  const std::vector<CellBond> faces = cell_bonds(cells, constant(1.0), rng);
  WorldOptions o;
  o.gravity = Vec3::Zero();
  World w(o);
  for (std::size_t c = 0; c < cells.cells.size(); ++c) {
    Body b = cube_cell_body(cells.cells[c], a, (0.5 + 0.5 * overlap) * a, rho);
    if (octants) {
      b.spheres.clear();
      for (int k = 0; k < 8; ++k)
        b.spheres.push_back(Sphere{0.25 * a * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1),
                                   (0.25 + 0.5 * overlap) * a});
    }
    const int layer = static_cast<int>(c) / 4;
    if (layer == 0 || layer == 3) {
      b.mass *= 1e12;
      b.moments *= 1e12;
      b.rotation_locked = true;
      if (layer == 3) b.velocity = Vec3(0, 0, velocity);
    }
    w.add_body(b);
  }
  add_cell_bonds(w, faces);
  w.options().timestep = 0.2 * critical_timestep(w);
  return w;
}

}  // namespace clumpkit::dem::test
