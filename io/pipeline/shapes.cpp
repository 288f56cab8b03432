#include "io/pipeline/shapes.h"

#include "geom/descriptors/descriptors.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/descriptor_table.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"
#include "io/pipeline/particle_runner.h"
#include "io/pipeline/particle_shape.h"

#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <set>

namespace fs = std::filesystem;

namespace clumpkit {

namespace {
struct Item {
  int fraction = 0;
  GeneratedShape shape;
  Descriptors desc;
};

}  // namespace

ShapeBatchResult run_shape_batch(const ShapeRecipe& recipe, const std::string& out_dir,
                                 const Interrupter& interrupter) {
  check_output_directory(out_dir);
  std::vector<Item> items;
  for (std::size_t f = 0; f < recipe.fractions.size(); ++f)
    for (int k = 0; k < recipe.fractions[f].count; ++k)
      items.push_back(Item{static_cast<int>(f), {}, {}});

  const std::size_t total = items.size();
  // Generation and descriptors in parallel; each particle owns its random stream.
  for_each_particle(
      recipe, particle_fractions(recipe), {}, 0,
      [&](std::size_t i) {
        items[i].shape = particle_shape(recipe, i, items[i].fraction).shape;
        items[i].desc = describe(items[i].shape.mesh);
      },
      "shapes", interrupter);

  const std::string staging = out_dir + ".partial";
  std::error_code ec;
  fs::remove_all(staging, ec);
  fs::create_directories(fs::path(staging) / "meshes", ec);
  if (ec) throw IoError(staging + ": cannot create directory: " + ec.message());
  try {
    for (std::size_t i = 0; i < total; ++i) {
      write_mesh((fs::path(staging) / "meshes" / (id_name(i) + ".stl")).string(),
                 items[i].shape.mesh);
    }

    // Parameter columns: union over fractions, in first-appearance order.
    std::vector<std::string> params;
    std::set<std::string> seen;
    for (const auto& it : items)
      for (const auto& [name, v] : it.shape.sampled)
        if (seen.insert(name).second) params.push_back(name);

    std::string names = "id,fraction,method,mesh,attempts";
    for (const auto& p : params) names += ",p_" + p;
    for (const auto& c : descriptor_csv_columns()) names += "," + c;
    write_file_atomically((fs::path(staging) / "shapes.csv").string(), [&](std::ostream& o) {
      o << csv_header("shapes", names, si_length()) << "\n";
      for (std::size_t i = 0; i < total; ++i) {
        const auto& it = items[i];
        const auto& fr = recipe.fractions[it.fraction];
        o << i << "," << csv_escape(fr.name) << "," << fr.method << ",meshes/" << id_name(i)
          << ".stl," << it.shape.attempts;
        for (const auto& p : params) {
          o << ",";
          for (const auto& [name, v] : it.shape.sampled)
            if (name == p) o << format_number(v);
        }
        for (double v : descriptor_csv_values(it.desc)) o << "," << format_number(v);
        o << "\n";
      }
    });

    nlohmann::ordered_json m = manifest_head("shapes", recipe);
    m["mesh_format"] = "binary STL, float32, units of the recipe (m)";
    auto& fr = m["fractions"] = nlohmann::ordered_json::array();
    std::size_t first = 0;
    for (const auto& f : recipe.fractions) {
      long attempts = 0;
      for (std::size_t i = first; i < first + static_cast<std::size_t>(f.count); ++i)
        attempts += items[i].shape.attempts;
      fr.push_back({{"name", f.name},
                    {"method", f.method},
                    {"count", f.count},
                    {"first_id", first},
                    {"attempts", attempts}});
      first += f.count;
    }
    add_units(m, si_length());
    write_file_atomically((fs::path(staging) / "manifest.json").string(),
                          [&](std::ostream& o) { o << m.dump(2) << "\n"; });
    publish_directory(staging, out_dir);
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
  return {total, out_dir};
}

}  // namespace clumpkit
