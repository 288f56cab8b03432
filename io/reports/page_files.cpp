#include "io/reports/page_files.h"

#include "geom/errors.h"
#include "io/base/atomic_file.h"

#include <fstream>
#include <sstream>

namespace clumpkit {

namespace fs = std::filesystem;

fs::path three_js_path() {
  return fs::path(CLUMPKIT_THREE_JS);
}

std::string page_script(const std::string& name, const std::string& json) {
  return "window." + name + " = " + json + ";\n";
}

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot read");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const fs::path& path, std::string_view text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw IoError(path.string() + ": cannot write");
}

}  // namespace

void write_page_files(const fs::path& dir, const std::vector<PageScript>& scripts) {
  const fs::path three = three_js_path();
  if (!fs::exists(three))
    throw IoError(three.string() +
                  ": three.js not found; install Debian's libjs-three (scripts/deps does)");
  const std::string three_text = slurp(three);
  // The licence travels with the copy (Debian's copyright file of the package).
  const fs::path licence = "/usr/share/doc/libjs-three/copyright";
  const std::string licence_text = fs::exists(licence)
                                       ? slurp(licence)
                                       : std::string("three.js: MIT licence, see threejs.org\n");
  const fs::path staging = dir / "page.partial", final_dir = dir / "page";
  fs::remove_all(staging);
  std::string index;
  for (const PageAsset& a : page_assets()) {
    if (std::string_view(a.name) == "index.html")
      index = std::string(a.text);
    else
      put(staging / a.name, a.text);
  }
  put(staging / "three.min.js", three_text);
  put(staging / "three-LICENSE.txt", licence_text);
  for (const PageScript& s : scripts) put(staging / s.name, s.text);
  fs::remove_all(final_dir);
  fs::rename(staging, final_dir);
  write_file_atomically((dir / "index.html").string(), [&](std::ostream& o) { o << index; });
}

}  // namespace clumpkit
