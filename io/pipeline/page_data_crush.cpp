// A crushing run's page data: its results table, each particle's force against travel, its
// cells before and after (cells/NNNNN.js), its plots.
#include "geom/errors.h"
#include "io/base/json_file.h"
#include "io/pipeline/page_data.h"

#include <algorithm>

namespace clumpkit::page_data {

std::size_t crush_data(const Folder& f, const fs::path& out, ordered_json& data,
                       std::vector<PageScript>& scripts) {
  const fs::path results = f.dir / "results.csv";
  const CsvTable t = read_table(results);
  const int id = t.column("id");
  if (id < 0) throw InvalidInput(results.string() + ": column id is required");
  ordered_json curves = ordered_json::object(), with_cells = ordered_json::array();
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const std::string name = id_stem(t.rows[k][static_cast<std::size_t>(id)], results);
    const fs::path p = f.dir / "particles" / (name + ".csv");
    if (!fs::exists(p)) continue;
    const CsvTable c = read_table(p);
    // A curve of at most about 400 points: the plot is small and there is one per particle.
    ordered_json s = series(c, name, "travel", 1e3, "force", 1);
    const std::size_t n = s["x"].size(), stride = std::max<std::size_t>(1, n / 400);
    ordered_json x = ordered_json::array(), y = ordered_json::array();
    for (std::size_t i = 0; i < n; i += stride) x.push_back(s["x"][i]), y.push_back(s["y"][i]);
    curves[std::to_string(static_cast<long long>(t.number(k, id)))] = {{"x", x}, {"y", y}};
    // The cells before and after (crushing runs write them beside the curve); the page loads
    // them when the row is clicked (clumpkit_cells, assets/page/crush.js).
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

}  // namespace clumpkit::page_data
