#include "dem/core/state_hash.h"

#include "geom/hash.h"

namespace clumpkit::dem {

std::uint64_t state_hash(const World& world) {
  Fnv1a h{1469598103934665603ULL};
  auto add = [&](const double* p, int n) { h.add_bytes(p, sizeof(double) * n); };
  for (const Body& b : world.bodies()) {
    add(b.position.data(), 3);
    add(b.velocity.data(), 3);
    add(b.orientation.coeffs().data(), 4);
    add(b.angular_velocity.data(), 3);
  }
  for (const PairContact& c : world.contacts()) add(c.state.shear.data(), 3);
  return h.value;
}

}  // namespace clumpkit::dem
