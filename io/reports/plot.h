// Line and point plots as PNG (OpenCV drawing): labelled axes with ticks and a legend, for
// curves such as a test's stress against strain or a calibration.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace clumpkit {

/// One curve: its points (x[k], y[k]), drawn as connected segments.
struct PlotCurve {
  std::vector<double> x, y;
};

/// One series of a plot: its points, how they are drawn and its legend entry.
struct PlotSeries {
  PlotCurve points;
  std::string label;                              ///< legend entry; empty: none
  std::array<unsigned char, 3> rgb{20, 70, 180};  ///< colour, RGB
  bool line = true;                               ///< connect the points in order
  int marker = 0;                                 ///< radius (px) of a dot at each point; 0: none
};

/// Draws the series on a 800 × 560 white canvas: a frame over the finite points' range, a grid
/// and five ticks per axis with their values, the axis labels (with units, the y label turned
/// upright), a title and a legend of the labelled series; writes it as PNG (atomically).
/// Non-finite points are skipped. Throws InvalidInput naming the path if no point is finite.
void write_plot(const std::string& path, const std::vector<PlotSeries>& series,
                const std::string& x_label, const std::string& y_label, const std::string& title);

/// write_plot of one unlabelled curve.
void write_line_plot(const std::string& path, const PlotCurve& curve, const std::string& x_label,
                     const std::string& y_label, const std::string& title);

}  // namespace clumpkit
