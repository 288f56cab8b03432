#include "dem/core/neighbour_search.h"

#include "dem/core/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clumpkit::dem {

namespace {

// Cell size h: sphere a scans the cells within R_a = 2·r_a + skin of it, column by column
// (dense table: a column of cells is one contiguous run). Expected cost per sphere ≈ columns
// visited + spheres checked ≈ (2R/h + 1)² · c_column + ρ·(2R + h)²·2R, ρ the number density
// over the bounding box; h tried at a few radius quantiles (2·r_q + skin) and halves of them,
// keeping the cell table at most 8n + 65536 cells.
double choose_cell_size(const std::vector<double>& sorted_radius, std::size_t n, const Vec3& extent,
                        double skin) {
  const double volume = extent.prod();
  double h = 2.0 * sorted_radius.back() + skin;
  {
    const double density = static_cast<double>(n) / volume;
    const double max_cells = 8.0 * static_cast<double>(n) + 65536.0;
    constexpr double kColumnCost = 4.0;  // a column start ≈ a few sphere checks
    double best = std::numeric_limits<double>::infinity();
    for (double q : {0.1, 0.25, 0.5, 0.75, 0.9, 0.97, 1.0})
      for (double f : {1.0, 0.5}) {
        const double r_q = sorted_radius[static_cast<std::size_t>(q * static_cast<double>(n - 1))];
        const double size = f * (2.0 * r_q + skin);
        if (!(size > 0.0)) continue;
        double cells = 1.0;
        for (int a = 0; a < 3; ++a) cells *= std::floor(extent[a] / size) + 1.0;
        if (cells > max_cells) continue;
        double cost = 0.0;
        for (std::size_t k = 0; k < n; k += std::max<std::size_t>(1, n / 4096)) {
          const double reach = 2.0 * sorted_radius[k] + skin;
          const double across = 2.0 * reach / size + 1.0;
          cost += kColumnCost * across * across +
                  density * (2.0 * reach + size) * (2.0 * reach + size) * 2.0 * reach;
        }
        if (cost < best) best = cost, h = size;
      }
  }
  if (!(h > 0.0)) h = 1.0;  // every radius and the skin zero: any size will do
  return h;
}

// The search grid over the bounding box: cells of size h from its low corner, dims[a] of them
// along axis a (cells in all), keyed linearly with z fastest.
struct CellGrid {
  Vec3 lo;
  double h;
  std::int64_t dims[3];
  double cells;

