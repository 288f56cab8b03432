#include "io/recipes/crush_recipe.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/text.h"
#include "io/recipes/section_table.h"
#include "io/recipes/toml_fields.h"

#include <cmath>
#include <set>

namespace clumpkit {

namespace {

// A number in (0, 1): "must be in (0, 1), got VALUE" otherwise.
void open_fraction(const TomlFields& f, const std::string& field, const toml::node& v, double x) {
  if (!(x > 0 && x < 1)) f.fail(field, "must be in (0, 1), got " + toml_show(v));
}

}  // namespace

const RecipeSection<CrushRecipe>& crush_section() {
  using R = CrushRecipe;
  static const RecipeSection<R> s{
      "crush",
      "The rig of `clumpkit crush`: rigid platens closing on one particle at a constant strain "
      "rate (Hu et al. 2023), the peak rule, and the statistics.",
      {custom_key<R>("seed", "", ">= 0", "seed of every random draw of the run", "1",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const long long n = f.integer(v, field);
                       if (n < 0) f.fail(field, "must be non-negative, got " + toml_show(v));
                       r.seed = static_cast<std::uint64_t>(n);
                     }),
       number_key<R>(
           "density", "kg/m³", "> 0", "particle density", [](R& r) -> double& { return r.density; },
           &TomlFields::positive),
       number_key<R>(
           "strain_rate", "1/s", "> 0", "closing speed over the initial gap",
           [](R& r) -> double& { return r.rig.strain_rate; }, &TomlFields::positive),
       number_key<R>(
           "platen_friction", "", ">= 0", "μ of cell–platen contacts",
           [](R& r) -> double& { return r.rig.platen_friction; }, &TomlFields::non_negative),
       number_key<R>(
           "platen_stiffness", "N/m", "> 0", "normal and shear stiffness of a corner on a platen",
           [](R& r) -> double& { return r.rig.platen_stiffness; }, &TomlFields::positive),
       number_key<R>(
           "local_damping", "", "[0, 1)", "PFC local damping α of every cell",
           [](R& r) -> double& { return r.rig.local_damping; }, &TomlFields::non_negative,
           below(1.0, "must be below 1")),
       number_key<R>(
           "timestep_safety", "", "(0, 0.5]", "time step over the critical one",
           [](R& r) -> double& { return r.rig.timestep_safety; }, &TomlFields::positive,
           at_most(0.5, "must be at most 0.5")),
       number_key<R>(
           "density_scaling", "", "[1, 1e6]",
           "every cell's mass and moments × λ (time step × √λ; reported)",
           [](R& r) -> double& { return r.rig.density_scaling; }, &TomlFields::number,
           [](const TomlFields& f, const std::string& field, const toml::node& v, double x) {
             if (!(x >= 1 && x <= 1e6)) f.fail(field, "must be in [1, 1e6], got " + toml_show(v));
           }),
       number_key<R>(
           "max_strain", "", "(0, 1)",
           "platen travel over the gap at which a test stops without a failure",
           [](R& r) -> double& { return r.rig.max_strain; }, &TomlFields::number, open_fraction),
       number_key<R>(
           "sample_strain", "", "(0, max_strain)", "travel between samples over the gap",
           [](R& r) -> double& { return r.rig.sample_strain; }, &TomlFields::number, open_fraction),
       number_key<R>(
           "drop", "", "(0, 1)",
           "the load drop, as a fraction of the running peak, that marks failure",
           [](R& r) -> double& { return r.rig.rule.drop; }, &TomlFields::number, open_fraction),
       number_key<R>(
           "intact_fraction", "", "(0.5, 1)",
           "split once no fragment holds this fraction of the particle's mass",
           [](R& r) -> double& { return r.rig.intact_fraction; }, &TomlFields::number,
           [](const TomlFields& f, const std::string& field, const toml::node& v, double x) {
             open_fraction(f, field, v, x);
             if (x <= 0.5) f.fail(field, "must be above 0.5, got " + toml_show(v));
           }),
       number_key<R>(
           "bed_depth", "", "[0, 0.5)",
           "the seat: cells within this fraction of the gap above the lower platen do not "
           "rotate (a bedded end); 0 for none",
           [](R& r) -> double& { return r.rig.bed_depth; }, &TomlFields::non_negative,
           below(0.5, "must be below 0.5")),
       custom_key<R>("bootstrap", "", "[100, 100000]",
                     "bootstrap resamples of the Weibull fits' 90 % intervals", "1000",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       r.bootstrap = f.integer_in(v, field, 100, 100000);
                     })}};
  return s;
}

namespace {

void read_crush(const TomlFields& f, const toml::node& t, CrushRecipe& r) {
  read_section(f, t, crush_section(), r);
  if (!(r.rig.sample_strain < r.rig.max_strain))
    f.fail("crush.sample_strain", "must be below crush.max_strain");
}

}  // namespace

