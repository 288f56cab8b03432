#include "io/views.h"

#include "geom/errors.h"
#include "io/png.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace clumpkit {

void write_views_png(const std::string& path, const Mesh& mesh, const Clump& clump, int pixels) {
  auto bb = bounding_box(mesh);
  for (const auto& s : clump.spheres) {
    bb[0] = bb[0].cwiseMin(s.center - Vec3::Constant(s.radius));
    bb[1] = bb[1].cwiseMax(s.center + Vec3::Constant(s.radius));
  }
  const double extent = (bb[1] - bb[0]).maxCoeff();
  const int margin = 10;
  const double scale = (pixels - 2 * margin) / extent;
  // Sub-pixel drawing: OpenCV takes fixed-point coordinates with `shift` fractional bits.
  const int shift = 4;
  const double fix = 1 << shift;
  cv::Mat image(pixels, 3 * pixels, CV_8UC3, cv::Scalar(255, 255, 255));
  const int axes[3][2] = {
      {1, 2}, {0, 2}, {0, 1}};  // view along x: (y, z); along y: (x, z); z: (x, y)
  for (int v = 0; v < 3; ++v) {
    const int a = axes[v][0], b = axes[v][1];
    auto to_px = [&](const Vec3& p) {
      const double x = v * pixels + margin + (p[a] - bb[0][a]) * scale;
      const double y = pixels - margin - (p[b] - bb[0][b]) * scale;  // image y points down
      return cv::Point(static_cast<int>(std::lround(x * fix)),
                       static_cast<int>(std::lround(y * fix)));
    };
    for (const auto& t : mesh.triangles) {
      const cv::Point pts[3] = {to_px(mesh.vertices[t[0]]), to_px(mesh.vertices[t[1]]),
                                to_px(mesh.vertices[t[2]])};
      cv::fillConvexPoly(image, pts, 3, cv::Scalar(200, 200, 200), cv::LINE_AA, shift);
    }
    for (const auto& s : clump.spheres)
      cv::circle(image, to_px(s.center), static_cast<int>(std::lround(s.radius * scale * fix)),
                 cv::Scalar(30, 30, 220), 1, cv::LINE_AA, shift);
    const char* names[3] = {"along x", "along y", "along z"};
    cv::putText(image, names[v], cv::Point(v * pixels + 4, 14), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                cv::Scalar(0, 0, 0));
  }
  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  write_png(path, rgb.cols, rgb.rows, 3, rgb.ptr<std::uint8_t>(0), rgb.step);
}

}  // namespace clumpkit
