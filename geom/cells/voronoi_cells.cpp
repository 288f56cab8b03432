#include "geom/cells/voronoi_cells.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/limits.h"
#include "geom/mesh/cgal_mesh.h"

#include <voro++/voro++.hh>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace clumpkit {

namespace {

constexpr int kParentWall = -10;  // voro++ wall id of every parent plane (box walls are −1…−6)

double mesh_size(const Mesh& mesh) {
  const auto box = bounding_box(mesh);
  return (box[1] - box[0]).norm();
}

// The cells of `seeds` (normalised coordinates) in `planes` (normalised), as voro++ gives them.
struct RawCell {
  std::vector<Vec3> vertices;
  std::vector<CellFace> faces;
  Vec3 centroid;
};

std::vector<RawCell> compute_cells(const std::vector<Vec3>& seeds,
                                   const std::vector<Halfspace>& planes) {
  const int n = static_cast<int>(seeds.size());
  // About five seeds per block (voro++'s advice); the parent fits in [−0.5, 0.5]³.
  const int blocks = std::max(1, static_cast<int>(std::lround(std::cbrt(n / 5.0))));
  const double b = 0.51;
  voro::container con(-b, b, -b, b, -b, b, blocks, blocks, blocks, false, false, false, 8);
  std::vector<voro::wall_plane> walls;
  walls.reserve(planes.size());  // add_wall keeps pointers
  for (const Halfspace& h : planes) {
    walls.emplace_back(h.normal.x(), h.normal.y(), h.normal.z(), h.offset, kParentWall);
    con.add_wall(walls.back());
  }
  for (int i = 0; i < n; ++i) con.put(i, seeds[i].x(), seeds[i].y(), seeds[i].z());
  std::vector<RawCell> cells(n);
  std::vector<char> done(n, 0);
  voro::c_loop_all loop(con);
  voro::voronoicell_neighbor c;
  std::vector<double> v;
  std::vector<int> fv, nb;
  if (loop.start()) do {
      if (!con.compute_cell(c, loop)) continue;
      const int id = loop.pid();
      double x, y, z;
      loop.pos(x, y, z);
      RawCell& cell = cells[id];
      c.vertices(x, y, z, v);
      for (std::size_t k = 0; k + 2 < v.size(); k += 3)
        cell.vertices.emplace_back(v[k], v[k + 1], v[k + 2]);
      c.face_vertices(fv);
      c.neighbors(nb);
      Vec3 inside = Vec3::Zero();
      for (const Vec3& p : cell.vertices) inside += p;
      inside /= static_cast<double>(cell.vertices.size());
      std::size_t at = 0;
      for (int f = 0; at < fv.size(); ++f) {
        CellFace face;
        const int k = fv[at++];
        face.vertices.assign(fv.begin() + at, fv.begin() + at + k);
        at += k;
        face.neighbour = nb[f] >= 0 ? nb[f] : -1;
        // Counter-clockwise seen from outside, whatever order voro++ used.
        const PolygonProperties pp = polygon_properties(cell.vertices, face.vertices);
        if (pp.normal.dot(pp.centroid - inside) < 0.0)
          std::reverse(face.vertices.begin(), face.vertices.end());
        cell.faces.push_back(std::move(face));
      }
      double cx, cy, cz;
      c.centroid(cx, cy, cz);
      cell.centroid = Vec3(x + cx, y + cy, z + cz);
      done[id] = 1;
    } while (loop.inc());
  for (int i = 0; i < n; ++i)
    if (!done[i] || cells[i].faces.size() < 4)
      throw NumericError("Voronoi cells: cell " + std::to_string(i) + " came out empty");
  return cells;
}

// Whether p lies inside every plane with a margin.
bool inside(const std::vector<Halfspace>& planes, const Vec3& p, double margin) {
  for (const Halfspace& h : planes)
    if (h.normal.dot(p) > h.offset - margin) return false;
  return true;
}

}  // namespace

void validate(const CellOptions& o) {
  if ((o.count > 0) == kCellSize.contains(o.cell_size))
    throw InvalidInput("cells: give exactly one of a cell count and a cell size, got count " +
                       std::to_string(o.count) + " and cell size " + format_number(o.cell_size));
  if (o.count != 0 && (o.count < 2 || o.count > 100000))
    throw InvalidInput("cells: count must be in [2, 100000], got " + std::to_string(o.count));
  if (o.count == 0) check_size(o.cell_size, "cells: cell size");
  require(kLloydSteps, o.lloyd, "cells: lloyd steps");
}

