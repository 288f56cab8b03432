// One progress and interrupt interface for all long work: report how far, ask whether to stop.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace clumpkit {

/// How far long work is: the fraction done (0..1) and, where the work comes in units a user
/// counts (particles of a library, particles of a crushing set), the units done of `total`
/// (total 0: no units, the fraction alone). Converts to the fraction, so an interrupter that only
/// wants the fraction takes a double.
struct Progress {
  double fraction = 0.0;
  std::size_t done = 0, total = 0;

  Progress(double f) : fraction(f) {}  // NOLINT(google-explicit-constructor): a fraction is one
  Progress(std::size_t units_done, std::size_t units_total)
      : fraction(units_total ? static_cast<double>(units_done) / static_cast<double>(units_total)
                             : 1.0),
        done(units_done),
        total(units_total) {}
  operator double() const { return fraction; }  // NOLINT(google-explicit-constructor)
};

/// Told by long work, between units of work, what it is doing (`stage`: "library",
/// "calibration", "run", …) and how far it is; returns true to ask the work to stop. Report and
/// poll in one call, as OpenVDB's interrupter (util::NullInterrupter) does. Work that runs in
/// parallel calls it from one thread at a time. Work that stops on request throws Interrupted
/// (geom/errors.h) or says so in its outcome; work that checkpoints saves a checkpoint first, so a
/// resumed run loses nothing.
using Interrupter = std::function<bool(std::string_view stage, Progress progress)>;

/// interrupter(stage, progress) when one is set; false (go on) otherwise.
inline bool interrupted(const Interrupter& interrupter, std::string_view stage, Progress progress) {
  return interrupter && interrupter(stage, progress);
}

}  // namespace clumpkit
