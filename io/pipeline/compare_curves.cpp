#include "io/pipeline/compare_curves.h"

#include "dem/measure/curve_residual.h"
#include "geom/errors.h"
#include "io/base/units.h"
#include "io/formats/curve_csv.h"
#include "io/reports/plot.h"

#include <cctype>

namespace clumpkit {

namespace {

// The unit both files give a column; InvalidInput when they give two.
std::string common_unit(const CompareCurvesOptions& o, const std::string& column,
                        const std::string& a, const std::string& b) {
  if (!a.empty() && !b.empty() && a != b)
    throw InvalidInput(o.b + ": column '" + column + "' is in " + b + ", in " + a + " in " + o.a +
                       ": compare curves of the same units");
  return a.empty() ? b : a;
}

// The square of a unit: "1" → "1", "Pa" → "Pa2", "N/m" → "(N/m)2".
std::string squared(const std::string& u) {
  if (u.empty() || u == kDimensionless) return u;
  for (char c : u)
    if (!std::isalpha(static_cast<unsigned char>(c))) return "(" + u + ")2";
  return u + "2";
}

}  // namespace

nlohmann::ordered_json compare_curves(const CompareCurvesOptions& o) {
  CurveUnits ua, ub;
  const dem::Curve a = read_curve_columns(o.a, o.x, o.y, &ua);
  const dem::Curve b = read_curve_columns(o.b, o.x, o.y, &ub);
  const std::string x_unit = common_unit(o, o.x, ua.x, ub.x),
                    y_unit = common_unit(o, o.y, ua.y, ub.y);
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
  add_units(j, si_length());
  nlohmann::ordered_json& units = j["units"];
  if (!x_unit.empty()) units["from"] = units["to"] = x_unit;
  if (!y_unit.empty()) units["residual_abs"] = squared(y_unit);
  return j;
}

}  // namespace clumpkit
