#include "geom/mesh/repair.h"

#include "geom/errors.h"
#include "geom/mesh/cgal_surface.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace clumpkit {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal_surface::Point;
using cgal_surface::SurfaceMesh;

RepairReport repair_mesh(Mesh& mesh) {
  RepairReport r;
  {
    const MeshCheck before = check_mesh(mesh);
    r.boundary_edges_before = before.boundary_edges;
    r.volume_before = before.volume;
  }
  // The soup: triangles with three distinct corners, each vertex triple once.
  std::vector<std::array<int, 3>> kept;
  std::set<std::array<int, 3>> seen;
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++r.repeated_vertex_triangles;
      continue;
    }
    std::array<int, 3> key = t;
    std::sort(key.begin(), key.end());
    if (!seen.insert(key).second) {
      ++r.duplicate_triangles;
      continue;
    }
    kept.push_back(t);
  }
  if (kept.empty()) throw InvalidInput("repair: no triangle with three distinct corners");
  cgal_surface::Soup soup = cgal_surface::used_soup(mesh, kept);
  std::vector<Point>& points = soup.points;
  std::vector<std::vector<std::size_t>>& polys = soup.polygons;
  const std::vector<std::vector<std::size_t>> as_read = polys;
  PMP::orient_polygon_soup(points, polys);
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polys, sm);
  for (std::size_t k = 0; k < polys.size() && !r.reoriented; ++k)
    r.reoriented = polys[k] != as_read[k];

  const std::size_t faces_before = sm.number_of_faces();
  PMP::remove_degenerate_faces(sm);
  sm.collect_garbage();
  const std::size_t faces_after = sm.number_of_faces();
  r.degenerate_triangles = static_cast<int>(faces_before - std::min(faces_before, faces_after));

  std::vector<SurfaceMesh::Halfedge_index> holes;
  PMP::extract_boundary_cycles(sm, std::back_inserter(holes));
  for (SurfaceMesh::Halfedge_index h : holes) {
    std::vector<SurfaceMesh::Face_index> patch;
    std::vector<SurfaceMesh::Vertex_index> added;
    const auto result = PMP::triangulate_refine_and_fair_hole(sm, h, std::back_inserter(patch),
                                                              std::back_inserter(added));
    if (!std::get<0>(result) && patch.empty())
      throw InvalidInput("repair: a hole of the mesh could not be closed");
    ++r.holes;
  }
  if (!CGAL::is_closed(sm)) throw InvalidInput("repair: the mesh could not be closed");
  if (PMP::does_self_intersect(sm))
    throw InvalidInput(
        "repair: the closed surface intersects itself, so it bounds no volume (its shells cross, "
        "or a hole's patch crosses the surface)");
  PMP::orient_to_bound_a_volume(sm);
  sm.collect_garbage();
  mesh = cgal_surface::from_surface_mesh(sm);
  const MeshCheck after = check_mesh(mesh);
  r.boundary_edges_after = after.boundary_edges;
  r.volume_after = after.volume;
  const auto box = bounding_box(mesh);
  if (!(r.volume_after > 1e-12 * std::pow((box[1] - box[0]).norm(), 3)))
    throw InvalidInput("repair: the closed surface encloses no volume (signed volume " +
                       std::to_string(r.volume_after) + ")");
  return r;
}

std::size_t collapse_degenerate_triangles(Mesh& mesh) {
  SurfaceMesh sm = cgal_surface::to_surface_mesh(mesh);
  std::size_t degenerate = 0;
  for (auto f : sm.faces()) degenerate += PMP::is_degenerate_triangle_face(f, sm) ? 1 : 0;
  if (!PMP::remove_degenerate_faces(sm))
    throw InvalidInput("a degenerate triangle (zero area) could not be removed");
  sm.collect_garbage();
  mesh = cgal_surface::from_surface_mesh(sm);
  return degenerate;
}

}  // namespace clumpkit
