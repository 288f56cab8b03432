// Worker threads of a job: the one default (all cores) and the one check, for the command line
// and the Python module alike.
#pragma once

#include <tbb/global_control.h>

#include <memory>

namespace clumpkit {

/// Worker threads when none are asked for: 0, all cores.
inline constexpr int kAllCores = 0;

/// At most `threads` TBB workers while the result lives (nullptr: all cores, for kAllCores).
/// Results do not depend on it (every job is deterministic for any thread count). Throws
/// InvalidInput "threads must be 0 (all cores) or more, got N" for a negative count.
std::unique_ptr<tbb::global_control> limit_threads(int threads);

}  // namespace clumpkit
