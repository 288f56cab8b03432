// Long library work called from Python: run off the main thread with the GIL released, progress
// handed to a Python callable, Ctrl-C turned into a stop request and a KeyboardInterrupt.
#pragma once

#include "geom/progress.h"

#include <pybind11/pybind11.h>

#include <functional>

namespace clumpkit::python {

/// Runs `work(interrupter)` on a worker thread while the calling (main) thread, holding the GIL
/// between waits, checks Python's signals every 50 ms and calls `progress(stage, fraction)` (a
/// Python callable or None) with the latest report of each stage entered since it last looked
/// (so a stage shorter than 50 ms is reported too). A report that starts a stage, advances it by
/// 1 % or ends it waits for that call, so a stop asked for in `progress` (an exception, or Ctrl-C
/// with _thread.interrupt_main) takes effect before the work goes on. Python runs signal handlers
/// on its main thread only, so the main thread must stay in Python's hands: a pending
/// KeyboardInterrupt (or an exception raised by `progress`) sets the flag the interrupter returns,
/// the work stops at its next poll (throwing Interrupted, or saying so in its outcome) and the
/// Python exception is raised once the worker has finished. Without a stop the work's own
/// exception, if any, is rethrown.
void run_interruptible(const std::function<void(const Interrupter&)>& work,
                       const pybind11::object& progress);

/// Maps the library's exceptions to Python's: InvalidInput → ValueError, IoError → OSError,
/// Interrupted → KeyboardInterrupt, NumericError → ArithmeticError.
void register_exceptions();

}  // namespace clumpkit::python
