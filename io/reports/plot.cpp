#include "io/reports/plot.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/formats/png.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace clumpkit {

namespace {

// Round tick values in [lo, hi]: a step of 1, 2 or 5 × 10^k giving four to ten ticks. Values
// within a millionth of a step of zero are zero (no "-1e-17" labels).
std::vector<double> round_ticks(double lo, double hi) {
  const double raw = (hi - lo) / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step); k * step <= hi + 1e-9 * step; k += 1.0)
    ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
  return ticks;
}

// One plot's image: the data range (margins included) mapped onto a fixed frame, and the
// drawing steps that share that mapping.
struct PlotCanvas {
  static constexpr int w = 800, h = 560, left = 110, right = 30, top = 50, bottom = 80;

  PlotCanvas(double x_lo_, double x_hi_, double y_lo_, double y_hi_)
      : x_lo(x_lo_), x_hi(x_hi_), y_lo(y_lo_), y_hi(y_hi_) {}

  // The pixel of the data point (x, y).
  cv::Point px(double x, double y) const {
    return cv::Point(
        left + static_cast<int>(std::lround((w - left - right) * (x - x_lo) / (x_hi - x_lo))),
        h - bottom -
            static_cast<int>(std::lround((h - top - bottom) * (y - y_lo) / (y_hi - y_lo))));
  }

  // The grid, the tick labels and the frame.
  void draw_axes() {
    // Ticks at round values (1, 2 or 5 × 10^k apart, four to ten of them), labelled centred.
    for (const double t : round_ticks(x_lo, x_hi)) {
      cv::line(img, px(t, y_lo), px(t, y_hi), grey, 1);
      const std::string text = format_number(t, 4);
      int base = 0;
      const int tw = cv::getTextSize(text, font, 0.5, 1, &base).width;
      cv::putText(img, text, px(t, y_lo) + cv::Point(-tw / 2, 22), font, 0.5, black, 1,
                  cv::LINE_AA);
    }
    for (const double t : round_ticks(y_lo, y_hi)) {
      cv::line(img, px(x_lo, t), px(x_hi, t), grey, 1);
      const std::string text = format_number(t, 4);
      int base = 0;
      const int tw = cv::getTextSize(text, font, 0.5, 1, &base).width;
      cv::putText(img, text, cv::Point(std::max(34, left - 8 - tw), px(x_lo, t).y + 5), font, 0.5,
                  black, 1, cv::LINE_AA);
    }
    cv::rectangle(img, cv::Point(left, top), cv::Point(w - right, h - bottom), black, 1);
  }

  // Each series' lines and markers; a non-finite point breaks its line.
  void draw_series(const std::vector<PlotSeries>& series) {
    for (const PlotSeries& s : series) {
      const cv::Scalar colour(s.rgb[0], s.rgb[1], s.rgb[2]);
      cv::Point previous;
      bool have_previous = false;
      for (std::size_t k = 0; k < std::min(s.points.x.size(), s.points.y.size()); ++k) {
        if (!std::isfinite(s.points.x[k]) || !std::isfinite(s.points.y[k])) {
          have_previous = false;
          continue;
        }
        const cv::Point p = px(s.points.x[k], s.points.y[k]);
        if (s.line && have_previous) cv::line(img, previous, p, colour, 2, cv::LINE_AA);
        if (s.marker > 0) cv::circle(img, p, s.marker, colour, cv::FILLED, cv::LINE_AA);
        previous = p;
        have_previous = true;
      }
    }
  }

