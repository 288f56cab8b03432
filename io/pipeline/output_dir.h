// The one output-directory rule of every job: DIR.partial while working, renamed to DIR at the
// end, and never an input overwritten.
#pragma once

#include <functional>
#include <string>

namespace clumpkit {

/// The one output-directory rule of every job: work is written beside DIR, in DIR.partial, and
/// renamed to DIR at the end, so a failed or killed run never leaves a partial DIR; an existing
/// DIR is replaced only when it is empty or holds a manifest.json (a clumpkit output). This
/// throws InvalidInput unless `dir` may be replaced (also when it is a file); jobs call it
/// before they start.
void check_output_directory(const std::string& dir);

/// Whether `path` is `dir` or lies inside it, comparing canonical paths component by component
/// (so any spelling of the same path, symbolic links resolved, counts as the same).
bool lies_within(const std::string& path, const std::string& dir);

/// Throws InvalidInput when replacing the output directory `dir` would remove the input `input`
/// (the same path, whatever its spelling, or a file or directory inside it); `what` names the
/// input in the message (e.g. "the source").
void check_output_spares(const std::string& dir, const std::string& input, const std::string& what);

/// Throws InvalidInput when the output file `out` (given as `option`) is the input `in` (the
/// same path, whatever its spelling, or a hard link to it) or lies inside it.
void check_not_input(const std::string& out, const std::string& option, const std::string& in);

/// Starts a job that resumes nothing: checks `dir` (check_output_directory), empties and creates
/// DIR.partial and returns its path. Throws IoError when it cannot be created.
std::string begin_staging(const std::string& dir);

/// Replaces `dir` by `staging` (check_output_directory's rule is checked again).
void publish_directory(const std::string& staging, const std::string& dir);

/// A job's whole output in one call: begin_staging, `write` fills the staging directory (its
/// path given), publish_directory. When `write` throws, the staging directory is removed and the
/// exception passed on: a failed job leaves neither DIR nor DIR.partial.
void write_staged(const std::string& dir, const std::function<void(const std::string&)>& write);

}  // namespace clumpkit
