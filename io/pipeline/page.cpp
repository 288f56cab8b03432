#include "io/pipeline/page.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/mesh_index.h"
#include "geom/mesh/ray_inside.h"
#include "io/base/json_file.h"
#include "io/base/text.h"
#include "io/formats/clump_io.h"
#include "io/formats/mesh_io.h"
#include "io/formats/specimen_csv.h"
#include "io/reports/page_files.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace clumpkit {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

// Six significant digits: a view needs no more, and the page's data shrink threefold.
double sig(double x) {
  return round_significant(x, 6);
}

// A CSV file of an output folder: its header and its rows, numbers where a cell parses whole.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<ordered_json>> rows;
  int column(const std::string& name) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
  }
  double number(std::size_t row, int col) const {
    const ordered_json& v = rows[row][static_cast<std::size_t>(col)];
    return v.is_number() ? v.get<double>() : NAN;
  }
};

CsvTable read_table(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError(path.string() + ": cannot open (the folder's manifest lists it)");
  CsvTable t;
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = split_csv(line);
    if (t.columns.empty()) {
      t.columns = std::move(cells);
      continue;
    }
    if (cells.size() != t.columns.size())
      throw InvalidInput(path.string() + ":" + std::to_string(line_no) + ": " +
                         std::to_string(cells.size()) + " fields, the header has " +
                         std::to_string(t.columns.size()));
    std::vector<ordered_json> row;
    for (const std::string& c : cells) {
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      if (!c.empty() && end == c.c_str() + c.size() && std::isfinite(v))
        row.emplace_back(sig(v));
      else
        row.emplace_back(c);
    }
    t.rows.push_back(std::move(row));
  }
  if (t.columns.empty()) throw InvalidInput(path.string() + ": empty table");
  return t;
}

// The report's numbers and words as one flat table (nested keys joined by dots; short arrays of
// numbers written out, long ones counted).
void flatten(const nlohmann::json& j, const std::string& prefix, ordered_json& out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    const nlohmann::json& v = it.value();
    if (v.is_object()) {
      flatten(v, key, out);
    } else if (v.is_number()) {
      out[key] = sig(v.get<double>());
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
    } else if (v.is_array()) {
      out[key] = std::to_string(v.size()) + " entries";
    }
  }
}

// One output folder as its manifest says.
struct Folder {
  fs::path dir;
  std::string command;  ///< the manifest's command
  std::string test;     ///< the kind of test (command test)
  nlohmann::json manifest, report;
};

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
  return f;
}

std::string display_name(const fs::path& dir) {
  const fs::path p = dir.has_filename() ? dir : dir.parent_path();
  return fs::absolute(p).lexically_normal().filename().string();
}

ordered_json folder_entry(const Folder& f) {
  ordered_json report = ordered_json::object();
  if (f.report.is_object()) flatten(f.report, "", report);
  if (f.command == "library" || f.command == "shapes") {  // no report.json: the manifest's numbers
    nlohmann::json m = f.manifest;
    m.erase("recipe");
    flatten(m, "", report);
  }
  return {{"name", display_name(f.dir)}, {"report", report}};
}

