#include "dem/measure/sampled_porosity.h"

#include "dem/core/parallel.h"
#include "geom/errors.h"
#include "geom/format.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clumpkit::dem {

double SampledRegion::porosity() const {
  return points > 0 ? 1.0 - double(solid) / double(points)
                    : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// Spheres listed in every cell of a uniform grid that their bounding cube touches: a point then
// tests the spheres of its own cell only.
struct CellLists {
  Vec3 lo;
  double cell = 1;
  std::array<long, 3> n{1, 1, 1};
  std::vector<int> first;  // cell -> offset in `items` (size cells + 1)
  std::vector<int> items;  // sphere indices

  long index(long i, long j, long k) const { return (k * n[1] + j) * n[0] + i; }
  long clamp_axis(double x, int a) const {
    return std::clamp(static_cast<long>(std::floor((x - lo[a]) / cell)), 0L, n[a] - 1);
  }
};

CellLists bin_spheres(const World& world, const Vec3& lo, const Vec3& hi, double r_min) {
  CellLists g;
  g.lo = lo;
  // Cells of the smallest radius, fewer when the box is huge against it (a memory bound).
  g.cell = r_min;
  for (int a = 0; a < 3; ++a)
    g.n[a] = std::max(1L, static_cast<long>(std::ceil((hi[a] - lo[a]) / g.cell)));
  while (double(g.n[0]) * double(g.n[1]) * double(g.n[2]) > 3e7) {
    g.cell *= 1.5;
    for (int a = 0; a < 3; ++a)
      g.n[a] = std::max(1L, static_cast<long>(std::ceil((hi[a] - lo[a]) / g.cell)));
  }
  const std::size_t cells = static_cast<std::size_t>(g.n[0] * g.n[1] * g.n[2]);
  std::vector<int> count(cells + 1, 0);
  const int ns = world.sphere_count();
  // Two passes (count, then fill) over each sphere's cell range.
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      g.first.assign(cells + 1, 0);
      for (std::size_t c = 0; c < cells; ++c) g.first[c + 1] = g.first[c] + count[c];
      g.items.assign(static_cast<std::size_t>(g.first[cells]), 0);
      std::fill(count.begin(), count.end(), 0);
    }
    for (int s = 0; s < ns; ++s) {
      const Vec3 c = world.sphere_center(s);
      const double r = world.sphere_radius(s);
      if ((c.array() + r < lo.array()).any() || (c.array() - r > hi.array()).any()) continue;
      const long i0 = g.clamp_axis(c.x() - r, 0), i1 = g.clamp_axis(c.x() + r, 0);
      const long j0 = g.clamp_axis(c.y() - r, 1), j1 = g.clamp_axis(c.y() + r, 1);
      const long k0 = g.clamp_axis(c.z() - r, 2), k1 = g.clamp_axis(c.z() + r, 2);
      for (long k = k0; k <= k1; ++k)
        for (long j = j0; j <= j1; ++j)
          for (long i = i0; i <= i1; ++i) {
            const long cell = g.index(i, j, k);
            if (pass == 0)
              ++count[cell];
            else
              g.items[g.first[cell] + count[cell]++] = s;
          }
    }
  }
  return g;
}

}  // namespace

std::vector<SampledRegion> sampled_regions(const World& world, const Vec3& lo, const Vec3& hi,
                                           double spacing, int regions,
                                           const PointRegion& region_of_point) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw InvalidInput("sampled porosity: spacing must be positive, got " + format_number(spacing));
  if (!lo.allFinite() || !hi.allFinite() || !((hi - lo).minCoeff() > 0.0))
    throw InvalidInput("sampled porosity: the box must have positive, finite edges");
  if (regions < 1) throw InvalidInput("sampled porosity: no region");
  std::array<long, 3> n{};
  double total = 1;
  for (int a = 0; a < 3; ++a) {
    // Enough points to cover the edge (a last one may lie beyond hi: the region decides).
    n[a] = std::max(1L, static_cast<long>(std::ceil((hi[a] - lo[a]) / spacing - 1e-9)));
    total *= double(n[a]);
  }
  if (total > 4e9)
    throw InvalidInput("sampled porosity: " + format_number(total, 3) +
                       " points: the spacing is too fine for the box");
  double r_min = std::numeric_limits<double>::infinity();
  for (int s = 0; s < world.sphere_count(); ++s) r_min = std::min(r_min, world.sphere_radius(s));
  if (!std::isfinite(r_min)) r_min = (hi - lo).maxCoeff();
  const CellLists cells = bin_spheres(world, lo, hi, r_min);

  // One task per z-layer of points, each with its own counts; summed in layer order.
  std::vector<std::vector<SampledRegion>> layer(static_cast<std::size_t>(n[2]),
                                                std::vector<SampledRegion>(regions));
  parallel_ranges(static_cast<std::size_t>(n[2]), 1, [&](std::size_t k0, std::size_t k1) {
    for (std::size_t k = k0; k < k1; ++k) {
      std::vector<SampledRegion>& out = layer[k];
      const double z = lo.z() + (double(k) + 0.5) * spacing;
      const long ck = cells.clamp_axis(z, 2);
      for (long j = 0; j < n[1]; ++j) {
        const double y = lo.y() + (double(j) + 0.5) * spacing;
        const long cj = cells.clamp_axis(y, 1);
        for (long i = 0; i < n[0]; ++i) {
          const Vec3 p(lo.x() + (double(i) + 0.5) * spacing, y, z);
          const int region = region_of_point(p);
          if (region < 0 || region >= regions) continue;
          ++out[region].points;
          const long cell = cells.index(cells.clamp_axis(p.x(), 0), cj, ck);
          for (int e = cells.first[cell]; e < cells.first[cell + 1]; ++e) {
            const int s = cells.items[e];
            const double r = world.sphere_radius(s);
            if ((world.sphere_center(s) - p).squaredNorm() <= r * r) {
              ++out[region].solid;
              break;
            }
          }
        }
      }
    }
  });
  std::vector<SampledRegion> sum(regions);
  for (const std::vector<SampledRegion>& l : layer)
    for (int r = 0; r < regions; ++r) sum[r].points += l[r].points, sum[r].solid += l[r].solid;
  return sum;
}

}  // namespace clumpkit::dem
