#include "io/reports/cpt_report.h"

#include "io/reports/plot.h"

#include <algorithm>

namespace clumpkit {

void add_cpt_summary(nlohmann::ordered_json& report, const std::vector<dem::CptRow>& curve) {
  const double last = curve.empty() ? 0.0 : curve.back().depth;
  double qc_max = 0, qc_sum = 0, fs_sum = 0;
  int n = 0;
  for (const dem::CptRow& c : curve) {
    qc_max = std::max(qc_max, c.qc);
    if (c.depth >= 0.5 * last) qc_sum += c.qc, fs_sum += c.fs, ++n;
  }
  report["qc_max"] = qc_max;
  report["qc_mean_second_half"] = n ? qc_sum / n : 0.0;
  report["fs_mean_second_half"] = n ? fs_sum / n : 0.0;
}

void write_cpt_plot(const std::string& path, const std::vector<dem::CptRow>& curve,
                    const std::string& title) {
  PlotCurve plot;
  for (const dem::CptRow& c : curve) plot.x.push_back(c.depth), plot.y.push_back(c.qc / 1e6);
  write_line_plot(path, plot, "depth (m)", "cone resistance qc (MPa)", title);
}

}  // namespace clumpkit
