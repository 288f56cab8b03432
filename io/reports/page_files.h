// The files of a static page beside an output folder: index.html, its script, style and three.js,
// its data as scripts (browsers refuse to fetch() files from file://), written all or nothing.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace clumpkit {

/// One of the page's own files (assets/page, compiled in): its name and text.
struct PageAsset {
  const char* name;
  std::string_view text;
};
const std::vector<PageAsset>& page_assets();

/// Where three.js is read from: Debian's libjs-three (the path found when clumpkit was built).
std::filesystem::path three_js_path();

/// A data script of the page: its path under DIR/page/ and its text.
struct PageScript {
  std::string name;
  std::string text;
};

/// Writes DIR/index.html and DIR/page/ (page.js, page.css, three.min.js with its licence, and
/// `scripts`), replacing an earlier page. The folder is built as DIR/page.partial and renamed
/// into place, so a failure leaves the earlier page (or none), never half of one. Throws IoError
/// naming three.js's path when libjs-three is not installed (before anything is written).
void write_page_files(const std::filesystem::path& dir, const std::vector<PageScript>& scripts);

/// `window.NAME = JSON;` with the JSON text of a data file.
std::string page_script(const std::string& name, const std::string& json);

}  // namespace clumpkit
