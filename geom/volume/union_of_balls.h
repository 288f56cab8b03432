// Exact volume, area, centroid and inertia of a union of balls (a clump) via the power diagram.
#pragma once

#include "geom/progress.h"
#include "geom/sphere.h"

namespace clumpkit {

/// Mass properties (unit density) and boundary area of a union of balls.
struct UnionProperties {
  MassProperties mass;  ///< volume, centroid, inertia about the centroid (units of the input)
  double area = 0.0;    ///< area of the boundary of the union (units²)
  /// Spheres that add nothing to the union: exact duplicates (all copies but one, and smaller
  /// balls on the same centre), spheres that are not vertices of the regular triangulation, and
  /// spheres whose power cell does not reach into their ball (nested or internally tangent
  /// spheres; a piece below 1e-13 of its ball's volume counts as nothing).
  int hidden = 0;
};

/// Exact (closed form, double precision) volume, boundary area, centroid and inertia tensor of
/// the union of the clump's balls, at unit density.
///
/// Method (Edelsbrunner 1995, "The union of balls and its dual shape"): the power diagram of the
/// balls (weight r²; CGAL Regular_triangulation_3) splits the union into the disjoint convex
/// pieces B_i ∩ PowerCell_i. Each piece is integrated by the divergence theorem from its ball
/// centre: a planar face at distance h contributes the cone (h/3, h/4, h/5)·(area moments of the
/// face ∩ disk) and the spherical part contributes (r³/3, r⁴/4, r⁵/5)·(solid-angle moments). The
/// solid angle of a triangle is Van Oosterom–Strackee's formula; its first and second moments are
/// sums over the great-circle edges of the spherical triangle (Stokes / the identity
/// Δ_S(ωωᵀ) = 2I − 6ωωᵀ on the unit sphere). Lower-dimensional input (collinear or coplanar
/// centres, fewer than four balls), duplicates, hidden balls and tangencies are handled exactly.
/// Large inputs are triangulated in chunks of 2¹⁸ balls (slabs along the longest axis with a
/// halo of 2·r_max, in parallel): the pieces are exactly those of one triangulation, in half the
/// memory or less. The interrupter is told ("union", the fraction of the balls integrated) after
/// each chunk's triangulation and every 2¹² balls, from one thread at a time; asked to stop, the
/// work throws Interrupted.
///
/// Throws InvalidInput for an empty clump or a non-finite centre or non-positive radius.
UnionProperties union_properties(const Clump& clump, const Interrupter& interrupter = {});

/// union_properties with chunks of `chunk` balls instead of 2¹⁸ (for tests: small chunks on a
/// small clump exercise the stitching). Same results for any chunk size (up to the rounding of
/// degenerate triangulations: four or more cospherical weighted points).
UnionProperties union_properties_in_chunks(const Clump& clump, int chunk,
                                           const Interrupter& interrupter = {});

/// Estimated peak bytes of union_properties: the program, the balls and their pieces, and the
/// regular triangulations of the chunks built at once (one per thread). 10⁶ balls on 2 threads: 652
/// MiB measured for the whole process (1,324 MiB with one triangulation of every ball, before issue
/// 34).
double union_bytes_estimate(const Clump& clump);

/// Estimated peak bytes of the measures that triangulate every ball at once (the alpha complex
/// of inclusion_exclusion.h, the analytic slicing of slicing.h): 1,500 per ball and 64 MiB for
/// the program (1,324 MiB measured for one triangulation of 10⁶ balls, the whole process).
double whole_triangulation_bytes_estimate(const Clump& clump);

}  // namespace clumpkit