void read_cells_table(const TomlFields& f, const toml::table& t, CrushRecipe& r) {
  for (const auto& [key, v] : t) {
    const std::string k(key.str()), field = "cells." + k;
    if (k == "cell_size") {
      r.cells.cell_size = f.positive(v, field);
    } else if (k == "lloyd") {
      r.cells.lloyd = f.integer_in(v, field, 0, 100);
    } else if (k == "face_subdivision") {
      r.face_subdivision = f.integer_in(v, field, 0, 3);
    } else if (k == "strength_factor") {
      r.strength = f.distribution(v, field);
      try {
        validate(r.strength, field);
      } catch (const InvalidInput& e) {
        f.fail(field, e.what());
      }
      if (!(lower_bound(r.strength) > 0))
        f.fail(field, "must draw positive factors (set min > 0), got " + toml_show(v));
    } else {
      f.fail(field, "unknown key (known: cell_size, lloyd, face_subdivision, strength_factor)");
    }
  }
}

const RecipeSection<CrushRecipe>& bond_section() {
  using R = CrushRecipe;
  static const RecipeSection<R> s{
      "bond",
      "The cohesive law of the bonds between cells (Hu et al. 2023 eqs. 5–11; defaults: their "
      "granite), per unit area; checked by dem::validate_values as read and by dem::validate once "
      "`scale` is applied.",
      {number_key<R>("kn", "N/m³", "> 0", "K_I, normal stiffness",
                     [](R& r) -> double& { return r.law.kn; }),
       number_key<R>("kt", "N/m³", "> 0", "K_II, shear stiffness",
                     [](R& r) -> double& { return r.law.kt; }),
       number_key<R>("sigma_n", "Pa", "> 0", "σ_eI, tensile strength (× scale)",
                     [](R& r) -> double& { return r.law.sigma_n; }),
       number_key<R>("sigma_t", "Pa", "> 0", "σ_eII, shear strength (× scale)",
                     [](R& r) -> double& { return r.law.sigma_t; }),
       number_key<R>("g_n", "J/m²", "> σ_eI²/(2 K_I)", "G_I, mode I fracture energy (× scale²)",
                     [](R& r) -> double& { return r.law.g_n; }),
       number_key<R>("g_t", "J/m²", "> σ_eII²/(2 K_II)", "G_II, mode II fracture energy (× scale²)",
                     [](R& r) -> double& { return r.law.g_t; }),
       number_key<R>("friction", "", ">= 0", "Coulomb coefficient of a damaged face in compression",
                     [](R& r) -> double& { return r.law.friction; }),
       number_key<R>(
           "scale", "", "> 0",
           "calibration factor s: strengths × s, energies × s² (the Brazilian "
           "calibration of crush-brazilian.toml gives 1.85)",
           [](R& r) -> double& { return r.scale; }, &TomlFields::positive)}};
  return s;
}

void read_bond_table(const TomlFields& f, const toml::node& t, CrushRecipe& r) {
  read_section(f, t, bond_section(), r);
  try {
    dem::validate_values(r.law);
  } catch (const InvalidInput& e) {
    f.fail("bond", e.what());
  }
}

void apply_bond_scale(const TomlFields& f, CrushRecipe& r) {
  // The calibration factor s (the paper's single factor on σ and G): strengths × s, energies ×
  // s², so that the openings at onset and at failure both scale by s and the softening keeps its
  // shape (G × s would leave less than the elastic energy at onset for s above about 1.1).
  r.law.sigma_n *= r.scale;
  r.law.sigma_t *= r.scale;
  r.law.g_n *= r.scale * r.scale;
  r.law.g_t *= r.scale * r.scale;
  try {
    dem::validate(r.law, upper_bound(r.strength));
  } catch (const InvalidInput& e) {
    f.fail("bond", e.what());
  }
}

namespace {}  // namespace

bool read_polyhedron_key(const TomlFields& f, const std::string& key, const toml::node& v,
                         const std::string& field, PolyhedronParams& p) {
  if (key == "planes")
    p.planes = f.integer_in(v, field, 4, 10000);
  else if (key == "E")
    p.E = f.number(v, field);
  else if (key == "F")
    p.F = f.number(v, field);
  else if (key == "offset_min")
    p.offset_min = f.number(v, field);
  else if (key == "offset_max")
    p.offset_max = f.number(v, field);
  else
    return false;
  return true;
}

