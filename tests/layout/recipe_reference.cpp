// Prints the recipe reference generated from the section tables (io/recipes/section_table.h), the
// part of docs/recipes.md between its "generated" markers (tests/layout/docs_check.py).
#include "io/recipes/crush_recipe.h"
#include "io/recipes/lab_recipe.h"
#include "io/recipes/specimen_recipe.h"

#include <iostream>

int main() {
  using namespace clumpkit;
  const SpecimenRecipe specimen;
  const CrushRecipe crush;
  std::cout << section_reference(density_section(), specimen) << "\n"
            << section_reference(contact_section(), specimen) << "\n"
            << section_reference(test_section(), TestRecipe{}) << "\n"
            << section_reference(probe_section(), dem::ProbeSettings{}) << "\n"
            << section_reference(crush_section(), crush) << "\n"
            << section_reference(bond_section(), crush);
  return 0;
}
