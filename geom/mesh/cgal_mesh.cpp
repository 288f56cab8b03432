#include "geom/mesh/cgal_mesh.h"

#include "geom/errors.h"
#include "geom/mesh/cgal_surface.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <numeric>

namespace clumpkit {

namespace {
using K = cgal_surface::K;
using Point = cgal_surface::Point;
using SurfaceMesh = cgal_surface::SurfaceMesh;
namespace PMP = CGAL::Polygon_mesh_processing;

using cgal_surface::from_surface_mesh;
using cgal_surface::to_surface_mesh;
}  // namespace

Mesh convex_hull(const std::vector<Vec3>& points) {
  // The hull is read off a triangulation of the points (its infinite cells) rather than taken
  // from CGAL::convex_hull_3: in CGAL 5.5 quickhull can erase the same list node twice (CGAL
  // issues 6543 and 8625; seen here under valgrind as a use-after-free that changed results run to
  // run). A plain Triangulation_3, not a Delaunay one: its hull needs only orientation tests, while
  // Delaunay insertion runs in-sphere tests that are all near-degenerate on a scanned convex
  // surface (every vertex on the hull, nearly cospherical): 0.8 s instead of 4.6 s for the
  // 655,362 vertices of a 1.3 M-triangle ellipsoid, the same faces. Points are sorted and
  // deduplicated first, then inserted in CGAL's Hilbert order (fixed seed) so that each point is
  // located from its predecessor: the result does not depend on input order.
  // Checked before sorting: a NaN breaks the strict weak order std::sort relies on.
  for (const auto& p : points)
    if (!p.allFinite()) throw InvalidInput("convex hull: a point has a non-finite coordinate");
  std::vector<Vec3> sorted = points;
  auto lex = [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(sorted.begin(), sorted.end(), lex);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 4)
    throw InvalidInput("convex hull needs at least 4 distinct points, got " +
                       std::to_string(sorted.size()));

  using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using Triangulation = CGAL::Triangulation_3<K, Tds>;
  std::vector<Point> cgal_points;
  cgal_points.reserve(sorted.size());
  for (const auto& p : sorted) cgal_points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::size_t> order(sorted.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  using SortTraits =
      CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<Point>::type>;
  CGAL::spatial_sort(order.begin(), order.end(), SortTraits(CGAL::make_property_map(cgal_points)));
  Triangulation tr;
  Triangulation::Vertex_handle hint;
  for (const std::size_t i : order) {
    hint = tr.insert(cgal_points[i], hint);
    hint->info() = static_cast<int>(i);
  }
  if (tr.dimension() < 3) throw InvalidInput("convex hull: points are coplanar or collinear");

  Vec3 centre = Vec3::Zero();
  for (const auto& p : sorted) centre += p;
  centre /= static_cast<double>(sorted.size());

  Mesh hull;
  std::vector<int> id(sorted.size(), -1);
  auto vertex = [&](int i) {
    if (id[i] < 0) {
      id[i] = static_cast<int>(hull.vertices.size());
      hull.vertices.push_back(sorted[i]);
    }
    return id[i];
  };
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    if (!tr.is_infinite(c)) continue;
    const int inf = c->index(tr.infinite_vertex());
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = c->vertex((inf + 1 + k) % 4)->info();
    // Orient outward: the centre of the points is strictly inside the hull.
    const Vec3 n = (sorted[t[1]] - sorted[t[0]]).cross(sorted[t[2]] - sorted[t[0]]);
    if (n.dot(sorted[t[0]] - centre) < 0) std::swap(t[1], t[2]);
    hull.triangles.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
  }
  canonicalize(hull);
  return hull;
}

bool self_intersects(const Mesh& mesh) {
  const SurfaceMesh sm = to_surface_mesh(mesh);
  return PMP::does_self_intersect(sm);
}

bool orient_outward(Mesh& mesh) {
  cgal_surface::Soup soup = cgal_surface::used_soup(mesh, mesh.triangles);
  std::vector<Point>& pts = soup.points;
  std::vector<std::vector<std::size_t>>& polys = soup.polygons;
  const std::vector<int>& original = soup.original;
  const std::size_t used = pts.size();
  PMP::orient_polygon_soup(pts, polys);
  if (pts.size() != used)
    throw InvalidInput("mesh is not manifold: orienting it required duplicating vertices");
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(pts, polys, sm);
  if (CGAL::is_closed(sm)) {
    // orient_to_bound_a_volume requires a surface that does not intersect itself (it reads out
    // of bounds otherwise, e.g. on two copies of one triangle); such a surface bounds no volume.
    if (PMP::does_self_intersect(sm))
      throw InvalidInput("the surface intersects itself, so it bounds no volume");
    PMP::orient_to_bound_a_volume(sm);
  }
  Mesh out = from_surface_mesh(sm);  // vertices in the order of `pts`
  for (auto& t : out.triangles)
    for (int& v : t) v = original[std::size_t(v)];
  out.vertices = mesh.vertices;
  bool changed = out.triangles.size() != mesh.triangles.size();
  for (size_t i = 0; !changed && i < out.triangles.size(); ++i) {
    // Same triangle up to rotation of indices?
    const auto& a = out.triangles[i];
    const auto& b = mesh.triangles[i];
    const bool same = (a == b) || (a == std::array<int, 3>{b[1], b[2], b[0]}) ||
                      (a == std::array<int, 3>{b[2], b[0], b[1]});
    changed = !same;
  }
  mesh = std::move(out);
  return changed;
}

}  // namespace clumpkit
