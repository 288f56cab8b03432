// Specimen recipes (TOML): container, gradation, rock library, materials, contact law and the
// target relative density of a DEM specimen (Jin et al. 2017 §4).
#pragma once

#include "dem/specimen/compression.h"
#include "dem/specimen/container.h"
#include "dem/specimen/specimen.h"
#include "dem/specimen/zones.h"
#include "io/recipes/section_table.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit {

/// One sieve class of the gradation, by mass.
struct SizeClass {
  double min = 0.0, max = 0.0;  ///< sieve sizes [m]
  double percent = 0.0;         ///< mass percent of the whole sample in this class
};

/// Everything `clumpkit specimen` needs, SI units. Defaults are the values of Jin et al. 2017.
struct SpecimenRecipe {
  std::string path, text;
  std::uint64_t seed = 1;
  /// [container] shape: "cylinder" (diameter, height), "cuboid" (size = edges x, y, z) or
  /// "segment" (the sector of `angle` degrees, in (0, 180], of the cylinder of diameter and
  /// height: a chamber cut by two frictionless planes of symmetry through its axis); the last two
  /// only with preparation.method = "compression".
  bool cuboid = false;
  bool segment = false;
  double segment_angle_deg = 90.0;
  /// Cylinder [m]: the defaults are dem::SpecimenSpec's, the cuboid's dem::CompressionSpec's
  /// (dem::check_container_length checks every length).
  double container_diameter = 2.0 * dem::SpecimenSpec{}.radius;
  double container_height = dem::SpecimenSpec{}.height;
  std::array<double, 3> container_size{dem::CompressionSpec{}.size.x(),
                                       dem::CompressionSpec{}.size.y(),
                                       dem::CompressionSpec{}.size.z()};  ///< cuboid edges [m]
  /// [preparation] method: "deposition" (under gravity, quasi-vibration calibration, layers:
  /// Jin et al. 2017) or "compression" (gravity off: homogeneous compression of a loose random
  /// packing to `porosity` at `friction`, dem/specimen/compression.h — specimens for element
  /// tests).
  bool compression = false;
  /// preparation.porosity and preparation.friction: the compression's (dem::CompressionSpec
  /// holds their defaults, dem::kTargetPorosity and dem::kFriction their ranges).
  double compression_porosity = dem::CompressionSpec{}.porosity;
  double compression_friction = dem::CompressionSpec{}.friction;
  /// [zones] (compression only): variable particle-size zones, innermost first (CTGU 2017) —
  /// coordinate "radial" (distance to the axis through origin), "depth" (below origin's z) or
  /// "spherical" (distance to origin); [[zones.region]] tables with `outer` (m) and `scale` (λ;
  /// the first is the core, λ = 1), or `mixed = true` with `small_volume_fraction` (one number,
  /// or [inner, outer] for a linear change). origin defaults to the axis (radial) or the
  /// container's top (depth); spherical zones need it. mixed_porosity: the mixed layers' target
  /// (default: preparation.porosity). zone_warnings: λ ratios above 2.
  dem::ZoneLayout zones;
  double mixed_porosity = 0.0;
  std::vector<std::string> zone_warnings;
  std::vector<double> sieves;         ///< sieve sizes [m], descending
  std::vector<double> passing;        ///< percent passing each sieve, descending, first = 100
  std::vector<SizeClass> classes;     ///< derived from sieves and passing
  double soil_rock_threshold = 0.02;  ///< particles above are rock clumps, below soil spheres [m]
  double rock_mass_fraction = 0.4;    ///< rock mass / total mass, 40 % in Jin et al. 2017
  double fines_below = 0.005;         ///< soil finer than this ...
  double fines_min = 0.005, fines_max = 0.010;  ///< ... is replaced by the same mass in this range
  /// [rock] crushable = true (compression only, every class rock): the rock particles are
  /// crushable — parents of Hu et al. 2023's kind (planes, E, F, offset_min, offset_max of
  /// [rock]; the classes' sizes their volume-equivalent diameters) cut into the cells of
  /// [cells], each cell filled with spheres_per_cell spheres on a grid of cell_voxels voxels
  /// across, bonded by the law of [bond] (the tables of the crushing recipes, scale applied)
  /// — instead of library clumps.
  bool crushable = false;
  /// [rock] unbreakable = true: the control of a crushable specimen — the same particles, cells
  /// and bonds, whose bonds cannot fail (strengths × 1e6, energies × 1e12: the same stiffness).
  bool unbreakable = false;
  dem::CrushableMaterial crushable_material;
  dem::CohesiveParams bond;  ///< strengths × scale, energies × scale²
  double bond_scale = 1.0;
  std::string library;  ///< directory made by `clumpkit library`, or
  std::string
      library_recipe;  ///< a shapes recipe with [fill] to build one (paths relative to the recipe)
  double soil_density = 2700.0, rock_density = 2870.0;  ///< [kg/m³]
  double kn = 1e6, ks = 1e6, friction = 0.8;            ///< contact law, N/m
  /// contact.stiffness_scaling = "linear": kn and ks are the values at diameter d_ref and each
  /// contact's stiffness scales with its bodies' diameters (CTGU 2017; dem/core/contact.h).
  bool linear_scaling = false;
  double d_ref = 0.0;  ///< m
  /// Viscous normal damping ratio β and PFC local damping α of the preparation (defaults of
  /// dem::deposition_contact()).
  double damping_ratio = 0.5, local_damping = 0.1;
  double target_relative_density = 0.5;
  int layers = 3;
  /// Friction values of the quasi-vibration calibration (deposition at the largest gives
  /// n_max, compaction at 0 gives n_min; at least dem::kMinCalibrationFrictions in all).
  std::vector<double> calibration_frictions = {0.0, 0.05, 0.1, 0.2, 0.4, 0.8};
};

