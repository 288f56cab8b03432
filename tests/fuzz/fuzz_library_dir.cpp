// Fuzzes what a library directory is read from: library.csv, then the template CSV of each row
// (the input is split at the first line "====": library.csv before, particles/00000.template.csv
// after; other ids have no file).
#include "fuzz_input.h"
#include "io/formats/library_table.h"

#include <filesystem>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t cut = text.find("\n====\n");
  const std::string dir = (fuzz::scratch() / "library").string();
  std::filesystem::remove_all(dir);
  fuzz::as_file(text.substr(0, cut), "library/library.csv");
  if (cut != std::string::npos)
    fuzz::as_file(text.substr(cut + 6), "library/particles/00000.template.csv");
  fuzz::refuse_only_cleanly([&] {
    clumpkit::read_rock_templates(dir);
    clumpkit::read_library_column(dir, "density_factor");
  });
  return 0;
}
