#include "geom/sphere.h"

#include "geom/errors.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace clumpkit {

void validate(const Clump& clump) {
  if (clump.spheres.empty()) throw InvalidInput("clump has no spheres");
  for (std::size_t i = 0; i < clump.spheres.size(); ++i) {
    const Sphere& s = clump.spheres[i];
    if (!s.center.allFinite())
      throw InvalidInput("sphere " + std::to_string(i) + ": centre is not finite");
    if (!(s.radius > 0.0) || !std::isfinite(s.radius))
      throw InvalidInput("sphere " + std::to_string(i) +
                         ": radius must be positive and finite, got " + std::to_string(s.radius));
  }
}

std::vector<int> distinct_balls(const std::vector<Sphere>& s) {
  const std::size_t n = s.size();
  if (n == 0) return {};
  // Why a tolerance and not only exact duplicates: where two centres nearly coincide, the
  // power-diagram plane between their balls lies at (d² + r_i² - r_j²) / 2d from the centre,
  // and the rounding of r_i² - r_j² divided by a d of a few ulps moves it by the whole radius:
  // the triangulation (exact predicates) and the floating-point half-spaces then disagree on
  // which balls bound which, and the union's volume came out up to 3e-3 high on fills that
  // had put copies of a sphere 1e-16 apart. A ball dropped here lies inside its
  // keeper but for a sliver no thicker than d, so the union loses at most 4πr²·d, 3e-8 of its
  // volume.
  Vec3 lo = s[0].center, hi = s[0].center;
  double r_max = 0.0;
  for (const Sphere& b : s) {
    lo = lo.cwiseMin(b.center);
    hi = hi.cwiseMax(b.center);
    r_max = std::max(r_max, b.radius);
  }
  const double tolerance = kCoincidentCentres * r_max;
  // Cells of many tolerances, so most balls look in their own cell only; capped at 2^40 cells
  // along the widest axis so the cell indices fit.
  const double cell = std::max(64.0 * tolerance, (hi - lo).maxCoeff() / 1099511627776.0);
  using Key = std::array<std::int64_t, 3>;
  auto key_of = [&](const Vec3& c) {
    return Key{std::int64_t(std::floor((c.x() - lo.x()) / cell)),
               std::int64_t(std::floor((c.y() - lo.y()) / cell)),
               std::int64_t(std::floor((c.z() - lo.z()) / cell))};
  };
  std::vector<std::pair<Key, int>> by_cell(n);
  for (std::size_t k = 0; k < n; ++k) by_cell[k] = {key_of(s[k].center), static_cast<int>(k)};
  tbb::parallel_sort(by_cell.begin(), by_cell.end());
  // Larger balls first, ties by index (a total order, so one result): a ball is dropped when a
  // ball kept before it, as large or larger, has its centre within the tolerance of that ball's
  // radius.
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) {
    return s[a].radius != s[b].radius ? s[a].radius > s[b].radius : a < b;
  });
  std::vector<char> kept(n, 0);
  for (const int i : order) {
    const Vec3& c = s[i].center;
    const Key own = key_of(c);
    // The neighbouring cell along an axis only where the centre lies within the tolerance of
    // that side.
    std::array<std::array<std::int64_t, 2>, 3> range;
    for (int a = 0; a < 3; ++a) {
      const double at = (c[a] - lo[a]) / cell - double(own[a]);
      range[a] = {own[a] - (at * cell <= tolerance ? 1 : 0),
                  own[a] + ((1.0 - at) * cell <= tolerance ? 1 : 0)};
    }
    bool near = false;
    for (std::int64_t x = range[0][0]; x <= range[0][1] && !near; ++x)
      for (std::int64_t y = range[1][0]; y <= range[1][1] && !near; ++y)
        for (std::int64_t z = range[2][0]; z <= range[2][1] && !near; ++z) {
          const Key k{x, y, z};
          auto at = std::lower_bound(by_cell.begin(), by_cell.end(), std::make_pair(k, -1));
          for (; at != by_cell.end() && at->first == k && !near; ++at) {
            const int j = at->second;
            near = kept[j] && (s[j].center - c).norm() <= kCoincidentCentres * s[j].radius;
          }
        }
    if (!near) kept[i] = 1;
  }
  std::vector<int> keep;
  for (std::size_t k = 0; k < n; ++k)
    if (kept[k]) keep.push_back(static_cast<int>(k));
  return keep;
}

}  // namespace clumpkit
