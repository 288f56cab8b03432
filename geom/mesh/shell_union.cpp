#include "geom/mesh/shell_union.h"

#include "geom/mesh/cgal_surface.h"
#include "geom/mesh/shells.h"

#include <CGAL/Polygon_mesh_processing/corefinement.h>

#include <numeric>
#include <vector>

namespace clumpkit {

namespace PMP = CGAL::Polygon_mesh_processing;
using cgal_surface::SurfaceMesh;

namespace {

int find_root(std::vector<int>& parent, int i) {
  while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)] = parent[parent[std::size_t(i)]];
  return i;
}

}  // namespace

int unite_crossing_shells(Mesh& mesh) {
  const std::vector<Shell> shells = mesh_shells(mesh);
  const int n = static_cast<int>(shells.size());
  if (n < 2) return 0;
  std::vector<int> shell_of(mesh.triangles.size(), 0);
  for (int s = 0; s < n; ++s)
    for (int t : shells[std::size_t(s)].triangles) shell_of[std::size_t(t)] = s;
  // Face i of the surface mesh is triangle i (to_surface_mesh adds them in order).
  const SurfaceMesh whole = cgal_surface::to_surface_mesh(mesh);
  std::vector<int> group(static_cast<std::size_t>(n));
  std::iota(group.begin(), group.end(), 0);
  std::vector<bool> crosses_itself(static_cast<std::size_t>(n), false);
  for (const auto& [f, g] : cgal_surface::crossing_faces(whole)) {
    const int a = shell_of[f.idx()], b = shell_of[g.idx()];
    if (a == b)
      crosses_itself[std::size_t(a)] = true;
    else
      group[std::size_t(find_root(group, a))] = find_root(group, b);
  }
  std::vector<std::vector<int>> members(static_cast<std::size_t>(n));
  for (int s = 0; s < n; ++s) members[std::size_t(find_root(group, s))].push_back(s);

  std::vector<int> kept;  // triangles of the shells left as they are
  Mesh united_shells;
  int joined = 0;
  for (const std::vector<int>& m : members) {
    if (m.empty()) continue;
    // The union needs each operand closed, free of crossings of its own, and bounding its
    // volume from outside (CGAL's preconditions); anything else stays as it is, for the wrap.
    // (A shell's depth says nothing here: a vertex of one crossing shell lies inside the other.)
    bool unitable = m.size() > 1;
    for (int s : m) {
      const Shell& shell = shells[std::size_t(s)];
      unitable = unitable && !crosses_itself[std::size_t(s)] && shell.volume > 0;
    }
    SurfaceMesh united;
    if (unitable) {
      united = cgal_surface::to_surface_mesh(mesh, &shells[std::size_t(m[0])].triangles);
      for (std::size_t k = 1; k < m.size() && unitable; ++k) {
        SurfaceMesh next =
            cgal_surface::to_surface_mesh(mesh, &shells[std::size_t(m[k])].triangles);
        SurfaceMesh result;
        unitable = PMP::corefine_and_compute_union(united, next, result);
        united = std::move(result);
      }
    }
    if (unitable) {
      append_mesh(united_shells, cgal_surface::from_surface_mesh(united));
      joined += static_cast<int>(m.size()) - 1;
    } else {
      for (int s : m)
        kept.insert(kept.end(), shells[std::size_t(s)].triangles.begin(),
                    shells[std::size_t(s)].triangles.end());
    }
  }
  if (joined == 0) return 0;
  Mesh out = cgal_surface::from_surface_mesh(cgal_surface::to_surface_mesh(mesh, &kept));
  append_mesh(out, united_shells);
  mesh = std::move(out);
  return joined;
}

}  // namespace clumpkit
