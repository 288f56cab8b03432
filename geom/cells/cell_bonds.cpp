#include "geom/cells/cell_bonds.h"

#include <algorithm>
#include <utility>

namespace clumpkit {

Distribution default_strength_factor() {
  Distribution d;
  d.kind = Distribution::Kind::Normal;
  d.a = 1.0;
  d.b = 0.125;
  d.min = 0.75;
  d.max = 1.25;
  return d;
}

std::vector<CellBond> cell_bonds(const Tessellation& t, const Distribution& strength, Rng& rng) {
  validate(strength, "strength factor");
  std::vector<CellBond> bonds;
  for (std::size_t a = 0; a < t.cells.size(); ++a) {
    const Cell& cell = t.cells[a];
    // voro++ may list two faces against the same neighbour only for degenerate seeds; each is a
    // bond of its own then.
    for (const CellFace& f : cell.faces) {
      if (f.neighbour <= static_cast<int>(a)) continue;  // the parent's surface, or seen from b
      const PolygonProperties pp = polygon_properties(cell.vertices, f.vertices);
      if (!(pp.area > 0.0)) continue;
      CellBond b;
      b.a = static_cast<int>(a);
      b.b = f.neighbour;
      b.area = pp.area;
      b.centroid = pp.centroid;
      b.normal = pp.normal;
      const std::size_t n = f.vertices.size();
      for (std::size_t k = 0; k < n; ++k) {
        const Vec3& p = cell.vertices[f.vertices[k]];
        const Vec3& q = cell.vertices[f.vertices[(k + 1) % n]];
        const double area = 0.5 * (p - pp.centroid).cross(q - pp.centroid).norm();
        if (area > 0.0) b.points.push_back({(pp.centroid + p + q) / 3.0, area});
      }
      bonds.push_back(std::move(b));
    }
  }
  std::stable_sort(bonds.begin(), bonds.end(), [](const CellBond& p, const CellBond& q) {
    return std::make_pair(p.a, p.b) < std::make_pair(q.a, q.b);
  });
  for (CellBond& b : bonds) b.strength_factor = sample(strength, rng);
  return bonds;
}

}  // namespace clumpkit
