#include "io/plot.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/png.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace clumpkit {

void write_line_plot(const std::string& path, const PlotCurve& curve, const std::string& x_label,
                     const std::string& y_label, const std::string& title) {
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (std::size_t k = 0; k < std::min(curve.x.size(), curve.y.size()); ++k) {
    if (!std::isfinite(curve.x[k]) || !std::isfinite(curve.y[k])) continue;
    x_lo = std::min(x_lo, curve.x[k]);
    x_hi = std::max(x_hi, curve.x[k]);
    y_lo = std::min(y_lo, curve.y[k]);
    y_hi = std::max(y_hi, curve.y[k]);
  }
  if (!(x_lo <= x_hi)) throw InvalidInput(path + ": nothing to plot (no finite point)");
  if (x_hi == x_lo) x_hi = x_lo + 1;
  if (y_hi == y_lo) y_hi = y_lo + 1;
  const int w = 800, h = 560, left = 110, right = 30, top = 50, bottom = 80;
  cv::Mat img(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  auto px = [&](double x, double y) {
    return cv::Point(
        left + static_cast<int>(std::lround((w - left - right) * (x - x_lo) / (x_hi - x_lo))),
        h - bottom -
            static_cast<int>(std::lround((h - top - bottom) * (y - y_lo) / (y_hi - y_lo))));
  };
  const cv::Scalar black(0, 0, 0), grey(200, 200, 200), blue(180, 70, 20);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  for (int k = 0; k <= 4; ++k) {
    const double x = x_lo + (x_hi - x_lo) * k / 4.0, y = y_lo + (y_hi - y_lo) * k / 4.0;
    cv::line(img, px(x, y_lo), px(x, y_hi), grey, 1);
    cv::line(img, px(x_lo, y), px(x_hi, y), grey, 1);
    cv::putText(img, format_number(x, 3), px(x, y_lo) + cv::Point(-20, 22), font, 0.5, black, 1,
                cv::LINE_AA);
    cv::putText(img, format_number(y, 3), cv::Point(36, px(x_lo, y).y + 5), font, 0.5, black, 1,
                cv::LINE_AA);
  }
  cv::rectangle(img, cv::Point(left, top), cv::Point(w - right, h - bottom), black, 1);
  cv::Point previous;
  bool have_previous = false;
  for (std::size_t k = 0; k < std::min(curve.x.size(), curve.y.size()); ++k) {
    if (!std::isfinite(curve.x[k]) || !std::isfinite(curve.y[k])) {
      have_previous = false;
      continue;
    }
    const cv::Point p = px(curve.x[k], curve.y[k]);
    if (have_previous) cv::line(img, previous, p, blue, 2, cv::LINE_AA);
    previous = p;
    have_previous = true;
  }
  cv::putText(img, x_label, cv::Point(left + (w - left - right) / 2 - 80, h - 25), font, 0.6, black,
              1, cv::LINE_AA);
  cv::Mat label(30, h - top - bottom, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::putText(label, y_label, cv::Point(10, 21), font, 0.6, black, 1, cv::LINE_AA);
  cv::rotate(label, label, cv::ROTATE_90_COUNTERCLOCKWISE);
  label.copyTo(img(cv::Rect(2, top, label.cols, label.rows)));
  cv::putText(img, title, cv::Point(left, 30), font, 0.65, black, 1, cv::LINE_AA);
  cv::Mat rgb;
  cv::cvtColor(img, rgb, cv::COLOR_BGR2RGB);
  write_png(path, rgb.cols, rgb.rows, 3, rgb.ptr<std::uint8_t>(0), rgb.step);
}

}  // namespace clumpkit
