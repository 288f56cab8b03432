// Inside geom/mesh: a Mesh as a CGAL Surface_mesh and back, for the files that call CGAL's
// polygon-mesh processing (cgal_mesh.cpp, shells.cpp, repair.cpp).
#pragma once

#include "geom/errors.h"
#include "geom/mesh/mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

namespace clumpkit::cgal_surface {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

/// The triangles of `mesh` (all, or those listed in `only`) as a Surface_mesh with the vertices
/// they use, in order of first use. Throws InvalidInput when a triangle cannot be added (the
/// triangles do not form a manifold surface).
inline SurfaceMesh to_surface_mesh(const Mesh& mesh, const std::vector<int>* only = nullptr) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> index(mesh.vertices.size());
  std::vector<bool> added(mesh.vertices.size(), false);
  const auto vertex = [&](int v) {
    if (!added[v]) {
      const Vec3& p = mesh.vertices[v];
      index[v] = sm.add_vertex(Point(p.x(), p.y(), p.z()));
      added[v] = true;
    }
    return index[v];
  };
  const auto add = [&](const std::array<int, 3>& t) {
    const auto a = vertex(t[0]), b = vertex(t[1]), c = vertex(t[2]);
    if (sm.add_face(a, b, c) == SurfaceMesh::null_face())
      throw InvalidInput("mesh is not a manifold surface: a triangle could not be added");
  };
  if (only)
    for (int t : *only) add(mesh.triangles[t]);
  else
    for (const auto& t : mesh.triangles) add(t);
  return sm;
}

/// Triangles as a CGAL polygon soup over the vertices they use only: an isolated vertex would
/// become a vertex without a halfedge, on which orient_to_bound_a_volume reads out of bounds
/// (found by fuzz_mesh_obj). `original[i]` is the mesh vertex of soup point i.
struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  std::vector<int> original;
};

inline Soup used_soup(const Mesh& mesh, const std::vector<std::array<int, 3>>& triangles) {
  Soup soup;
  std::vector<int> compact(mesh.vertices.size(), -1);
  soup.polygons.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::vector<std::size_t> poly;
    for (int v : t) {
      if (compact[std::size_t(v)] < 0) {
        compact[std::size_t(v)] = static_cast<int>(soup.original.size());
        soup.original.push_back(v);
        const Vec3& p = mesh.vertices[std::size_t(v)];
        soup.points.emplace_back(p.x(), p.y(), p.z());
      }
      poly.push_back(std::size_t(compact[std::size_t(v)]));
    }
    soup.polygons.push_back(std::move(poly));
  }
  return soup;
}

/// The faces of `sm` (triangles) as a Mesh, vertices in index order. Throws NumericError for a
/// face that is not a triangle.
inline Mesh from_surface_mesh(const SurfaceMesh& sm) {
  Mesh mesh;
  std::vector<int> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  for (auto v : sm.vertices()) {
    index[v.idx()] = static_cast<int>(mesh.vertices.size());
    const Point& p = sm.point(v);
    mesh.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : sm.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k < 3) t[k] = index[v.idx()];
      ++k;
    }
    if (k != 3) throw NumericError("CGAL produced a face that is not a triangle");
    mesh.triangles.push_back(t);
  }
  return mesh;
}

/// Whether two faces that CGAL finds intersecting only touch at corners they have at one
/// position (the copies of a vertex split between two shells): shrunk towards their centroids by
/// a millionth, the triangles no longer meet.
inline bool faces_only_touch(const SurfaceMesh& sm, SurfaceMesh::Face_index f,
                             SurfaceMesh::Face_index g) {
  auto corners = [&](SurfaceMesh::Face_index face) {
    std::vector<Point> out;
    for (const auto v : CGAL::vertices_around_face(sm.halfedge(face), sm))
      out.push_back(sm.point(v));
    return out;
  };
  const std::vector<Point> a = corners(f), b = corners(g);
  bool shared = false;
  for (const Point& p : a)
    for (const Point& q : b) shared = shared || p == q;
  if (!shared || a.size() != 3 || b.size() != 3) return false;
  auto shrunk = [](const std::vector<Point>& t) {
    const Point c = CGAL::centroid(t[0], t[1], t[2]);
    auto in = [&](const Point& p) { return c + (1.0 - 1e-6) * (p - c); };
    return K::Triangle_3(in(t[0]), in(t[1]), in(t[2]));
  };
  return CGAL::do_intersect(shrunk(a), shrunk(b)) == false;
}

/// The pairs of faces of `sm` that cross (CGAL PMP self_intersections), less those that only
/// touch at a shared corner position (faces_only_touch).
inline std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> crossing_faces(
    const SurfaceMesh& sm) {
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(sm, std::back_inserter(pairs));
  pairs.erase(
      std::remove_if(pairs.begin(), pairs.end(),
                     [&](const auto& fg) { return faces_only_touch(sm, fg.first, fg.second); }),
      pairs.end());
  return pairs;
}

}  // namespace clumpkit::cgal_surface
