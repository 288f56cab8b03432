// Reading shape recipes (TOML): seed and fractions of particles to generate.
#pragma once

#include "geom/fill/fill.h"
#include "geom/shapes/shape_fraction.h"

#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit {

/// A shape-library recipe (`clumpkit shapes`). Lengths in metres (SI), like every recipe.
struct ShapeRecipe {
  std::string path;  ///< file it came from
  std::string name;
  std::string description;
  std::uint64_t seed = 1;
  /// Every generated mesh subdivided to at least this many triangles (geom/mesh/refine.h;
  /// 0: as generated), so scan-sized meshes can be made and tested.
  std::int64_t refine_triangles = 0;
  std::vector<FractionSpec> fractions;
  bool has_fill = false;  ///< a [fill] table was given (used by `clumpkit library`)
  FillOptions fill;
  std::string text;  ///< the recipe file as read, stored in manifests
};

/// Parses and fully validates a recipe. Any problem (missing file, TOML syntax, unknown key,
/// NaN, bad range) throws InvalidInput/IoError with one line "FILE: FIELD: what, got VALUE".
///
/// Format:
///   seed = 2017                       # optional, default 1
///   refine_triangles = 100000         # optional: subdivide every mesh to at least this many
///   name = "..."; description = "..." # optional
///   [[fraction]]
///   name = "rock 20-40 mm"; method = "block"; count = 200
///   W = { uniform = [0.020, 0.040] }                      # distribution forms:
///   L_over_H = { lognormal = { mu = 0.4, sigma = 0.2, min = 1.0, max = 3.0 } }
///   nd = 2                                                # number: a constant
///   # also { normal = { mu, sigma, min, max } } and { integers = [a, b] };
///   # hull fractions accept roundness = [min, max].
///   [fill]                            # optional, for `clumpkit library`
///   spheres = 47; coverage = 0.9; min_radius = 0.002; voxels = 40
///   max_overshoot = 0.01             # fraction of the volume the clump may put outside
ShapeRecipe read_shape_recipe(const std::string& path);

/// Same, from text already in memory; `path` is only used in messages.
ShapeRecipe parse_shape_recipe(const std::string& text, const std::string& path);

/// Fraction index of every particle of the recipe, in id order.
std::vector<int> particle_fractions(const ShapeRecipe& recipe);

/// One [[fraction]] table as its keys are read: the fraction, and the folder of a mesh
/// fraction's files, which are listed once the whole table (its method) is read.
struct FractionTable {
  FractionSpec spec;
  std::string folder;
};

// Declared only: the many files that read shape recipes need not parse toml++ for these tables
// (io/recipes/section_table.h defines it).
template <class Spec>
struct RecipeSection;

/// The table of a [[fraction]]'s own keys (io/recipes/section_table.h); any other key of the
/// table is a parameter of its method. Defaults from FractionTable{}.
const RecipeSection<FractionTable>& fraction_section();
/// The table of [fill], the clumps of `clumpkit library`; defaults from FillOptions{}.
const RecipeSection<FillOptions>& fill_section();

}  // namespace clumpkit
