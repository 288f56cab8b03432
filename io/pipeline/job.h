// What every pipeline job shares: the output-directory rule, the manifest schema and the
// parallel per-particle runner (progress and interruption through geom/progress.h).
#pragma once

#include "geom/progress.h"
#include "io/recipes/recipe.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace clumpkit {

/// Runs work(i) for every particle i with todo[i] (all if todo is empty) in parallel (TBB).
/// Stops at the first failure and rethrows it as InvalidInput "RECIPE: fraction 'NAME' particle
/// NNNNN: why" (fraction_of[i] names the fraction). After each particle the interrupter is told
/// (`stage`, particles done / total, counting `already` done ones); when it asks to stop, no
/// new particle starts and Interrupted is thrown once the running ones are done.
void for_each_particle(const ShapeRecipe& recipe, const std::vector<int>& fraction_of,
                       const std::vector<char>& todo, std::size_t already,
                       const std::function<void(std::size_t)>& work, std::string_view stage,
                       const Interrupter& interrupter);

/// The checksum of a per-particle record: FNV-1a 64 of its compact JSON without the field. A
/// record changed on disk (a flipped byte, an edit) no longer matches and is redone, never reused.
std::string record_checksum(const nlohmann::ordered_json& record);

/// Writes `record` to `path` atomically, as indented JSON with its "checksum" added last.
void write_sealed_record(const std::string& path, const nlohmann::ordered_json& record);

/// Reads a record written by write_sealed_record into `record` (its checksum removed); false when
/// it does not parse or fails its checksum (atomic writes cannot leave one, but disks and users
/// can). Throws IoError when the file cannot be read.
bool read_sealed_record(const std::string& path, nlohmann::ordered_json& record);

/// A JSON file of a clumpkit output (report.json, manifest.json). Throws IoError when it cannot
/// be opened and InvalidInput naming it when it is not JSON.
nlohmann::json read_json_file(const std::string& path);

/// Fraction index of every particle of the recipe, in id order.
std::vector<int> particle_fractions(const ShapeRecipe& recipe);

/// Format version of every manifest.json (one schema: tool, format_version,
/// version, command, recipe_path, recipe (its text), seed, then the command's own fields).
inline constexpr int kManifestFormat = 1;

/// The manifest fields every output shares: tool, format_version, version, command, recipe_path,
/// recipe (the text), seed.
nlohmann::ordered_json manifest_head(const std::string& command, const std::string& recipe_path,
                                     const std::string& recipe_text, std::uint64_t seed);

/// The manifest fields every output of a shape recipe shares: tool, format_version, version,
/// command, recipe path and text, seed, particle count.
nlohmann::ordered_json manifest_head(const std::string& command, const ShapeRecipe& recipe);

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

}  // namespace clumpkit
