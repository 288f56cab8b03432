// Crash-safe file writing: fill a temporary file next to the target, then rename it into place.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace clumpkit {

/// Writes `path` atomically: calls `fill` on a stream to a temporary file in the same directory
/// (so the rename never crosses file systems), then renames it over `path`. On any failure,
/// including an exception thrown by `fill`, the temporary file is removed and `path` is left as
/// it was. Stream and rename failures throw IoError naming `path`; exceptions from `fill`
/// propagate unchanged. `binary` opens the stream in binary mode (no newline translation).
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill,
                           bool binary = true);

/// Removes, anywhere under `dir`, the temporary files write_file_atomically leaves behind when
/// a process is killed mid-write (".NAME.tmp-PID-N"): a resumed job's work directory must hold
/// only finished files, or the stray ones would be published with it. A missing dir is fine.
void remove_stray_temporaries(const std::string& dir);

}  // namespace clumpkit