std::vector<Halfspace> convex_planes(const Mesh& mesh) {
  const double size = mesh_size(mesh);
  const double volume = signed_volume(mesh);
  if (!(volume > 0.0) || !(size > 0.0))
    throw InvalidInput("convex parent: the mesh has no volume (or faces inward)");
  // Convex: the mesh fills its convex hull (to 1e-6, room for float32 corners of an STL).
  const double hull = signed_volume(convex_hull(mesh.vertices));
  if (volume < (1.0 - 1e-6) * hull)
    throw InvalidInput("convex parent: the mesh is not convex: its volume " +
                       format_number(volume, 10) + " is " +
                       format_number(100.0 * (1.0 - volume / hull), 3) +
                       " % below its convex hull's " + format_number(hull, 10));
  // Faces: edge-connected triangles whose corners lie within 1e-7 of the size of one plane,
  // grown from the largest triangle left. A face's plane is the area-weighted mean of its
  // triangles' (the normal of a sliver triangle between float32 corners may be off by 1e-3 rad,
  // and its plane, extended across the parent, would cut it).
  const double tol = 1e-7 * size;
  const std::size_t nt = mesh.triangles.size();
  std::vector<Vec3> twice(nt);  // area-weighted normals
  std::vector<std::size_t> order;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& tri = mesh.triangles[t];
    twice[t] = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                   .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
    order.push_back(t);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t p, std::size_t q) { return twice[p].norm() > twice[q].norm(); });
  std::map<std::pair<int, int>, std::vector<int>> edge;
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      edge[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(t));
    }
  std::vector<char> taken(nt, 0);
  std::vector<Halfspace> planes;
  for (std::size_t seed : order) {
    if (taken[seed] || !(twice[seed].norm() > 0.0)) continue;
    taken[seed] = 1;
    Vec3 normal_sum = twice[seed];
    Vec3 point_sum = twice[seed].norm() * mesh.vertices[mesh.triangles[seed][0]];
    double weight = twice[seed].norm();
    std::vector<int> queue{static_cast<int>(seed)};
    for (std::size_t at = 0; at < queue.size(); ++at) {
      const auto& tri = mesh.triangles[queue[at]];
      for (int k = 0; k < 3; ++k) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        for (int other : edge[{std::min(a, b), std::max(a, b)}]) {
          if (taken[other]) continue;
          const Vec3 n = normal_sum.normalized();
          const double h = n.dot(point_sum / weight);
          bool flat = true;
          for (int v : mesh.triangles[other])
            flat = flat && std::abs(n.dot(mesh.vertices[v]) - h) <= tol;
          if (!flat) continue;
          taken[other] = 1;
          const double w = twice[other].norm();
          normal_sum += twice[other];
          point_sum += w * mesh.vertices[mesh.triangles[other][0]];
          weight += w;
          queue.push_back(other);
        }
      }
    }
    const Vec3 n = normal_sum.normalized();
    planes.push_back({n, n.dot(point_sum / weight)});
  }
  return planes;
}

int cell_count(const CellOptions& o, double parent_volume) {
  if (o.count > 0) return o.count;
  const double d = std::cbrt(6.0 * parent_volume / M_PI);
  const double n = std::round(std::pow(d / o.cell_size, 3.0));
  if (!(n >= 2.0))
    throw InvalidInput("cells: cell size " + format_number(o.cell_size) +
                       " gives fewer than two cells of a parent of volume-equivalent diameter " +
                       format_number(d));
  if (n > 100000.0)
    throw InvalidInput("cells: cell size " + format_number(o.cell_size) + " gives " +
                       format_number(n) + " cells, more than 100000");
  return static_cast<int>(n);
}

namespace {

// The cells of seeds given in normalised coordinates (x' = (x − c)·s), Lloyd-relaxed, returned
// in the parent's frame.
Tessellation tessellate(const Mesh& parent, const std::vector<Halfspace>& unit, const Vec3& c,
                        double s, std::vector<Vec3> seeds, int lloyd) {
  Tessellation t;
  t.parent_volume = signed_volume(parent);
  const std::size_t n = seeds.size();
  std::vector<RawCell> raw = compute_cells(seeds, unit);
  for (int step = 0; step < lloyd; ++step) {
    for (std::size_t i = 0; i < n; ++i) seeds[i] = raw[i].centroid;
    raw = compute_cells(seeds, unit);
  }
  t.cells.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Cell& cell = t.cells[i];
    cell.seed = seeds[i] / s + c;
    for (const Vec3& p : raw[i].vertices) cell.vertices.push_back(p / s + c);
    cell.faces = std::move(raw[i].faces);
    const Mesh m = cell_mesh(cell);
    cell.mass.volume = signed_volume(m);
    cell.mass.centroid = solid_centroid(m);
    cell.mass.inertia = solid_inertia(m, cell.mass.centroid);
  }
  return t;
}

