#include "io/recipes/specimen_recipe.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/text.h"
#include "io/recipes/crush_recipe.h"
#include "io/recipes/section_table.h"
#include "io/recipes/toml_fields.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace clumpkit {

namespace {

// What the sections said that the checks across sections need.
struct Seen {
  bool gradation = false, diameter = false, size = false, angle = false;
  bool cells = false, bond = false;
  bool rock_shape = false;  // [rock] gave a key of the parent's shape (polyhedron_keys)
  bool zones = false, zone_origin = false;
  std::vector<std::string> deposition_keys;  // keys that only the deposition method uses
};

// What reading the recipe fills: the recipe, what its sections said, and the crushing tables.
struct Reading {
  SpecimenRecipe& r;
  Seen& seen;
  CrushRecipe& tables;
};

bool has(const std::vector<std::string>& given, const char* key) {
  return std::find(given.begin(), given.end(), key) != given.end();
}

void read_container(const TomlFields& f, const toml::node& v, Reading& in) {
  const std::vector<std::string> given = read_section(f, v, container_section(), in.r);
  if (has(given, "diameter") || has(given, "height")) in.seen.diameter = true;
  if (has(given, "size")) in.seen.size = true;
  if (has(given, "angle")) in.seen.angle = true;
}

void read_preparation(const TomlFields& f, const toml::node& v, Reading& in) {
  read_section(f, v, preparation_section(), in.r);
}

void read_zones(const TomlFields& f, const toml::node& v, Reading& in) {
  in.seen.zones = true;
  if (has(read_section(f, v, zones_section(), in.r), "origin")) in.seen.zone_origin = true;
  if (in.r.zones.regions.empty()) f.fail("zones.region", "missing (at least the core)");
}

// Checked with the rest by check_gradation.
void read_gradation(const TomlFields& f, const toml::node& v, Reading& in) {
  in.seen.gradation = true;
  read_section(f, v, gradation_section(), in.r);
}

void read_fines(const TomlFields& f, const toml::node& v, Reading& in) {
  SpecimenRecipe& r = in.r;
  read_section(f, v, fines_section(), r);
  if (!(r.fines_min > 0 && r.fines_min < r.fines_max))
    f.fail("fines.replace_with", "expected 0 < low < high, got [" + format_number(r.fines_min) +
                                     ", " + format_number(r.fines_max) + "]");
}

// Library or recipe resolved by resolve_library, a crushable material by check_crushable.
void read_rock(const TomlFields& f, const toml::node& v, Reading& in) {
  for (const std::string& k : read_section(f, v, rock_section(), in.r))
    for (const auto& shape_key : polyhedron_keys())
      if (k == shape_key.name) in.seen.rock_shape = true;
}

// [cells] and [bond]: the crushing recipes' tables.
void read_cells(const TomlFields& f, const toml::node& v, Reading& in) {
  in.seen.cells = true;
  read_cells_table(f, f.table(v, "cells"), in.tables);
}

void read_bond(const TomlFields& f, const toml::node& v, Reading& in) {
  in.seen.bond = true;
  read_bond_table(f, f.table(v, "bond"), in.tables);
}

void read_density(const TomlFields& f, const toml::node& v, Reading& in) {
  read_section(f, v, density_section(), in.r);
}

void read_contact(const TomlFields& f, const toml::node& v, Reading& in) {
  read_section(f, v, contact_section(), in.r);
}

// One entry at the top of the recipe: a section and its reader, or (no reader) a key of
// specimen_top_section(); `deposition`: a key only the deposition method uses.
struct TopLevel {
  const char* name;
  void (*read)(const TomlFields&, const toml::node&, Reading&);
  bool deposition;
};

// In the order the "unknown key" message lists them.
const std::vector<TopLevel>& top_level() {
  static const std::vector<TopLevel> t{{"seed", nullptr, false},
                                       {"name", nullptr, false},
                                       {"description", nullptr, false},
                                       {"container", read_container, false},
                                       {"gradation", read_gradation, false},
                                       {"soil_rock_threshold", nullptr, false},
                                       {"rock_mass_fraction", nullptr, false},
                                       {"fines", read_fines, false},
                                       {"rock", read_rock, false},
                                       {"cells", read_cells, false},
                                       {"bond", read_bond, false},
                                       {"density", read_density, false},
                                       {"contact", read_contact, false},
                                       {"preparation", read_preparation, false},
                                       {"zones", read_zones, false},
                                       {"target_relative_density", nullptr, true},
                                       {"layers", nullptr, true},
                                       {"calibration_frictions", nullptr, true}};
  return t;
}

// The top-level entry `k`, or "k: unknown key (known: ...)".
const TopLevel& top_entry(const TomlFields& f, const std::string& k) {
  std::string known;
  for (const TopLevel& e : top_level()) {
    if (e.name == k) return e;
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  f.fail(k, "unknown key (known: " + known + ")");
}

// A top-level key (not a section), read by its entry in specimen_top_section().
void read_top_key(const TomlFields& f, const toml::node& v, const std::string& k,
                  SpecimenRecipe& r) {
  for (const auto& key : specimen_top_section().keys)
    if (key.name == k) return key.read(f, v, k, r);
  f.fail(k, "has no entry in specimen_top_section()");  // a table out of step with top_level()
}

// A crushable specimen's material from [rock], [cells] and [bond]: compression only, every
// class rock, no zones, no library; the cells' and the fill's settings checked. The parent's
// shape, where [rock] gives it, is checked as a whole (offset_max against offset_min) either way.
void check_crushable(const TomlFields& f, SpecimenRecipe& r, const Seen& seen,
                     CrushRecipe& tables) {
  if (!r.crushable) {
    if (r.unbreakable) f.fail("rock.unbreakable", "is for crushable particles (crushable = true)");
    if (seen.cells || seen.bond)
      f.fail(seen.cells ? "cells" : "bond", "is for crushable particles ([rock] crushable = true)");
    if (seen.rock_shape) {
      try {
        validate(r.crushable_material.shape);
      } catch (const InvalidInput& e) {
        f.fail("rock", e.what());
      }
    }
    return;
  }
  if (!r.compression) f.fail("rock.crushable", "needs preparation.method = \"compression\"");
  if (seen.zones) f.fail("rock.crushable", "a crushable specimen cannot be zoned");
  if (!r.library.empty() || !r.library_recipe.empty())
    f.fail("rock", "crushable particles are made from [cells], not from a library");
  if (std::abs(r.rock_mass_fraction - 1.0) > 1e-12)
    f.fail("rock_mass_fraction",
           "a crushable specimen is all rock (1, with soil_rock_threshold at or below the "
           "finest sieve), got " +
               format_number(r.rock_mass_fraction));
  apply_bond_scale(f, tables);
  dem::CrushableMaterial& m = r.crushable_material;
  m.cells = tables.cells;
  m.face_subdivision = tables.face_subdivision;
  m.strength = tables.strength;
  m.density = r.rock_density;
  m.fill.voxels_from_count = false;
  r.bond = tables.law;
  r.bond_scale = tables.scale;
  if (r.unbreakable) r.bond = dem::unbreakable(r.bond);  // the control
  try {
    dem::validate(m);
  } catch (const InvalidInput& e) {
    f.fail("rock", e.what());
  }
  // A cell as large as the smallest parent leaves it one cell: refused before any work.
  const double d = r.sieves.back();
  if (std::round(std::pow(d / m.cells.cell_size, 3)) < 2 && m.cells.count == 0)
    f.fail("cells.cell_size", format_number(m.cells.cell_size) +
                                  " leaves the smallest particles (" + format_number(d) +
                                  " m) fewer than 2 cells");
}

// The preparation and its container.
void check_preparation(const TomlFields& f, const SpecimenRecipe& r, const Seen& seen) {
  if (r.linear_scaling && !(r.d_ref > 0))
    f.fail("contact.d_ref",
           "needed by stiffness_scaling = \"linear\" (the diameter at which kn "
           "and ks hold)");
  if (r.segment && !r.compression)
    f.fail("container.shape",
           "a segment needs preparation.method = \"compression\" (deposition builds whole "
           "cylinders)");
  if (seen.angle && !r.segment) f.fail("container.angle", "is for shape = \"segment\"");
  if (r.cuboid && !r.compression)
    f.fail("container.shape",
           "a cuboid needs preparation.method = \"compression\" (deposition "
           "builds cylinders)");
  if (r.cuboid && seen.diameter)
    f.fail("container", "a cuboid has size = [x, y, z], not diameter or height");
  if (!r.cuboid && seen.size)
    f.fail("container.size", "is for shape = \"cuboid\" (a cylinder has diameter and height)");
  if (r.compression && !seen.deposition_keys.empty())
    f.fail(seen.deposition_keys.front(), "applies to preparation.method = \"deposition\" only");
}

// Gradation: sieves descending, passing descending from exactly 100; the size classes from them.
void check_gradation(const TomlFields& f, SpecimenRecipe& r, const Seen& seen) {
  if (!seen.gradation) f.fail("gradation", "missing (sieves = [...], passing = [...])");
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
}

// Rock share implied by the gradation must match the stated rock fraction; the container must hold
// the largest particles. Returns the rock percentage.
double check_sizes(const TomlFields& f, const SpecimenRecipe& r) {
  double rock = 0.0;
  for (const auto& c : r.classes)
    if (c.min >= r.soil_rock_threshold - 1e-12) rock += c.percent;
  if (std::abs(rock / 100.0 - r.rock_mass_fraction) > 0.005)
    f.fail("rock_mass_fraction", "the gradation gives " + format_number(rock) +
                                     " % above the threshold " +
                                     format_number(r.soil_rock_threshold) + " m, got " +
                                     format_number(100 * r.rock_mass_fraction) + " %");
  const double narrowest = r.cuboid
                               ? *std::min_element(r.container_size.begin(), r.container_size.end())
                               : std::min(r.container_diameter, r.container_height);
  if (r.compression) {
    // Crushable classes are sized by the parents' volume-equivalent diameter D, above their
    // sieve size (intermediate dimension): three D across hold about four sieve sizes.
    const double across = r.crushable ? 3 : 4;
    if (across * r.sieves.front() > narrowest)
      f.fail(r.cuboid ? "container.size" : "container.diameter",
             "must be at least " + std::string(r.crushable ? "three" : "four") +
                 " largest particles (" + format_number(r.sieves.front()) + " m) across, got " +
                 format_number(narrowest));
  } else if (2 * r.sieves.front() >= r.container_diameter)
    f.fail("container.diameter", "not wider than twice the largest particle (" +
                                     format_number(r.sieves.front()) + " m), got " +
                                     format_number(r.container_diameter));
  // Porosity is measured one largest sieve size away from floor, top and wall, in each layer
  // too: a layer must be thicker than two of them, the container wider than two more.
  if (!r.compression && 2 * r.sieves.front() >= r.container_height / r.layers)
    f.fail("container.height", "a layer (" + format_number(r.container_height / r.layers) +
                                   " m) must be thicker than twice the largest particle (" +
                                   format_number(r.sieves.front()) + " m), got " +
                                   format_number(r.container_height));
  // dem::check_spec's rules, refused here before anything is simulated.
  const std::vector<double>& mu = r.calibration_frictions;
  if (mu.size() < static_cast<std::size_t>(dem::kMinCalibrationFrictions))
    f.fail("calibration_frictions",
           "need at least " + std::to_string(dem::kMinCalibrationFrictions) +
               " values (the two end points and the rest in between), got " +
               std::to_string(mu.size()));
  for (std::size_t i = 0; i < mu.size(); ++i)
    if (!dem::kFriction.contains(mu[i]))
      f.fail("calibration_frictions[" + std::to_string(i) + "]",
             outside(dem::kFriction, mu[i]) + ", got " + format_number(mu[i]));
  return rock;
}

// Zones: the layout's guard rails (dem/specimen/zones.h), with the core's largest particle.
void check_zones(const TomlFields& f, SpecimenRecipe& r, const Seen& seen) {
  if (seen.zones) {
    if (!r.compression)
      f.fail("zones",
             "need preparation.method = \"compression\" (zones are placed loose and "
             "compressed)");
    if (r.zones.coordinate == dem::ZoneCoordinate::spherical && !seen.zone_origin)
      f.fail("zones.origin", "needed by coordinate = \"spherical\" (the centre, m)");
    if (!seen.zone_origin && r.zones.coordinate == dem::ZoneCoordinate::depth)
      r.zones.origin = Vec3(0, 0, r.cuboid ? r.container_size[2] : r.container_height);
    try {
      r.zone_warnings = dem::validate_zones(r.zones, r.sieves.front());
    } catch (const InvalidInput& e) {
      throw InvalidInput(f.file + ": " + e.what());
    }
  }
  if (r.mixed_porosity > 0 && !seen.zones)
    f.fail("zones.mixed_porosity", "is for recipes with zones");
}

// The rock library: an existing `clumpkit library` directory, or a recipe to make one (paths
// relative to the recipe).
void resolve_library(const TomlFields& f, SpecimenRecipe& r, double rock) {
  const fs::path base = fs::path(f.file).parent_path();
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
}

}  // namespace

SpecimenRecipe parse_specimen_recipe(const std::string& text, const std::string& path) {
  const TomlFields f{path};
  const toml::table root = parse_toml(text, path);
  SpecimenRecipe r;
  r.path = path;
  r.text = text;
  Seen seen;
  CrushRecipe tables;  // [cells] and [bond] of crushable particles, with the crushing defaults
  set_crushable_fill_defaults(r);
  Reading in{r, seen, tables};
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    const TopLevel& e = top_entry(f, k);
    if (e.deposition) seen.deposition_keys.push_back(k);
    if (e.read)
      e.read(f, val, in);
    else
      read_top_key(f, val, k, r);
  }

  check_preparation(f, r, seen);
  check_gradation(f, r, seen);
  check_crushable(f, r, seen, tables);
  const double rock = check_sizes(f, r);
  check_zones(f, r, seen);
  if (!r.crushable) resolve_library(f, r, rock);
  return r;
}

SpecimenRecipe read_specimen_recipe(const std::string& path) {
  return parse_specimen_recipe(read_file(path, "recipe file"), path);
}

}  // namespace clumpkit
