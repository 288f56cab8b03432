#include "dem/core/crushable.h"

#include "geom/errors.h"
#include "geom/fill/fill.h"
#include "geom/template/clump_template.h"

#include <algorithm>
#include <limits>

namespace clumpkit::dem {

Body cell_body(const Cell& cell, double density) {
  require(kDensity, density, "crushable particle: density");
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
  // A cell's spheres must not reach into its bonded neighbours: the fill's per-sphere rule
  // (a few percent of each radius) only, not the pass that spends the rest of the budget.
  FillOptions options = fill_options;
  options.spend_budget = false;
  const FillResult filled = fill(cell_mesh(cell), options);
  // The fill's spheres are in the parent's frame: into the body's principal frame.
  const Eigen::Quaterniond to_body = b.orientation.conjugate();
  b.spheres.clear();
  for (const Sphere& s : filled.clump.spheres)
    b.spheres.push_back(Sphere{to_body * (s.center - b.position), s.radius});
  b.vertices.clear();
  return b;
}

namespace {

// The bond of face f between the cells' bodies a and b at their present poses.
Bond cell_bond(const Body& a, const Body& b, const CellBond& f) {
  std::vector<Vec3> points;
  std::vector<double> areas;
  for (const FacePoint& q : f.points) points.push_back(q.position), areas.push_back(q.area);
  return make_bond(a, b, f.a, f.b, f.normal, points, areas, f.strength_factor);
}

}  // namespace

void add_cell_bonds(World& w, const std::vector<CellBond>& bonds) {
  for (const CellBond& f : bonds) w.add_bond(cell_bond(w.bodies()[f.a], w.bodies()[f.b], f));
}

CrushableBodies crushable_bodies(const Tessellation& cells, const std::vector<CellBond>& bonds,
                                 double density, const FillOptions* fill) {
  CrushableBodies p;
  for (const Cell& cell : cells.cells)
    p.cells.push_back(fill ? cell_clump_body(cell, density, *fill) : cell_body(cell, density));
  for (const CellBond& f : bonds) p.bonds.push_back(cell_bond(p.cells[f.a], p.cells[f.b], f));
  return p;
}

int add_crushable(World& world, const CrushableBodies& particle, const Eigen::Quaterniond& q,
                  const Vec3& t) {
  const int first = static_cast<int>(world.bodies().size());
  for (Body b : particle.cells) {
    b.position = q * b.position + t;
    b.orientation = q * b.orientation;  // exact for the identity: the rig's bytes unchanged
    world.add_body(std::move(b));
  }
  for (Bond bond : particle.bonds) {
    bond.a += first;
    bond.b += first;
    world.add_bond(std::move(bond));
  }
  return first;
}

World crushable_particle(const Tessellation& cells, const std::vector<CellBond>& bonds,
                         double density, const WorldOptions& options) {
  World w(options);
  add_crushable(w, crushable_bodies(cells, bonds, density), Eigen::Quaterniond::Identity(),
                Vec3::Zero());
  return w;
}

WorldOptions cell_packing_options(WorldOptions o, const CohesiveParams& law) {
  o.cohesive = law;
  o.broken_bonds_act = false;
  o.sort_every = 0;
  return o;
}

}  // namespace clumpkit::dem
