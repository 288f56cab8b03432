// The job of `clumpkit crush`: sets of crushable particles crushed between platens, their
// strengths and Weibull statistics, resumable (Hu et al. 2023).
#pragma once

#include "geom/progress.h"
#include "io/recipes/crush_recipe.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace clumpkit {

struct CrushJobResult {
  std::size_t particles = 0;
  std::size_t resumed = 0;          ///< particles found finished from an earlier run and kept
  std::vector<std::string> redone;  ///< damaged records of an earlier run, redone
  nlohmann::ordered_json report;    ///< report.json
};

/// Crushes every sample of every set. Particle i (sets in order, samples in order) uses the
/// random stream (seed, i) for its parent shape, its cells' seeds and its bonds' strength
/// factors, in that order: the parent (make_polyhedron in its principal frame, or make_cylinder
/// along z) turned to rest on a face when the set asks for it, cut into cells
/// (voronoi_cells), bonded (cell_bonds), built in a world (crushable_particle, the recipe's bond
/// law) and crushed (crush_particle along the set's axis). Writes DIR/particles/NNNNN.json (the
/// record, with a checksum) and NNNNN.csv (travel, force, split), DIR/results.csv (one row per
/// particle), DIR/report.json (SI, snake_case: per set diameter, samples, failed, sigma0,
/// sigma0_ci90, weibull_modulus, weibull_modulus_ci90 — least squares on ln ln(1/Ps), the
/// paper's fit — and the maximum-likelihood pair with its intervals, mean strength and peak force;
/// overall
/// size_exponent, size_coefficient with D in m and σ0 in Pa, size_exponent_ci90, spearman),
/// DIR/curves_SET.png, DIR/weibull.png, DIR/size.png (with two or more sizes), DIR/recipe.toml
/// and DIR/manifest.json. The rules of job.h and library.h: work in DIR.partial, resumed by a
/// rerun of the same recipe (checksummed records kept, damaged ones redone), the same bytes for
/// any thread count; the interrupter (stage "crush", particles done / total) may stop the run
/// between particles (Interrupted, the finished ones kept). Strengths σ = Fp/D² with D the
/// parent's volume-equivalent diameter (eq. 13); a particle that never meets the peak rule
/// within max_strain counts as failed and is left out of the fits. Throws InvalidInput naming
/// the recipe for a parent the cells refuse.
CrushJobResult run_crush(const CrushRecipe& recipe, const std::string& out_dir,
                         const Interrupter& interrupter = {});

}  // namespace clumpkit