  std::int64_t cell_of(const Vec3& x, int a) const {
    return std::min<std::int64_t>(static_cast<std::int64_t>(std::floor((x[a] - lo[a]) / h)),
                                  dims[a] - 1);
  }
  std::int64_t key_of(std::int64_t cx, std::int64_t cy, std::int64_t cz) const {
    return (cx * dims[1] + cy) * dims[2] + cz;
  }
  std::int64_t first_cell(double v, int axis) const {
    return std::max<std::int64_t>(static_cast<std::int64_t>(std::floor((v - lo[axis]) / h)), 0);
  }
  std::int64_t last_cell(double v, int axis) const {
    return std::min<std::int64_t>(static_cast<std::int64_t>(std::floor((v - lo[axis]) / h)),
                                  dims[axis] - 1);
  }
  double gap(double v, std::int64_t cell, int axis) const {  // distance from v to a cell's slab
    const double c0 = lo[axis] + static_cast<double>(cell) * h;
    return v < c0 ? c0 - v : std::max(v - (c0 + h), 0.0);
  }
};

// The grid of cell size h (or a multiple of it) over the box [lo, hi].
CellGrid make_grid(const Vec3& lo, const Vec3& hi, double h) {
  CellGrid g;
  g.lo = lo;
  double cells = 1.0;
  for (;;) {
    cells = 1.0;
    for (int a = 0; a < 3; ++a) {
      g.dims[a] = static_cast<std::int64_t>(std::floor((hi[a] - lo[a]) / h)) + 1;
      cells *= static_cast<double>(g.dims[a]);
    }
    if (cells < 1e15) break;
    h *= 2.0;  // keep linear cell keys inside 64 bits for very sparse worlds
  }
  g.h = h;
  g.cells = cells;
  return g;
}

// Spheres of each cell, in index order: a dense cell table (counting sort) when the grid is
// small, else spheres sorted by (cell key, index) and binary search.
void bucket_spheres(const std::vector<Vec3>& position, const std::vector<double>& radius,
                    const std::vector<int>& body_of, const CellGrid& g, bool dense,
                    NeighbourGrid& grid, std::vector<std::pair<std::int64_t, int>>& keyed) {
  const std::size_t n = position.size();
  std::vector<std::int64_t>& cell_start = grid.cell_start;
  std::vector<NeighbourGrid::CellSphere>& cell_spheres = grid.cell_spheres;
  std::vector<std::size_t>& offsets = grid.offsets;
  std::vector<std::int64_t> key(n);
  parallel_items(n, [&](std::size_t k) {
    const Vec3& x = position[k];
    key[k] = g.key_of(g.cell_of(x, 0), g.cell_of(x, 1), g.cell_of(x, 2));
  });
  if (dense) {
    cell_start.assign(static_cast<std::size_t>(g.cells) + 1, 0);
    for (std::size_t k = 0; k < n; ++k) ++cell_start[key[k] + 1];
    for (std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
    cell_spheres.resize(n);
    offsets.assign(cell_start.begin(), cell_start.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& x = position[k];
      cell_spheres[offsets[key[k]]++] = NeighbourGrid::CellSphere{
          x.x(), x.y(), x.z(), radius[k], static_cast<int>(k), body_of[k]};
    }
  } else {
    keyed.resize(n);
    for (std::size_t k = 0; k < n; ++k) keyed[k] = {key[k], static_cast<int>(k)};
    std::sort(keyed.begin(), keyed.end());
  }
}

// The search of one sphere's partners in the bucketed grid (dense table or sorted keys).
struct PartnerSearch {
  const std::vector<Vec3>& position;
  const std::vector<double>& radius;
  const std::vector<int>& body_of;
  double skin;
  const CellGrid g;  // a copy: the scan reads it for every cell
  bool dense;
  const std::vector<std::int64_t>& cell_start;
  const std::vector<NeighbourGrid::CellSphere>& cell_spheres;
  const std::vector<std::pair<std::int64_t, int>>& keyed;

  // Appends to `out` the partners b that sphere a finds (r_b < r_a, or equal radii and b > a).
  void operator()(std::size_t a, std::vector<int>& out) const {
    const Vec3& x = position[a];
    const double ra = radius[a];
    const int body = body_of[a];
    const double reach = 2.0 * ra + skin;  // farthest partner centre: r_a + r_b + skin, r_b ≤ r_a
    // Branch-free tests: which sphere of a pair finds it depends on radii in random order, so a
    // branch on it is mispredicted half the time; only the rare hit branches.
    auto consider = [&](const NeighbourGrid::CellSphere& c) {
      const double rb = c.r;
      const bool finds = (rb < ra) | ((rb == ra) & (c.index > static_cast<int>(a)));
      const double dx = c.x - x.x(), dy = c.y - x.y(), dz = c.z - x.z();
      const double r = ra + rb + skin;
      if (finds & (c.body != body) & (dx * dx + dy * dy + dz * dz < r * r)) out.push_back(c.index);
    };
    auto consider_index = [&](int b) {
      const Vec3& y = position[b];
      consider(NeighbourGrid::CellSphere{y.x(), y.y(), y.z(), radius[b], b, body_of[b]});
    };
    // Cells overlapping the box x ± reach; per column, only z cells within the reach left
    // after the column's horizontal distance (columns beyond the reach are skipped).
    const std::int64_t x0 = g.first_cell(x.x() - reach, 0), x1 = g.last_cell(x.x() + reach, 0);
    const std::int64_t y0 = g.first_cell(x.y() - reach, 1), y1 = g.last_cell(x.y() + reach, 1);
    for (std::int64_t cx = x0; cx <= x1; ++cx) {
      const double gx = g.gap(x.x(), cx, 0);
      for (std::int64_t cy = y0; cy <= y1; ++cy) {
        const double gy = g.gap(x.y(), cy, 1);
        const double left = reach * reach - gx * gx - gy * gy;
        if (!(left >= 0.0)) continue;
        const double dz = std::sqrt(left);
        const std::int64_t z0 = g.first_cell(x.z() - dz, 2), z1 = g.last_cell(x.z() + dz, 2);
        if (z0 > z1) continue;
        if (dense) {
          // Cells (cx, cy, z0..z1) are consecutive in the table.
          const std::int64_t first = g.key_of(cx, cy, z0), last = g.key_of(cx, cy, z1);
          for (std::int64_t s = cell_start[first]; s < cell_start[last + 1]; ++s)
            consider(cell_spheres[s]);
        } else {
          for (std::int64_t cz = z0; cz <= z1; ++cz) {
            const std::int64_t cell = g.key_of(cx, cy, cz);
            auto it = std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(cell, -1));
            for (; it != keyed.end() && it->first == cell; ++it) consider_index(it->second);
          }
        }
      }
    }
  }
};

// Calls f(a, b) for every partner b of a that grid.block_partners holds, in sphere order.
template <class F>
inline void each_found(const NeighbourGrid& grid, std::size_t n, F&& f) {
  constexpr std::size_t kBlock = NeighbourGrid::kBlock;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  for (std::size_t block = 0; block < blocks; ++block) {
    const std::vector<int>& list = grid.block_partners[block];
    std::size_t at = 0;
    const std::size_t end = std::min(n, (block + 1) * kBlock);
    for (std::size_t a = block * kBlock; a < end; ++a)
      for (std::uint32_t c = 0; c < grid.found[a]; ++c) f(a, list[at++]);
  }
}

// Pairs (min, max) grouped by their first sphere (counting sort), each group sorted by j.
void collect_pairs(NeighbourGrid& grid, std::size_t n, std::vector<std::pair<int, int>>& pairs) {
  std::vector<std::size_t>& offsets = grid.offsets;
  offsets.assign(n + 1, 0);
  each_found(grid, n, [&](std::size_t a, int b) { ++offsets[std::min<std::size_t>(a, b) + 1]; });
  for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
  pairs.resize(offsets[n]);
  {
    std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
    each_found(grid, n, [&](std::size_t a, int b) {
      const int i = std::min(static_cast<int>(a), b), j = std::max(static_cast<int>(a), b);
      pairs[fill[i]++] = {i, j};
    });
  }
  std::vector<std::vector<int>>().swap(grid.block_partners);
  std::vector<std::uint32_t>().swap(grid.found);
  parallel_items(n, [&](std::size_t i) {
    std::sort(pairs.begin() + static_cast<std::ptrdiff_t>(offsets[i]),
              pairs.begin() + static_cast<std::ptrdiff_t>(offsets[i + 1]));
  });
}

}  // namespace

