// The DEM's parallel loop over items: fixed-size chunks, each item written by one task only.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace clumpkit::dem {

/// Calls f(k) for k in [0, n) in parallel, in chunks of 32. Results are thread-count independent
/// as long as f(k) writes only to slots of item k.
template <class F>
void parallel_items(std::size_t n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 32),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k != r.end(); ++k) f(k);
                    });
}

}  // namespace clumpkit::dem