// An image of the folder if it exists, with a path from the page's folder; one outside that
// folder (a page made elsewhere with --out, a comparison) is copied under page/img/, so the page
// requests nothing outside its folder and survives being zipped and mailed.
struct Images {
  fs::path out;
  std::vector<PageScript>* copies;
  ordered_json list = ordered_json::array();
  void add(const fs::path& file, const std::string& caption) {
    if (!fs::exists(file)) return;
    std::string src = fs::relative(file, out).generic_string();
    if (src.rfind("..", 0) == 0 || fs::path(src).is_absolute()) {
      std::ifstream in(file, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      const std::string name =
          "img/" + std::to_string(list.size()) + "-" + file.filename().string();
      copies->push_back({name, bytes});
      src = "page/" + name;
    }
    list.push_back({{"src", src}, {"caption", caption}});
  }
};

ordered_json table_json(const CsvTable& t, const std::vector<std::string>& keep) {
  std::vector<int> cols;
  ordered_json columns = ordered_json::array(), rows = ordered_json::array();
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (keep.empty() || std::find(keep.begin(), keep.end(), t.columns[c]) != keep.end()) {
      cols.push_back(static_cast<int>(c));
      columns.push_back(t.columns[c]);
    }
  for (const auto& r : t.rows) {
    ordered_json row = ordered_json::array();
    for (int c : cols) row.push_back(r[static_cast<std::size_t>(c)]);
    rows.push_back(std::move(row));
  }
  return {{"columns", columns}, {"rows", rows}};
}

// A sphere "reaches outside" its mesh when it pokes through the surface by more than this share
// of its radius: the fill's spheres touch the surface from inside up to the voxel size and the
// overshoot contract, which reach a few percent of a radius; a tenth is a sphere to look at.
constexpr double kOutside = 0.1;

// A particle for the 3-D view: its mesh, its spheres with whether each reaches outside the mesh
// (kOutside) and by how much (share of its radius), and its bounds. Returns the count of such
// spheres.
int particle_json(const fs::path& mesh_path, const fs::path& clump_path, ordered_json& part) {
  const Mesh mesh = read_mesh(mesh_path.string());
  ordered_json v = ordered_json::array(), f = ordered_json::array(), s = ordered_json::array();
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& x : mesh.vertices) {
    for (int k = 0; k < 3; ++k) v.push_back(sig(x[k]));
    lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  }
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) f.push_back(t[k]);
  int outside = 0;
  if (!clump_path.empty()) {
    const Clump clump = read_clump(clump_path.string());
    const MeshIndex index(mesh);
    const RayInside in(mesh);
    for (const Sphere& sp : clump.spheres) {
      const double d = index.distance(sp.center);
      const double reach = in.inside(sp.center) ? sp.radius - d : sp.radius + d;
      const bool out = reach > kOutside * sp.radius;
      outside += out ? 1 : 0;
      s.push_back({sig(sp.center.x()), sig(sp.center.y()), sig(sp.center.z()), sig(sp.radius),
                   out ? 1 : 0, sig(reach / sp.radius)});
      lo = lo.cwiseMin(sp.center - Vec3::Constant(sp.radius));
      hi = hi.cwiseMax(sp.center + Vec3::Constant(sp.radius));
    }
  }
  part = {{"v", v},
          {"f", f},
          {"s", s},
          {"lo", {lo.x(), lo.y(), lo.z()}},
          {"hi", {hi.x(), hi.y(), hi.z()}}};
  return outside;
}

std::string part_name(const ordered_json& id) {
  char name[32];
  std::snprintf(name, sizeof name, "%05lld", static_cast<long long>(id.get<double>()));
  return name;
}

// A library (or a shape set, without clumps): the descriptors and fidelity table, one script per
// particle for the 3-D view, the renders as thumbnails.
std::size_t library_data(const Folder& f, const fs::path& out, ordered_json& data,
                         std::vector<PageScript>& scripts) {
  const bool shapes = f.command == "shapes";
  CsvTable t = read_table(f.dir / (shapes ? "shapes.csv" : "library.csv"));
  const int id = t.column("id"), mesh = t.column("mesh"), clump = t.column("clump");
  if (id < 0 || mesh < 0)
    throw InvalidInput((f.dir / (shapes ? "shapes.csv" : "library.csv")).string() +
                       ": columns id and mesh are required");
  t.columns.push_back("outside");
  Images images{out, &scripts};
  images.add(f.dir / "contact_sheet.png", "contact sheet");
  for (auto& row : t.rows) {
    if (!row[static_cast<std::size_t>(id)].is_number())
      throw InvalidInput(f.dir.string() + ": a particle id is not a number");
    const fs::path m = f.dir / row[static_cast<std::size_t>(mesh)].get<std::string>();
    const fs::path c =
        clump >= 0 ? f.dir / row[static_cast<std::size_t>(clump)].get<std::string>() : fs::path();
    ordered_json part;
    row.emplace_back(particle_json(m, c, part));
    const std::string name = part_name(row[static_cast<std::size_t>(id)]);
    scripts.push_back({"parts/" + name + ".js", "clumpkit_part(" + part.dump() + ");\n"});
    images.add(fs::path(m).replace_extension(".png"), "particle " + name);
  }
  data["table"] =
      table_json(t, {"id", "fraction", "method", "L", "W", "H", "volume", "equivalent_diameter",
                     "sphericity", "E", "F", "AR", "convexity", "weighted_roundness", "spheres",
                     "covered_fraction", "overshoot_fraction", "surface_max_distance", "outside"});
  data["parts"] = "page/parts/";
  data["images"] = images.list;
  return t.rows.size();
}

