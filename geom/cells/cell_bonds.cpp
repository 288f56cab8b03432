#include "geom/cells/cell_bonds.h"

#include "geom/errors.h"

#include <algorithm>
#include <string>
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

namespace {

// The integration points of triangle (a, b, c): its centroid with its area, or those of its four
// midpoint children, `level` times over.
void add_points(std::vector<FacePoint>& out, const Vec3& a, const Vec3& b, const Vec3& c,
                int level) {
  if (level > 0) {
    const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    add_points(out, a, ab, ca, level - 1);
    add_points(out, ab, b, bc, level - 1);
    add_points(out, ca, bc, c, level - 1);
    add_points(out, ab, bc, ca, level - 1);
    return;
  }
  const double area = 0.5 * (b - a).cross(c - a).norm();
  if (area > 0.0) out.push_back({(a + b + c) / 3.0, area});
}

}  // namespace

std::vector<CellBond> cell_bonds(const Tessellation& t, const Distribution& strength, Rng& rng,
                                 int subdivisions) {
  validate(strength, "strength factor");
  require(kFaceSubdivisions, subdivisions, "cell bonds: subdivisions");
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
        add_points(b.points, pp.centroid, p, q, subdivisions);
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
