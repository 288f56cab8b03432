// The head every manifest.json shares (tool, format version, version, command, recipe, seed).
#pragma once

#include "io/recipes/recipe.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace clumpkit {

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

}  // namespace clumpkit
