// PNG files (libpng): 8-bit grey or RGB images, written atomically.
#pragma once

#include <cstdint>
#include <string>

namespace clumpkit {

/// Writes a width × height image with `channels` = 1 (grey) or 3 (RGB) bytes per pixel, rows top
/// to bottom, `stride` bytes apart (0 = width·channels). Throws IoError naming the path.
void write_png(const std::string& path, int width, int height, int channels,
               const std::uint8_t* pixels, std::size_t stride = 0);

}  // namespace clumpkit
