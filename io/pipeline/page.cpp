// The job of `clumpkit page`: output folders read, their kind of page chosen, the page written
// (each kind's data: io/pipeline/page_data_*.cpp; the contract with assets/page: docs/pages.md).
#include "io/pipeline/page.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/json_file.h"
#include "io/base/units.h"
#include "io/pipeline/page_data.h"
#include "io/reports/page_files.h"

#include <nlohmann/json.hpp>

#include <algorithm>

// The helpers in page_data too, not in clumpkit's anonymous namespace: io builds as unity units
// (page_data.h).
namespace clumpkit::page_data {

namespace {

// The report's numbers and words as one flat table (nested keys joined by dots; short arrays of
// numbers written out, long ones counted), and in `out_units` the unit of each row of numbers by
// the file's "units" map (docs/units.md); the map itself is no row.
void flatten(const nlohmann::json& j, std::vector<std::string>& path, const nlohmann::json& units,
             ordered_json& out, ordered_json& out_units) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (path.empty() && it.key() == "units" && it.value().is_object()) continue;
    path.push_back(it.key());
    std::string key;
    for (const std::string& p : path) key += (key.empty() ? "" : ".") + p;
    const nlohmann::json& v = it.value();
    bool numbers = false;
    if (v.is_object()) {
      flatten(v, path, units, out, out_units);
    } else if (v.is_number()) {
      out[key] = sig(v.get<double>());
      numbers = true;
    } else if (v.is_boolean()) {
      out[key] = v.get<bool>() ? "true" : "false";
    } else if (v.is_string()) {
      const std::string s = v.get<std::string>();
      if (s.size() <= 200 && s.find('\n') == std::string::npos) out[key] = s;
    } else if (v.is_array() && !v.empty() && v.size() <= 8 &&
               std::all_of(v.begin(), v.end(), [](const auto& x) { return x.is_number(); })) {
      std::string s;
      for (const auto& x : v) s += (s.empty() ? "" : ", ") + format_number(x.get<double>(), 6);
      out[key] = s;
      numbers = true;
    } else if (v.is_array()) {
      out[key] = std::to_string(v.size()) + " entries";
    }
    if (numbers) {
      const std::string u = json_unit(units, path);
      if (!u.empty()) out_units[key] = u;
    }
    path.pop_back();
  }
}

// The "units" map of a JSON file (null for a file written before units).
const nlohmann::json& units_of(const nlohmann::json& j) {
  static const nlohmann::json none;
  return j.is_object() && j.contains("units") && j["units"].is_object() ? j["units"] : none;
}

Folder read_folder(const fs::path& dir) {
  const fs::path manifest = dir / "manifest.json";
  if (!fs::is_directory(dir)) throw IoError(dir.string() + ": no such folder");
  if (!fs::exists(manifest))
    throw InvalidInput(manifest.string() +
                       ": not found; a page is made for a clumpkit output folder (library, "
                       "shapes, specimen, test, crush)");
  Folder f;
  f.dir = dir;
  f.manifest = read_json_file(manifest.string());
  if (!f.manifest.is_object() || !f.manifest.contains("command") ||
      !f.manifest["command"].is_string())
    throw InvalidInput(manifest.string() + ": field command: missing (not a clumpkit manifest)");
  f.command = f.manifest["command"].get<std::string>();
  if (f.command == "test") f.test = f.manifest.value("test", std::string());
  if (fs::exists(dir / "report.json")) f.report = read_json_file((dir / "report.json").string());
  f.units_recorded = !units_of(f.manifest).is_null() || !units_of(f.report).is_null();
  return f;
}

ordered_json folder_entry(const Folder& f) {
  ordered_json report = ordered_json::object(), units = ordered_json::object();
  std::vector<std::string> path;
  if (f.report.is_object()) flatten(f.report, path, units_of(f.report), report, units);
  if (f.command == "library" || f.command == "shapes") {  // no report.json: the manifest's numbers
    nlohmann::json m = f.manifest;
    m.erase("recipe");
    flatten(m, path, units_of(f.manifest), report, units);
  }
  return {{"name", display_name(f.dir)}, {"report", report}, {"units", units}};
}

std::string kind_of(const Folder& f) {
  if (f.command == "library" || f.command == "shapes") return "library";
  if (f.command == "specimen" || f.command == "specimen-scale") return "specimen";
  if (f.command == "test") return "test";
  if (f.command == "crush") return "crush";
  throw InvalidInput((f.dir / "manifest.json").string() + ": command '" + f.command +
                     "' has no page (library, shapes, specimen, test, crush)");
}

}  // namespace

}  // namespace clumpkit::page_data

namespace clumpkit {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

PageResult write_page(const PageOptions& o) {
  if (o.dirs.empty()) throw InvalidInput("page: no folder given");
  if (o.dirs.size() > 1 && o.out.empty())
    throw InvalidInput("page: several folders need --out for the comparison page");
  std::vector<page_data::Folder> folders;
  for (const fs::path& d : o.dirs) folders.push_back(page_data::read_folder(d));
  const std::string kind = page_data::kind_of(folders.front());
  for (const page_data::Folder& f : folders)
    if (folders.size() > 1 && (f.command != "test" || f.test != folders.front().test))
      throw InvalidInput((f.dir / "manifest.json").string() + ": command '" + f.command +
                         (f.test.empty() ? "" : " " + f.test) +
                         "': a page of several folders compares tests of one kind" +
                         (folders.front().test.empty() ? "" : " (" + folders.front().test + ")"));
  const fs::path out = o.out.empty() ? folders.front().dir : o.out;
  fs::create_directories(out);
  ordered_json data;
  data["kind"] = kind;
  std::vector<PageScript> scripts;
  PageResult result;
  result.kind = kind;
  const page_data::Folder& first = folders.front();
  if (kind == "library")
    result.items = page_data::library_data(first, out, data, scripts);
  else if (kind == "specimen")
    result.items = page_data::specimen_data(first, out, o.max_spheres, data, scripts);
  else if (kind == "crush")
    result.items = page_data::crush_data(first, out, data, scripts);
  else
    result.items = page_data::test_data(folders, out, data, scripts);
  ordered_json entries = ordered_json::array();
  for (const page_data::Folder& f : folders) entries.push_back(page_data::folder_entry(f));
  data["folders"] = entries;
  data["units_recorded"] = std::all_of(folders.begin(), folders.end(),
                                       [](const page_data::Folder& f) { return f.units_recorded; });
  std::string title = first.command + (first.test.empty() ? "" : " " + first.test);
  if (folders.size() > 1) title = std::to_string(folders.size()) + " " + first.test + " tests";
  data["title"] =
      "clumpkit " + title + ": " + page_data::display_name(folders.size() > 1 ? out : first.dir);
  std::string sources;
  for (const page_data::Folder& f : folders)
    sources += (sources.empty() ? "" : ", ") + fs::absolute(f.dir).lexically_normal().string();
  data["subtitle"] = "from " + sources;
  scripts.push_back({"data.js", page_script("CLUMPKIT_PAGE", data.dump())});
  write_page_files(out, scripts);
  result.index = out / "index.html";
  return result;
}

}  // namespace clumpkit
