#include "io/pipeline/compare_curves.h"

#include "dem/measure/curve_residual.h"
#include "io/formats/curve_csv.h"
#include "io/reports/plot.h"

namespace clumpkit {

nlohmann::ordered_json compare_curves(const CompareCurvesOptions& o) {
  const dem::Curve a = read_curve_columns(o.a, o.x, o.y);
  const dem::Curve b = read_curve_columns(o.b, o.x, o.y);
  const dem::CurveResidual r = dem::curve_residual(a, b, o.points, o.from, o.to);
  if (!o.png.empty()) {
    PlotSeries pa{{a.x, a.y}, o.a, {20, 70, 180}}, pb{{b.x, b.y}, o.b, {200, 40, 30}};
    write_plot(o.png, {pa, pb}, o.x, o.y, o.y + " against " + o.x);
  }
  nlohmann::ordered_json j;
  j["a"] = o.a;
  j["b"] = o.b;
  j["x"] = o.x;
  j["y"] = o.y;
  j["from"] = r.from;
  j["to"] = r.to;
  j["points"] = r.points;
  j["residual_abs"] = r.residual_abs;
  j["residual_rel"] = r.residual_rel;
  j["relative_points"] = r.relative_points;
  return j;
}

}  // namespace clumpkit