namespace {

CrushSet read_set(const TomlFields& f, const toml::table& t, const std::string& prefix) {
  CrushSet s;
  bool have_diameter = false;
  for (const auto& [key, v] : t) {
    const std::string k(key.str()), field = prefix + "." + k;
    if (k == "name") {
      s.name = f.string(v, field);
      if (s.name.empty()) f.fail(field, "must not be empty");
    } else if (k == "shape") {
      s.shape = f.string(v, field);
      if (s.shape != "polyhedron" && s.shape != "cylinder")
        f.fail(field, "expected \"polyhedron\" or \"cylinder\", got " + toml_show(v));
    } else if (k == "diameter") {
      s.polyhedron.diameter = f.positive(v, field);
      have_diameter = true;
    } else if (k == "samples") {
      s.samples = f.integer_in(v, field, 3, 100000);
    } else if (k == "axis") {
      const std::string a = f.string(v, field);
      if (a == "long" || a == "x")
        s.axis = 0;
      else if (a == "intermediate" || a == "y")
        s.axis = 1;
      else if (a == "short" || a == "z")
        s.axis = 2;
      else
        f.fail(field, "expected long, intermediate, short, x, y or z, got " + toml_show(v));
    } else if (k == "rest") {
      const std::string a = f.string(v, field);
      if (a != "face" && a != "corner")
        f.fail(field, "expected \"face\" or \"corner\", got " + toml_show(v));
      s.rest_on_face = a == "face";
    } else if (k == "size_law") {
      const auto* b = v.as_boolean();
      if (!b) f.fail(field, "expected true or false, got " + toml_show(v));
      s.size_law = b->get();
    } else if (read_polyhedron_key(f, k, v, field, s.polyhedron)) {
    } else if (k == "height") {
      s.height = f.positive(v, field);
    } else if (k == "sides") {
      s.sides = f.integer_in(v, field, 3, 4096);
    } else {
      f.fail(field,
             "unknown key (known: name, shape, diameter, samples, axis, rest, size_law, planes, "
             "E, F, offset_min, offset_max, height, sides)");
    }
  }
  if (s.name.empty()) f.fail(prefix + ".name", "is required");
  if (!have_diameter) f.fail(prefix + ".diameter", "is required (m)");
  if (s.shape == "polyhedron") {
    try {
      validate(s.polyhedron);
    } catch (const InvalidInput& e) {
      f.fail(prefix, e.what());
    }
  } else if (!(s.height > 0)) {
    f.fail(prefix + ".height", "is required for a cylinder (m)");
  }
  return s;
}

}  // namespace

CrushRecipe parse_crush_recipe(const std::string& text, const std::string& path) {
  const TomlFields f{path};
  const toml::table root = parse_toml(text, path);
  CrushRecipe r;
  r.path = path;
  r.text = text;
  r.strength = default_strength_factor();
  r.cells.cell_size = 0.0065;
  for (const auto& [key, val] : root) {
    const std::string k(key.str());
    if (k == "name") {
      r.name = f.string(val, k);
    } else if (k == "description") {
      f.string(val, k);
    } else if (k == "crush") {
      read_crush(f, f.table(val, k), r);
    } else if (k == "cells") {
      read_cells_table(f, f.table(val, k), r);
    } else if (k == "bond") {
      read_bond_table(f, f.table(val, k), r);
    } else if (k == "set") {
      const auto* sets = val.as_array();
      if (!sets) f.fail(k, "expected [[set]] tables, got " + toml_show(val));
      for (std::size_t i = 0; i < sets->size(); ++i) {
        const std::string prefix = "set[" + std::to_string(i) + "]";
        r.sets.push_back(read_set(f, f.table((*sets)[i], prefix), prefix));
      }
    } else {
      f.fail(k, "unknown key (known: name, description, crush, cells, bond, set)");
    }
  }
  if (r.sets.empty()) f.fail("set", "at least one [[set]] is required");
  std::set<std::string> names;
  for (std::size_t i = 0; i < r.sets.size(); ++i) {
    const CrushSet& s = r.sets[i];
    const std::string prefix = "set[" + std::to_string(i) + "]";
    if (!names.insert(s.name).second) f.fail(prefix + ".name", "repeats \"" + s.name + "\"");
    // The number of cells, before any cutting: at least 2 (voronoi_cells refuses fewer).
    const double d = s.polyhedron.diameter;
    const double d_eq = s.shape == "cylinder" ? std::cbrt(1.5 * d * d * s.height) : d;
    const double cells = std::round(std::pow(d_eq / r.cells.cell_size, 3));
    if (cells < 2)
      f.fail("cells.cell_size", format_number(r.cells.cell_size) + " leaves set \"" + s.name +
                                    "\" (diameter " + format_number(d_eq) + ") fewer than 2 cells");
    if (cells > 100000)
      f.fail("cells.cell_size", format_number(r.cells.cell_size) + " gives set \"" + s.name +
                                    "\" more than 100000 cells");
  }
  apply_bond_scale(f, r);
  return r;
}

CrushRecipe read_crush_recipe(const std::string& path) {
  return parse_crush_recipe(read_file(path, "recipe file"), path);
}

}  // namespace clumpkit
