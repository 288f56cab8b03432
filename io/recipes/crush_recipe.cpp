#include "io/recipes/crush_recipe.h"

#include "dem/core/body.h"
#include "dem/core/contact.h"
#include "dem/lab/weibull.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/limits.h"
#include "geom/random.h"
#include "geom/shapes/primitives.h"
#include "io/base/text.h"
#include "io/recipes/section_table.h"
#include "io/recipes/toml_fields.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <utility>

namespace clumpkit {

namespace {

// A number in (0, 1): "must be in (0, 1), got VALUE" otherwise.
void open_fraction(const TomlFields& f, const std::string& field, const toml::node& v, double x) {
  if (!(x > 0 && x < 1)) f.fail(field, "must be in (0, 1), got " + toml_show(v));
}

// An integer key in [lo, hi] (TomlFields::integer_in's message) landing in the int `at(spec)`,
// its default read off the defaults as number_key does for a double.
template <class Spec, class At>
RecipeKey<Spec> integer_in_key(std::string name, std::string help, At at, long long lo,
                               long long hi) {
  RecipeKey<Spec> k{std::move(name), "", "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                    std::move(help), {}, {}};
  k.read = [at, lo, hi](const TomlFields& f, const toml::node& v, const std::string& field,
                        Spec& s) { at(s) = f.integer_in(v, field, lo, hi); };
  k.shown = [at](const Spec& defaults) {
    Spec copy = defaults;
    return std::to_string(at(copy));
  };
  return k;
}

}  // namespace

const RecipeSection<CrushRecipe>& crush_section() {
  using R = CrushRecipe;
  static const RecipeSection<R> s{
      "crush",
      "The rig of `clumpkit crush`: rigid platens closing on one particle at a constant strain "
      "rate (Hu et al. 2023), the peak rule, and the statistics.",
      {range_key<R>("seed", "", kSeed, "seed of every random draw of the run",
                    [](R& r) -> std::uint64_t& { return r.seed; }),
       range_key<R>("density", "kg/m³", dem::kDensity, "particle density",
                    [](R& r) -> double& { return r.density; }),
       range_key<R>("strain_rate", "1/s", dem::kCrushStrainRate,
                    "closing speed over the initial gap",
                    [](R& r) -> double& { return r.rig.strain_rate; }),
       range_key<R>("platen_friction", "", dem::kFriction, "μ of cell–platen contacts",
                    [](R& r) -> double& { return r.rig.platen_friction; }),
       range_key<R>("platen_stiffness", "N/m", dem::kPlatenStiffness,
                    "normal and shear stiffness of a corner on a platen",
                    [](R& r) -> double& { return r.rig.platen_stiffness; }),
       range_key<R>("local_damping", "", dem::kLocalDamping, "PFC local damping α of every cell",
                    [](R& r) -> double& { return r.rig.local_damping; }),
       range_key<R>("timestep_safety", "", dem::kTimestepSafety, "time step over the critical one",
                    [](R& r) -> double& { return r.rig.timestep_safety; }),
       range_key<R>("density_scaling", "", dem::kDensityScaling,
                    "every cell's mass and moments × λ (time step × √λ; reported)",
                    [](R& r) -> double& { return r.rig.density_scaling; }),
       range_key<R>("max_strain", "", dem::kCrushMaxStrain,
                    "platen travel over the gap at which a test stops without a failure",
                    [](R& r) -> double& { return r.rig.max_strain; }),
       number_key<R>(
           "sample_strain", "", "(0, max_strain)", "travel between samples over the gap",
           [](R& r) -> double& { return r.rig.sample_strain; }, &TomlFields::number, open_fraction),
       range_key<R>("drop", "", dem::kPeakDrop,
                    "the load drop, as a fraction of the running peak, that marks failure",
                    [](R& r) -> double& { return r.rig.rule.drop; }),
       range_key<R>("intact_fraction", "", dem::kIntactFraction,
                    "split once no fragment holds this fraction of the particle's mass",
                    [](R& r) -> double& { return r.rig.intact_fraction; }),
       range_key<R>("bed_depth", "", dem::kBedDepth,
                    "the seat: cells within this fraction of the gap above the lower platen do "
                    "not rotate (a bedded end); 0 for none",
                    [](R& r) -> double& { return r.rig.bed_depth; }),
       range_key<R>("bootstrap", "", dem::kBootstrapResamples,
                    "bootstrap resamples of the Weibull fits' 90 % intervals",
                    [](R& r) -> int& { return r.bootstrap; })}};
  return s;
}

namespace {

void read_crush(const TomlFields& f, const toml::node& t, CrushRecipe& r) {
  read_section(f, t, crush_section(), r);
  if (!(r.rig.sample_strain < r.rig.max_strain))
    f.fail("crush.sample_strain", "must be below crush.max_strain");
}

}  // namespace

const RecipeSection<CrushRecipe>& cells_section() {
  using R = CrushRecipe;
  static const RecipeSection<R> s{
      "cells",
      "The Voronoi cells a parent is cut into (as `clumpkit cells`) and the spread of their "
      "bonds' strengths; a crushable specimen's recipe reads the same table.",
      {range_key<R>("cell_size", "m", kCellSize,
                    "a cell's volume-equivalent diameter ℓ: a parent of diameter D gets "
                    "round((D/ℓ)³) cells",
                    [](R& r) -> double& { return r.cells.cell_size; }),
       range_key<R>(
           "lloyd", "", kLloydSteps,
           "Lloyd steps moving each seed to its cell's centroid (0: raw Poisson–Voronoi cells)",
           [](R& r) -> int& { return r.cells.lloyd; }),
       range_key<R>("face_subdivision", "", kFaceSubdivisions,
                    "s: each fan triangle of a face splits into 4^s integration points (a "
                    "numerical control)",
                    [](R& r) -> int& { return r.face_subdivision; }),
       [] {
         auto k = custom_key<R>(
             "strength_factor", "", "a number or distribution drawing factors > 0",
             "factor on each bond's strengths, drawn per face", "",
             [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
               r.strength = f.distribution(v, field);
               try {
                 validate(r.strength, field);
               } catch (const InvalidInput& e) {
                 f.fail(field, e.what());
               }
               if (!(lower_bound(r.strength) > 0))
                 f.fail(field, "must draw positive factors (set min > 0), got " + toml_show(v));
             });
         k.shown = [](const R& defaults) { return describe(defaults.strength); };
         return k;
       }()}};
  return s;
}

void read_cells_table(const TomlFields& f, const toml::table& t, CrushRecipe& r) {
  read_section(f, t, cells_section(), r);
}

const RecipeSection<CrushRecipe>& bond_section() {
  using R = CrushRecipe;
  static const RecipeSection<R> s{
      "bond",
      "The cohesive law of the bonds between cells (Hu et al. 2023 eqs. 5–11; defaults: their "
      "granite), per unit area; checked by dem::validate_values as read and by dem::validate once "
      "`scale` is applied.",
      {range_key<R>("kn", "N/m³", dem::kBondStiffness, "K_I, normal stiffness",
                    [](R& r) -> double& { return r.law.kn; }),
       range_key<R>("kt", "N/m³", dem::kBondStiffness, "K_II, shear stiffness",
                    [](R& r) -> double& { return r.law.kt; }),
       range_key<R>("sigma_n", "Pa", dem::kBondStrength, "σ_eI, tensile strength (× scale)",
                    [](R& r) -> double& { return r.law.sigma_n; }),
       range_key<R>("sigma_t", "Pa", dem::kBondStrength, "σ_eII, shear strength (× scale)",
                    [](R& r) -> double& { return r.law.sigma_t; }),
       number_key<R>("g_n", "J/m²", "> σ_eI²/(2 K_I)", "G_I, mode I fracture energy (× scale²)",
                     [](R& r) -> double& { return r.law.g_n; }),
       number_key<R>("g_t", "J/m²", "> σ_eII²/(2 K_II)", "G_II, mode II fracture energy (× scale²)",
                     [](R& r) -> double& { return r.law.g_t; }),
       range_key<R>("friction", "", dem::kFriction,
                    "Coulomb coefficient of a damaged face in compression",
                    [](R& r) -> double& { return r.law.friction; }),
       range_key<R>("scale", "", dem::kBondScale,
                    "calibration factor s: strengths × s, energies × s² (the Brazilian "
                    "calibration of crush-brazilian.toml gives 1.85)",
                    [](R& r) -> double& { return r.scale; })}};
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

const std::vector<RecipeKey<PolyhedronParams>>& polyhedron_keys() {
  using P = PolyhedronParams;
  // Each key is read in its range of validate(PolyhedronParams) (geom/shapes/polyhedron.h);
  // offset_max, read in kPlaneOffset, is checked against offset_min by validate, which the set
  // and [rock] call on the values read, naming the set or [rock].
  static const std::vector<RecipeKey<P>> keys{
      range_key<P>("planes", "", kPolyhedronPlanes,
                   "random planes cutting the sphere (Hu et al. 2023; 0: the faceted sphere)",
                   [](P& p) -> int& { return p.planes; }),
      range_key<P>("E", "", kAxisRatio, "elongation I/L the parent is stretched to",
                   [](P& p) -> double& { return p.E; }),
      range_key<P>("F", "", kAxisRatio, "flatness S/I the parent is stretched to",
                   [](P& p) -> double& { return p.F; }),
      range_key<P>("offset_min", "", kPlaneOffset,
                   "nearest a plane passes to the centre, over the sphere's radius",
                   [](P& p) -> double& { return p.offset_min; }),
      [] {
        auto k = range_key<P>("offset_max", "", kPlaneOffset,
                              "farthest a plane passes from the centre, over the sphere's radius",
                              [](P& p) -> double& { return p.offset_max; });
        k.range = "[offset_min, 1]";
        return k;
      }()};
  return keys;
}

bool read_polyhedron_key(const TomlFields& f, const std::string& key, const toml::node& v,
                         const std::string& field, PolyhedronParams& p) {
  for (const auto& k : polyhedron_keys())
    if (k.name == key) {
      k.read(f, v, field, p);
      return true;
    }
  return false;
}

namespace {

// [[set]] shape: "polyhedron" or "cylinder".
void read_shape(const TomlFields& f, const toml::node& v, const std::string& field, CrushSet& s) {
  s.shape = f.string(v, field);
  if (s.shape != "polyhedron" && s.shape != "cylinder")
    f.fail(field, "expected \"polyhedron\" or \"cylinder\", got " + toml_show(v));
}

// [[set]] axis: by the parent's axes or by the frame's letters.
void read_axis(const TomlFields& f, const toml::node& v, const std::string& field, CrushSet& s) {
  static const std::pair<const char*, int> names[] = {
      {"long", 0}, {"x", 0}, {"intermediate", 1}, {"y", 1}, {"short", 2}, {"z", 2}};
  const std::string a = f.string(v, field);
  for (const auto& [name, axis] : names)
    if (a == name) {
      s.axis = axis;
      return;
    }
  f.fail(field, "expected long, intermediate, short, x, y or z, got " + toml_show(v));
}

}  // namespace

const RecipeSection<CrushSet>& set_section() {
  using S = CrushSet;
  static const RecipeSection<S> s = [] {
    RecipeSection<S> t{
        "set",
        "One set of samples of `clumpkit crush`: a parent shape drawn per sample, loaded along "
        "one axis (one [[set]] per size or shape).",
        {custom_key<S>(
             "name", "", "non-empty, unique", "the set's name in the report", "required",
             [](const TomlFields& f, const toml::node& v, const std::string& field, S& s) {
               s.name = f.string(v, field);
               if (s.name.empty()) f.fail(field, "must not be empty");
             }),
         custom_key<S>("shape", "", "\"polyhedron\" or \"cylinder\"",
                       "a sphere cut by random planes (Hu et al. 2023), or a cylinder (the "
                       "Brazilian test)",
                       "\"polyhedron\"", read_shape),
         shown_as(range_key<S>("diameter", "m", kSize,
                               "volume-equivalent diameter D of a polyhedron; a cylinder's "
                               "diameter",
                               [](S& s) -> double& { return s.polyhedron.diameter; }),
                  "required"),
         integer_in_key<S>(
             "samples", "particles crushed", [](S& s) -> int& { return s.samples; }, 3, 100000),
         custom_key<S>("axis", "", "\"long\", \"intermediate\", \"short\", \"x\", \"y\" or \"z\"",
                       "loading axis of the parent's frame (long = x, intermediate = y, short = "
                       "z; a cylinder's axis is z)",
                       "\"short\"", read_axis),
         custom_key<S>(
             "rest", "", "\"face\" or \"corner\"",
             "face: the parent turned so that its largest face within 30° of the lower "
             "platen lies flat on it; corner: as drawn",
             "\"face\"",
             [](const TomlFields& f, const toml::node& v, const std::string& field, S& s) {
               const std::string a = f.string(v, field);
               if (a != "face" && a != "corner")
                 f.fail(field, "expected \"face\" or \"corner\", got " + toml_show(v));
               s.rest_on_face = a == "face";
             }),
         custom_key<S>(
             "size_law", "", "true or false",
             "part of the size law σ0 = k·D^−α fitted over the sets", "true",
             [](const TomlFields& f, const toml::node& v, const std::string& field, S& s) {
               const auto* b = v.as_boolean();
               if (!b) f.fail(field, "expected true or false, got " + toml_show(v));
               s.size_law = b->get();
             })}};
    for (const auto& k : polyhedron_keys())
      t.keys.push_back(nested_key<S>(k, [](S& s) -> PolyhedronParams& { return s.polyhedron; }));
    t.keys.push_back(shown_as(range_key<S>("height", "m", kSize, "cylinder height",
                                           [](S& s) -> double& { return s.height; }),
                              "required for a cylinder"));
    t.keys.push_back(range_key<S>("sides", "", kCylinderSides, "facets of a cylinder",
                                  [](S& s) -> int& { return s.sides; }));
    return t;
  }();
  return s;
}

namespace {

// One [[set]], its fields named "set[i].KEY": the table read under that name.
CrushSet read_set(const TomlFields& f, const toml::node& t, const std::string& prefix) {
  RecipeSection<CrushSet> named = set_section();
  named.name = prefix;
  CrushSet s;
  const std::vector<std::string> given = read_section(f, t, named, s);
  if (s.name.empty()) f.fail(prefix + ".name", "is required");
  if (std::find(given.begin(), given.end(), "diameter") == given.end())
    f.fail(prefix + ".diameter", "is required (m)");
  if (s.shape == "polyhedron") {
    try {
      validate(s.polyhedron);
    } catch (const InvalidInput& e) {
      f.fail(prefix, e.what());
    }
  }
  if (s.shape == "cylinder" && !(s.height > 0))
    f.fail(prefix + ".height", "is required for a cylinder (m)");
  return s;
}

void read_sets(const TomlFields& f, const toml::node& val, CrushRecipe& r) {
  const auto* sets = val.as_array();
  if (!sets) f.fail("set", "expected [[set]] tables, got " + toml_show(val));
  for (std::size_t i = 0; i < sets->size(); ++i)
    r.sets.push_back(read_set(f, (*sets)[i], "set[" + std::to_string(i) + "]"));
}

}  // namespace

CrushRecipe parse_crush_recipe(const std::string& text, const std::string& path) {
  const TomlFields f{path};
  const toml::table root = parse_toml(text, path);
  CrushRecipe r;
  r.path = path;
  r.text = text;
  // The top level: each key's reader, in the order the unknown-key message lists them.
  const TopLevelReaders top{
      {"name", [&](const toml::node& v) { r.name = f.string(v, "name"); }},
      {"description", [&](const toml::node& v) { f.string(v, "description"); }},
      {"crush", [&](const toml::node& v) { read_crush(f, f.table(v, "crush"), r); }},
      {"cells", [&](const toml::node& v) { read_cells_table(f, f.table(v, "cells"), r); }},
      {"bond", [&](const toml::node& v) { read_bond_table(f, f.table(v, "bond"), r); }},
      {"set", [&](const toml::node& v) { read_sets(f, v, r); }}};
  read_top_level(f, root, top);
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
