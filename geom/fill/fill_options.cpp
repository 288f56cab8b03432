#include "geom/fill/fill_options.h"

#include "geom/errors.h"

#include <cmath>
#include <string>

namespace clumpkit {

void validate(const FillOptions& o) {
  if (o.spheres != 0) require(kSphereBudget, o.spheres, "--spheres");
  if (!(o.field.voxel_size > 0.0)) require(kFieldVoxels, o.field.voxels, "--voxels");
  require(kCoverage, o.coverage, "--coverage");
  require(kMinRadius, o.min_radius, "--min-radius");
  if (!std::isfinite(o.tolerance) || !(o.tolerance_voxels >= 0.0) ||
      !std::isfinite(o.tolerance_voxels))
    throw InvalidInput("--tolerance must be finite and non-negative, got " +
                       std::to_string(o.tolerance));
  if (!(o.tolerance_relative >= 0.0 && o.tolerance_relative < 1.0))
    throw InvalidInput("--relative-tolerance must be in [0, 1), got " +
                       std::to_string(o.tolerance_relative));
  require(kMaxOvershoot, o.max_overshoot, "--max-overshoot");
  require(kRefineIterations, o.refine_iterations, "--refine-iterations");
  if (!std::isfinite(o.refine_work))
    throw InvalidInput("refine_work must be finite, got " + std::to_string(o.refine_work));
  if (!(o.refine_min_gain >= 0.0) || !std::isfinite(o.refine_min_gain))
    throw InvalidInput("refine_min_gain must be finite and non-negative, got " +
                       std::to_string(o.refine_min_gain));
  if (!(o.ridge > 0.0 && o.ridge <= 1.0))
    throw InvalidInput("ridge threshold must be in (0, 1], got " + std::to_string(o.ridge));
}

FieldOptions fill_field_options(const Mesh& mesh, const FillOptions& options) {
  FieldOptions field = options.field;
  const double volume = signed_volume(mesh);
  if (options.voxels_from_count && options.spheres > 0 && !field.vote_sign && volume > 0.0)
    field.count_voxel =
        kSmallestSphereOverSpacing * std::cbrt(volume / options.spheres) / kVoxelsPerSmallestRadius;
  return field;
}

}  // namespace clumpkit
