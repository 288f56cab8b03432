// Checks on rendered pictures shared by the io and end-to-end tests: ink in a region.
#pragma once

#include "io/formats/png.h"

namespace clumpkit::test {

/// Pixels of `im` in [x0, x1) × [y0, y1) that are not pure white, the pictures' background.
inline long drawn_pixels(const RgbImage& im, int x0, int y0, int x1, int y1) {
  long n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = im.at(x, y);
      n += !(p[0] == 255 && p[1] == 255 && p[2] == 255);
    }
  return n;
}

}  // namespace clumpkit::test
