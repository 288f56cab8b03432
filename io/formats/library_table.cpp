#include "io/formats/library_table.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/clump_io.h"
#include "io/formats/descriptor_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace clumpkit {

namespace fs = std::filesystem;

namespace {

// Opens a library.csv and returns its column names (column_name: without units, so a table
// written before units were reads the same); `in` is left at the first row.
std::vector<std::string> open_library_csv(const fs::path& csv, std::ifstream& in) {
  in.open(csv);
  if (!in) throw IoError(csv.string() + ": cannot open clump library table");
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return column_names(split_csv(line));
}

}  // namespace

const std::vector<std::string>& library_fidelity_columns() {
  static const std::vector<std::string> c = {"spheres",
                                             "clump_volume",
                                             "covered_fraction",
                                             "overshoot_fraction",
                                             "surface_mean_distance",
                                             "surface_max_distance",
                                             "centroid_offset",
                                             "inertia_error",
                                             "overshoot_depth_max"};
  return c;
}

void write_library_table(const std::string& path,
                         const std::vector<nlohmann::ordered_json>& records) {
  // Parameter columns: union over particles, first-appearance order.
  std::vector<std::string> params;
  for (const auto& rec : records)
    for (const auto& [k, v] : rec["parameters"].items())
      if (std::find(params.begin(), params.end(), k) == params.end()) params.push_back(k);
  std::string names = "id,fraction,method,mesh,clump,attempts";
  for (const auto& p : params) names += ",p_" + p;
  for (const auto& c : descriptor_csv_columns()) names += "," + c;
  for (const auto& c : library_fidelity_columns()) names += "," + c;
  names += ",density_factor,I1,I2,I3,qw,qx,qy,qz,cx,cy,cz";
  write_file_atomically(path, [&](std::ostream& o) {
    o << csv_header("library", names, si_length()) << "\n";
    for (std::size_t i = 0; i < records.size(); ++i) {
      const auto& rec = records[i];
      o << i << "," << csv_escape(rec["fraction"].get<std::string>()) << ","
        << rec["method"].get<std::string>() << ",particles/" << id_name(i) << ".stl,particles/"
        << id_name(i) << ".csv," << rec["attempts"].get<int>();
      for (const auto& p : params) {
        o << ",";
        if (rec["parameters"].contains(p)) o << format_number(rec["parameters"][p].get<double>());
      }
      for (const auto& c : descriptor_csv_columns())
        o << "," << format_number(rec["descriptors"][c].get<double>());
      for (const auto& c : library_fidelity_columns())
        o << "," << format_number(rec["fidelity"][c].get<double>());
      const auto& t = rec["template"];
      o << "," << format_number(t["density_factor"].get<double>());
      for (const char* k : {"principal_moments", "orientation_wxyz", "centroid"})
        for (const auto& v : t[k]) o << "," << format_number(v.get<double>());
      o << "\n";
    }
  });
}

std::vector<dem::RockTemplate> read_rock_templates(const std::string& library_dir) {
  const fs::path csv = fs::path(library_dir) / "library.csv";
  std::ifstream in;
  const std::vector<std::string> head = open_library_csv(csv, in);
  std::string line;
  auto column = [&](const std::string& name) {
    const auto it = std::find(head.begin(), head.end(), name);
    if (it == head.end())
      throw InvalidInput(csv.string() + ": column " + name + " missing (not a clump library?)");
    return static_cast<std::size_t>(it - head.begin());
  };
  const std::size_t c_id = column("id"), c_w = column("W"), c_v = column("clump_volume");
  const std::size_t c_i[3] = {column("I1"), column("I2"), column("I3")};
  std::vector<dem::RockTemplate> out;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != head.size())
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) + " has " +
                         std::to_string(cells.size()) + " fields, header " +
                         std::to_string(head.size()));
    dem::RockTemplate t;
    t.sieve_size = to_number(cells[c_w]).value_or(NAN);
    ClumpTemplate& clump = t.clump;
    clump.mass.volume = to_number(cells[c_v]).value_or(NAN);
    if (!(t.sieve_size > 0) || !(clump.mass.volume > 0) || !std::isfinite(t.sieve_size) ||
        !std::isfinite(clump.mass.volume))
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) +
                         ": W and clump_volume must be positive, got " + cells[c_w] + " and " +
                         cells[c_v]);
    for (int a = 0; a < 3; ++a) {
      clump.principal_moments[a] = to_number(cells[c_i[a]]).value_or(NAN);
      if (!(clump.principal_moments[a] > 0) || !std::isfinite(clump.principal_moments[a]))
        throw InvalidInput(csv.string() + ": line " + std::to_string(row) + ": I" +
                           std::to_string(a + 1) + " must be positive, got " + cells[c_i[a]]);
    }
    clump.mass.inertia = clump.principal_moments.asDiagonal();
    const std::optional<long long> id = to_integer(cells[c_id]);
    if (!id || *id < 0)
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) +
                         ": id must be a non-negative integer, got " + cells[c_id]);
    clump.spheres = read_clump((fs::path(library_dir) / "particles" /
                                (id_name(static_cast<std::size_t>(*id)) + ".template.csv"))
                                   .string())
                        .spheres;
    out.push_back(std::move(t));
  }
  if (out.empty()) throw InvalidInput(csv.string() + ": the clump library holds no particles");
  return out;
}

std::vector<double> read_library_column(const std::string& library_dir, const std::string& name) {
  const fs::path csv = fs::path(library_dir) / "library.csv";
  std::ifstream in;
  const std::vector<std::string> head = open_library_csv(csv, in);
  std::string line;
  const auto it = std::find(head.begin(), head.end(), name);
  if (it == head.end())
    throw InvalidInput(csv.string() + ": column " + name +
                       " missing (a library of an older clumpkit; build it again)");
  const std::size_t c = static_cast<std::size_t>(it - head.begin());
  std::vector<double> out;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    const double v = c < cells.size() ? to_number(cells[c]).value_or(NAN) : NAN;
    if (!(v > 0) || !std::isfinite(v))
      throw InvalidInput(csv.string() + ": line " + std::to_string(row) + ": " + name +
                         " must be positive, got '" + (c < cells.size() ? cells[c] : "") + "'");
    out.push_back(v);
  }
  return out;
}

}  // namespace clumpkit
