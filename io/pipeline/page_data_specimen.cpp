// A specimen's page data: its spheres (decimated beyond a count) with body, kind, zone and the
// report's porosity bands, its slices and calibration plot.
#include "io/formats/specimen_csv.h"
#include "io/pipeline/page_data.h"

#include <algorithm>

namespace clumpkit::page_data {

std::size_t specimen_data(const Folder& f, const fs::path& out, std::size_t max_spheres,
                          ordered_json& data, std::vector<PageScript>& scripts) {
  const std::vector<SpecimenBody> bodies = read_specimen_csv((f.dir / "specimen.csv").string());
  std::size_t total = 0;
  for (const SpecimenBody& b : bodies) total += b.spheres.size();
  const std::size_t stride = std::max<std::size_t>(1, (total + max_spheres - 1) / max_spheres);
  ordered_json x = ordered_json::array(), y = x, z = x, r = x, body = x, kind = x, zone = x;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  std::size_t k = 0, shown = 0;
  for (const SpecimenBody& b : bodies)
    for (const Sphere& s : b.spheres) {
      // The bounds of every sphere, drawn or not: the view frames the whole specimen.
      lo = lo.cwiseMin(s.center - Vec3::Constant(s.radius));
      hi = hi.cwiseMax(s.center + Vec3::Constant(s.radius));
      if (k++ % stride) continue;
      x.push_back(sig(s.center.x())), y.push_back(sig(s.center.y())),
          z.push_back(sig(s.center.z()));
      r.push_back(sig(s.radius)), body.push_back(b.id), zone.push_back(b.zone);
      kind.push_back(b.kind == dem::BodyKind::rock ? 1 : 0);
      ++shown;
    }
  data["spheres"] = {{"total", total},
                     {"shown", shown},
                     {"stride", stride},
                     {"lo", {lo.x(), lo.y(), lo.z()}},
                     {"hi", {hi.x(), hi.y(), hi.z()}},
                     {"x", x},
                     {"y", y},
                     {"z", z},
                     {"r", r},
                     {"body", body},
                     {"kind", kind},
                     {"zone", zone}};
  // The porosity bands of the report (equal heights of the measurement region), for colouring.
  const nlohmann::json& rep = f.report;
  if (rep.is_object() && rep.contains("band_porosity") && rep["band_porosity"].is_array() &&
      !rep["band_porosity"].empty() && rep.contains("measurement_region"))
    data["spheres"]["bands"] = {{"z_lo", rep["measurement_region"].value("z_lo", 0.0)},
                                {"z_hi", rep["measurement_region"].value("z_hi", 0.0)},
                                {"porosity", rep["band_porosity"]}};
  Images images{out, &scripts};
  std::vector<fs::path> slices;
  if (fs::is_directory(f.dir / "slices"))
    for (const auto& e : fs::directory_iterator(f.dir / "slices"))
      if (e.path().extension() == ".png") slices.push_back(e.path());
  std::sort(slices.begin(), slices.end());
  for (const fs::path& p : slices) images.add(p, "slice " + p.stem().string());
  images.add(f.dir / "calibration.png", "calibration");
  data["images"] = images.list;
  return total;
}

}  // namespace clumpkit::page_data