struct Normalised {
  std::vector<Halfspace> planes;  // n·x' ≤ (h − n·c)·s
  Vec3 c;
  double s;
};

// The parent in [−0.5, 0.5]³: voro++'s tolerances are absolute lengths.
Normalised normalise(const Mesh& parent) {
  Normalised u;
  const auto box = bounding_box(parent);
  u.c = 0.5 * (box[0] + box[1]);
  u.s = 1.0 / (box[1] - box[0]).maxCoeff();
  for (const Halfspace& h : convex_planes(parent))
    u.planes.push_back({h.normal, (h.offset - h.normal.dot(u.c)) * u.s});
  return u;
}

}  // namespace

Tessellation voronoi_cells(const Mesh& parent, const CellOptions& options, Rng& rng) {
  validate(options);
  const Normalised u = normalise(parent);
  const int n = cell_count(options, signed_volume(parent));
  const auto box = bounding_box(parent);
  const Vec3 lo = (box[0] - u.c) * u.s, hi = (box[1] - u.c) * u.s;
  std::vector<Vec3> seeds;
  for (long tries = 0; static_cast<int>(seeds.size()) < n; ++tries) {
    if (tries > 1000L * n + 100000L)
      throw NumericError("Voronoi cells: could not place the seeds inside the parent");
    const Vec3 p = rng.uniform(lo, hi);
    if (inside(u.planes, p, 1e-6)) seeds.push_back(p);
  }
  return tessellate(parent, u.planes, u.c, u.s, std::move(seeds), options.lloyd);
}

Tessellation voronoi_cells(const Mesh& parent, const std::vector<Vec3>& seeds, int lloyd) {
  const Normalised u = normalise(parent);
  std::vector<Vec3> unit;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    unit.push_back((seeds[i] - u.c) * u.s);
    if (!inside(u.planes, unit.back(), 0.0))
      throw InvalidInput("Voronoi cells: seed " + std::to_string(i) + " lies outside the parent");
  }
  if (seeds.size() < 2)
    throw InvalidInput("Voronoi cells: need at least two seeds, got " +
                       std::to_string(seeds.size()));
  return tessellate(parent, u.planes, u.c, u.s, std::move(unit), lloyd);
}

std::vector<Mesh> voronoi_cells_by_halfspaces(const Mesh& parent, const std::vector<Vec3>& seeds) {
  const std::vector<Halfspace> planes = convex_planes(parent);
  std::vector<Mesh> cells;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    std::vector<Halfspace> h = planes;
    for (std::size_t j = 0; j < seeds.size(); ++j)
      if (j != i)  // |x − s_i|² ≤ |x − s_j|²  ⇔  2(s_j − s_i)·x ≤ |s_j|² − |s_i|²
        h.push_back({2.0 * (seeds[j] - seeds[i]), seeds[j].squaredNorm() - seeds[i].squaredNorm()});
    cells.push_back(intersect_halfspaces(h, seeds[i]));
  }
  return cells;
}

Mesh cell_mesh(const Cell& cell) {
  Mesh m;
  m.vertices = cell.vertices;
  for (const CellFace& f : cell.faces)
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k)
      m.triangles.push_back({f.vertices[0], f.vertices[k], f.vertices[k + 1]});
  return m;
}

PolygonProperties polygon_properties(const std::vector<Vec3>& v, const std::vector<int>& polygon) {
  PolygonProperties p;
  Vec3 normal = Vec3::Zero();
  const Vec3& o = v[polygon[0]];
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    const Vec3& a = v[polygon[k]];
    const Vec3& b = v[polygon[k + 1]];
    const Vec3 twice = (a - o).cross(b - o);  // about the first vertex: no far-origin rounding
    normal += twice;
    const double area = 0.5 * twice.norm();
    p.area += area;
    p.centroid += area * (o + a + b) / 3.0;
  }
  if (p.area > 0.0) p.centroid /= p.area;
  if (normal.norm() > 0.0) p.normal = normal.normalized();
  return p;
}

}  // namespace clumpkit
