// Repair of a triangle soup into a closed solid: duplicates and degenerate triangles removed,
// holes closed, orientation made to bound a volume.
#pragma once

#include "geom/mesh/mesh.h"

#include <cstddef>

namespace clumpkit {

/// What repair_mesh found and did.
struct RepairReport {
  int boundary_edges_before = 0, boundary_edges_after = 0;
  double volume_before = 0, volume_after = 0;  ///< signed volumes (divergence theorem)
  int repeated_vertex_triangles = 0;           ///< triangles with a repeated corner, dropped
  int duplicate_triangles = 0;                 ///< second copies of a triangle, dropped
  int degenerate_triangles = 0;                ///< zero-area triangles collapsed away (CGAL)
  int holes = 0;                               ///< holes closed
  bool reoriented = false;                     ///< some triangles were flipped
};

/// Repairs `mesh` (welded already: io/formats/mesh_io.h welds on reading) into a closed,
/// outward, manifold surface: drops triangles with a repeated corner and second copies of a
/// triangle (either orientation), orients the soup (CGAL PMP orient_polygon_soup, which splits
/// non-manifold vertices), collapses zero-area triangles (remove_degenerate_faces), closes every
/// hole by a triangulation refined to the density around it and faired to join the surface
/// smoothly (triangulate_refine_and_fair_hole, Liepa 2003), and orients the result to bound a
/// volume (orient_to_bound_a_volume). Throws InvalidInput with one line when no triangle is
/// left, when a hole cannot be closed, or when the result intersects itself or encloses no
/// volume.
RepairReport repair_mesh(Mesh& mesh);

/// Collapses the zero-area triangles of a manifold mesh (CGAL PMP remove_degenerate_faces:
/// edge collapses and flips, which keep a closed mesh closed); returns how many triangles fewer
/// the mesh has. Throws InvalidInput when the triangles are not a manifold surface or some
/// degenerate triangle cannot be removed.
std::size_t collapse_degenerate_triangles(Mesh& mesh);

}  // namespace clumpkit
