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

// A container length: a number, checked by the specs' one rule (dem::check_container_length).
double container_length(const TomlFields& f, const std::string& field, double v) {
  try {
    dem::check_container_length(v);
  } catch (const InvalidInput& e) {
    f.fail(field, e.what());
  }
  return v;
}

// One [[zones.region]] table.
dem::ZoneRegion zone_region(const TomlFields& f, const toml::node& n, const std::string& at) {
  dem::ZoneRegion z;
  bool have_outer = false, have_scale = false, have_fraction = false;
  for (const auto& [key, v] : f.table(n, at)) {
    const std::string k(key.str()), field = at + "." + k;
    if (k == "outer") {
      z.outer = f.positive(v, field);
      have_outer = true;
    } else if (k == "scale") {
      z.scale = f.positive(v, field);
      have_scale = true;
    } else if (k == "mixed") {
      const auto* b = v.as_boolean();
      if (!b) f.fail(field, "expected true or false, got " + toml_show(v));
      z.mixed = b->get();
    } else if (k == "small_volume_fraction") {
      have_fraction = true;
      if (v.is_array()) {
        const std::vector<double> ends = f.numbers(v, field);
        if (ends.size() != 2)
          f.fail(field, "expected one number or [inner, outer], got " + toml_show(v));
        z.small_fraction = ends[0], z.small_fraction_outer = ends[1];
      } else {
        z.small_fraction = z.small_fraction_outer = f.number(v, field);
      }
      for (const double x : {z.small_fraction, z.small_fraction_outer})
        if (!(x >= 0 && x <= 1)) f.fail(field, "must be in [0, 1], got " + toml_show(v));
    } else {
      f.fail(field, "unknown key (known: outer, scale, mixed, small_volume_fraction)");
    }
  }
  if (!have_outer) f.fail(at + ".outer", "missing (the region's outer bound, m)");
  if (z.mixed && have_scale)
    f.fail(at + ".scale", "a mixed layer takes its neighbours' sizes, not a scale");
  if (z.mixed && !have_fraction)
    f.fail(at + ".small_volume_fraction", "missing (the small particles' share of the layer)");
  if (!z.mixed && have_fraction)
    f.fail(at + ".small_volume_fraction", "is for mixed layers (mixed = true)");
  return z;
}

// The [zones] section; `have_origin` tells whether the origin was given.
void read_zones(const TomlFields& f, const toml::node& n, SpecimenRecipe& r, bool& have_origin) {
  for (const auto& [key, v] : f.table(n, "zones")) {
    const std::string k(key.str()), field = "zones." + k;
    if (k == "coordinate") {
      const std::string c = f.string(v, field);
      if (c == "radial")
        r.zones.coordinate = dem::ZoneCoordinate::radial;
      else if (c == "depth")
        r.zones.coordinate = dem::ZoneCoordinate::depth;
      else if (c == "spherical")
        r.zones.coordinate = dem::ZoneCoordinate::spherical;
      else
        f.fail(field, "expected \"radial\", \"depth\" or \"spherical\", got " + toml_show(v));
    } else if (k == "origin") {
      const std::vector<double> o = f.numbers(v, field);
      if (o.size() != 3) f.fail(field, "expected [x, y, z] in m, got " + toml_show(v));
      r.zones.origin = Vec3(o[0], o[1], o[2]);
      have_origin = true;
    } else if (k == "mixed_porosity") {
      r.mixed_porosity = f.number(v, field);
      if (!(r.mixed_porosity > 0.2 && r.mixed_porosity < 0.9))
        f.fail(field, "must be in (0.2, 0.9), got " + toml_show(v));
    } else if (k == "region") {
      const auto* a = v.as_array();
      if (!a || a->empty())
        f.fail(field, "expected [[zones.region]] tables, innermost first, got " + toml_show(v));
      for (std::size_t i = 0; i < a->size(); ++i)
        r.zones.regions.push_back(
            zone_region(f, *a->get(i), "zones.region[" + std::to_string(i + 1) + "]"));
    } else {
      f.fail(field, "unknown key (known: coordinate, origin, mixed_porosity, region)");
    }
  }
  if (r.zones.regions.empty()) f.fail("zones.region", "missing (at least the core)");
}