  // The legend of the labelled series, if any.
  void draw_legend(const std::vector<PlotSeries>& series) {
    // The legend: in the corner of the frame where it hides the fewest drawn pixels (neither
    // background nor grid), a sample of each labelled series' style.
    std::vector<const PlotSeries*> labelled;
    int text_w = 0;
    for (const PlotSeries& s : series)
      if (!s.label.empty()) {
        labelled.push_back(&s);
        int base = 0;
        text_w = std::max(text_w, cv::getTextSize(s.label, font, 0.5, 1, &base).width);
      }
    if (!labelled.empty()) {
      const int box_w = text_w + 52, box_h = 22 * static_cast<int>(labelled.size()) + 8;
      cv::Rect best;
      long best_hidden = -1;
      for (const cv::Point corner :
           {cv::Point(w - right - 6 - box_w, top + 6), cv::Point(left + 6, top + 6),
            cv::Point(w - right - 6 - box_w, h - bottom - 6 - box_h),
            cv::Point(left + 6, h - bottom - 6 - box_h)}) {
        // Clipped to the image: a very long label must not take the box outside it.
        const cv::Rect r = cv::Rect(corner, cv::Size(box_w, box_h)) & cv::Rect(0, 0, w, h);
        long hidden = 0;
        for (int y = r.y; y < r.y + r.height; ++y)
          for (int x = r.x; x < r.x + r.width; ++x) {
            const auto& p = img.at<cv::Vec3b>(y, x);
            hidden += !(p == cv::Vec3b(255, 255, 255) || p == cv::Vec3b(200, 200, 200));
          }
        if (best_hidden < 0 || hidden < best_hidden) {
          best_hidden = hidden;
          best = r;
        }
      }
      cv::rectangle(img, best, cv::Scalar(255, 255, 255), cv::FILLED);
      cv::rectangle(img, best, cv::Scalar(160, 160, 160), 1);
      for (std::size_t k = 0; k < labelled.size(); ++k) {
        const PlotSeries& s = *labelled[k];
        const cv::Scalar colour(s.rgb[0], s.rgb[1], s.rgb[2]);
        const int x0 = best.x + 8, y = best.y + 20 + 22 * static_cast<int>(k);
        if (s.line)
          cv::line(img, cv::Point(x0, y - 5), cv::Point(x0 + 28, y - 5), colour, 2, cv::LINE_AA);
        if (s.marker > 0)
          cv::circle(img, cv::Point(x0 + 14, y - 5), s.marker, colour, cv::FILLED, cv::LINE_AA);
        cv::putText(img, s.label, cv::Point(x0 + 40, y), font, 0.5, black, 1, cv::LINE_AA);
      }
    }
  }

  // The axis labels and the title.
  void draw_labels(const std::string& x_label, const std::string& y_label,
                   const std::string& title) {
    // Axis labels centred on the frame (the y label turned upright).
    int base = 0;
    const int xw = cv::getTextSize(x_label, font, 0.6, 1, &base).width;
    cv::putText(img, x_label, cv::Point(std::max(4, left + (w - left - right - xw) / 2), h - 25),
                font, 0.6, black, 1, cv::LINE_AA);
    cv::Mat label(30, h - top - bottom, CV_8UC3, cv::Scalar(255, 255, 255));
    const int yw = cv::getTextSize(y_label, font, 0.6, 1, &base).width;
    cv::putText(label, y_label, cv::Point(std::max(4, (label.cols - yw) / 2), 21), font, 0.6, black,
                1, cv::LINE_AA);
    cv::rotate(label, label, cv::ROTATE_90_COUNTERCLOCKWISE);
    label.copyTo(img(cv::Rect(2, top, label.cols, label.rows)));
    cv::putText(img, title, cv::Point(left, 30), font, 0.65, black, 1, cv::LINE_AA);
  }

  const double x_lo, x_hi, y_lo, y_hi;
  // Drawn in RGB throughout (OpenCV only draws; the PNG is written as RGB).
  cv::Mat img = cv::Mat(h, w, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Scalar black = cv::Scalar(0, 0, 0), grey = cv::Scalar(200, 200, 200);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
};

}  // namespace

void write_plot(const std::string& path, const std::vector<PlotSeries>& series,
                const std::string& x_label, const std::string& y_label, const std::string& title) {
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (const PlotSeries& s : series)
    for (std::size_t k = 0; k < std::min(s.points.x.size(), s.points.y.size()); ++k) {
      const double x = s.points.x[k], y = s.points.y[k];
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      x_lo = std::min(x_lo, x);
      x_hi = std::max(x_hi, x);
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, y);
    }
  if (!(x_lo <= x_hi)) throw InvalidInput(path + ": nothing to plot (no finite point)");
  if (x_hi == x_lo) x_hi = x_lo + 1;
  if (y_hi == y_lo) y_hi = y_lo + 1;
  // A margin of 5 % inside the frame, so markers and lines on the range's edge stay whole.
  const double xm = 0.05 * (x_hi - x_lo), ym = 0.05 * (y_hi - y_lo);
  x_lo -= xm;
  x_hi += xm;
  y_lo -= ym;
  y_hi += ym;
  PlotCanvas canvas(x_lo, x_hi, y_lo, y_hi);
  canvas.draw_axes();
  canvas.draw_series(series);
  canvas.draw_legend(series);
  canvas.draw_labels(x_label, y_label, title);
  const cv::Mat& img = canvas.img;
  write_png(path, img.cols, img.rows, 3, img.ptr<std::uint8_t>(0), img.step);
}

void write_line_plot(const std::string& path, const PlotCurve& curve, const std::string& x_label,
                     const std::string& y_label, const std::string& title) {
  PlotSeries s;
  s.points = curve;
  write_plot(path, {s}, x_label, y_label, title);
}

}  // namespace clumpkit
