// Fuzzes the shape/library recipe reader (TOML, every method's fields).
#include "fuzz_input.h"
#include "io/recipes/recipe.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::refuse_only_cleanly([&] { clumpkit::parse_shape_recipe(text, "recipe.toml"); });
  return 0;
}
