// Neighbour search of the DEM: the grid search of the Verlet skin list and the near-list filter.
#pragma once

#include "geom/sphere.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace clumpkit::dem {

/// Scratch memory of find_skin_pairs, kept between calls so repeated searches do not allocate.
struct NeighbourGrid {
  struct CellSphere {  // a sphere as the search scans it: cell by cell, in index order
    double x, y, z, r;
    int index, body;
  };
  // The partners found, block by block of kBlock spheres in index order (one vector a block,
  // not one a sphere: a million small vectors cost more than the pairs), and per sphere how many.
  static constexpr std::size_t kBlock = 2048;
  std::vector<std::vector<int>> block_partners;
  std::vector<std::uint32_t> found;
  std::vector<std::int64_t> cell_start;  // dense cell table: first sphere of each cell
  std::vector<CellSphere> cell_spheres;  // spheres in cell order
  std::vector<std::size_t> offsets;      // counting-sort offsets
};

/// Every pair (i, j), i < j, of spheres of different bodies (body_of[i] != body_of[j]) whose
/// centres are closer than r_i + r_j + skin (m), sorted by (i, j), written to `pairs`. A grid
/// search: each pair is found by its larger sphere, scanning the cells within 2·r + skin of it,
/// with the cell size chosen by a cost model; the result does not depend on the grid.
/// Positions, radii and body ids are per sphere and of equal length.
void find_skin_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius,
                     const std::vector<int>& body_of, double skin, NeighbourGrid& grid,
                     std::vector<std::pair<int, int>>& pairs);

/// Whether spheres i and j are closer than r_i + r_j + near (m) at `position`: the near list's
/// test (filter_pairs, and the World's merge of freed pairs, which must keep the same pairs).
inline bool near_pair(const std::vector<Vec3>& position, const std::vector<double>& radius,
                      double near, int i, int j) {
  const double r = radius[i] + radius[j] + near;
  return (position[j] - position[i]).squaredNorm() < r * r;
}

/// The pairs of `pairs` whose centres are closer than r_i + r_j + near (m) at `position`, in the
/// same order, written to `out` (the near list of the two-level Verlet list); `keep` is scratch.
void filter_pairs(const std::vector<std::pair<int, int>>& pairs, const std::vector<Vec3>& position,
                  const std::vector<double>& radius, double near, std::vector<std::uint8_t>& keep,
                  std::vector<std::pair<int, int>>& out);

}  // namespace clumpkit::dem
