#include "geom/volume/pixel_slicing.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/volume/slicing.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace clumpkit {

namespace {

// Slice spacing, pixel size and the one pixel grid every slice shares (anchored at the clump's
// lower xy corner).
struct SliceGrid {
  double spacing = 0, pixel = 0;
  int slices = 0, cols = 0, rows = 0;
  Vec3 lo, hi;
};

SliceGrid slice_grid(const Clump& clump, const PixelSliceOptions& opt) {
  validate(clump);
  if (opt.slices_across_smallest < 1)
    throw InvalidInput("pixel slicing: slices_across_smallest must be at least 1, got " +
                       std::to_string(opt.slices_across_smallest));
  if (!(opt.pixel >= 0.0) || !std::isfinite(opt.pixel))
    throw InvalidInput("pixel slicing: pixel size must be finite and >= 0, got " +
                       std::to_string(opt.pixel));
  SliceGrid g;
  double rmin = clump.spheres[0].radius;
  g.lo = clump.spheres[0].center;
  g.hi = g.lo;
  for (const Sphere& s : clump.spheres) {
    rmin = std::min(rmin, s.radius);
    g.lo = g.lo.cwiseMin(Vec3(s.center.array() - s.radius));
    g.hi = g.hi.cwiseMax(Vec3(s.center.array() + s.radius));
  }
  g.spacing = 2.0 * rmin / opt.slices_across_smallest;
  g.pixel = opt.pixel > 0.0 ? opt.pixel : g.spacing;
  // Slabs of height h from z_min; the last may overhang z_max (its slice is then empty or thin).
  const double slices = std::ceil((g.hi.z() - g.lo.z()) / g.spacing - 1e-9);
  const double cols = std::ceil((g.hi.x() - g.lo.x()) / g.pixel - 1e-9);
  const double rows = std::ceil((g.hi.y() - g.lo.y()) / g.pixel - 1e-9);
  // An int indexes slices, rows and columns (cv::Mat), and one slice's pixels.
  if (!(slices < 2e9) || !(cols * rows < 2e9))
    throw InvalidInput("pixel slicing: " + format_number(slices) + " slices of " +
                       format_number(cols) + " x " + format_number(rows) +
                       " pixels is beyond the 2e9 an index holds; use fewer slices or a larger "
                       "pixel");
  g.slices = std::max(1, static_cast<int>(slices));
  g.cols = std::max(1, static_cast<int>(cols));
  g.rows = std::max(1, static_cast<int>(rows));
  return g;
}

}  // namespace

double pixel_slice_bytes_estimate(const Clump& clump, const PixelSliceOptions& opt) {
  const SliceGrid g = slice_grid(clump, opt);
  return 64.0 * 1048576.0 + 3.0 * double(g.cols) * g.rows + 64.0 * double(clump.spheres.size());
}

PixelSliceResult pixel_slice_volume(const Clump& clump, const PixelSliceOptions& opt) {
  const SliceGrid g = slice_grid(clump, opt);
  PixelSliceResult res;
  res.spacing = g.spacing;
  res.pixel = g.pixel;
  res.slices = g.slices;
  const double h = res.spacing, p = res.pixel;
  const int cols = g.cols, rows = g.rows;
  const Vec3 lo = g.lo;
  cv::Mat image(rows, cols, CV_8UC1);

  std::vector<Disk> disks;
  for (int k = 0; k < res.slices; ++k) {
    const double z = lo.z() + (k + 0.5) * h;
    disks.clear();
    for (const Sphere& s : clump.spheres) {
      const double dz = z - s.center.z();
      if (std::abs(dz) >= s.radius) continue;
      // Slice radius R' = √(R² − (z_cp − z₀)²), Jin et al. 2017 eq. 2.
      disks.push_back({s.center.x(), s.center.y(), std::sqrt((s.radius - dz) * (s.radius + dz))});
    }
    image.setTo(0);
    for (int r = 0; r < rows; ++r) {
      unsigned char* row = image.ptr<unsigned char>(r);
      const double y0 = lo.y() + r * p, y1 = y0 + p, yc = y0 + 0.5 * p;
      for (const Disk& d : disks) {
        int c0, c1;  // filled columns [c0, c1)
        if (opt.rule == PixelRule::Touch) {
          const double dy = d.y < y0 ? y0 - d.y : (d.y > y1 ? d.y - y1 : 0.0);
          if (dy >= d.r) continue;
          const double w = std::sqrt((d.r - dy) * (d.r + dy));
          // Column i spans [x_i, x_i + p]; it meets the open interval (cx − w, cx + w) iff
          // x_i < cx + w and x_i + p > cx − w.
          const double a = (d.x - w - lo.x()) / p, b = (d.x + w - lo.x()) / p;
          c0 = static_cast<int>(std::floor(a));  // smallest i with i + 1 > a
          c1 = static_cast<int>(std::ceil(b));   // i < b
        } else {
          const double dy = yc - d.y;
          if (std::abs(dy) >= d.r) continue;
          const double w = std::sqrt((d.r - dy) * (d.r + dy));
          // Centre x_i + p/2 strictly inside (cx − w, cx + w).
          const double a = (d.x - w - lo.x()) / p - 0.5, b = (d.x + w - lo.x()) / p - 0.5;
          c0 = static_cast<int>(std::floor(a)) + 1;  // smallest i > a
          c1 = static_cast<int>(std::ceil(b));       // i < b
        }
        c0 = std::max(c0, 0);
        c1 = std::min(c1, cols);
        if (c1 > c0) std::memset(row + c0, 255, static_cast<std::size_t>(c1 - c0));
      }
    }
    const double area = cv::countNonZero(image) * p * p;
    res.z.push_back(z);
    res.pixel_area.push_back(area);
    res.exact_area.push_back(union_of_disks(disks).area);
    res.volume += area * h;
    if (opt.on_slice) {
      cv::Mat out;
      cv::flip(image, out, 0);  // image rows go downwards; put +y up
      opt.on_slice(k, out.cols, out.rows, out.ptr<std::uint8_t>(0));
    }
  }
  return res;
}

}  // namespace clumpkit
