// Welding vertices: exact copies as a triangle soup is read, and copies within a tolerance.
#pragma once

#include "geom/mesh/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace clumpkit {

/// Joins copies of vertices as they come, so that a reader of a triangle soup (STL: each corner
/// stored once per triangle, about six copies of every vertex) never holds the soup: exact copies,
/// or points in the same cell of a grid. Open addressing, no node per vertex: a scan-sized STL has
/// 4·10⁶ corners.
class VertexWelder {
 public:
  /// Exact copies (−0 and +0 alike). `expected` distinct vertices: a hint for the table's first
  /// size, which grows as needed.
  explicit VertexWelder(std::size_t expected = 0);
  /// Points in the same cell of size `cell` counted from `origin` (each coordinate's
  /// (p − origin) / cell rounded to the nearest integer); with `cell` ≤ 0, exact copies.
  VertexWelder(std::size_t expected, const Vec3& origin, double cell);
  /// The index of the first vertex added to the same key, adding `p` (kept as it is, the
  /// representative of its cell) if the key is new.
  int add(const Vec3& p);
  /// add() for `n` points in order, their indices to `index`: the table's lines are fetched
  /// ahead, since a scan's corners hit a table of 10⁶ keys at random (latency, not work, is the
  /// cost).
  void add(const Vec3* points, std::size_t n, int* index);
  /// The distinct vertices in the order of first addition (moved out; the welder is spent).
  std::vector<Vec3> take_vertices() { return std::move(vertices_); }

  /// The table behind add(): keys of three 64-bit words, numbered in order of first addition.
  using Key = std::array<std::uint64_t, 3>;
  int add_key(const Key& key, bool& added);

 private:
  Key key_of(const Vec3& p) const;
  int add_key(const Key& key, std::size_t hash, bool& added);
  void grow();
  Vec3 origin_ = Vec3::Zero();
  double cell_ = 0.0;
  std::size_t mask_ = 0;
  std::vector<int> slots_;
  std::vector<Key> keys_;
  std::vector<Vec3> vertices_;
};

/// Merges vertices closer than `tolerance` (relative to the bounding-box diagonal): vertex i
/// joins the first vertex with the same cell of that size from the box's corner (with 0, the
/// same coordinates), survivors in the order of first occurrence; drops triangles that become
/// degenerate. After reading STL and, with a tolerance asked for, OBJ and PLY. A mesh with a
/// non-finite coordinate is left as it is.
void weld_vertices(Mesh& mesh, double relative_tolerance = 1e-9);

}  // namespace clumpkit
