// An element test's or CPT's page data, one folder or several of one kind: their curves
// overlaid on the kind's plots (io/pipeline/test_kinds.h), their curve pictures.
#include "io/pipeline/page_data.h"
#include "io/pipeline/test_kinds.h"

#include <algorithm>

namespace clumpkit::page_data {

namespace {

// The plots of a test folder: its kind's, then breakage's (a crushable specimen's curve.csv has
// hardin_br).
std::vector<PagePlot> test_plots(const std::string& test, bool breakage) {
  std::vector<PagePlot> p;
  for (const TestKind& k : test_kinds())
    if (test == k.name) p = k.page_plots;
  if (breakage) {
    p.push_back({"breakage against stress", "axial stress (MPa)", "Hardin's Br", "axial_stress",
                 "hardin_br", 1e-6, 1});
    p.push_back({"breakage against work", "input work (kJ/m3)", "Hardin's Br", "work", "hardin_br",
                 1e-3, 1});
  }
  return p;
}

// Each curve named by its folder; folders of one name by their parent and name.
std::vector<std::string> curve_labels(const std::vector<Folder>& folders) {
  std::vector<std::string> labels;
  for (const Folder& f : folders) labels.push_back(display_name(f.dir));
  for (std::size_t k = 0; k < folders.size(); ++k)
    if (std::count(labels.begin(), labels.end(), display_name(folders[k].dir)) > 1)
      labels[k] = display_name(fs::absolute(folders[k].dir).lexically_normal().parent_path()) +
                  "/" + labels[k];
  return labels;
}

}  // namespace

std::size_t test_data(const std::vector<Folder>& folders, const fs::path& out, ordered_json& data,
                      std::vector<PageScript>& scripts) {
  std::vector<CsvTable> tables;
  for (const Folder& f : folders) tables.push_back(read_table(f.dir / "curve.csv"));
  const bool breakage = tables.front().column("hardin_br") >= 0;
  ordered_json plots = ordered_json::array();
  Images images{out, &scripts};
  std::size_t rows = 0;
  const std::vector<std::string> labels = curve_labels(folders);
  for (const PagePlot& p : test_plots(folders.front().test, breakage)) {
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

}  // namespace clumpkit::page_data
