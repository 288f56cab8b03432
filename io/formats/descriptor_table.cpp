#include "io/formats/descriptor_table.h"

namespace clumpkit {

nlohmann::json to_json(const Descriptors& d) {
  nlohmann::json j;
  j["volume"] = d.volume;
  j["area"] = d.area;
  j["sphericity"] = d.sphericity;
  j["equivalent_diameter"] = d.equivalent_diameter;
  j["L"] = d.L;
  j["W"] = d.W;
  j["H"] = d.H;
  j["axes"] = {d.axes[0], d.axes[1], d.axes[2]};
  j["E"] = d.E;
  j["F"] = d.F;
  j["AR"] = d.AR;
  j["convexity"] = d.convexity;
  j["weighted_roundness"] = d.roundness.weighted;
  j["view_roundness"] = {d.roundness.view[0], d.roundness.view[1], d.roundness.view[2]};
  return j;
}

const std::vector<std::string>& descriptor_csv_columns() {
  static const std::vector<std::string> c = {"volume",
                                             "area",
                                             "sphericity",
                                             "equivalent_diameter",
                                             "L",
                                             "W",
                                             "H",
                                             "axis_S",
                                             "axis_I",
                                             "axis_L",
                                             "E",
                                             "F",
                                             "AR",
                                             "convexity",
                                             "weighted_roundness",
                                             "roundness_S",
                                             "roundness_I",
                                             "roundness_L"};
  return c;
}

std::vector<double> descriptor_csv_values(const Descriptors& d) {
  return {d.volume,
          d.area,
          d.sphericity,
          d.equivalent_diameter,
          d.L,
          d.W,
          d.H,
          d.axes[0],
          d.axes[1],
          d.axes[2],
          d.E,
          d.F,
          d.AR,
          d.convexity,
          d.roundness.weighted,
          d.roundness.view[0],
          d.roundness.view[1],
          d.roundness.view[2]};
}

}  // namespace clumpkit
