#include "io/pipeline/specimen_scale.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/json_file.h"
#include "io/base/text.h"
#include "io/base/units.h"
#include "io/formats/specimen_csv.h"
#include "io/formats/specimen_vtp.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"

#include <cmath>
#include <filesystem>

namespace clumpkit {

namespace fs = std::filesystem;

nlohmann::ordered_json run_specimen_scale(const std::string& specimen_dir, double factor,
                                          const std::string& out_dir) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw InvalidInput("--factor must be positive and finite, got " + format_number(factor));
  check_output_directory(out_dir);
  check_output_spares(out_dir, specimen_dir, "the source");
  const fs::path src = specimen_dir;
  const std::string report_path = (src / "report.json").string();
  std::vector<SpecimenBody> rows = read_specimen_csv((src / "specimen.csv").string());
  read_json_file(report_path);  // refuses a missing or malformed report, naming it
  nlohmann::ordered_json rep = nlohmann::ordered_json::parse(read_file(report_path));
  if (!rep.is_object()) throw InvalidInput(report_path + ": not a JSON object");

  const double l2 = factor * factor, l3 = l2 * factor;
  double largest = 0;
  for (SpecimenBody& b : rows) {
    b.position *= factor;
    for (Sphere& s : b.spheres) {
      s.center *= factor;
      s.radius *= factor;
      largest = std::max(largest, s.center.cwiseAbs().maxCoeff() + s.radius);
    }
    b.mass *= l3;
    b.volume *= l3;
    b.moments *= l3 * l2;
    b.scale *= factor;
  }
  if (!(largest < 1e30))
    throw InvalidInput("--factor " + format_number(factor) +
                       " takes the specimen beyond 1e30 m: choose a smaller factor");

  // report.json: the same fields in the same order, lengths and stiffnesses scaled.
  auto scale = [&](nlohmann::ordered_json& j, const char* key, double by) {
    if (j.contains(key) && j[key].is_number()) j[key] = j[key].get<double>() * by;
  };
  if (rep.contains("container")) {
    scale(rep["container"], "diameter", factor);
    scale(rep["container"], "height", factor);
    for (const char* k : {"size", "lo", "hi"})
      if (rep["container"].contains(k) && rep["container"][k].is_array())
        for (auto& x : rep["container"][k])
          if (x.is_number()) x = x.get<double>() * factor;
  }
  scale(rep, "height", factor);
  scale(rep, "layer_height", factor);
  if (rep.contains("measurement_region")) {
    for (const char* k : {"radius", "z_lo", "z_hi"}) scale(rep["measurement_region"], k, factor);
  }
  if (rep.contains("contact")) {
    // A size-scaled law (kn at d_ref) scales through the diameters: kn_ref and d_ref stay.
    const bool linear = rep["contact"].value("stiffness_scaling", std::string()) == "linear";
    if (!linear) {
      scale(rep["contact"], "kn", factor);
      scale(rep["contact"], "ks", factor);
    }
  }
  rep["scaled_from"] = specimen_dir;
  rep["scale_factor"] = factor;
  add_units(rep, si_length());  // the source's map, if any, replaced

  write_staged(out_dir, [&](const std::string& staging) {
    const fs::path out = staging;
    write_specimen_csv((out / "specimen.csv").string(), rows);
    write_specimen_vtp((out / "specimen.vtp").string(), rows);
    write_file_atomically((out / "report.json").string(),
                          [&](std::ostream& f) { f << rep.dump(2) << "\n"; });
    nlohmann::ordered_json m = manifest_head("specimen-scale", "", "", 0);
    m["source"] = specimen_dir;
    m["factor"] = factor;
    m["bodies"] = rows.size();
    m["files"] = {"specimen.csv", "specimen.vtp", "report.json"};
    add_units(m, si_length());
    write_file_atomically((out / "manifest.json").string(),
                          [&](std::ostream& f) { f << m.dump(2) << "\n"; });
  });
  return rep;
}

}  // namespace clumpkit