// A specimen: every sphere (or every k-th beyond max_spheres) with its body, kind and zone.
std::size_t specimen_data(const Folder& f, const fs::path& out, std::size_t max_spheres,
                          ordered_json& data, std::vector<PageScript>& scripts) {
  const std::vector<SpecimenBody> bodies = read_specimen_csv((f.dir / "specimen.csv").string());
  std::size_t total = 0;
  for (const SpecimenBody& b : bodies) total += b.spheres.size();
  const std::size_t stride = std::max<std::size_t>(1, (total + max_spheres - 1) / max_spheres);
  ordered_json x = ordered_json::array(), y = x, z = x, r = x, body = x, kind = x, zone = x;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  std::size_t k = 0, shown = 0;
  for (const SpecimenBody& b : bodies)
    for (const Sphere& s : b.spheres) {
      lo = lo.cwiseMin(s.center - Vec3::Constant(s.radius));
      hi = hi.cwiseMax(s.center + Vec3::Constant(s.radius));
      if (k++ % stride) continue;
      x.push_back(sig(s.center.x())), y.push_back(sig(s.center.y())),
          z.push_back(sig(s.center.z()));
      r.push_back(sig(s.radius)), body.push_back(b.id), zone.push_back(b.zone);
      kind.push_back(b.kind == dem::BodyKind::rock ? 1 : 0);
      ++shown;
    }
  data["spheres"] = {{"total", total},
                     {"shown", shown},
                     {"stride", stride},
                     {"lo", {lo.x(), lo.y(), lo.z()}},
                     {"hi", {hi.x(), hi.y(), hi.z()}},
                     {"x", x},
                     {"y", y},
                     {"z", z},
                     {"r", r},
                     {"body", body},
                     {"kind", kind},
                     {"zone", zone}};
  // The porosity bands of the report (equal heights of the measurement region), for colouring.
  const nlohmann::json& rep = f.report;
  if (rep.is_object() && rep.contains("band_porosity") && rep["band_porosity"].is_array() &&
      !rep["band_porosity"].empty() && rep.contains("measurement_region"))
    data["spheres"]["bands"] = {{"z_lo", rep["measurement_region"].value("z_lo", 0.0)},
                                {"z_hi", rep["measurement_region"].value("z_hi", 0.0)},
                                {"porosity", rep["band_porosity"]}};
  Images images{out, &scripts};
  std::vector<fs::path> slices;
  if (fs::is_directory(f.dir / "slices"))
    for (const auto& e : fs::directory_iterator(f.dir / "slices"))
      if (e.path().extension() == ".png") slices.push_back(e.path());
  std::sort(slices.begin(), slices.end());
  for (const fs::path& p : slices) images.add(p, "slice " + p.stem().string());
  images.add(f.dir / "calibration.png", "calibration");
  data["images"] = images.list;
  return total;
}

// A curve of one table: x and y columns, each times a factor, at most `points` rows.
ordered_json series(const CsvTable& t, const std::string& label, const std::string& x, double fx,
                    const std::string& y, double fy, bool log_x = false) {
  const int cx = t.column(x), cy = t.column(y);
  ordered_json xs = ordered_json::array(), ys = ordered_json::array();
  if (cx < 0 || cy < 0) return {{"label", label}, {"x", xs}, {"y", ys}};
  const std::size_t stride = std::max<std::size_t>(1, t.rows.size() / 2000);
  for (std::size_t k = 0; k < t.rows.size(); k += stride) {
    double a = t.number(k, cx) * fx;
    const double b = t.number(k, cy) * fy;
    if (log_x) a = a > 0 ? std::log10(a) : NAN;
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    xs.push_back(sig(a)), ys.push_back(sig(b));
  }
  return {{"label", label}, {"x", xs}, {"y", ys}};
}

