// One piece of a union of balls: the integrals (volume, spherical area, first and second
// moments) over a ball cut by the half-spaces of its power cell, the building block of
// geom/volume/union_of_balls.h.
#pragma once

#include "geom/sphere.h"

#include <vector>

namespace clumpkit::detail {

using Vec2 = Eigen::Vector2d;

// Half-space {u : n·u ≤ h}, u relative to the ball centre, n a unit vector. For a neighbour j of
// ball i it is the power half-space pow_i ≤ pow_j, with h = (D² + r_i² − r_j²) / (2D).
struct HalfSpace {
  Vec3 n;
  double h;
};

// Integrals over one piece B_i ∩ C_i, moments relative to the ball centre.
struct Piece {
  double volume = 0.0;         // ∫ dV
  double area = 0.0;           // area of the spherical part of the boundary
  Vec3 first = Vec3::Zero();   // ∫ u dV
  Mat3 second = Mat3::Zero();  // ∫ u uᵀ dV
  bool empty = false;          // known to be empty (the ball lies outside one half-space)
};

// Working arrays of ball_piece and integrate_face, reused from ball to ball (allocating them per
// face cost a tenth of the time on 10⁶ balls).
struct Scratch {
  std::vector<HalfSpace> kept;
  std::vector<Vec3> poly, clipped, dir;
  std::vector<double> f;
  std::vector<int> radial;
  std::vector<Vec2> q;
  std::vector<char> gone;  // planes whose face is empty
};

// Integrals over B(0, r) ∩ ⋂ planes. Half-spaces that contain the ball are dropped, a half-space
// that excludes it (h ≤ −r) empties the piece; the rest are bounded by the cube |u|∞ ≤ 2r (which
// leaves the ball untouched) so that every face is a bounded polygon, built by clipping a large
// square in its plane by all other half-spaces.
Piece ball_piece(double r, const std::vector<HalfSpace>& planes, Scratch& w);

}  // namespace clumpkit::detail
