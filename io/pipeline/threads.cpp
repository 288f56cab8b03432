#include "io/pipeline/threads.h"

#include "geom/errors.h"

#include <cstddef>
#include <string>

namespace clumpkit {

std::unique_ptr<tbb::global_control> limit_threads(int threads) {
  if (threads < 0)
    throw InvalidInput("threads must be 0 (all cores) or more, got " + std::to_string(threads));
  if (threads == kAllCores) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                               static_cast<std::size_t>(threads));
}

}  // namespace clumpkit
