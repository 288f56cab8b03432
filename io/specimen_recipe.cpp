#include "io/specimen_recipe.h"

#include "geom/errors.h"
#include "io/report.h"
#include "io/toml_fields.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace clumpkit {

namespace {

std::vector<double> numbers(const TomlFields& f, const toml::node& n, const std::string& field) {
  const auto* a = n.as_array();
  if (!a || a->empty()) f.fail(field, "expected a non-empty array of numbers, got " + toml_show(n));
  std::vector<double> v;
  for (std::size_t i = 0; i < a->size(); ++i)
    v.push_back(f.number(*a->get(i), field + "[" + std::to_string(i) + "]"));
  return v;
}

double positive(const TomlFields& f, const toml::node& n, const std::string& field) {
  const double x = f.number(n, field);
  if (!(x > 0.0)) f.fail(field, "must be positive, got " + toml_show(n));
  return x;
}

}  // namespace

SpecimenRecipe parse_specimen_recipe(const std::string& text, const std::string& path) {
  const TomlFields f{path};
  const toml::table root = parse_toml(text, path);
  SpecimenRecipe r;
  r.path = path;
  r.text = text;
  bool have_gradation = false;
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    if (k == "seed") {
      const long long s = f.integer(val, k);
      if (s < 0) f.fail(k, "must be non-negative, got " + toml_show(val));
      r.seed = static_cast<std::uint64_t>(s);
    } else if (k == "name" || k == "description") {
      f.string(val, k);
    } else if (k == "container") {
      for (const auto& [ck, cv] : f.table(val, k)) {
        const std::string c(ck.str()), field = "container." + c;
        if (c == "diameter")
          r.container_diameter = positive(f, cv, field);
        else if (c == "height")
          r.container_height = positive(f, cv, field);
        else
          f.fail(field, "unknown key (known: diameter, height)");
      }
    } else if (k == "gradation") {
      have_gradation = true;
      for (const auto& [gk, gv] : f.table(val, k)) {
        const std::string g(gk.str()), field = "gradation." + g;
        if (g == "sieves")
          r.sieves = numbers(f, gv, field);
        else if (g == "passing")
          r.passing = numbers(f, gv, field);
        else
          f.fail(field, "unknown key (known: sieves, passing)");
      }
    } else if (k == "soil_rock_threshold") {
      r.soil_rock_threshold = positive(f, val, k);
    } else if (k == "rock_mass_fraction") {
      r.rock_mass_fraction = f.number(val, k);
      if (r.rock_mass_fraction < 0 || r.rock_mass_fraction > 1)
        f.fail(k, "must be in [0, 1], got " + toml_show(val));
    } else if (k == "fines") {
      for (const auto& [fk, fv] : f.table(val, k)) {
        const std::string g(fk.str()), field = "fines." + g;
        if (g == "below")
          r.fines_below = positive(f, fv, field);
        else if (g == "replace_with")
          std::tie(r.fines_min, r.fines_max) = f.pair(fv, field);
        else
          f.fail(field, "unknown key (known: below, replace_with)");
      }
      if (!(r.fines_min > 0 && r.fines_min < r.fines_max))
        f.fail("fines.replace_with", "expected 0 < low < high, got [" + format_number(r.fines_min) +
                                         ", " + format_number(r.fines_max) + "]");
    } else if (k == "rock") {
      for (const auto& [rk, rv] : f.table(val, k)) {
        const std::string g(rk.str()), field = "rock." + g;
        if (g == "library")
          r.library = f.string(rv, field);
        else if (g == "recipe")
          r.library_recipe = f.string(rv, field);
        else
          f.fail(field, "unknown key (known: library, recipe)");
      }
    } else if (k == "density") {
      for (const auto& [dk, dv] : f.table(val, k)) {
        const std::string g(dk.str()), field = "density." + g;
        if (g == "soil")
          r.soil_density = positive(f, dv, field);
        else if (g == "rock")
          r.rock_density = positive(f, dv, field);
        else
          f.fail(field, "unknown key (known: soil, rock)");
      }
    } else if (k == "contact") {
      for (const auto& [ck, cv] : f.table(val, k)) {
        const std::string g(ck.str()), field = "contact." + g;
        if (g == "kn") {
          r.kn = positive(f, cv, field);
        } else if (g == "ks") {
          r.ks = positive(f, cv, field);
        } else if (g == "friction") {
          r.friction = f.number(cv, field);
          if (r.friction < 0) f.fail(field, "must not be negative, got " + toml_show(cv));
        } else if (g == "damping_ratio") {
          r.damping_ratio = f.number(cv, field);
          if (!(r.damping_ratio >= 0 && r.damping_ratio < 1))
            f.fail(field, "must be in [0, 1), got " + toml_show(cv));
        } else if (g == "local_damping") {
          r.local_damping = f.number(cv, field);
          if (!(r.local_damping >= 0 && r.local_damping < 1))
            f.fail(field, "must be in [0, 1), got " + toml_show(cv));
        } else {
          f.fail(field, "unknown key (known: kn, ks, friction, damping_ratio, local_damping)");
        }
      }
    } else if (k == "target_relative_density") {
      r.target_relative_density = f.number(val, k);
      if (r.target_relative_density < 0 || r.target_relative_density > 1)
        f.fail(k, "must be in [0, 1], got " + toml_show(val));
    } else if (k == "layers") {
      const long long n = f.integer(val, k);
      if (n < 1 || n > 100) f.fail(k, "must be in [1, 100], got " + toml_show(val));
      r.layers = static_cast<int>(n);
    } else if (k == "calibration_frictions") {
      r.calibration_frictions = numbers(f, val, k);
    } else {
      f.fail(
          k,
          "unknown key (known: seed, name, description, container, gradation, soil_rock_threshold, "
          "rock_mass_fraction, fines, rock, density, contact, target_relative_density, layers, "
          "calibration_frictions)");
    }
  }

  // Gradation: sieves descending, passing descending from exactly 100.
  if (!have_gradation) f.fail("gradation", "missing (sieves = [...], passing = [...])");
  if (r.sieves.size() != r.passing.size() || r.sieves.size() < 2)
    f.fail("gradation", "sieves and passing need the same length, at least 2, got " +
                            std::to_string(r.sieves.size()) + " and " +
                            std::to_string(r.passing.size()));
  for (std::size_t i = 0; i < r.sieves.size(); ++i) {
    if (!(r.sieves[i] > 0))
      f.fail("gradation.sieves[" + std::to_string(i) + "]",
             "must be positive, got " + format_number(r.sieves[i]));
    if (i > 0 && !(r.sieves[i] < r.sieves[i - 1]))
      f.fail("gradation.sieves[" + std::to_string(i) + "]",
             "sieves must decrease, got " + format_number(r.sieves[i]) + " after " +
                 format_number(r.sieves[i - 1]));
    if (i > 0 && r.passing[i] > r.passing[i - 1])
      f.fail("gradation.passing[" + std::to_string(i) + "]",
             "percent passing must not increase, got " + format_number(r.passing[i]) + " after " +
                 format_number(r.passing[i - 1]));
    if (r.passing[i] < 0)
      f.fail("gradation.passing[" + std::to_string(i) + "]", "must not be negative");
  }
  if (std::abs(r.passing.front() - 100.0) > 1e-9)
    f.fail("gradation.passing[0]",
           "the class percentages must sum to 100 (100 % passing the largest sieve), got " +
               format_number(r.passing.front()));
  r.classes.clear();
  for (std::size_t i = 0; i + 1 < r.sieves.size(); ++i)
    r.classes.push_back(SizeClass{r.sieves[i + 1], r.sieves[i], r.passing[i] - r.passing[i + 1]});
  if (r.passing.back() > 0)  // what passes the finest sieve: a class down to zero... kept as fines
    r.classes.push_back(SizeClass{0.0, r.sieves.back(), r.passing.back()});

  // Rock share implied by the gradation must match the stated rock fraction.
  double rock = 0.0;
  for (const auto& c : r.classes)
    if (c.min >= r.soil_rock_threshold - 1e-12) rock += c.percent;
  if (std::abs(rock / 100.0 - r.rock_mass_fraction) > 0.005)
    f.fail("rock_mass_fraction", "the gradation gives " + format_number(rock) +
                                     " % above the threshold " +
                                     format_number(r.soil_rock_threshold) + " m, got " +
                                     format_number(100 * r.rock_mass_fraction) + " %");
  if (2 * r.sieves.front() >= r.container_diameter)
    f.fail("container.diameter", "not wider than twice the largest particle (" +
                                     format_number(r.sieves.front()) + " m), got " +
                                     format_number(r.container_diameter));
  // Porosity is measured one largest sieve size away from floor, top and wall, in each layer
  // too: a layer must be thicker than two of them, the container wider than two more.
  if (2 * r.sieves.front() >= r.container_height / r.layers)
    f.fail("container.height", "a layer (" + format_number(r.container_height / r.layers) +
                                   " m) must be thicker than twice the largest particle (" +
                                   format_number(r.sieves.front()) + " m), got " +
                                   format_number(r.container_height));
  if (r.calibration_frictions.size() < 6)
    f.fail("calibration_frictions", "need the two end points and at least four in between, got " +
                                        std::to_string(r.calibration_frictions.size()) + " values");
  for (double mu : r.calibration_frictions)
    if (mu < 0)
      f.fail("calibration_frictions", "friction must not be negative, got " + format_number(mu));

  // The rock library: an existing `clumpkit library` directory, or a recipe to make one.
  const fs::path base = fs::path(path).parent_path();
  if (rock > 0) {
    if (r.library.empty() == r.library_recipe.empty())
      f.fail("rock", "give exactly one of library (a directory from `clumpkit library`) or recipe");
    if (!r.library.empty()) {
      const fs::path lib = base / r.library;
      // manifest.json; library.json in libraries written by earlier builds of clumpkit 0.1.
      if (!fs::exists(lib / "manifest.json") && !fs::exists(lib / "library.json"))
        f.fail("rock.library", "no clump library (manifest.json) at " + lib.string());
      r.library = lib.string();
    } else {
      const fs::path rec = base / r.library_recipe;
      if (!fs::exists(rec)) f.fail("rock.recipe", "file not found: " + rec.string());
      r.library_recipe = rec.string();
    }
  }
  return r;
}

SpecimenRecipe read_specimen_recipe(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open recipe file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_specimen_recipe(ss.str(), path);
}

}  // namespace clumpkit
