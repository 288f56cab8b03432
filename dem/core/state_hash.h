// A hash of a DEM world's dynamic state, so "same bits" is checked by a test, not by eye.
#pragma once

#include "dem/core/world.h"

#include <cstdint>

namespace clumpkit::dem {

/// FNV-1a 64 over every body's position, velocity, orientation (Eigen's coefficient order
/// x, y, z, w) and angular velocity, then every pair contact's shear force, as raw IEEE-754
/// bytes: equal hashes mean bit-identical runs. The offset basis is the one the benchmark
/// hashes in tests/bench/RESULTS.md were recorded with (FNV's basis with its last decimal digit
/// missing), kept so those records stay comparable.
std::uint64_t state_hash(const World& world);

}  // namespace clumpkit::dem