/// Reads and validates a specimen recipe before anything is simulated: unknown keys, NaN,
/// target relative density outside [0, 1], a gradation whose passing percentages do not start at
/// 100 or do not decrease, a rock fraction that contradicts the gradation, a container narrower
/// than the largest particle, a missing library. Each gives InvalidInput "FILE: FIELD: what,
/// got VALUE" (IoError for an unreadable recipe).
SpecimenRecipe read_specimen_recipe(const std::string& path);

/// The section tables of a specimen recipe (io/recipes/section_table.h; defined in
/// io/recipes/specimen_sections.cpp), each read into a SpecimenRecipe unless said otherwise.
/// The keys at the top of the recipe, outside any section (name ""; fields are the bare keys).
const RecipeSection<SpecimenRecipe>& specimen_top_section();
/// [container]: shape, diameter, height, size, angle.
const RecipeSection<SpecimenRecipe>& container_section();
/// [preparation]: method, porosity, friction.
const RecipeSection<SpecimenRecipe>& preparation_section();
/// [zones]: coordinate, origin, mixed_porosity, region (each read by zone_region_section).
const RecipeSection<SpecimenRecipe>& zones_section();
/// One [[zones.region]] table, read into a dem::ZoneRegion (named "zones.region[i]" when read).
const RecipeSection<dem::ZoneRegion>& zone_region_section();
/// [gradation]: sieves, passing.
const RecipeSection<SpecimenRecipe>& gradation_section();
/// [fines]: below, replace_with.
const RecipeSection<SpecimenRecipe>& fines_section();
/// [rock]: library or recipe, or a crushable material's parent and fill.
const RecipeSection<SpecimenRecipe>& rock_section();
/// [density]: soil, rock.
const RecipeSection<SpecimenRecipe>& density_section();
/// [contact]: the contact law.
const RecipeSection<SpecimenRecipe>& contact_section();
/// Gives `r` the fill of a crushable cell that a recipe starts from (6 spheres on a grid of 16
/// voxels across; a SpecimenRecipe{} holds the fill's own defaults), as rock_section shows it.
void set_crushable_fill_defaults(SpecimenRecipe& r);
SpecimenRecipe parse_specimen_recipe(const std::string& text, const std::string& path);

}  // namespace clumpkit
