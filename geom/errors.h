// Exception types shared by every clumpkit library: bad input, file trouble, interruption,
// numerical failure.
#pragma once

#include <stdexcept>
#include <string>

namespace clumpkit {

/// Input that violates a documented precondition (bad value, malformed file content).
/// The CLI maps it to exit code 2. Messages name the file, field and value.
struct InvalidInput : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// A file could not be opened, read or written. The CLI maps it to exit code 2.
struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Long work stopped because its Interrupter (geom/progress.h) asked it to (exit code 130, as
/// for SIGINT). The message says what was kept for a resumed run.
struct Interrupted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A computation failed to converge or produced a non-finite value (exit code 1).
struct NumericError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace clumpkit
