#include "io/formats/png.h"

#include "geom/errors.h"
#include "io/base/atomic_file.h"

#include <png.h>

#include <vector>

namespace clumpkit {

namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + n);
}
void flush(png_structp) {}

// What encode reads, behind one pointer: libpng reports errors by longjmp, and nothing that
// encode's frame holds may change between its setjmp and the jump.
struct PngJob {
  int width, height, channels;
  const std::uint8_t* pixels;
  std::size_t row_stride;
  std::vector<std::uint8_t>* out;
};

// Encodes into job->out; false where libpng failed. No object with a destructor lives in this
// frame, so the jump skips none.
bool encode(const PngJob* job) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, job->out, append, flush);
  png_set_IHDR(png, info, job->width, job->height, 8,
               job->channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < job->height; ++y)
    png_write_row(png, const_cast<png_bytep>(job->pixels + y * job->row_stride));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

void write_png(const std::string& path, int width, int height, int channels,
               const std::uint8_t* pixels, std::size_t stride) {
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3))
    throw IoError(path + ": cannot write a " + std::to_string(width) + "x" +
                  std::to_string(height) + "x" + std::to_string(channels) + " PNG");
  // Encoded into memory, then the file written atomically.
  std::vector<std::uint8_t> encoded;
  const PngJob job{
      width,   height, channels, pixels, stride == 0 ? std::size_t(width) * channels : stride,
      &encoded};
  if (!encode(&job)) throw IoError(path + ": PNG encoding failed");
  write_file_atomically(path, [&](std::ostream& o) {
    o.write(reinterpret_cast<const char*>(encoded.data()),
            static_cast<std::streamsize>(encoded.size()));
  });
}

RgbImage read_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw IoError(path + ": cannot read PNG: " + image.message);
  image.format = PNG_FORMAT_RGB;
  RgbImage out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) {
    const std::string why = image.message;
    png_image_free(&image);
    throw IoError(path + ": cannot decode PNG: " + why);
  }
  return out;
}

}  // namespace clumpkit