// What the sections said that the checks across sections need.
struct Seen {
  bool gradation = false, diameter = false, size = false, angle = false;
  bool cells = false, bond = false;
  bool zones = false, zone_origin = false;
  std::vector<std::string> deposition_keys;  // keys that only the deposition method uses
};

// [container]: shape, diameter, height, size, angle.
void read_container(const TomlFields& f, const toml::node& val, SpecimenRecipe& r, Seen& seen) {
  const std::string k = "container";
  for (const auto& [ck, cv] : f.table(val, k)) {
    const std::string c(ck.str()), field = "container." + c;
    if (c == "diameter") {
      r.container_diameter = container_length(f, field, f.number(cv, field));
      seen.diameter = true;
    } else if (c == "height") {
      r.container_height = container_length(f, field, f.number(cv, field));
      seen.diameter = true;
    } else if (c == "shape") {
      const std::string shape = f.string(cv, field);
      if (shape != "cylinder" && shape != "cuboid" && shape != "segment")
        f.fail(field, "expected \"cylinder\", \"cuboid\" or \"segment\", got " + toml_show(cv));
      r.cuboid = shape == "cuboid";
      r.segment = shape == "segment";
    } else if (c == "angle") {
      r.segment_angle_deg = f.number(cv, field);
      if (!(r.segment_angle_deg > 0 && r.segment_angle_deg <= 180))
        f.fail(field, "must be in (0, 180] degrees, got " + toml_show(cv));
      seen.angle = true;
    } else if (c == "size") {
      const std::vector<double> v = f.numbers(cv, field);
      if (v.size() != 3) f.fail(field, "expected [x, y, z] edges, got " + toml_show(cv));
      for (int a = 0; a < 3; ++a)
        r.container_size[a] = container_length(f, field + "[" + std::to_string(a) + "]", v[a]);
      seen.size = true;
    } else {
      f.fail(field, "unknown key (known: shape, diameter, height, size, angle)");
    }
  }
}

// [preparation]: method, porosity, friction.
void read_preparation(const TomlFields& f, const toml::node& val, SpecimenRecipe& r) {
  const std::string k = "preparation";
  for (const auto& [pk, pv] : f.table(val, k)) {
    const std::string c(pk.str()), field = "preparation." + c;
    if (c == "method") {
      const std::string m = f.string(pv, field);
      if (m != "deposition" && m != "compression")
        f.fail(field, "expected \"deposition\" or \"compression\", got " + toml_show(pv));
      r.compression = m == "compression";
    } else if (c == "porosity") {
      r.compression_porosity = f.number(pv, field);
      try {
        dem::check_target_porosity(r.compression_porosity);
      } catch (const InvalidInput& e) {
        f.fail(field, e.what());
      }
    } else if (c == "friction") {
      r.compression_friction = f.number(pv, field);
      if (!(r.compression_friction >= 0 && r.compression_friction <= 10))
        f.fail(field, "must be in [0, 10], got " + toml_show(pv));
    } else {
      f.fail(field, "unknown key (known: method, porosity, friction)");
    }
  }
}

// [gradation]: sieves and passing, checked with the rest (check_gradation).
void read_gradation(const TomlFields& f, const toml::node& val, SpecimenRecipe& r) {
  const std::string k = "gradation";
  for (const auto& [gk, gv] : f.table(val, k)) {
    const std::string g(gk.str()), field = "gradation." + g;
    if (g == "sieves")
      r.sieves = f.numbers(gv, field);
    else if (g == "passing")
      r.passing = f.numbers(gv, field);
    else
      f.fail(field, "unknown key (known: sieves, passing)");
  }
}

// [fines]: below, replace_with.
void read_fines(const TomlFields& f, const toml::node& val, SpecimenRecipe& r) {
  const std::string k = "fines";
  for (const auto& [fk, fv] : f.table(val, k)) {
    const std::string g(fk.str()), field = "fines." + g;
    if (g == "below")
      r.fines_below = f.positive(fv, field);
    else if (g == "replace_with")
      std::tie(r.fines_min, r.fines_max) = f.pair(fv, field);
    else
      f.fail(field, "unknown key (known: below, replace_with)");
  }
  if (!(r.fines_min > 0 && r.fines_min < r.fines_max))
    f.fail("fines.replace_with", "expected 0 < low < high, got [" + format_number(r.fines_min) +
                                     ", " + format_number(r.fines_max) + "]");
}

