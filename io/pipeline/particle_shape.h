// The mesh of one particle of a shape recipe: drawn by its fraction's method, or read from the
// fraction's mesh files (repaired in memory when asked).
#pragma once

#include "geom/mesh/repair.h"
#include "io/recipes/recipe.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace clumpkit {

/// A particle's shape, and where a read one came from.
struct ParticleShape {
  GeneratedShape shape;
  std::string source;             ///< the mesh file of a mesh fraction ("" when drawn)
  nlohmann::ordered_json repair;  ///< what the repair did (repair_json), when one ran
};

/// Particle `i` of `recipe` (its fraction `fraction`): drawn with the random stream (seed, i)
/// by generate_shape, or for a fraction of method mesh read from its file (the particle's place
/// within the fraction picks the file) and scaled by the fraction's scale. A read mesh must be
/// a solid (read_mesh's checks) unless `repair` is given: then it is repaired in memory first
/// (read_repaired_mesh) and must be a solid after. Either way the mesh is refined to
/// recipe.refine_triangles. Throws InvalidInput naming the file for what cannot be read.
ParticleShape particle_shape(const ShapeRecipe& recipe, std::size_t i, int fraction,
                             const RepairOptions* repair = nullptr);

}  // namespace clumpkit
