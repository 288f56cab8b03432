// Batch generation of a shape library from a recipe: meshes, descriptor table and manifest.
#pragma once

#include "io/recipe.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace clumpkit {

/// Progress callback: (items done, items total). May be called from worker threads, never
/// concurrently.
using Progress = std::function<void(std::size_t, std::size_t)>;

struct ShapeBatchResult {
  std::size_t particles = 0;
  std::string out_dir;
};

/// Generates every particle of the recipe in parallel (TBB) and writes
///   DIR/meshes/NNNNN.stl, DIR/shapes.csv, DIR/manifest.json.
/// Particle i uses the random stream (recipe.seed, i), so outputs are byte-identical for any
/// thread count. Everything is written into DIR.partial first and renamed at the end, so a failed
/// run leaves no partial DIR. An existing DIR is replaced only if it is empty or holds a
/// manifest.json (a previous clumpkit output); otherwise InvalidInput.
ShapeBatchResult run_shape_batch(const ShapeRecipe& recipe, const std::string& out_dir,
                                 const Progress& progress = {});

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

/// The manifest fields every output shares: tool, format_version, version, command, recipe path
/// and text, seed, particle count.
nlohmann::ordered_json manifest_head(const std::string& command, const ShapeRecipe& recipe);

/// Throws InvalidInput unless `dir` may be replaced by an output: it does not exist, is empty
/// or holds a manifest.json (a previous clumpkit output). Long jobs call it before they start.
void check_output_directory(const std::string& dir);

/// Replaces `dir` by `staging` (see run_shape_batch for the safety rule).
void publish_directory(const std::string& staging, const std::string& dir);

}  // namespace clumpkit
