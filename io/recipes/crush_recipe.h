// Crushing recipes (`clumpkit crush`): particle sets, their Voronoi cells, the bond law and the
// rig, read from TOML.
#pragma once

#include "dem/core/cohesive_law.h"
#include "dem/lab/crush.h"
#include "geom/cells/cell_bonds.h"
#include "geom/cells/voronoi_cells.h"
#include "geom/shapes/distribution.h"
#include "geom/shapes/polyhedron.h"
#include "io/recipes/section_table.h"

#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit {

/// One set of samples: a parent shape drawn per sample, loaded along one axis.
struct CrushSet {
  std::string name;
  std::string shape = "polyhedron";  ///< "polyhedron" (make_polyhedron) or "cylinder"
  PolyhedronParams polyhedron;       ///< diameter and shape (polyhedron)
  double height = 0.0;               ///< cylinder height (m); its diameter is polyhedron.diameter
  int sides = 64;                    ///< cylinder facets
  int samples = 30;
  /// Loading axis of the parent's frame: 0 x (long axis of a polyhedron), 1 y (intermediate),
  /// 2 z (short; a cylinder's axis).
  int axis = 2;
  /// The parent turned so that its largest face within 30° of the lower platen lies flat on it
  /// (as a particle set down on a platen rests), rather than touching at a corner.
  bool rest_on_face = true;
  bool size_law = true;  ///< part of the size law σ0 = k·D^−α fitted over the sets
};

/// A crushing recipe. [crush]: seed, density (kg/m³), the rig (dem::CrushOptions: strain_rate,
/// platen_friction, platen_stiffness, local_damping, timestep_safety, density_scaling,
/// max_strain, sample_strain, drop, intact_fraction), bootstrap (resamples of the 90 %
/// intervals). [cells]: cell_size (m), lloyd,
/// face_subdivision (4^s points per fan triangle), strength_factor (a distribution). [bond]: kn, kt
/// (N/m³), sigma_n, sigma_t (Pa), g_n, g_t (J/m²), friction, scale (Hu et al. 2023's one
/// Brazilian calibration factor s: strengths × s, energies × s², openings × s). [[set]]: name,
/// shape, diameter (m), samples, axis ("long" | "intermediate" | "short" | "x" | "y" | "z"), rest
/// ("face" | "corner"), size_law, and the shape's parameters (planes, E, F, offset_min, offset_max
/// for a polyhedron; height, sides for a cylinder).
struct CrushRecipe {
  std::string path, text;
  std::string name;
  std::uint64_t seed = 1;
  double density = 2650.0;
  dem::CrushOptions rig;
  int bootstrap = 1000;
  /// Hu et al. 2023's cell size, 6.5 mm (their 75 … 307 cells at 27.5 … 43.9 mm), held here so
  /// that a default recipe shows the defaults the reader keeps (cells_section).
  CellOptions cells = [] {
    CellOptions c;
    c.cell_size = 0.0065;
    return c;
  }();
  int face_subdivision = 0;  ///< integration points per fan triangle: 4^s (cell_bonds)
  Distribution strength = default_strength_factor();
  dem::CohesiveParams law;  ///< with `scale` applied (σ × s, G × s²)
  double scale = 1.0;
  std::vector<CrushSet> sets;
};

/// Parses a crushing recipe; throws InvalidInput naming the file, the field and the value for an
/// unknown key, a wrong type or a value out of range, and IoError for a missing file.
CrushRecipe parse_crush_recipe(const std::string& text, const std::string& path);
CrushRecipe read_crush_recipe(const std::string& path);

/// The [cells] and [bond] tables of a crushing recipe, read into `r` (a crushable specimen's
/// recipe reads the same tables); apply_bond_scale then multiplies the strengths by [bond] scale
/// and the energies by its square and checks the law against the strength factors' upper
/// bound. Each throws InvalidInput naming the file, field and value.
void read_cells_table(const TomlFields& f, const toml::table& t, CrushRecipe& r);
/// One key of a parent polyhedron (planes, E, F, offset_min, offset_max; Hu et al. 2023's cut
/// sphere) read into `p`, as a crushing set and a crushable specimen's [rock] give them; false
/// for any other key. The values are checked together by validate(PolyhedronParams).
bool read_polyhedron_key(const TomlFields& f, const std::string& key, const toml::node& v,
                         const std::string& field, PolyhedronParams& p);
void read_bond_table(const TomlFields& f, const toml::node& t, CrushRecipe& r);
void apply_bond_scale(const TomlFields& f, CrushRecipe& r);

/// The tables of the [crush] and [bond] sections (io/recipes/section_table.h).
const RecipeSection<CrushRecipe>& crush_section();
const RecipeSection<CrushRecipe>& bond_section();
/// The table of [cells]: the Voronoi cells of a parent and its bonds' strength factors.
const RecipeSection<CrushRecipe>& cells_section();
/// The table of one [[set]] (read under its own name, "set[i]"); defaults from CrushSet{}.
const RecipeSection<CrushSet>& set_section();
/// The keys of a parent polyhedron, shared by [[set]] and a crushable specimen's [rock].
const std::vector<RecipeKey<PolyhedronParams>>& polyhedron_keys();

}  // namespace clumpkit
