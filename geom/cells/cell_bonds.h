// Bonds between Voronoi cells: one per shared face, with the integration points over the face on
// which the cohesive law acts (Hu et al. 2023 §2.2, eqs. 5–11).
#pragma once

#include "geom/cells/voronoi_cells.h"
#include "geom/random.h"
#include "geom/shapes/distribution.h"

#include <vector>

namespace clumpkit {

/// The subdivisions s of cell_bonds: each fan triangle of a face splits into 4^s integration
/// points (a numerical control; 3 gives 64 per triangle).
inline constexpr Range kFaceSubdivisions = integers(0, 3);

/// An integration point of a bond: a position on the face and the face area it stands for.
struct FacePoint {
  Vec3 position = Vec3::Zero();
  double area = 0.0;
};

/// The bond across the face shared by cells a < b.
struct CellBond {
  int a = 0, b = 0;
  double area = 0.0;              ///< face area (as seen from cell a)
  Vec3 centroid = Vec3::Zero();   ///< face centroid
  Vec3 normal = Vec3::Zero();     ///< unit normal from a towards b
  std::vector<FacePoint> points;  ///< one per fan triangle (face centroid, v_k, v_k+1)
  /// Factor on the bond's strengths σ_I and σ_II (the paper's heterogeneity: each interface's
  /// strengths times a factor drawn from a normal distribution within [0.75, 1.25]).
  double strength_factor = 1.0;
};

/// The default strength factor: normal, mean 1, sd 0.125, truncated to [0.75, 1.25]. The paper
/// gives the window, not the spread; ±2 sd filling the window is our assumption.
Distribution default_strength_factor();

/// One bond per face shared by two cells, in order of (a, b), from cell a's copy of the face:
/// the polygon is fanned from its centroid and each triangle gives an integration point at its
/// centroid weighted by its area, so the points' areas sum to the face's and their first moment
/// is the face centroid's (a face's bending and twisting come from the spread of the points).
/// Faces of zero area bound nothing and carry no bond. Strength factors are drawn from
/// `strength` with `rng` in bond order. `subdivisions` s splits each fan triangle 4^s times at
/// its edge midpoints (more points per face, the same area and centroid: a numerical control).
/// Throws InvalidInput for s outside kFaceSubdivisions.
std::vector<CellBond> cell_bonds(const Tessellation& cells, const Distribution& strength, Rng& rng,
                                 int subdivisions = 0);

}  // namespace clumpkit
