#include "dem/measure/strain_rate.h"

#include <algorithm>
#include <limits>

namespace clumpkit::dem {

double interior_axial_strain_rate(const World& world, double z_lo, double z_hi) {
  // Sums centred on the band's middle keep the slope's cancellation small.
  const double mid = 0.5 * (z_lo + z_hi);
  double n = 0, sz = 0, sv = 0, szz = 0, szv = 0;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const Body& b : world.bodies()) {
    const double z = b.position.z();
    if (!(z >= z_lo && z <= z_hi)) continue;
    const double x = z - mid, v = b.velocity.z();
    n += 1, sz += x, sv += v, szz += x * x, szv += x * v;
    lowest = std::min(lowest, z), highest = std::max(highest, z);
  }
  if (n < 2 || !(highest > lowest)) return 0.0;
  return -(n * szv - sz * sv) / (n * szz - sz * sz);
}

}  // namespace clumpkit::dem