// [rock]: library or recipe, resolved by resolve_library.
void read_rock(const TomlFields& f, const toml::node& val, SpecimenRecipe& r) {
  const std::string k = "rock";
  dem::CrushableMaterial& m = r.crushable_material;
  for (const auto& [rk, rv] : f.table(val, k)) {
    const std::string g(rk.str()), field = "rock." + g;
    if (g == "library") {
      r.library = f.string(rv, field);
    } else if (g == "recipe") {
      r.library_recipe = f.string(rv, field);
    } else if (g == "crushable") {
      const auto* b = rv.as_boolean();
      if (!b) f.fail(field, "expected true or false, got " + toml_show(rv));
      r.crushable = b->get();
    } else if (g == "unbreakable") {
      const auto* b = rv.as_boolean();
      if (!b) f.fail(field, "expected true or false, got " + toml_show(rv));
      r.unbreakable = b->get();
    } else if (read_polyhedron_key(f, g, rv, field, m.shape)) {
    } else if (g == "spheres_per_cell") {
      m.fill.spheres = f.integer_in(rv, field, 1, 100);
    } else if (g == "cell_voxels") {
      m.fill.field.voxels = f.integer_in(rv, field, 8, 200);
    } else {
      f.fail(field,
             "unknown key (known: library, recipe, crushable, unbreakable, planes, E, F, "
             "offset_min, offset_max, spheres_per_cell, cell_voxels)");
    }
  }
}

// A crushable specimen's material from [rock], [cells] and [bond]: compression only, every
// class rock, no zones, no library; the cells' and the fill's settings checked.
void check_crushable(const TomlFields& f, SpecimenRecipe& r, const Seen& seen,
                     CrushRecipe& tables) {
  if (!r.crushable) {
    if (r.unbreakable) f.fail("rock.unbreakable", "is for crushable particles (crushable = true)");
    if (seen.cells || seen.bond)
      f.fail(seen.cells ? "cells" : "bond", "is for crushable particles ([rock] crushable = true)");
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

// A number in [0, 1): "must be in [0, 1), got VALUE" otherwise.
void unit_fraction(const TomlFields& f, const std::string& field, const toml::node& v, double x) {
  if (!(x >= 0 && x < 1)) f.fail(field, "must be in [0, 1), got " + toml_show(v));
}

}  // namespace

const RecipeSection<SpecimenRecipe>& density_section() {
  using R = SpecimenRecipe;
  static const RecipeSection<R> s{
      "density",
      "Particle densities of the specimen.",
      {number_key<R>(
           "soil", "kg/m³", "> 0", "density of the soil spheres",
           [](R& r) -> double& { return r.soil_density; }, &TomlFields::positive),
       number_key<R>(
           "rock", "kg/m³", "> 0", "density of the rock clumps",
           [](R& r) -> double& { return r.rock_density; }, &TomlFields::positive)}};
  return s;
}

const RecipeSection<SpecimenRecipe>& contact_section() {
  using R = SpecimenRecipe;
  static const RecipeSection<R> s{
      "contact",
      "The contact law of the specimen (linear spring, dashpot and Coulomb friction; "
      "dem/core/contact.h).",
      {number_key<R>(
           "kn", "N/m", "> 0", "normal stiffness (at d_ref with linear scaling)",
           [](R& r) -> double& { return r.kn; }, &TomlFields::positive),
       number_key<R>(
           "ks", "N/m", "> 0", "shear stiffness (at d_ref with linear scaling)",
           [](R& r) -> double& { return r.ks; }, &TomlFields::positive),
       number_key<R>(
           "friction", "", ">= 0", "interparticle μ", [](R& r) -> double& { return r.friction; },
           &TomlFields::number,
           [](const TomlFields& f, const std::string& field, const toml::node& v, double x) {
             if (x < 0) f.fail(field, "must not be negative, got " + toml_show(v));
           }),
       number_key<R>(
           "damping_ratio", "", "[0, 1)", "viscous normal damping ratio β",
           [](R& r) -> double& { return r.damping_ratio; }, &TomlFields::number, unit_fraction),
       number_key<R>(
           "local_damping", "", "[0, 1)", "PFC local damping α of the preparation",
           [](R& r) -> double& { return r.local_damping; }, &TomlFields::number, unit_fraction),
       custom_key<R>("stiffness_scaling", "", "\"none\" or \"linear\"",
                     "linear: kn and ks scale with the bodies' diameters (CTGU 2017)", "\"none\"",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const std::string m = f.string(v, field);
                       if (m != "none" && m != "linear")
                         f.fail(field, "expected \"none\" or \"linear\", got " + toml_show(v));
                       r.linear_scaling = m == "linear";
                     }),
       shown_as(number_key<R>(
                    "d_ref", "m", "> 0",
                    "diameter at which kn and ks hold (stiffness_scaling = \"linear\")",
                    [](R& r) -> double& { return r.d_ref; }, &TomlFields::positive),
                "required with linear scaling")}};
  return s;
}

