// The shapes job: a shape library from a recipe (meshes, descriptor table and manifest).
#pragma once

#include "io/recipes/recipe.h"

#include <functional>
#include <string>
#include <vector>

namespace clumpkit {

struct ShapeBatchResult {
  std::size_t particles = 0;
  std::string out_dir;
};

/// Generates every particle of the recipe in parallel (TBB) and writes
///   DIR/meshes/NNNNN.stl, DIR/shapes.csv, DIR/manifest.json
/// (every number with its SI unit: shapes.csv's header cells, the manifest's "units").
/// Particle i uses the random stream (recipe.seed, i), so outputs are byte-identical for any
/// thread count. Everything is written into DIR.partial first and renamed at the end, so a failed
/// run leaves no partial DIR (the rule of job.h: an existing DIR is replaced only if it is empty
/// or holds a manifest.json, a previous clumpkit output; otherwise InvalidInput). The
/// interrupter is told ("shapes", fraction of particles generated); asked to stop, the job
/// throws Interrupted and writes nothing.
ShapeBatchResult run_shape_batch(const ShapeRecipe& recipe, const std::string& out_dir,
                                 const Interrupter& interrupter = {});

}  // namespace clumpkit
