// Fuzzes the specimen recipe reader (TOML; its [rock] recipe path is read relative to it).
#include "fuzz_input.h"
#include "io/recipes/specimen_recipe.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::as_file(data, size, "specimen/recipe.toml");
  fuzz::refuse_only_cleanly([&] { clumpkit::read_specimen_recipe(path); });
  return 0;
}