struct PlotSpec {
  std::string title, x_label, y_label, x, y;
  double fx = 1, fy = 1;
  bool log_x = false;
};

std::vector<PlotSpec> test_plots(const std::string& test, bool breakage) {
  std::vector<PlotSpec> p;
  if (test == "triaxial") {
    p.push_back({"deviator stress", "axial strain", "q (kPa)", "axial_strain", "q_pa", 1, 1e-3});
    p.push_back({"volumetric strain", "axial strain", "volumetric strain", "axial_strain",
                 "volumetric_strain"});
  } else if (test == "oedometer") {
    p.push_back({"vertical stress", "axial strain", "axial stress (MPa)", "axial_strain",
                 "axial_stress_pa", 1, 1e-6});
    p.push_back({"compression", "log10 axial stress (MPa)", "porosity", "axial_stress_pa",
                 "porosity", 1e-6, 1, true});
  } else if (test == "isotropic") {
    p.push_back({"isotropic compression", "volumetric strain", "p (kPa)", "volumetric_strain",
                 "p_pa", 1, 1e-3});
  } else if (test == "cpt") {
    p.push_back({"cone resistance", "depth (m)", "qc (MPa)", "depth_m", "qc_pa", 1, 1e-6});
    p.push_back({"sleeve friction", "depth (m)", "fs (kPa)", "depth_m", "fs_pa", 1, 1e-3});
  }
  if (breakage) {
    p.push_back({"breakage against stress", "axial stress (MPa)", "Hardin's Br", "axial_stress_pa",
                 "hardin_br", 1e-6, 1});
    p.push_back({"breakage against work", "input work (kJ/m3)", "Hardin's Br", "work_pa",
                 "hardin_br", 1e-3, 1});
  }
  return p;
}

// Element tests or CPTs of one kind: their curves overlaid, one series per folder.
std::size_t test_data(const std::vector<Folder>& folders, const fs::path& out, ordered_json& data,
                      std::vector<PageScript>& scripts) {
  std::vector<CsvTable> tables;
  for (const Folder& f : folders) tables.push_back(read_table(f.dir / "curve.csv"));
  const bool breakage = tables.front().column("hardin_br") >= 0;
  ordered_json plots = ordered_json::array();
  Images images{out, &scripts};
  std::size_t rows = 0;
  // Each curve named by its folder; folders of one name by their parent and name.
  std::vector<std::string> labels;
  for (const Folder& f : folders) labels.push_back(display_name(f.dir));
  for (std::size_t k = 0; k < folders.size(); ++k)
    if (std::count(labels.begin(), labels.end(), display_name(folders[k].dir)) > 1)
      labels[k] = display_name(fs::absolute(folders[k].dir).lexically_normal().parent_path()) +
                  "/" + labels[k];
  for (const PlotSpec& p : test_plots(folders.front().test, breakage)) {
    ordered_json all = ordered_json::array();
    for (std::size_t k = 0; k < folders.size(); ++k)
      all.push_back(series(tables[k], labels[k], p.x, p.fx, p.y, p.fy, p.log_x));
    plots.push_back({{"title", p.title}, {"x", p.x_label}, {"y", p.y_label}, {"series", all}});
  }
  for (std::size_t k = 0; k < folders.size(); ++k) {
    rows += tables[k].rows.size();
    const std::string& name = labels[k];
    for (const char* png : {"curve.png", "grading.png", "breakage.png", "breakage_work.png"})
      images.add(folders[k].dir / png, name + ": " + png);
  }
  data["plots"] = plots;
  data["images"] = images.list;
  return rows;
}

