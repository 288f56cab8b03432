#include "io/recipes/recipe.h"

#include "geom/errors.h"
#include "io/base/text.h"
#include "io/recipes/toml_fields.h"

#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace clumpkit {

namespace {

std::string show(const toml::node& n) {
  return toml_show(n);
}

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
    FractionSpec f;
    std::string folder;
    bool scaled = false;
    for (const auto& [key, val] : t) {
      const std::string k(key.str());
      const std::string field = prefix + "." + k;
      if (k == "name") {
        if (!val.is_string()) fail(field, "expected a string, got " + show(val));
        f.name = val.as_string()->get();
      } else if (k == "method") {
        if (!val.is_string()) fail(field, "expected a string, got " + show(val));
        f.method = val.as_string()->get();
      } else if (k == "count") {
        const auto* i = val.as_integer();
        if (!i) fail(field, "expected an integer, got " + show(val));
        if (i->get() < 0 || i->get() > 10000000)
          fail(field, "must be in [0, 10000000], got " + show(val));
        f.count = static_cast<int>(i->get());
      } else if (k == "folder") {
        folder = string(val, field);
      } else if (k == "scale") {
        f.scale = positive(val, field);
        scaled = true;
      } else if (k == "roundness") {
        const auto [lo, hi] = pair(val, field);
        f.params["roundness_min"] = constant(lo);
        f.params["roundness_max"] = constant(hi);
        if (lo > hi) fail(field, "low exceeds high, got " + show(val));
      } else {
        f.params[k] = distribution(val, field);
      }
    }
    if (f.method.empty())
      fail(prefix + ".method", "missing (one of block, hull, polyhedron, ellipsoid, mesh)");
    if (f.method == kMeshMethod) {
      if (folder.empty()) fail(prefix + ".folder", "missing (the folder of the mesh files)");
      f.files = mesh_files(folder, prefix + ".folder");
      if (!t.contains("count")) f.count = static_cast<int>(f.files.size());
    } else {
      if (!folder.empty()) fail(prefix + ".folder", "only for method mesh");
      if (scaled) fail(prefix + ".scale", "only for method mesh");
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
  bool any = false;
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    if (k == "seed") {
      const auto* i = val.as_integer();
      if (!i || i->get() < 0) p.fail("seed", "expected a non-negative integer, got " + show(val));
      r.seed = static_cast<std::uint64_t>(i->get());
    } else if (k == "refine_triangles") {
      const auto* i = val.as_integer();
      if (!i || i->get() < 0 || i->get() > 50000000)
        p.fail(k, "expected an integer in [0, 5e7], got " + show(val));
      r.refine_triangles = i->get();
    } else if (k == "name" || k == "description") {
      if (!val.is_string()) p.fail(k, "expected a string, got " + show(val));
      (k == "name" ? r.name : r.description) = val.as_string()->get();
    } else if (k == "fraction") {
      const auto* arr = val.as_array();
      if (!arr || !arr->is_array_of_tables()) p.fail(k, "expected [[fraction]] tables");
      int i = 0;
      for (const auto& f : *arr) {
        r.fractions.push_back(p.fraction(*f.as_table(), "fraction[" + std::to_string(i++) + "]"));
        any = true;
      }
    } else if (k == "fill") {
      const auto* t = val.as_table();
      if (!t) p.fail(k, "expected a [fill] table");
      r.has_fill = true;
      for (const auto& [fk, fv] : *t) {
        const std::string name(fk.str());
        const std::string field = "fill." + name;
        if (name == "spheres") {
          const auto* i = fv.as_integer();
          if (!i || i->get() < 1) p.fail(field, "expected an integer >= 1, got " + show(fv));
          r.fill.spheres = static_cast<int>(i->get());
        } else if (name == "voxels") {
          const auto* i = fv.as_integer();
          if (!i || i->get() < 4 || i->get() > 2000)
            p.fail(field, "expected an integer in [4, 2000], got " + show(fv));
          r.fill.field.voxels = static_cast<int>(i->get());
          r.fill.voxels_from_count = false;  // a resolution given holds, as fill --voxels
        } else if (name == "coverage") {
          r.fill.coverage = p.number(fv, field);
        } else if (name == "min_radius") {
          r.fill.min_radius = p.number(fv, field);
        } else if (name == "max_overshoot") {
          r.fill.max_overshoot = p.number(fv, field);
        } else if (name == "refine_iterations") {
          const auto* i = fv.as_integer();
          if (!i || i->get() < 0 || i->get() > 1000)
            p.fail(field, "expected an integer in [0, 1000], got " + show(fv));
          r.fill.refine_iterations = static_cast<int>(i->get());
        } else {
          p.fail(field,
                 "unknown key (known: spheres, coverage, min_radius, voxels, max_overshoot, "
                 "refine_iterations)");
        }
      }
      try {
        validate(r.fill);
      } catch (const InvalidInput& e) {
        p.fail("fill", e.what());
      }
    } else {
      p.fail(k, "unknown key (known: seed, name, description, refine_triangles, fraction, fill)");
    }
  }
  if (!any) p.fail("fraction", "the recipe lists no [[fraction]]");
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
