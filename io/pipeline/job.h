// What every pipeline job shares: progress, the output-directory rule, the manifest schema and
// the parallel per-particle runner.
#pragma once

#include "io/recipe.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace clumpkit {

/// Progress callback: (items done, items total). May be called from worker threads, never
/// concurrently.
using Progress = std::function<void(std::size_t, std::size_t)>;

/// Runs work(i) for every particle i with todo[i] (all if todo is empty) in parallel (TBB).
/// Stops at the first failure and rethrows it as InvalidInput "RECIPE: fraction 'NAME' particle
/// NNNNN: why" (fraction_of[i] names the fraction). progress(done, total) starts from `already`.
void for_each_particle(const ShapeRecipe& recipe, const std::vector<int>& fraction_of,
                       const std::vector<char>& todo, std::size_t already,
                       const std::function<void(std::size_t)>& work, const Progress& progress);

/// Fraction index of every particle of the recipe, in id order.
std::vector<int> particle_fractions(const ShapeRecipe& recipe);

/// Format version of every manifest.json / library.json (one schema: tool, format_version,
/// version, command, recipe_path, recipe (its text), seed, then the command's own fields).
inline constexpr int kManifestFormat = 1;

/// The manifest fields every output shares: tool, format_version, version, command, recipe_path,
/// recipe (the text), seed.
nlohmann::ordered_json manifest_head(const std::string& command, const std::string& recipe_path,
                                     const std::string& recipe_text, std::uint64_t seed);

/// The manifest fields every output of a shape recipe shares: tool, format_version, version,
/// command, recipe path and text, seed, particle count.
nlohmann::ordered_json manifest_head(const std::string& command, const ShapeRecipe& recipe);

/// Throws InvalidInput unless `dir` may be replaced by an output: it does not exist, is empty
/// or holds a manifest.json (a previous clumpkit output). Long jobs call it before they start.
void check_output_directory(const std::string& dir);

/// Replaces `dir` by `staging` (see run_shape_batch for the safety rule).
void publish_directory(const std::string& staging, const std::string& dir);

}  // namespace clumpkit
