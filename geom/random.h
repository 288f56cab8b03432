// Seeded, platform-independent random numbers: generator, distributions and per-item streams.
#pragma once

#include "geom/range.h"
#include "geom/vec.h"

#include <cstdint>

namespace clumpkit {

/// The seed of a run (Rng's, from a recipe: a TOML integer, so at most 2^63 − 1). Every value
/// is a seed: the type holds the range, and Rng has nothing to check.
inline constexpr Range kSeed = integers_from(0);

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
  /// Point uniform in the box [lo, hi), its components drawn z first, then y, then x. Written
  /// as Vec3(uniform(..), uniform(..), uniform(..)) the order would be the compiler's (C++ leaves
  /// the order of arguments open: GCC takes them right to left, clang left to right) and so
  /// would every result; z, y, x is the order GCC gave, so results made before are unchanged.
  Vec3 uniform(const Vec3& lo, const Vec3& hi);
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n);
  /// Standard normal by the Box–Muller transform.
  double normal();
  /// Quaternion of four standard normals (w, x, y, z), drawn z, y, x, w (GCC's order, as above),
  /// not normalised: a uniform random rotation once normalised.
  Eigen::Quaterniond normal_quaternion();
  /// Uniform direction on the unit sphere (Marsaglia's method via z and angle).
  Vec3 unit_vector();

 private:
  std::uint64_t s_[4];
};

}  // namespace clumpkit
