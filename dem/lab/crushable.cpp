#include "dem/lab/crushable.h"

#include "geom/errors.h"
#include "geom/fill/fill.h"
#include "geom/format.h"
#include "geom/template/clump_template.h"

#include <algorithm>
#include <limits>

namespace clumpkit::dem {

Body cell_body(const Cell& cell, double density) {
  if (!(density > 0.0) || !std::isfinite(density))
    throw InvalidInput("crushable particle: density must be positive, got " +
                       format_number(density));
  if (!(cell.mass.volume > 0.0)) throw InvalidInput("crushable particle: a cell has no volume");
  Vec3 moments;
  const Mat3 axes = principal_axes(cell.mass.inertia, moments);
  const Vec3& c = cell.mass.centroid;
  Body b;
  b.kind = BodyKind::rock;
  b.volume = cell.mass.volume;
  b.mass = density * cell.mass.volume;
  b.moments = density * moments;
  b.position = c;
  b.orientation = Eigen::Quaterniond(axes).normalized();
  for (const Vec3& v : cell.vertices) b.vertices.push_back(axes.transpose() * (v - c));
  // The largest sphere about the centroid inside the cell: its distance to the nearest face.
  double r = std::numeric_limits<double>::infinity();
  for (const CellFace& f : cell.faces) {
    const PolygonProperties p = polygon_properties(cell.vertices, f.vertices);
    if (p.area > 0.0) r = std::min(r, p.normal.dot(p.centroid - c));
  }
  if (!(r > 0.0) || !std::isfinite(r))
    throw InvalidInput("crushable particle: a cell's centroid is not inside it");
  b.spheres = {Sphere{Vec3::Zero(), r}};
  return b;
}

Body cell_clump_body(const Cell& cell, double density, const FillOptions& fill_options) {
  Body b = cell_body(cell, density);
  const FillResult filled = fill(cell_mesh(cell), fill_options);
  // The fill's spheres are in the parent's frame: into the body's principal frame.
  const Eigen::Quaterniond to_body = b.orientation.conjugate();
  b.spheres.clear();
  for (const Sphere& s : filled.clump.spheres)
    b.spheres.push_back(Sphere{to_body * (s.center - b.position), s.radius});
  b.vertices.clear();
  return b;
}

void add_cell_bonds(World& w, const std::vector<CellBond>& bonds) {
  for (const CellBond& f : bonds) {
    std::vector<Vec3> points;
    std::vector<double> areas;
    for (const FacePoint& p : f.points) points.push_back(p.position), areas.push_back(p.area);
    w.add_bond(make_bond(w.bodies()[f.a], w.bodies()[f.b], f.a, f.b, f.normal, points, areas,
                         f.strength_factor));
  }
}

World crushable_particle(const Tessellation& cells, const std::vector<CellBond>& bonds,
                         double density, const WorldOptions& options) {
  World w(options);
  for (const Cell& cell : cells.cells) w.add_body(cell_body(cell, density));
  add_cell_bonds(w, bonds);
  return w;
}

World crushable_clump_particle(const Tessellation& cells, const std::vector<CellBond>& bonds,
                               double density, const FillOptions& fill,
                               const WorldOptions& options) {
  World w(options);
  for (const Cell& cell : cells.cells) w.add_body(cell_clump_body(cell, density, fill));
  add_cell_bonds(w, bonds);
  return w;
}

}  // namespace clumpkit::dem
