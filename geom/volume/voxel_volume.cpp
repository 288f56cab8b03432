#include "geom/volume/voxel_volume.h"

#include "geom/errors.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <cmath>
#include <mutex>
#include <string>

namespace clumpkit {

VoxelVolumeResult voxel_volume(const Clump& clump, double voxel_size) {
  validate(clump);
  if (!(voxel_size > 0.0) || !std::isfinite(voxel_size))
    throw InvalidInput("voxel volume: voxel size must be positive and finite, got " +
                       std::to_string(voxel_size));
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });

  Vec3 lo = clump.spheres[0].center, hi = lo;
  for (const Sphere& s : clump.spheres) {
    lo = lo.cwiseMin(Vec3(s.center.array() - s.radius));
    hi = hi.cwiseMax(Vec3(s.center.array() + s.radius));
  }
  const Vec3 cells = (hi - lo) / voxel_size;
  if (cells.prod() > 2e9)
    throw InvalidInput("voxel volume: voxel size " + std::to_string(voxel_size) +
                       " gives more than 2e9 voxels; use a larger voxel");
  const Vec3 ref = 0.5 * (lo + hi);

  openvdb::FloatGrid::Ptr grid;
  for (const Sphere& s : clump.spheres) {
    const Vec3 c = s.center - ref;
    auto ball = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        static_cast<float>(s.radius), openvdb::Vec3f(float(c.x()), float(c.y()), float(c.z())),
        static_cast<float>(voxel_size));
    if (!grid)
      grid = ball;
    else
      openvdb::tools::csgUnion(*grid, *ball);  // level-set union: pointwise min
  }

  VoxelVolumeResult r;
  r.voxel = voxel_size;
  if (grid->activeVoxelCount() == 0) return r;  // every ball under 1.5 voxels: nothing drawn
  const auto inside = openvdb::tools::sdfInteriorMask(*grid, 0.0f);
  r.volume_count = static_cast<double>(inside->activeVoxelCount()) * std::pow(voxel_size, 3);
  r.volume_levelset = openvdb::tools::levelSetVolume(*grid, true);
  return r;
}

}  // namespace clumpkit
