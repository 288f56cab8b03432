// One progress and interrupt interface for all long work: report how far, ask whether to stop.
#pragma once

#include <functional>
#include <string_view>

namespace clumpkit {

/// Told by long work, between units of work, what it is doing (`stage`: "library",
/// "calibration", "run", …) and the fraction of it done (0..1); returns true to ask the work to
/// stop. Report and poll in one call, as OpenVDB's interrupter (util::NullInterrupter) does.
/// Work that runs in parallel calls it from one thread at a time. Work that stops on request
/// throws Interrupted (geom/errors.h) or says so in its outcome; work that checkpoints saves a
/// checkpoint first, so a resumed run loses nothing.
using Interrupter = std::function<bool(std::string_view stage, double fraction)>;

/// interrupter(stage, fraction) when one is set; false (go on) otherwise.
inline bool interrupted(const Interrupter& interrupter, std::string_view stage, double fraction) {
  return interrupter && interrupter(stage, fraction);
}

}  // namespace clumpkit
