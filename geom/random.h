// Seeded, platform-independent random numbers: generator, distributions and per-item streams.
#pragma once

#include "geom/mesh/mesh.h"

#include <cstdint>

namespace clumpkit {

/// xoshiro256** generator seeded through splitmix64. Our own distributions below give the same
/// numbers on every standard library, which std:: distributions do not.
class Rng {
 public:
  explicit Rng(std::uint64_t seed);
  /// Independent stream for item `index` of a run seeded with `seed` (e.g. particle i), so that
  /// results do not depend on which thread generates which item.
  static Rng stream(std::uint64_t seed, std::uint64_t index);

  std::uint64_t next();
  /// Uniform in [0, 1) with 53 random bits.
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi);
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n);
  /// Standard normal by the Box–Muller transform.
  double normal();
  /// Uniform direction on the unit sphere (Marsaglia's method via z and angle).
  Vec3 unit_vector();

 private:
  std::uint64_t s_[4];
};

}  // namespace clumpkit
