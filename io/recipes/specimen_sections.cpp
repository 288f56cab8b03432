// The section tables of specimen recipes: each key's reader, unit, range, default and help.
#include "dem/core/body.h"
#include "dem/specimen/specimen_particles.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "geom/random.h"
#include "io/recipes/crush_recipe.h"
#include "io/recipes/section_table.h"
#include "io/recipes/specimen_recipe.h"
#include "io/recipes/toml_fields.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace clumpkit {

namespace {

using R = SpecimenRecipe;

// What parse_specimen_recipe puts in each crushable cell: a SpecimenRecipe{} holds the fill's own
// defaults, so the reference shows these instead.
constexpr int kDefaultCellSpheres = 6, kDefaultCellVoxels = 16;

// The key `k` with its default read off the spec by `show` (a default that is not one double).
template <class Spec, class Show>
RecipeKey<Spec> shown_by(RecipeKey<Spec> k, Show show) {
  k.shown = show;
  return k;
}

// "[a, b, c]" of numbers, as a default.
template <class Numbers>
std::string show_numbers(const Numbers& xs) {
  std::string s;
  for (const double x : xs) s += (s.empty() ? "" : ", ") + format_number(x);
  return "[" + s + "]";
}

bool boolean(const TomlFields& f, const toml::node& v, const std::string& field) {
  const auto* b = v.as_boolean();
  if (!b) f.fail(field, "expected true or false, got " + toml_show(v));
  return b->get();
}

// A container length (an edge of a cuboid): a number, checked by the specs' one rule
// (dem::check_container_length, in dem::kContainerLength's words).
void container_length(const TomlFields& f, const std::string& field, double x) {
  try {
    dem::check_container_length(x);
  } catch (const InvalidInput& e) {
    f.fail(field, e.what());
  }
}

// A number in [0, 1]: "must be in [0, 1], got VALUE" otherwise.
void closed_fraction(const TomlFields& f, const std::string& field, const toml::node& v, double x) {
  if (!(x >= 0 && x <= 1)) f.fail(field, "must be in [0, 1], got " + toml_show(v));
}

}  // namespace

const RecipeSection<SpecimenRecipe>& specimen_top_section() {
  static const RecipeSection<R> s{
      "",
      "Keys at the top of a specimen recipe, outside any section.",
      {range_key<R>("seed", "", kSeed, "seed of every random draw",
                    [](R& r) -> std::uint64_t& { return r.seed; }),
       custom_key<R>("name", "", "text", "the recipe's name (for the reader only)", "none",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R&) {
                       f.string(v, field);
                     }),
       custom_key<R>("description", "", "text", "what the recipe makes (for the reader only)",
                     "none",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R&) {
                       f.string(v, field);
                     }),
       range_key<R>("soil_rock_threshold", "m", dem::kSoilRockThreshold,
                    "sieve size parting rock clumps (classes above) from soil spheres (below)",
                    [](R& r) -> double& { return r.soil_rock_threshold; }),
       range_key<R>("rock_mass_fraction", "", dem::kRockMassFraction,
                    "rock mass over the total: must match the gradation above "
                    "soil_rock_threshold (1 for a crushable specimen)",
                    [](R& r) -> double& { return r.rock_mass_fraction; }),
       range_key<R>("target_relative_density", "", dem::kTargetRelativeDensity,
                    "deposition: the relative density Dr the specimen is built to",
                    [](R& r) -> double& { return r.target_relative_density; }),
       range_key<R>("layers", "", dem::kSpecimenLayers,
                    "deposition: layers the specimen is stacked from",
                    [](R& r) -> int& { return r.layers; }),
       shown_by(custom_key<R>("calibration_frictions", "",
                              "at least " + std::to_string(dem::kMinCalibrationFrictions) +
                                  " numbers, each " + dem::kFriction.text(),
                              "deposition: frictions of the quasi-vibration calibration (the "
                              "largest gives n_max, 0 gives n_min)",
                              "",
                              [](const TomlFields& f, const toml::node& v, const std::string& field,
                                 R& r) { r.calibration_frictions = f.numbers(v, field); }),
                [](const R& d) { return show_numbers(d.calibration_frictions); })}};
  return s;
}

const RecipeSection<SpecimenRecipe>& density_section() {
  static const RecipeSection<R> s{
      "density",
      "Particle densities of the specimen.",
      {range_key<R>("soil", "kg/m³", dem::kDensity, "density of the soil spheres",
                    [](R& r) -> double& { return r.soil_density; }),
       range_key<R>("rock", "kg/m³", dem::kDensity, "density of the rock clumps",
                    [](R& r) -> double& { return r.rock_density; })}};
  return s;
}

