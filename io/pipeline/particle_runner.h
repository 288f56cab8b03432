// The parallel per-particle runner of the library jobs (progress and interruption through
// geom/progress.h).
#pragma once

#include "geom/progress.h"
#include "io/recipes/recipe.h"

#include <cstddef>
#include <functional>
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

}  // namespace clumpkit
