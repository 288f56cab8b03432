// Repair of a triangle soup into a closed solid, as a pipeline of named steps: duplicates and
// double walls, non-manifold edges and vertices split, degenerate triangles, small components,
// holes, crossings mended (locally, by union, by a wrap), orientation, and a final check.
#pragma once

#include "geom/mesh/crossings.h"
#include "geom/mesh/mesh.h"

#include <cstddef>
#include <string>
#include <vector>

namespace clumpkit {

/// When repair_mesh wraps the surface (CGAL 3D Alpha Wrapping) instead of keeping its triangles.
enum class WrapMode {
  fallback,  ///< only when the local mend and the union leave faces crossing
  always,    ///< every mesh, after the holes are closed
  never,     ///< never: crossings left are refused
};

/// Parses "fallback", "always" or "never"; throws InvalidInput naming `field` otherwise.
WrapMode wrap_mode_from_string(const std::string& text, const std::string& field);
const char* to_string(WrapMode mode);

/// What repair_mesh may discard and how it mends what crosses.
struct RepairOptions {
  /// Components (after the split at non-manifold edges and vertices) with fewer triangles than
  /// this fraction of the largest component's are debris and removed; 0 keeps every component.
  double min_component = 0.01;
  WrapMode wrap = WrapMode::fallback;
  /// The wrap's alpha (cavities and gaps narrower than about this are bridged) and offset (the
  /// wrap lies this far outside the surface), as fractions of the bounding-box diagonal. The
  /// defaults keep what the fill sees: its default voxel is about 1/70 of a compact particle's
  /// diagonal, so alpha at 1/100 bridges nothing the fill resolves; the offset adds about
  /// offset × area to the volume (0.3 % for a sphere at 1/3000 of the diagonal).
  double wrap_alpha = 0.01;
  double wrap_offset = 1.0 / 3000.0;
  /// Rounds of the local mend at most, per shell (each a call of CGAL's
  /// remove_self_intersections; the mend stops earlier when a round does not shrink the
  /// crossings).
  int local_rounds = 4;
  /// The local mend is skipped (the union and the wrap take the crossings) when more pairs of
  /// faces cross within shells than this fraction of the triangles (at least 32): a soup rather
  /// than a scan's folds.
  double local_limit = 0.02;
  /// A wrap whose sampled distance to the input exceeds this fraction of the diagonal is
  /// reported in RepairReport::warnings with the place.
  double wrap_warn_distance = 0.02;
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
  // crossings: the closed surface after the holes, before anything below changed it
  double volume_capped = 0;  ///< its signed volume (shells through each other counted twice)
  int crossings_within = 0, crossings_between = 0;  ///< pairs of faces crossing (crossings.h)
  std::vector<CrossingRound> local_rounds;          ///< the local mend, round by round
  int united_shells = 0;                            ///< shells joined into another by their union
  /// Triangles of (nearly) zero area collapsed away after the mends (the input's own, or the
  /// needles and caps a mend leaves).
  int slivers = 0;
  // wrap
  bool wrapped = false;
  double wrap_alpha = 0, wrap_offset = 0;  ///< used, in the mesh's units
  double wrap_seconds = 0;
  /// What mended the crossings: "" (none to mend), "local", "union", "local and union",
  /// "slivers" (their collapse) or "wrap".
  std::string mended_by;
  /// Whenever the surface was changed beyond welding and hole closing (a mend or a wrap): the
  /// sampled one-sided distance from the result to the closed surface before the mends (the
  /// input with its holes closed), as fractions of the bounding-box diagonal, and the place of
  /// the largest.
  bool changed = false;
  double distance_max = 0, distance_mean = 0;
  Vec3 distance_max_at = Vec3::Zero();
  double diagonal = 0;  ///< of the input's bounding box
  // orientation
  bool reoriented = false;  ///< some triangles were flipped
  /// What the user should hear: a wrap that moved the surface by more than
  /// options.wrap_warn_distance, naming the place.
  std::vector<std::string> warnings;
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
///  6. volume: a closed surface that encloses no volume (a sheet, a single triangle, faces of a
///     point cloud, capped on themselves) is refused here;
///  7. self-intersections: crossings within a shell (folds, a patch through the surface) mended
///     locally (mend_crossings_locally), then shells through each other joined by their union
///     (unite_crossing_shells);
///     then triangles of (nearly) zero area collapsed (CGAL remove_degenerate_faces and
///     experimental::remove_almost_degenerate_faces);
///  8. wrap: with options.wrap fallback, when faces still cross, a sliver stays, or the surface
///     touches itself so that it would not read back as a solid once written (its equal
///     positions joined), the closed surface of step 5 is replaced by its alpha wrap
///     (alpha_wrap); always: every mesh; never: not at all;
///  9. orientation: orient_to_bound_a_volume;
/// 10. self-intersection check.
/// Throws InvalidInput with one line "repair, step '<step>': <what> [at (x, y, z)]" naming the
/// step that could not finish and the first place: no triangle left, a hole no method closes,
/// no enclosed volume, the surface intersecting itself (the first pair of faces) or touching
/// itself, or a triangle of (nearly) zero area.
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
