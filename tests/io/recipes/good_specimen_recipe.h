// A valid deposited specimen recipe of library clumps, shared by the recipe tests (relative paths
// resolve in assets/recipes).
#pragma once

#include <string>

inline const std::string kGoodSpecimenRecipe = R"(
rock_mass_fraction = 0.4
soil_rock_threshold = 0.02
[container]
diameter = 0.3
height = 0.6
[gradation]
sieves = [0.06, 0.04, 0.02, 0.01, 0.005]
passing = [100, 80, 60, 40, 20]
[rock]
recipe = "srm-rock-blocks.toml"
)";
