// Repair of a triangle soup into a closed solid, as a pipeline of named steps: duplicates and
// double walls, non-manifold edges and vertices split, degenerate triangles, small components,
// holes, orientation, and a final self-intersection check.
#pragma once

#include "geom/mesh/mesh.h"

#include <cstddef>
#include <string>
#include <vector>

namespace clumpkit {

/// What repair_mesh may discard.
struct RepairOptions {
  /// Components (after the split at non-manifold edges and vertices) with fewer triangles than
  /// this fraction of the largest component's are debris and removed; 0 keeps every component.
  double min_component = 0.01;
};

/// One hole closed: its edge count, where it was (the centroid of its boundary vertices), and
/// how: "refined and faired" (Liepa 2003), "refined" (fairing failed), "triangulated" (CGAL
/// triangulate_hole) or "planar cap" (a fan from the boundary's centroid).
struct RepairHole {
  int edges = 0;
  Vec3 at = Vec3::Zero();
  std::string method;
};

/// What repair_mesh found and did, step by step.
struct RepairReport {
  int boundary_edges_before = 0, boundary_edges_after = 0;
  double volume_before = 0, volume_after = 0;  ///< signed volumes (divergence theorem)
  // duplicates
  int repeated_vertex_triangles = 0;  ///< triangles with a repeated corner, dropped
  int duplicate_triangles = 0;        ///< further copies of a triangle in the same orientation
  int double_wall_triangles = 0;      ///< copies of a triangle in both orientations: all dropped
  // non-manifold
  int nonmanifold_edges = 0;  ///< edges shared by more than two triangles (before the split)
  int split_vertices = 0;     ///< vertices duplicated to split non-manifold edges and vertices
  /// Split vertices welded again after the holes were closed (holes that met at a vertex), when
  /// that leaves a closed manifold surface.
  int rejoined_vertices = 0;
  // degenerate
  int degenerate_triangles = 0;  ///< zero-area triangles collapsed away (CGAL)
  // small components
  int small_components = 0, small_component_triangles = 0;
  // holes
  int holes = 0;  ///< holes closed
  std::vector<RepairHole> closed_holes;
  // orientation
  bool reoriented = false;  ///< some triangles were flipped
};

/// Repairs `mesh` (welded already: io/formats/mesh_io.h welds on reading) into a closed,
/// outward, manifold surface, in named steps:
///  1. duplicates: triangles with a repeated corner dropped; a triangle present more than once
///     keeps one copy when every copy has one orientation, and loses every copy when both
///     orientations occur (a zero-thickness double wall bounds nothing);
///  2. non-manifold: the soup oriented (CGAL PMP orient_polygon_soup), which splits each edge
///     shared by more than two triangles, and each vertex where separate fans meet, by
///     duplicating its vertices, so that lobes touching along an edge or at a vertex become
///     separate components and a fin on an edge its own;
///  3. degenerate: zero-area triangles collapsed (remove_degenerate_faces);
///  4. small components: components with fewer triangles than options.min_component of the
///     largest one's removed (fins, loose triangles, floating debris);
///  5. holes: each boundary cycle closed by triangulate_refine_and_fair_hole, falling back to
///     triangulate_hole and then to a planar cap (a fan from the boundary's centroid); split
///     vertices welded again when that leaves a closed manifold (holes that met at a vertex);
///  6. orientation: orient_to_bound_a_volume;
///  7. self-intersection check.
/// Throws InvalidInput with one line "repair, step '<step>': <what> [at (x, y, z)]" naming the
/// step that could not finish and the first place: no triangle left, a hole no method closes,
/// the surface intersecting itself (the first pair of faces), or no enclosed volume.
RepairReport repair_mesh(Mesh& mesh, const RepairOptions& options = {});

/// Splits each edge shared by more than two triangles, and each vertex where separate fans meet,
/// by duplicating its vertices (CGAL PMP orient_polygon_soup, which also orients each piece
/// consistently): closed lobes that touch along an edge or at a vertex become separate shells
/// (copies of the vertices at one position). Unused vertices are dropped. Returns the number of
/// vertices added.
std::size_t split_nonmanifold(Mesh& mesh);

/// Collapses the zero-area triangles of a manifold mesh (CGAL PMP remove_degenerate_faces:
/// edge collapses and flips, which keep a closed mesh closed); returns how many triangles fewer
/// the mesh has. Throws InvalidInput when the triangles are not a manifold surface or some
/// degenerate triangle cannot be removed.
std::size_t collapse_degenerate_triangles(Mesh& mesh);

}  // namespace clumpkit
