#include "io/pipeline/manifest.h"

#include "geom/version.h"

namespace clumpkit {

nlohmann::ordered_json manifest_head(const std::string& command, const std::string& recipe_path,
                                     const std::string& recipe_text, std::uint64_t seed) {
  nlohmann::ordered_json m;
  m["tool"] = "clumpkit";
  m["format_version"] = kManifestFormat;
  m["version"] = version();
  m["commit"] = commit();
  m["command"] = command;
  m["recipe_path"] = recipe_path;
  m["recipe"] = recipe_text;
  m["seed"] = seed;
  return m;
}

nlohmann::ordered_json manifest_head(const std::string& command, const ShapeRecipe& recipe) {
  nlohmann::ordered_json m = manifest_head(command, recipe.path, recipe.text, recipe.seed);
  m["particles"] = particle_fractions(recipe).size();
  return m;
}

}  // namespace clumpkit
