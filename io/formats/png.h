// PNG files (libpng): 8-bit grey or RGB images, written atomically and read back.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clumpkit {

/// Writes a width × height image with `channels` = 1 (grey) or 3 (RGB) bytes per pixel, rows top
/// to bottom, `stride` bytes apart (0 = width·channels). Throws IoError naming the path.
void write_png(const std::string& path, int width, int height, int channels,
               const std::uint8_t* pixels, std::size_t stride = 0);

/// An 8-bit RGB image, rows top to bottom, 3 bytes per pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
  const std::uint8_t* at(int x, int y) const { return &pixels[(std::size_t(y) * width + x) * 3]; }
};

/// Reads any PNG as 8-bit RGB (grey expanded, alpha composed on black). Throws IoError naming
/// the path.
RgbImage read_png(const std::string& path);

}  // namespace clumpkit
