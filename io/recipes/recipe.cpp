#include "io/recipes/recipe.h"

#include "geom/errors.h"
#include "io/base/text.h"
#include "io/recipes/section_table.h"
#include "io/recipes/toml_fields.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

namespace clumpkit {

namespace {

// An integer in [lo, hi], refused as "expected WHAT, got VALUE" (the shape recipes' wording).
long long integer_within(const TomlFields& f, const toml::node& v, const std::string& field,
                         long long lo, long long hi, const std::string& what) {
  const auto* i = v.as_integer();
  if (!i || i->get() < lo || i->get() > hi)
    f.fail(field, "expected " + what + ", got " + toml_show(v));
  return i->get();
}

}  // namespace

const RecipeSection<FractionTable>& fraction_section() {
  using T = FractionTable;
  static const RecipeSection<T> s{
      "fraction",
      "One fraction of a shape library: its method and count; every other key is a parameter of "
      "its method (`clumpkit shape METHOD --help`), a number or a distribution.",
      {custom_key<T>("name", "", "text", "the fraction's name", "the method",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, T& t) {
                       t.spec.name = f.string(v, field);
                     }),
       custom_key<T>("method", "", "block, hull, polyhedron, ellipsoid or mesh",
                     "how its particles are made", "required",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, T& t) {
                       t.spec.method = f.string(v, field);
                     }),
       shown_as(range_key<T>("count", "", kFractionCount, "particles of the fraction",
                             [](T& t) -> int& { return t.spec.count; }),
                "required; mesh: the number of files"),
       custom_key<T>("folder", "", "a folder, relative to the recipe's",
                     "mesh: every .stl, .obj and .ply file in it is one particle, in the order of "
                     "their names",
                     "required for mesh",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, T& t) {
                       t.folder = f.string(v, field);
                     }),
       range_key<T>("scale", "", kMeshScale,
                    "mesh: factor from the files' length unit to metres (0.001 for millimetres)",
                    [](T& t) -> double& { return t.spec.scale; }),
       custom_key<T>("roundness", "", "[min, max], min <= max",
                     "hull: the band of weighted roundness the hull is redrawn into", "[1, 10]",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, T& t) {
                       const auto [lo, hi] = f.pair(v, field);
                       t.spec.params["roundness_min"] = constant(lo);
                       t.spec.params["roundness_max"] = constant(hi);
                       if (lo > hi) f.fail(field, "low exceeds high, got " + toml_show(v));
                     })}};
  return s;
}

const RecipeSection<FillOptions>& fill_section() {
  using O = FillOptions;
  static const RecipeSection<O> s{
      "fill",
      "The clump of each particle for `clumpkit library` (as `clumpkit fill`): a sphere budget, "
      "a coverage or a smallest radius; checked by validate(FillOptions).",
      {shown_as(range_key<O>("spheres", "", kSphereBudget, "sphere budget of each clump",
                             [](O& o) -> int& { return o.spheres; }),
                "none"),
       shown_as(range_key<O>("coverage", "", kCoverage,
                             "stop once this fraction of the interior volume is covered",
                             [](O& o) -> double& { return o.coverage; }),
                "none"),
       range_key<O>("min_radius", "m", kMinRadius,
                    "R_lim of Jin et al. 2017: smaller spheres are never placed",
                    [](O& o) -> double& { return o.min_radius; }),
       [] {
         auto k = range_key<O>(
             "voxels", "", kFieldVoxels,
             "voxels across the mesh's smallest principal extent (distance field and coverage "
             "grid)",
             [](O& o) -> int& { return o.field.voxels; });
         // A resolution given holds, as fill --voxels: no refining from the sphere count.
         k.read = [read = k.read](const TomlFields& f, const toml::node& v,
                                  const std::string& field, O& o) {
           read(f, v, field, o);
           o.voxels_from_count = false;
         };
         k.shown = [](const O& d) {
           return std::to_string(d.field.voxels) + ", finer from a sphere budget";
         };
         return k;
       }(),
       range_key<O>("max_overshoot", "", kMaxOvershoot,
                    "the clump's volume outside the mesh, over the mesh's volume",
                    [](O& o) -> double& { return o.max_overshoot; }),
       range_key<O>("refine_iterations", "", kRefineIterations,
                    "sweeps of the refinement after the greedy pass (0: none)",
                    [](O& o) -> int& { return o.refine_iterations; })}};
  return s;
}