const RecipeSection<SpecimenRecipe>& contact_section() {
  static const RecipeSection<R> s{
      "contact",
      "The contact law of the specimen (linear spring, dashpot and Coulomb friction; "
      "dem/core/contact.h).",
      {range_key<R>("kn", "N/m", dem::kNormalStiffness,
                    "normal stiffness (at d_ref with linear scaling)",
                    [](R& r) -> double& { return r.kn; }),
       range_key<R>("ks", "N/m", dem::kShearStiffness,
                    "shear stiffness (at d_ref with linear scaling)",
                    [](R& r) -> double& { return r.ks; }),
       range_key<R>("friction", "", dem::kFriction, "interparticle μ",
                    [](R& r) -> double& { return r.friction; }),
       range_key<R>("damping_ratio", "", dem::kDampingRatio, "viscous normal damping ratio β",
                    [](R& r) -> double& { return r.damping_ratio; }),
       range_key<R>("local_damping", "", dem::kLocalDamping,
                    "PFC local damping α of the preparation",
                    [](R& r) -> double& { return r.local_damping; }),
       custom_key<R>("stiffness_scaling", "", "\"none\" or \"linear\"",
                     "linear: kn and ks scale with the bodies' diameters (CTGU 2017)", "\"none\"",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const std::string m = f.string(v, field);
                       if (m != "none" && m != "linear")
                         f.fail(field, "expected \"none\" or \"linear\", got " + toml_show(v));
                       r.linear_scaling = m == "linear";
                     }),
       shown_as(range_key<R>("d_ref", "m", dem::kReferenceDiameter,
                             "diameter at which kn and ks hold (stiffness_scaling = \"linear\")",
                             [](R& r) -> double& { return r.d_ref; }),
                "required with linear scaling")}};
  return s;
}

const RecipeSection<SpecimenRecipe>& container_section() {
  static const RecipeSection<R> s{
      "container",
      "The container the specimen is made in (dem::check_container_length checks every length).",
      {custom_key<R>("shape", "", "\"cylinder\", \"cuboid\" or \"segment\"",
                     "cylinder: diameter and height; cuboid: size; segment: the sector of angle "
                     "of the cylinder, cut by two frictionless planes through its axis (cuboid "
                     "and segment with preparation.method = \"compression\" only)",
                     "\"cylinder\"",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const std::string shape = f.string(v, field);
                       if (shape != "cylinder" && shape != "cuboid" && shape != "segment")
                         f.fail(field, "expected \"cylinder\", \"cuboid\" or \"segment\", got " +
                                           toml_show(v));
                       r.cuboid = shape == "cuboid";
                       r.segment = shape == "segment";
                     }),
       range_key<R>("diameter", "m", dem::kContainerLength, "diameter of a cylinder or segment",
                    [](R& r) -> double& { return r.container_diameter; }),
       range_key<R>("height", "m", dem::kContainerLength, "height of a cylinder or segment",
                    [](R& r) -> double& { return r.container_height; }),
       shown_by(custom_key<R>(
                    "size", "m", "[x, y, z], each > 0", "edges of a cuboid", "",
                    [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                      const std::vector<double> e = f.numbers(v, field);
                      if (e.size() != 3)
                        f.fail(field, "expected [x, y, z] edges, got " + toml_show(v));
                      for (int a = 0; a < 3; ++a) {
                        container_length(f, field + "[" + std::to_string(a) + "]", e[a]);
                        r.container_size[a] = e[a];
                      }
                    }),
                [](const R& d) { return show_numbers(d.container_size); }),
       range_key<R>("angle", "degree", dem::kSegmentAngleDegrees, "a segment's angle",
                    [](R& r) -> double& { return r.segment_angle_deg; })}};
  return s;
}

const RecipeSection<SpecimenRecipe>& preparation_section() {
  static const RecipeSection<R> s{
      "preparation",
      "How the specimen is made: deposition under gravity (Jin et al. 2017) or compression of a "
      "loose packing with gravity off (dem/specimen/compression.h).",
      {custom_key<R>("method", "", "\"deposition\" or \"compression\"",
                     "deposition: quasi-vibration calibration and layers; compression: a loose "
                     "random packing compressed to porosity at friction (specimens for element "
                     "tests)",
                     "\"deposition\"",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const std::string m = f.string(v, field);
                       if (m != "deposition" && m != "compression")
                         f.fail(field,
                                "expected \"deposition\" or \"compression\", got " + toml_show(v));
                       r.compression = m == "compression";
                     }),
       range_key<R>("porosity", "", dem::kTargetPorosity, "compression: the target porosity",
                    [](R& r) -> double& { return r.compression_porosity; }),
       range_key<R>("friction", "", dem::kFriction,
                    "compression: interparticle μ while compressing (0: the densest packing the "
                    "porosity allows); the specimen keeps contact.friction",
                    [](R& r) -> double& { return r.compression_friction; })}};
  return s;
}

