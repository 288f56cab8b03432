#include "geom/volume/voxel_volume.h"

#include "geom/errors.h"
#include "geom/format.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/LevelSetMeasure.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include <cmath>
#include <mutex>
#include <string>

namespace clumpkit {

namespace {

struct Box {
  Vec3 lo, hi;
};

// The clump's bounding box, after checking the input.
Box checked_box(const Clump& clump, double voxel_size) {
  validate(clump);
  if (!(voxel_size > 0.0) || !std::isfinite(voxel_size))
    throw InvalidInput("voxel volume: voxel size must be positive and finite, got " +
                       std::to_string(voxel_size));
  Box b{clump.spheres[0].center, clump.spheres[0].center};
  for (const Sphere& s : clump.spheres) {
    b.lo = b.lo.cwiseMin(Vec3(s.center.array() - s.radius));
    b.hi = b.hi.cwiseMax(Vec3(s.center.array() + s.radius));
  }
  const Vec3 cells = (b.hi - b.lo) / voxel_size;
  if (!(cells.maxCoeff() < 1e9))
    throw InvalidInput("voxel volume: voxel size " + format_number(voxel_size) + " gives " +
                       format_number(cells.maxCoeff()) +
                       " voxels along one axis, beyond OpenVDB's 32-bit coordinates; use a "
                       "larger voxel");
  return b;
}

}  // namespace

double voxel_volume_bytes_estimate(const Clump& clump, double voxel_size) {
  checked_box(clump, voxel_size);
  double surface = 0;
  for (const Sphere& s : clump.spheres) {
    const double r = s.radius / voxel_size;
    if (r >= 1.5) surface += 4.0 * M_PI * r * r;  // OpenVDB drops smaller balls
  }
  return 64.0 * 1048576.0 + 100.0 * surface;
}

VoxelVolumeResult voxel_volume(const Clump& clump, double voxel_size) {
  const Box box = checked_box(clump, voxel_size);
  const Vec3 lo = box.lo, hi = box.hi;
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
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
