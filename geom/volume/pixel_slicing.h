// Pixel virtual slicing (Jin et al. 2017 §3): clump volume from rasterised horizontal slices.
#pragma once

#include "geom/sphere.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace clumpkit {

/// Which pixels a disk fills when a slice is rasterised.
enum class PixelRule {
  Centre,  ///< the pixel's centre lies inside the disk (unbiased on average)
  Touch,   ///< the disk's interior meets the pixel square at all (over-counts the rim)
};

/// Options of pixel_slice_volume. Defaults follow Jin et al. 2017 Table 1.
struct PixelSliceOptions {
  int slices_across_smallest = 100;  ///< slices across the smallest ball's diameter (>= 1)
  double pixel = 0;                  ///< pixel size, clump units; 0 = the slice spacing
  PixelRule rule = PixelRule::Touch;
  /// Called for each slice with its 8-bit image (255 = filled, rows from +y down to −y, so it
  /// reads like a map); the CLI writes PNGs from it. geom does no file I/O.
  std::function<void(int slice, int width, int height, const std::uint8_t* pixels)> on_slice;
};

/// Outcome of pixel_slice_volume; per-slice vectors are in slice order (increasing z).
struct PixelSliceResult {
  double volume = 0;  ///< Σ pixel_area · spacing, clump units³
  int slices = 0;
  double spacing = 0, pixel = 0;
  std::vector<double> z;           ///< slice heights (mid-heights of the slabs)
  std::vector<double> pixel_area;  ///< filled pixels × pixel²
  std::vector<double> exact_area;  ///< exact area of the slice (union_of_disks)
};

/// Volume of a clump by Jin et al. 2017 §3 (virtual slicing + digital image processing): the clump
/// is cut by horizontal planes at spacing h = 2·r_min / slices_across_smallest, at the mid-heights
/// z_k = z_min + (k + ½)h of the slabs covering [z_min, z_max]; each ball cut by a plane gives a
/// disk of radius R' = √(R² − (z − z₀)²) (Jin et al. 2017 eq. 2). Each slice is rasterised into a
/// cv::Mat over the clump's xy bounding box (pixel grid anchored at its lower corner, so all
/// slices share one grid) by an exact per-row span computation — not cv::circle, whose
/// Bresenham rim follows neither rule: for pixel row [y₀, y₀ + p] a disk (cx, cy, r) fills
///   Touch:  the columns whose x-range meets (cx − w, cx + w), w = √(r² − δ²), δ the distance
///           from cy to the row (0 when cy lies in it), if δ < r;
///   Centre: the columns whose centre x satisfies |x − cx| < w, w = √(r² − (y_c − cy)²), y_c the
///           row's centre, if |y_c − cy| < r.
/// The volume is Σ_k (filled pixels_k · p²) · h (Jin et al. 2017 §3.2). Units: those of the clump.
/// Throws InvalidInput for bad spheres or options, or when one slice would exceed 10⁸ pixels.
PixelSliceResult pixel_slice_volume(const Clump& clump, const PixelSliceOptions& opt);

/// Estimated peak bytes of pixel_slice_volume: 3 per pixel of one slice (the image, its inverted
/// copy and the PNG encoder's buffer when slices are written), 64 per ball and 64 MiB for the
/// program. Throws what pixel_slice_volume throws for bad options.
double pixel_slice_bytes_estimate(const Clump& clump, const PixelSliceOptions& opt);

}  // namespace clumpkit
