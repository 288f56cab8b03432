#include "geom/sphere.h"

#include "geom/errors.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

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
  std::vector<int> order(s.size());
  std::iota(order.begin(), order.end(), 0);
  // A total order (ties broken by index), so the parallel sort gives one result.
  tbb::parallel_sort(order.begin(), order.end(), [&](int a, int b) {
    const Vec3& p = s[a].center;
    const Vec3& q = s[b].center;
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    if (s[a].radius != s[b].radius) return s[a].radius > s[b].radius;
    return a < b;
  });
  std::vector<int> keep;
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || s[order[k]].center != s[order[k - 1]].center) keep.push_back(order[k]);
  std::sort(keep.begin(), keep.end());
  return keep;
}

}  // namespace clumpkit
