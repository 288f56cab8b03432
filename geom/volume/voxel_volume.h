// Voxel volume of a clump from an OpenVDB level set (a cross-check of the slicing volumes).
#pragma once

#include "geom/sphere.h"

namespace clumpkit {

/// Two voxel estimates of the volume of the union of the clump's balls, clump units³.
struct VoxelVolumeResult {
  double volume_count = 0;  ///< interior voxels (level-set value < 0) × voxel³
  double volume_levelset =
      0;             ///< openvdb::tools::levelSetVolume (sub-voxel, from the zero crossing)
  double voxel = 0;  ///< the voxel size used
};

/// Rasterises each ball into a narrow-band signed-distance level set
/// (openvdb::tools::createLevelSetSphere, half-width 3 voxels), unites them with
/// openvdb::tools::csgUnion (min of the distances), and measures the union two ways: by counting
/// the voxels whose centres lie inside (openvdb::tools::sdfInteriorMask, value < 0) and by
/// openvdb::tools::levelSetVolume. Both converge to the exact union volume as voxel_size → 0; the
/// level-set measure is the more accurate one. OpenVDB drops balls whose radius is under 1.5
/// voxels (below the grid's Nyquist limit). The clump is recentred on its bounding-box centre
/// before rasterising (OpenVDB works in single precision). Throws InvalidInput for bad spheres or
/// a voxel size that is not positive and finite, or when the box spans 10⁹ voxels along an axis
/// (OpenVDB's coordinates are 32-bit).
VoxelVolumeResult voxel_volume(const Clump& clump, double voxel_size);

/// Estimated peak bytes of voxel_volume: 100 per voxel of the balls' surfaces, Σ 4πr²/h² (the
/// narrow band, 3 voxels each side, in OpenVDB leaves; one ball at r/h = 400 and 1,000 measured
/// 80, the whole process; an upper bound for overlapping balls, whose union has less surface),
/// and 64 MiB for the program. The interior is held in tiles, so the box's volume adds nothing
/// measurable. Throws what voxel_volume throws for bad input.
double voxel_volume_bytes_estimate(const Clump& clump, double voxel_size);

}  // namespace clumpkit