namespace {

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
  if (r.calibration_frictions.size() < 6)
    f.fail("calibration_frictions", "need the two end points and at least four in between, got " +
                                        std::to_string(r.calibration_frictions.size()) + " values");
  for (double mu : r.calibration_frictions)
    if (mu < 0)
      f.fail("calibration_frictions", "friction must not be negative, got " + format_number(mu));
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
  tables.strength = default_strength_factor();
  tables.cells.cell_size = 0.0065;
  r.crushable_material.fill.spheres = 6;
  r.crushable_material.fill.field.voxels = 16;
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    if (k == "target_relative_density" || k == "layers" || k == "calibration_frictions")
      seen.deposition_keys.push_back(k);
    if (k == "seed") {
      const long long s = f.integer(val, k);
      if (s < 0) f.fail(k, "must be non-negative, got " + toml_show(val));
      r.seed = static_cast<std::uint64_t>(s);
    } else if (k == "name" || k == "description") {
      f.string(val, k);
    } else if (k == "container") {
      read_container(f, val, r, seen);
    } else if (k == "preparation") {
      read_preparation(f, val, r);
    } else if (k == "zones") {
      seen.zones = true;
      read_zones(f, val, r, seen.zone_origin);
    } else if (k == "gradation") {
      seen.gradation = true;
      read_gradation(f, val, r);
    } else if (k == "soil_rock_threshold") {
      r.soil_rock_threshold = f.positive(val, k);
    } else if (k == "rock_mass_fraction") {
      r.rock_mass_fraction = f.number(val, k);
      if (r.rock_mass_fraction < 0 || r.rock_mass_fraction > 1)
        f.fail(k, "must be in [0, 1], got " + toml_show(val));
    } else if (k == "fines") {
      read_fines(f, val, r);
    } else if (k == "rock") {
      read_rock(f, val, r);
    } else if (k == "cells" || k == "bond") {
      (k == "cells" ? seen.cells : seen.bond) = true;
      if (k == "cells")  // the crushing recipes' tables
        read_cells_table(f, f.table(val, k), tables);
      else
        read_bond_table(f, f.table(val, k), tables);
    } else if (k == "density") {
      read_section(f, val, density_section(), r);
    } else if (k == "contact") {
      read_section(f, val, contact_section(), r);
    } else if (k == "target_relative_density") {
      r.target_relative_density = f.number(val, k);
      if (r.target_relative_density < 0 || r.target_relative_density > 1)
        f.fail(k, "must be in [0, 1], got " + toml_show(val));
    } else if (k == "layers") {
      const long long n = f.integer(val, k);
      if (n < 1 || n > 100) f.fail(k, "must be in [1, 100], got " + toml_show(val));
      r.layers = static_cast<int>(n);
    } else if (k == "calibration_frictions") {
      r.calibration_frictions = f.numbers(val, k);
    } else {
      f.fail(
          k,
          "unknown key (known: seed, name, description, container, gradation, soil_rock_threshold, "
          "rock_mass_fraction, fines, rock, cells, bond, density, contact, preparation, zones, "
          "target_relative_density, layers, calibration_frictions)");
    }
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
