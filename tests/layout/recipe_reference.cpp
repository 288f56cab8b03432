// Prints the recipe reference generated from the section tables (io/recipes/section_table.h), the
// part of docs/recipes.md between its "generated" markers (tests/layout/docs_check.py).
#include "io/recipes/crush_recipe.h"
#include "io/recipes/lab_recipe.h"

#include <iostream>

int main() {
  std::cout << clumpkit::test_recipe_reference() << "\n"
            << clumpkit::section_reference(clumpkit::bond_section(), clumpkit::CrushRecipe{});
  return 0;
}
