// Union-of-balls volume and area by inclusion–exclusion over the dual complex (a cross-check).
#pragma once

#include "geom/sphere.h"

namespace clumpkit {

/// Volume and boundary area of a union of balls (units³, units²).
struct UnionMeasure {
  double volume = 0.0, area = 0.0;
};

/// Volume and area of the union of the clump's balls by Edelsbrunner's short inclusion–exclusion
/// formula over the dual complex K (the alpha complex at alpha = 0 of the weighted centres,
/// weight r²): measure(∪B) = Σ_{σ∈K} (−1)^dim σ measure(∩_{i∈σ} B_i)
/// (Edelsbrunner 1995, "The union of balls and its dual shape"; the area uses the boundary area
/// of each intersection). In dimension 3 K comes from CGAL::Fixed_alpha_shape_3 at alpha 0; for
/// coplanar or collinear centres the same classification (orthogonal-sphere radius ≤ 0, or a
/// coface in K) is done with CGAL's exact predicates. The 2-, 3- and 4-ball intersections are
/// closed forms: lens = two caps; a 3- or 4-ball intersection is split by the farthest-point power
/// diagram into "double caps" and "triple caps" (ball ∩ 2 or 3 half-spaces whose common line or
/// point lies in the ball, Edelsbrunner & Fu 1994), each measured by Gauss–Bonnet (spherical
/// part) and the divergence theorem from the ball centre; spheres meeting in a single point are
/// handled as limits. Exact duplicates are removed first. Independent of union_properties() apart
/// from the CGAL triangulation.
///
/// Throws InvalidInput for an empty clump or a non-finite centre or non-positive radius.
UnionMeasure union_measure_inclusion_exclusion(const Clump& clump);

}  // namespace clumpkit
