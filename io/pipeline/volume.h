// The job of `clumpkit volume`: volume, area, centroid and inertia of a union of spheres by the
// methods asked for (exact power diagram, inclusion–exclusion, analytic and pixel slicing, voxels).
#pragma once

#include "geom/progress.h"
#include "geom/sphere.h"
#include "io/base/units.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <limits>
#include <string>

namespace clumpkit {

/// What the volume job reads (units of the clump file).
struct VolumeJobOptions {
  std::string clump;             ///< clump CSV (x,y,z,r)
  std::string method = "exact";  ///< exact|inclusion-exclusion|analytic-slice|pixel-slice|voxel|all
  int slices = 100;              ///< pixel-slice: slices across the smallest sphere
  double pixel = 0.0;            ///< pixel-slice: pixel size (0: the slice spacing)
  std::string rule = "touch";    ///< pixel-slice: centre or touch
  std::string png;               ///< pixel-slice: slice images into this directory ("": none)
  double voxel = 0.0;            ///< voxel: voxel size (0: smallest radius / 10)
  /// Refuse a method estimated to need more than this (bytes).
  double max_bytes = std::numeric_limits<double>::infinity();
  /// The clump file's length unit as the user names it (--length-unit; "": not named).
  std::string length_unit;
};

/// What the volume job measured.
struct VolumeJobResult {
  std::size_t spheres = 0;
  /// One object per method run, keyed exact, inclusion_exclusion, analytic_slice, pixel_slice,
  /// voxel, in that order: volume, and what the method gives besides (area, centroid, inertia,
  /// slices, voxel, ...), and seconds.
  nlohmann::ordered_json methods;
  /// The unit of the lengths: the one named, else the one the clump file's header names, else L.
  /// A header's L (unnamed) may be named.
  LengthUnit length;
};

/// Checks the options and the memory estimate of every method asked for before the first runs
/// (InvalidInput naming the option, method and estimate), then runs them. A named length unit
/// other than the one the clump file's header names (other than L) is refused (InvalidInput)
/// before any work.
VolumeJobResult run_volume_job(const VolumeJobOptions& options);
/// Throws InvalidInput for an unknown method or pixel rule.
void check_volume_options(const VolumeJobOptions& options);
/// The measures of run_volume_job on a clump in memory (options.clump unused; `name` stands for
/// it in messages): the `methods` object. The interrupter is the exact method's
/// (geom/volume/union_of_balls.h).
nlohmann::ordered_json measure_volume(const Clump& clump, const VolumeJobOptions& options,
                                      const std::string& name, const Interrupter& interrupter = {});

}  // namespace clumpkit
