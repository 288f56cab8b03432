// A line plot as PNG (OpenCV drawing): labelled axes with ticks, for curves such as a test's
// stress against strain.
#pragma once

#include <string>
#include <vector>

namespace clumpkit {

/// One curve: its points (x[k], y[k]), drawn as connected segments.
struct PlotCurve {
  std::vector<double> x, y;
};

/// Draws the curve on a 800 × 560 white canvas with a frame, five ticks per axis with their
/// values, the axis labels (with units) and a title, and writes it as PNG (atomically).
/// Non-finite points are skipped. Throws InvalidInput for a curve with no finite point.
void write_line_plot(const std::string& path, const PlotCurve& curve, const std::string& x_label,
                     const std::string& y_label, const std::string& title);

}  // namespace clumpkit
