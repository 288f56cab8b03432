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

/// Calls f(begin, end) on disjoint ranges covering [0, n), in parallel, each at most `grain`
/// items long: for kernels that work on batches of items. Thread-count independent under the
/// same condition as parallel_items.
template <class F>
void parallel_ranges(std::size_t n, std::size_t grain, F&& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

}  // namespace clumpkit::dem
