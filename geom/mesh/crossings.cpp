#include "geom/mesh/crossings.h"

#include "geom/mesh/cgal_surface.h"
#include "geom/mesh/shells.h"

#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>

#include <utility>

namespace clumpkit {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal_surface::SurfaceMesh;

namespace {

Vec3 face_centroid(const SurfaceMesh& sm, SurfaceMesh::Face_index f) {
  Vec3 c = Vec3::Zero();
  for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
    const auto& p = sm.point(v);
    c += Vec3(p.x(), p.y(), p.z());
  }
  return c / 3.0;
}

int count_crossings(const SurfaceMesh& sm) {
  return static_cast<int>(cgal_surface::crossing_faces(sm).size());
}

bool closed(const SurfaceMesh& sm) {
  for (const auto h : sm.halfedges())
    if (sm.is_border(h)) return false;
  return true;
}

}  // namespace

Crossings find_crossings(const Mesh& mesh) {
  Crossings c;
  if (mesh.triangles.empty()) return c;
  const std::vector<Shell> shells = mesh_shells(mesh);
  std::vector<int> shell_of(mesh.triangles.size(), 0);
  for (std::size_t s = 0; s < shells.size(); ++s)
    for (int t : shells[s].triangles) shell_of[std::size_t(t)] = static_cast<int>(s);
  // to_surface_mesh adds the faces in the order of the triangles, so face i is triangle i.
  const SurfaceMesh sm = cgal_surface::to_surface_mesh(mesh);
  const auto pairs = cgal_surface::crossing_faces(sm);
  for (const auto& [f, g] : pairs)
    ++(shell_of[f.idx()] == shell_of[g.idx()] ? c.within_shells : c.between_shells);
  if (!pairs.empty()) c.first = face_centroid(sm, pairs.front().first);
  return c;
}

std::vector<CrossingRound> mend_crossings_locally(Mesh& mesh, int max_rounds) {
  std::vector<CrossingRound> rounds;
  const std::vector<Shell> shells = mesh_shells(mesh);
  Mesh out;
  for (std::size_t s = 0; s < shells.size(); ++s) {
    SurfaceMesh sm = cgal_surface::to_surface_mesh(mesh, &shells[s].triangles);
    int pairs = count_crossings(sm);
    for (int round = 0; round < max_rounds && pairs > 0; ++round) {
      SurfaceMesh before = sm;
      // Faces that only touch at a corner position are not crossings (the copies of a vertex
      // split where holes met); the default (genus kept, seven growing steps) otherwise.
      const auto only_touch =
          [&sm](const std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>& fg) {
            return cgal_surface::faces_only_touch(sm, fg.first, fg.second);
          };
      PMP::experimental::remove_self_intersections(sm, PMP::parameters::filter(only_touch));
      sm.collect_garbage();
      // A round that opens the shell or adds crossings is undone: the wrap takes what is left.
      const int after = closed(sm) ? count_crossings(sm) : pairs + 1;
      rounds.push_back({static_cast<int>(s) + 1, pairs, std::min(after, pairs)});
      if (after >= pairs) {
        sm = std::move(before);
        break;
      }
      pairs = after;
    }
    append_mesh(out, cgal_surface::from_surface_mesh(sm));
  }
  mesh = std::move(out);
  return rounds;
}

}  // namespace clumpkit