const RecipeSection<dem::ZoneRegion>& zone_region_section() {
  using Z = dem::ZoneRegion;
  static const RecipeSection<Z> s{
      "zones.region",
      "One [[zones.region]] table, innermost first: a uniform zone (the core gradation × scale) "
      "or a mixed layer holding both neighbours' particles.",
      {shown_as(range_key<Z>("outer", "m", dem::kZoneOuter, "the region's outer bound",
                             [](Z& z) -> double& { return z.outer; }),
                "required"),
       range_key<Z>("scale", "", dem::kZoneScale,
                    "uniform zone: size factor λ of the gradation (the core's is 1)",
                    [](Z& z) -> double& { return z.scale; }),
       custom_key<Z>("mixed", "", "true or false",
                     "a mixed layer: its neighbours' particles, no scale", "false",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, Z& z) {
                       z.mixed = boolean(f, v, field);
                     }),
       custom_key<Z>("small_volume_fraction", "", "[0, 1], or [inner, outer] each in [0, 1]",
                     "mixed layer: the small particles' share of the solid volume (a pair: "
                     "linear from the inner to the outer bound)",
                     "required with mixed",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, Z& z) {
                       if (v.is_array()) {
                         const std::vector<double> ends = f.numbers(v, field);
                         if (ends.size() != 2)
                           f.fail(field,
                                  "expected one number or [inner, outer], got " + toml_show(v));
                         z.small_fraction = ends[0], z.small_fraction_outer = ends[1];
                       } else {
                         z.small_fraction = z.small_fraction_outer = f.number(v, field);
                       }
                       for (const double x : {z.small_fraction, z.small_fraction_outer})
                         closed_fraction(f, field, v, x);
                     })}};
  return s;
}

namespace {

// One [[zones.region]] table at `at` ("zones.region[i]"), with the checks across its keys.
dem::ZoneRegion zone_region(const TomlFields& f, const toml::node& n, const std::string& at) {
  RecipeSection<dem::ZoneRegion> s = zone_region_section();
  s.name = at;  // fields named by the region's place in the array
  dem::ZoneRegion z;
  const std::vector<std::string> given = read_section(f, n, s, z);
  auto has = [&](const char* k) { return std::find(given.begin(), given.end(), k) != given.end(); };
  if (!has("outer")) f.fail(at + ".outer", "missing (the region's outer bound, m)");
  if (z.mixed && has("scale"))
    f.fail(at + ".scale", "a mixed layer takes its neighbours' sizes, not a scale");
  if (z.mixed && !has("small_volume_fraction"))
    f.fail(at + ".small_volume_fraction", "missing (the small particles' share of the layer)");
  if (!z.mixed && has("small_volume_fraction"))
    f.fail(at + ".small_volume_fraction", "is for mixed layers (mixed = true)");
  return z;
}

void read_coordinate(const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
  static const std::pair<const char*, dem::ZoneCoordinate> names[] = {
      {"radial", dem::ZoneCoordinate::radial},
      {"depth", dem::ZoneCoordinate::depth},
      {"spherical", dem::ZoneCoordinate::spherical}};
  const std::string c = f.string(v, field);
  for (const auto& [name, coordinate] : names)
    if (c == name) {
      r.zones.coordinate = coordinate;
      return;
    }
  f.fail(field, "expected \"radial\", \"depth\" or \"spherical\", got " + toml_show(v));
}

}  // namespace

const RecipeSection<SpecimenRecipe>& zones_section() {
  static const RecipeSection<R> s{
      "zones",
      "Variable particle-size zones (CTGU 2017; compression only; dem/specimen/zones.h).",
      {custom_key<R>("coordinate", "", "\"radial\", \"depth\" or \"spherical\"",
                     "what the regions' bounds measure: distance to the vertical axis through "
                     "origin, depth below origin's z, or distance to origin",
                     "\"radial\"", read_coordinate),
       custom_key<R>("origin", "m", "[x, y, z]", "the axis's point, the surface or the centre",
                     "the axis (radial), the container's top (depth); required for spherical",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const std::vector<double> o = f.numbers(v, field);
                       if (o.size() != 3)
                         f.fail(field, "expected [x, y, z] in m, got " + toml_show(v));
                       r.zones.origin = Vec3(o[0], o[1], o[2]);
                     }),
       shown_as(range_key<R>("mixed_porosity", "", dem::kTargetPorosity,
                             "target porosity of the mixed layers",
                             [](R& r) -> double& { return r.mixed_porosity; }),
                "preparation.porosity"),
       custom_key<R>("region", "", "[[zones.region]] tables, innermost first",
                     "the regions (see [zones.region])", "required (at least the core)",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       const auto* a = v.as_array();
                       if (!a || a->empty())
                         f.fail(field, "expected [[zones.region]] tables, innermost first, got " +
                                           toml_show(v));
                       for (std::size_t i = 0; i < a->size(); ++i)
                         r.zones.regions.push_back(zone_region(
                             f, *a->get(i), "zones.region[" + std::to_string(i + 1) + "]"));
                     })}};
  return s;
}