// A crushing run: the results table, each particle's force against travel, the plots.
std::size_t crush_data(const Folder& f, const fs::path& out, ordered_json& data,
                       std::vector<PageScript>& scripts) {
  const CsvTable t = read_table(f.dir / "results.csv");
  const int id = t.column("id");
  if (id < 0) throw InvalidInput((f.dir / "results.csv").string() + ": column id is required");
  ordered_json curves = ordered_json::object(), with_cells = ordered_json::array();
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const std::string name = part_name(t.rows[k][static_cast<std::size_t>(id)]);
    const fs::path p = f.dir / "particles" / (name + ".csv");
    if (!fs::exists(p)) continue;
    const CsvTable c = read_table(p);
    ordered_json s = series(c, name, "travel_m", 1e3, "force_n", 1);
    const std::size_t n = s["x"].size(), stride = std::max<std::size_t>(1, n / 400);
    ordered_json x = ordered_json::array(), y = ordered_json::array();
    for (std::size_t i = 0; i < n; i += stride) x.push_back(s["x"][i]), y.push_back(s["y"][i]);
    curves[std::to_string(static_cast<long long>(t.number(k, id)))] = {{"x", x}, {"y", y}};
    // The cells before and after (crushing runs write them beside the curve).
    const fs::path cells = f.dir / "particles" / (name + ".cells.json");
    if (fs::exists(cells)) {
      scripts.push_back({"cells/" + name + ".js",
                         "clumpkit_cells(" + read_json_file(cells.string()).dump() + ");\n"});
      with_cells.push_back(static_cast<long long>(t.number(k, id)));
    }
  }
  data["table"] = table_json(t, {});
  data["curves"] = curves;
  data["cells"] = "page/cells/";
  data["cells_ids"] = with_cells;
  Images images{out, &scripts};
  images.add(f.dir / "weibull.png", "Weibull plot");
  images.add(f.dir / "size.png", "size effect");
  std::vector<fs::path> sets;
  for (const auto& e : fs::directory_iterator(f.dir))
    if (e.path().filename().string().rfind("curves_", 0) == 0 && e.path().extension() == ".png")
      sets.push_back(e.path());
  std::sort(sets.begin(), sets.end());
  for (const fs::path& p : sets) images.add(p, p.stem().string());
  data["images"] = images.list;
  return t.rows.size();
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

PageResult write_page(const PageOptions& o) {
  if (o.dirs.empty()) throw InvalidInput("page: no folder given");
  if (o.dirs.size() > 1 && o.out.empty())
    throw InvalidInput("page: several folders need --out for the comparison page");
  std::vector<Folder> folders;
  for (const fs::path& d : o.dirs) folders.push_back(read_folder(d));
  const std::string kind = kind_of(folders.front());
  for (const Folder& f : folders)
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
  const Folder& first = folders.front();
  if (kind == "library")
    result.items = library_data(first, out, data, scripts);
  else if (kind == "specimen")
    result.items = specimen_data(first, out, o.max_spheres, data, scripts);
  else if (kind == "crush")
    result.items = crush_data(first, out, data, scripts);
  else
    result.items = test_data(folders, out, data, scripts);
  ordered_json entries = ordered_json::array();
  for (const Folder& f : folders) entries.push_back(folder_entry(f));
  data["folders"] = entries;
  std::string title = first.command + (first.test.empty() ? "" : " " + first.test);
  if (folders.size() > 1) title = std::to_string(folders.size()) + " " + first.test + " tests";
  data["title"] = "clumpkit " + title + ": " + display_name(folders.size() > 1 ? out : first.dir);
  std::string sources;
  for (const Folder& f : folders)
    sources += (sources.empty() ? "" : ", ") + fs::absolute(f.dir).lexically_normal().string();
  data["subtitle"] = "from " + sources;
  scripts.push_back({"data.js", page_script("CLUMPKIT_PAGE", data.dump())});
  write_page_files(out, scripts);
  result.index = out / "index.html";
  return result;
}

}  // namespace clumpkit