namespace {

struct Parser : TomlFields {
  // The .stl, .obj and .ply files of `folder` (relative to the recipe's folder), by name.
  std::vector<std::string> mesh_files(const std::string& folder, const std::string& field) const {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(folder).is_absolute()
                             ? fs::path(folder)
                             : fs::path(file).parent_path() / fs::path(folder);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) fail(field, "no such folder: " + dir.string());
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      std::string ext = entry.path().extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (entry.is_regular_file() && (ext == ".stl" || ext == ".obj" || ext == ".ply"))
        files.push_back(entry.path().string());
    }
    if (ec) fail(field, "cannot list " + dir.string() + ": " + ec.message());
    if (files.empty()) fail(field, "no .stl, .obj or .ply file in " + dir.string());
    std::sort(files.begin(), files.end());
    return files;
  }

  FractionSpec fraction(const toml::table& t, const std::string& prefix) const {
    FractionTable table;
    FractionSpec& f = table.spec;
    const auto& keys = fraction_section().keys;
    for (const auto& [key, val] : t) {
      const std::string k(key.str()), field = prefix + "." + k;
      const auto it = std::find_if(keys.begin(), keys.end(),
                                   [&](const RecipeKey<FractionTable>& e) { return e.name == k; });
      // Any other key is a parameter of the method, checked against its table by validate().
      if (it == keys.end())
        f.params[k] = distribution(val, field);
      else
        it->read(*this, val, field, table);
    }
    if (f.method.empty())
      fail(prefix + ".method", "missing (one of block, hull, polyhedron, ellipsoid, mesh)");
    if (f.method == kMeshMethod) {
      if (table.folder.empty()) fail(prefix + ".folder", "missing (the folder of the mesh files)");
      f.files = mesh_files(table.folder, prefix + ".folder");
      if (!t.contains("count")) f.count = static_cast<int>(f.files.size());
    } else {
      if (!table.folder.empty()) fail(prefix + ".folder", "only for method mesh");
      if (t.contains("scale")) fail(prefix + ".scale", "only for method mesh");
    }
    if (!t.contains("count") && f.method != kMeshMethod) fail(prefix + ".count", "missing");
    if (f.name.empty()) f.name = f.method;
    try {
      validate(f, prefix);
    } catch (const InvalidInput& e) {
      throw InvalidInput(file + ": " + e.what());
    }
    return f;
  }
};

}  // namespace

ShapeRecipe parse_shape_recipe(const std::string& text, const std::string& path) {
  Parser p{{path}};
  const toml::table root = parse_toml(text, path);
  ShapeRecipe r;
  r.path = path;
  r.text = text;
  auto read_fractions = [&](const toml::node& v) {
    const auto* arr = v.as_array();
    if (!arr || !arr->is_array_of_tables()) p.fail("fraction", "expected [[fraction]] tables");
    for (const auto& f : *arr) {
      const std::string prefix = "fraction[" + std::to_string(r.fractions.size()) + "]";
      r.fractions.push_back(p.fraction(*f.as_table(), prefix));
    }
  };
  auto read_fill = [&](const toml::node& v) {
    if (!v.is_table()) p.fail("fill", "expected a [fill] table");
    r.has_fill = true;
    read_section(p, v, fill_section(), r.fill);
    try {
      validate(r.fill);
    } catch (const InvalidInput& e) {
      p.fail("fill", e.what());
    }
  };
  // The top level: each key's reader, in the order the unknown-key message lists them.
  const TopLevelReaders top{
      {"seed",
       [&](const toml::node& v) {
         const long long n = p.integer(v, "seed");
         const std::string why = outside(kSeed, static_cast<double>(n));
         if (!why.empty()) p.fail("seed", why + ", got " + toml_show(v));
         r.seed = static_cast<std::uint64_t>(n);
       }},
      {"name", [&](const toml::node& v) { r.name = p.string(v, "name"); }},
      {"description", [&](const toml::node& v) { r.description = p.string(v, "description"); }},
      {"refine_triangles",
       [&](const toml::node& v) {
         r.refine_triangles =
             integer_within(p, v, "refine_triangles", 0, 50000000, "an integer in [0, 5e7]");
       }},
      {"fraction", read_fractions},
      {"fill", read_fill}};
  read_top_level(p, root, top);
  if (r.fractions.empty()) p.fail("fraction", "the recipe lists no [[fraction]]");
  return r;
}

ShapeRecipe read_shape_recipe(const std::string& path) {
  return parse_shape_recipe(read_file(path, "recipe file"), path);
}

std::vector<int> particle_fractions(const ShapeRecipe& recipe) {
  std::vector<int> f;
  for (std::size_t k = 0; k < recipe.fractions.size(); ++k)
    f.insert(f.end(), static_cast<std::size_t>(recipe.fractions[k].count), static_cast<int>(k));
  return f;
}

}  // namespace clumpkit