const RecipeSection<SpecimenRecipe>& gradation_section() {
  static const RecipeSection<R> s{
      "gradation",
      "The grading curve by mass (required); its classes run between neighbouring sieves, and "
      "what passes the finest sieve is one more class.",
      {custom_key<R>("sieves", "m", "> 0, decreasing, at least 2", "sieve sizes", "required",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       r.sieves = f.numbers(v, field);
                     }),
       custom_key<R>("passing", "%", "from 100, not increasing, >= 0, one per sieve",
                     "percent passing each sieve", "required",
                     [](const TomlFields& f, const toml::node& v, const std::string& field, R& r) {
                       r.passing = f.numbers(v, field);
                     })}};
  return s;
}

const RecipeSection<SpecimenRecipe>& fines_section() {
  static const RecipeSection<R> s{
      "fines",
      "Soil finer than `below` is replaced by the same mass of spheres in `replace_with`.",
      {range_key<R>("below", "m", dem::kFinesBelow, "size below which soil counts as fines",
                    [](R& r) -> double& { return r.fines_below; }),
       shown_by(custom_key<R>("replace_with", "m", "[low, high], 0 < low < high",
                              "size range of the spheres that replace the fines", "",
                              [](const TomlFields& f, const toml::node& v, const std::string& field,
                                 R& r) { std::tie(r.fines_min, r.fines_max) = f.pair(v, field); }),
                [](const R& d) {
                  return show_numbers(std::vector<double>{d.fines_min, d.fines_max});
                })}};
  return s;
}

const RecipeSection<SpecimenRecipe>& rock_section() {
  static const RecipeSection<R> s = [] {
    RecipeSection<R> t{
        "rock",
        "The rock particles: clumps of a library, or crushable particles (Hu et al. 2023's "
        "parents cut into the cells of [cells], bonded by [bond]; compression only, every class "
        "rock).",
        {custom_key<R>("library", "", "directory",
                       "a library made by `clumpkit library` (relative to the recipe); one of "
                       "library or recipe for rock clumps",
                       "none",
                       [](const TomlFields& f, const toml::node& v, const std::string& field,
                          R& r) { r.library = f.string(v, field); }),
         custom_key<R>("recipe", "", "file",
                       "a shapes recipe with [fill] to build the library from (relative to the "
                       "recipe)",
                       "none",
                       [](const TomlFields& f, const toml::node& v, const std::string& field,
                          R& r) { r.library_recipe = f.string(v, field); }),
         custom_key<R>("crushable", "", "true or false",
                       "crushable particles instead of library clumps", "false",
                       [](const TomlFields& f, const toml::node& v, const std::string& field,
                          R& r) { r.crushable = boolean(f, v, field); }),
         custom_key<R>("unbreakable", "", "true or false",
                       "crushable: the control, whose bonds cannot fail (strengths × 1e6, "
                       "energies × 1e12: the same stiffness)",
                       "false",
                       [](const TomlFields& f, const toml::node& v, const std::string& field,
                          R& r) { r.unbreakable = boolean(f, v, field); })}};
    // The parent's keys as a crushing set takes them, so that both recipes read the same values.
    for (const auto& k : polyhedron_keys())
      t.keys.push_back(
          nested_key<R>(k, [](R& r) -> PolyhedronParams& { return r.crushable_material.shape; }));
    t.keys.push_back(
        shown_as(range_key<R>("spheres_per_cell", "", dem::kCellSpheres,
                              "crushable: spheres filling each cell",
                              [](R& r) -> int& { return r.crushable_material.fill.spheres; }),
                 std::to_string(kDefaultCellSpheres)));
    t.keys.push_back(
        shown_as(range_key<R>("cell_voxels", "", dem::kCellVoxels,
                              "crushable: voxels across the grid each cell is filled on",
                              [](R& r) -> int& { return r.crushable_material.fill.field.voxels; }),
                 std::to_string(kDefaultCellVoxels)));
    return t;
  }();
  return s;
}

void set_crushable_fill_defaults(SpecimenRecipe& r) {
  r.crushable_material.fill.spheres = kDefaultCellSpheres;
  r.crushable_material.fill.field.voxels = kDefaultCellVoxels;
}

}  // namespace clumpkit