// Candidate pairs: spheres of different bodies closer than r_i + r_j + skin. Each pair is found
// by its larger sphere (ties: by the lower index), which scans the cells within 2·r + skin of
// it, so the cell size can follow the typical sphere instead of the largest: in a soil–rock
// mixture (5 mm soil, clump spheres up to 50 mm) a largest-sphere grid puts thousands of small
// spheres in each of the 27 cells a small sphere scans. The cell size is the one of a few
// radius quantiles with the fewest expected distance checks. The candidate set does not depend
// on the grid, so neither does anything downstream.
void find_skin_pairs(const std::vector<Vec3>& position, const std::vector<double>& radius,
                     const std::vector<int>& body_of, double skin, NeighbourGrid& grid,
                     std::vector<std::pair<int, int>>& pairs) {
  std::vector<std::pair<int, int>>().swap(pairs);  // the old list is not held during the search
  const std::size_t n = position.size();
  if (n < 2) return;

  Vec3 lo = position[0], hi = position[0];
  for (std::size_t k = 0; k < n; ++k) {
    lo = lo.cwiseMin(position[k]);
    hi = hi.cwiseMax(position[k]);
  }
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));

  std::vector<double> sorted_radius(radius);
  std::sort(sorted_radius.begin(), sorted_radius.end());
  const CellGrid g = make_grid(lo, hi, choose_cell_size(sorted_radius, n, extent, skin));

  const bool dense = g.cells <= 8.0 * static_cast<double>(n) + 65536.0;
  std::vector<std::pair<std::int64_t, int>> keyed;
  bucket_spheres(position, radius, body_of, g, dense, grid, keyed);

  std::vector<double>().swap(sorted_radius);
  // Each sphere a lists the partners b it finds (r_b < r_a, or equal radii and b > a), appended
  // to its block's list.
  constexpr std::size_t kBlock = NeighbourGrid::kBlock;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  grid.block_partners.resize(blocks);
  grid.found.resize(n);
  const PartnerSearch search{position, radius,          body_of,           skin, g,
                             dense,    grid.cell_start, grid.cell_spheres, keyed};
  parallel_items(blocks, [&](std::size_t block) {
    std::vector<int>& out = grid.block_partners[block];
    out.clear();
    const std::size_t end = std::min(n, (block + 1) * kBlock);
    for (std::size_t a = block * kBlock; a < end; ++a) {
      const std::size_t before = out.size();
      search(a, out);
      grid.found[a] = static_cast<std::uint32_t>(out.size() - before);
    }
  });
  std::vector<NeighbourGrid::CellSphere>().swap(grid.cell_spheres);
  std::vector<std::int64_t>().swap(grid.cell_start);

  collect_pairs(grid, n, pairs);
}

void filter_pairs(const std::vector<std::pair<int, int>>& pairs, const std::vector<Vec3>& position,
                  const std::vector<double>& radius, double near, std::vector<std::uint8_t>& keep,
                  std::vector<std::pair<int, int>>& out) {
  const std::size_t m = pairs.size();
  keep.resize(m);
  parallel_items(m, [&](std::size_t k) {
    const auto [i, j] = pairs[k];
    keep[k] = near_pair(position, radius, near, i, j);
  });
  std::size_t kept = 0;
  for (std::size_t k = 0; k < m; ++k) kept += keep[k];
  out.resize(kept);  // exactly: a growing vector would hold up to twice the list at its peak
  std::size_t at = 0;
  for (std::size_t k = 0; k < m; ++k)
    if (keep[k]) out[at++] = pairs[k];
}

}  // namespace clumpkit::dem
