#include "io/reports/views.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/reports/render.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace clumpkit {

namespace {

const Vec3 kOblique(-1.2, 1.0, -0.8);  // from the front right, above

/// Copies `image` (RGB) into `canvas` (RGB, CV_8UC3) with its top-left corner at (x, y).
void paste(cv::Mat& canvas, const RgbImage& image, int x, int y) {
  for (int r = 0; r < image.height; ++r)
    std::memcpy(canvas.ptr<std::uint8_t>(y + r) + 3 * x, image.at(0, r),
                3 * std::size_t(image.width));
}

/// Writes `text` at (x, y) in `canvas`, at `scale` or smaller so it ends before `right`.
void put_text(cv::Mat& canvas, const std::string& text, int x, int y, double scale, int right) {
  int base = 0;
  const int w = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base).width;
  if (x + w > right) scale *= double(right - x) / w;
  cv::putText(canvas, text, cv::Point(x, y), cv::FONT_HERSHEY_SIMPLEX, scale,
              cv::Scalar(20, 20, 20), 1, cv::LINE_AA);
}

void write_rgb(const std::string& path, const cv::Mat& rgb) {
  write_png(path, rgb.cols, rgb.rows, 3, rgb.ptr<std::uint8_t>(0), rgb.step);
}

/// A length with a unit a reader takes in at a glance (m, mm or µm as "um").
std::string length_text(double metres) {
  if (metres >= 1.0) return format_number(metres, 3) + " m";
  if (metres >= 1e-3) return format_number(metres * 1e3, 3) + " mm";
  return format_number(metres * 1e6, 3) + " um";
}

}  // namespace

void write_particle_png(const std::string& path, const Mesh& mesh, const Clump& clump,
                        const std::string& caption, int panel, bool metres) {
  write_particle_png(path, ClumpRenderer(mesh, clump), caption, panel, metres);
}

void write_particle_png(const std::string& path, const ClumpRenderer& renderer,
                        const std::string& caption, int panel, bool metres) {
  const int header = 62;
  // Everything here is RGB (OpenCV only draws; colours are given as RGB triples).
  cv::Mat canvas(2 * panel + header, 2 * panel, CV_8UC3, cv::Scalar(255, 255, 255));
  struct View {
    Vec3 direction, up;
    const char* label;
  };
  const View views[4] = {{Vec3(0, 1, 0), Vec3(0, 0, 1), "front: along +y (x right, z up)"},
                         {Vec3(-1, 0, 0), Vec3(0, 0, 1), "side: along -x (y right, z up)"},
                         {Vec3(0, 0, -1), Vec3(0, 1, 0), "top: along -z (x right, y up)"},
                         {kOblique, Vec3(0, 0, 1), "oblique (z up)"}};
  for (int v = 0; v < 4; ++v) {
    const int x = (v % 2) * panel, y = header + (v / 2) * panel;
    paste(canvas, renderer.render(views[v].direction, views[v].up, panel), x, y);
    put_text(canvas, views[v].label, x + 8, y + 22, 0.55, x + panel - 8);
  }
  cv::line(canvas, cv::Point(panel, header), cv::Point(panel, 2 * panel + header),
           cv::Scalar(170, 170, 170), 1);
  cv::line(canvas, cv::Point(0, header + panel), cv::Point(2 * panel, header + panel),
           cv::Scalar(170, 170, 170), 1);
  cv::line(canvas, cv::Point(0, header - 1), cv::Point(2 * panel, header - 1),
           cv::Scalar(170, 170, 170), 1);
  put_text(canvas, caption, 10, 24, 0.62, 2 * panel - 10);
  put_text(canvas,
           "each view " +
               (metres ? length_text(renderer.frame_width())
                       : format_number(renderer.frame_width(), 3) + " mesh units") +
               " across; spheres lit and darker with depth under the translucent mesh; red: "
               "sphere caps outside the mesh",
           10, 50, 0.5, 2 * panel - 10);
  write_rgb(path, canvas);
}

RgbImage render_oblique(const Mesh& mesh, const Clump& clump, int pixels) {
  return render_oblique(ClumpRenderer(mesh, clump), pixels);
}

RgbImage render_oblique(const ClumpRenderer& renderer, int pixels) {
  return renderer.render(kOblique, Vec3(0, 0, 1), pixels);
}

void write_contact_sheet(const std::string& path, const std::string& title,
                         const std::vector<SheetTile>& tiles, int max_columns) {
  if (tiles.empty()) throw InvalidInput(path + ": a contact sheet of no particles");
  const int tile = tiles.front().image.width, label = 24, header = 40;
  for (const SheetTile& t : tiles)
    if (t.image.width != tile || t.image.height != tile)
      throw InvalidInput(path + ": contact sheet tiles of different sizes");
  const int n = static_cast<int>(tiles.size());
  const int columns =
      std::clamp(static_cast<int>(std::ceil(std::sqrt(double(n)))), 1, std::max(1, max_columns));
  const int rows = (n + columns - 1) / columns;
  // At least 800 px wide, so the title fits and the sheet opens at a readable size.
  const int width = std::max(800, columns * tile);
  cv::Mat canvas(header + rows * (tile + label), width, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int i = 0; i < n; ++i) {
    const int x = (i % columns) * tile, y = header + (i / columns) * (tile + label);
    paste(canvas, tiles[i].image, x, y);
    put_text(canvas, tiles[i].label, x + 6, y + tile + 17, 0.5, x + tile - 4);
  }
  put_text(canvas, title, 10, 27, 0.62, width - 10);
  write_rgb(path, canvas);
}

}  // namespace clumpkit
