// A specimen recipe turned into the build spec of dem/specimen: gradation with the fines moved,
// contact law, densities, container.
#pragma once

#include "dem/specimen/compression.h"
#include "dem/specimen/specimen.h"
#include "io/recipes/specimen_recipe.h"

#include <vector>

namespace clumpkit {

/// The build spec of a recipe: gradation classes with the fines (classes finer than fines_below)
/// moved, by mass, into the class [fines_min, fines_max] (Jin et al. 2017 §4.1); classes at or
/// above the soil/rock threshold are rock. Contact damping as in deposition_contact().
dem::SpecimenSpec specimen_spec(const SpecimenRecipe& recipe,
                                std::vector<dem::RockTemplate> templates);

/// The spec of a recipe with preparation.method = "compression" (gravity-free cuboid or
/// cylinder at a target porosity), classes as specimen_spec makes them.
dem::CompressionSpec compression_spec(const SpecimenRecipe& recipe,
                                      std::vector<dem::RockTemplate> templates);

}  // namespace clumpkit
