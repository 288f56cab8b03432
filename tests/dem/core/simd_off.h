// Test helper: the scalar pair kernel for the lifetime of the guard (the SIMD one restored after).
#pragma once

#include "dem/core/pair_kernel.h"

namespace clumpkit::dem {

struct SimdOff {
  bool was = simd_enabled();
  SimdOff() { set_simd(false); }
  ~SimdOff() { set_simd(was); }
};

}  // namespace clumpkit::dem
