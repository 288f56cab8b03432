// One Embree BVH over a mesh for the queries a fill makes: exact point-to-mesh distance and
// the surface crossings of axis-parallel lines.
#pragma once

#include "geom/mesh/mesh.h"

#include <memory>
#include <vector>

namespace clumpkit {

/// Built once in O(n log n) (Embree, single-threaded, a few hundred ms for 10⁶ triangles; a CGAL
/// AABB tree took seconds and three times the memory), then queried in about O(log n). Embree
/// culls in float; the distances themselves are computed in double from the mesh's vertices, so
/// they are exact up to double rounding. Queries are thread-safe.
class MeshIndex {
 public:
  /// Keeps a reference to `mesh`: it must outlive the index.
  explicit MeshIndex(const Mesh& mesh);
  ~MeshIndex();
  MeshIndex(const MeshIndex&) = delete;
  MeshIndex& operator=(const MeshIndex&) = delete;

  const Mesh& mesh() const { return mesh_; }

  /// The nearest triangle to a point and its distance; triangle −1 (and distance = limit) when
  /// none lies within `limit`.
  struct Nearest {
    double distance = 0.0;
    int triangle = -1;
  };
  Nearest nearest(const Vec3& p, double limit) const;

  /// From `start` (a triangle and its distance to p), moves to a triangle sharing a vertex with
  /// the current one while that is nearer to p (ties to the lower index), and returns where the
  /// walk ends: a descent of the distance over the surface. It reaches the nearest triangle when
  /// that lies downhill of the start (a start near it; any start for a point outside a convex
  /// mesh); else a local minimum. A few dozen point–triangle distances per step, no tree.
  Nearest descend(const Vec3& p, Nearest start) const;

  /// Distance from p to triangle t of the mesh.
  double distance_to_triangle(const Vec3& p, int t) const;

  /// Unsigned distance from p to the nearest triangle.
  double distance(const Vec3& p) const;
  /// The same, but any distance above `limit` comes back as `limit`: a bounded search, much
  /// faster where only nearby triangles matter (the narrow band of a distance field).
  double distance(const Vec3& p, double limit) const;

  /// Where the line {(x, y, z)} crosses the surface, ascending in x, each crossing once (one
  /// through an edge or vertex shared by several triangles counts once, with one of them). For a
  /// closed mesh an even count: inside between the 1st and 2nd, 3rd and 4th, ...; an odd count
  /// means the line grazed the surface and its parity cannot be trusted.
  struct Crossing {
    double x = 0.0;
    int triangle = -1;
  };
  std::vector<Crossing> crossings_x(double y, double z) const;
  /// crossings_x, cast again up to three times while the count is odd, each time `nudge` times
  /// a golden-ratio fraction to the side; still odd means the row runs in a face's plane.
  std::vector<Crossing> even_crossings_x(double y, double z, double nudge) const;

 private:
  struct Impl;
  const Mesh& mesh_;
  std::unique_ptr<Impl> impl_;
};

/// Closest point of the triangle (a, b, c) to p (Voronoi regions of its vertices, edges and face;
/// Ericson, Real-Time Collision Detection §5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace clumpkit
