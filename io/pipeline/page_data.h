// Private to `clumpkit page` (io/pipeline/page*.cpp): an output folder as read, and the data of
// each kind of page as JSON for page/data.js (the contract with assets/page: docs/pages.md).
#pragma once

#include "geom/format.h"
#include "io/reports/page_files.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

// A named namespace, not an anonymous one: io builds as unity units, where every file's anonymous
// helpers share one translation unit with seven other files.
namespace clumpkit::page_data {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

/// Six significant digits: a view needs no more, and the page's data shrink threefold.
inline double sig(double x) {
  return round_significant(x, 6);
}

/// A CSV file of an output folder: its header and its rows, a cell a number (six digits) where
/// all of it is a finite number, else its text.
struct CsvTable {
  /// Each column's name without its unit (io/base/units.h's column_name: "volume", also for a
  /// folder written before units, "strength_pa" read as "strength").
  std::vector<std::string> columns;
  /// Each column's unit from its header cell ("m3", "1"); "" for a text column, or any column of
  /// a folder written before units.
  std::vector<std::string> units;
  std::vector<std::vector<ordered_json>> rows;
  /// The column's index, −1 when the header lacks it; `name` is read as column_name reads it
  /// (a unit or an old name, "q_pa", finds "q").
  int column(const std::string& name) const;
  /// The cell as a number, NaN when it holds text.
  double number(std::size_t row, int col) const;
};

/// Throws IoError when the file cannot be opened (the folder's manifest lists it), InvalidInput
/// "PATH:LINE: ..." for a row of another width than the header, "PATH: empty table" for none.
CsvTable read_table(const fs::path& path);

/// {"columns": [...], "units": [...], "rows": [[...], ...]} of the columns named in `keep` (bare
/// names) that the table has, in the table's order; every column when `keep` is empty.
ordered_json table_json(const CsvTable& t, const std::vector<std::string>& keep);

/// {"label", "x", "y"}: columns x and y times fx and fy (x as log10 when log_x), rows with a
/// non-finite value left out, at most about 2000 points (every k-th row). Empty arrays when the
/// table lacks either column.
ordered_json series(const CsvTable& t, const std::string& label, const std::string& x, double fx,
                    const std::string& y, double fy, bool log_x = false);

/// The folder's own name, also for "dir/" and "." (what a page calls it).
std::string display_name(const fs::path& dir);

/// The five-digit stem of a particle's files ("00042", io/base/text.h's id_name) from its id
/// cell; throws InvalidInput naming `table` when the cell is not a whole number ≥ 0.
std::string id_stem(const ordered_json& id, const fs::path& table);

/// The images of a page, [{"src", "caption"}]: `src` relative to the page's folder `out`; one
/// outside that folder (a page made elsewhere with --out, a comparison) is copied under page/img/
/// through `copies`, so the page requests nothing outside its folder and survives being zipped.
struct Images {
  fs::path out;
  std::vector<PageScript>* copies;
  ordered_json list = ordered_json::array();
  /// Adds `file` when it exists; nothing otherwise.
  void add(const fs::path& file, const std::string& caption);
};

/// One output folder as its manifest says.
struct Folder {
  fs::path dir;
  std::string command;  ///< the manifest's command
  std::string test;     ///< the kind of test (command test)
  nlohmann::json manifest, report;
  /// Its manifest.json or report.json has a "units" map: false for a folder written before
  /// clumpkit recorded units (docs/units.md).
  bool units_recorded = false;
};

// The data of each kind of page: each adds its keys to `data` (page/data.js) and its per-item
// scripts and copied images to `scripts`, and returns the count of items shown (PageResult).

/// library or shapes: table, parts (scripts parts/NNNNN.js), images.
std::size_t library_data(const Folder& f, const fs::path& out, ordered_json& data,
                         std::vector<PageScript>& scripts);
/// specimen or specimen-scale: spheres (every k-th beyond max_spheres), images.
std::size_t specimen_data(const Folder& f, const fs::path& out, std::size_t max_spheres,
                          ordered_json& data, std::vector<PageScript>& scripts);
/// test (element tests, CPT), one or several folders of one kind: plots, images.
std::size_t test_data(const std::vector<Folder>& folders, const fs::path& out, ordered_json& data,
                      std::vector<PageScript>& scripts);
/// crush: table, curves, cells (scripts cells/NNNNN.js), cells_ids, images.
std::size_t crush_data(const Folder& f, const fs::path& out, ordered_json& data,
                       std::vector<PageScript>& scripts);

}  // namespace clumpkit::page_data
