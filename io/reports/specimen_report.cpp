#include "io/reports/specimen_report.h"

#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"
#include "io/formats/png.h"
#include "io/reports/plot.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace clumpkit {

namespace fs = std::filesystem;

void write_calibration_csv(const std::string& path, const dem::SpecimenResult& result) {
  write_file_atomically(path, [&](std::ostream& o) {
    o << csv_header("calibration", "friction,porosity,void_ratio,relative_density,steps,stopped_by",
                    si_length())
      << "\n";
    for (const dem::CalibrationPoint& p : result.calibration)
      o << format_number(p.friction) << "," << format_number(p.porosity) << ","
        << format_number(p.void_ratio) << ","
        << format_number(
               dem::relative_density(p.porosity, result.porosity_max, result.porosity_min))
        << "," << p.steps << "," << p.stopped_by << "\n";
  });
}

void write_calibration_plot(const std::string& path, const dem::SpecimenResult& result,
                            double target_relative_density) {
  PlotSeries measured, target, chosen;
  measured.label = "porosity after compaction at friction mu";
  measured.marker = 4;
  double fmax = 0;
  for (const dem::CalibrationPoint& p : result.calibration) {
    measured.points.x.push_back(p.friction);
    measured.points.y.push_back(p.porosity);
    fmax = std::max(fmax, p.friction);
  }
  if (!(fmax > 0)) fmax = 1;
  target.points = {{0.0, fmax}, {result.target_porosity, result.target_porosity}};
  target.label = "target Dr " + format_fixed(target_relative_density, 2) +
                 ": n = " + format_fixed(result.target_porosity, 4);
  target.rgb = {150, 150, 150};
  chosen.points = {{result.friction_compaction}, {result.target_porosity}};
  chosen.label = "chosen mu* = " + format_fixed(result.friction_compaction, 3);
  chosen.rgb = {210, 30, 30};
  chosen.line = false;
  chosen.marker = 6;
  write_plot(path, {target, measured, chosen}, "friction coefficient during compaction, mu (-)",
             "porosity n (-)", "clumpkit specimen: calibration of porosity against friction");
}

std::vector<std::string> write_slices(const std::string& dir, const dem::SpecimenResult& result,
                                      double radius, const std::vector<double>& heights,
                                      int pixels) {
  fs::create_directories(dir);
  std::vector<std::string> names;
  const double scale = pixels / (2.0 * radius);  // pixels per metre
  for (double z : heights) {
    cv::Mat img(pixels, pixels, CV_8UC3, cv::Scalar(255, 255, 255));
    auto to_px = [&](double x, double y) {
      return cv::Point(static_cast<int>(std::lround((x + radius) * scale * 16)),
                       static_cast<int>(std::lround((radius - y) * scale * 16)));
    };
    for (const dem::Body& b : result.world.bodies()) {
      const bool rock = b.kind == dem::BodyKind::rock;
      for (const Sphere& s : b.spheres) {
        const Vec3 c = b.orientation * s.center + b.position;
        const double dz = z - c.z(), r2 = s.radius * s.radius - dz * dz;
        if (r2 <= 0) continue;
        const int r = static_cast<int>(std::lround(std::sqrt(r2) * scale * 16));
        cv::circle(img, to_px(c.x(), c.y()), r,
                   rock ? cv::Scalar(40, 40, 210) : cv::Scalar(200, 90, 30), cv::FILLED,
                   cv::LINE_AA, 4);
      }
    }
    cv::circle(img, to_px(0, 0), static_cast<int>(std::lround(radius * scale * 16)) - 16,
               cv::Scalar(120, 120, 120), 1, cv::LINE_AA, 4);
    char name[64];
    std::snprintf(name, sizeof name, "z%05.0fmm.png", z * 1000.0);
    cv::putText(img,
                std::string("z = ") + std::to_string(static_cast<int>(std::lround(z * 1000))) +
                    " mm  (rock red, soil blue)",
                cv::Point(8, 18), cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0));
    cv::Mat rgb;
    cv::cvtColor(img, rgb, cv::COLOR_BGR2RGB);
    write_png((fs::path(dir) / name).string(), rgb.cols, rgb.rows, 3, rgb.ptr<std::uint8_t>(0),
              rgb.step);
    names.push_back(name);
  }
  return names;
}

namespace {

// The contact law as report.json records it (the test command and the exports read it back).
nlohmann::ordered_json contact_json(const SpecimenRecipe& recipe) {
  nlohmann::ordered_json c = {{"kn", recipe.kn},
                              {"ks", recipe.ks},
                              {"friction", recipe.friction},
                              {"damping_ratio", recipe.damping_ratio},
                              {"local_damping", recipe.local_damping},
                              {"stiffness_scaling", recipe.linear_scaling ? "linear" : "none"}};
  if (recipe.linear_scaling) c["d_ref"] = recipe.d_ref;
  return c;
}

nlohmann::ordered_json report_head(const SpecimenRecipe& recipe) {
  nlohmann::ordered_json j;
  j["recipe"] = recipe.path;
  j["seed"] = recipe.seed;
  return j;
}

// bodies, rocks, soil and spheres of a built specimen.
void add_counts(nlohmann::ordered_json& j, const dem::World& world) {
  std::size_t spheres = 0, rocks = 0;
  for (const dem::Body& b : world.bodies()) {
    spheres += b.spheres.size();
    rocks += b.kind == dem::BodyKind::rock;
  }
  j["bodies"] = world.bodies().size();
  j["rocks"] = rocks;
  j["soil"] = world.bodies().size() - rocks;
  j["spheres"] = spheres;
}

}  // namespace

nlohmann::ordered_json specimen_report(const SpecimenRecipe& recipe, const dem::SpecimenResult& r) {
  nlohmann::ordered_json j = report_head(recipe);
  j["porosity"] = r.porosity;
  j["relative_density"] = r.relative_density;
  j["target_relative_density"] = recipe.target_relative_density;
  j["target_porosity"] = r.target_porosity;
  j["porosity_max"] = r.porosity_max;
  j["porosity_min"] = r.porosity_min;
  j["friction_compaction"] = r.friction_compaction;
  j["friction"] = recipe.friction;
  j["container"] = {{"diameter", recipe.container_diameter}, {"height", recipe.container_height}};
  j["density"] = {{"rock", recipe.rock_density}, {"soil", recipe.soil_density}};
  j["contact"] = contact_json(recipe);
  j["height"] = r.height;
  j["layer_height"] = r.layer_height;
  j["layer_porosity_compacted"] = r.layer_porosity_compacted;
  add_counts(j, r.world);
  j["layer_porosity"] = r.layer_porosity;
  double lo = 1, hi = 0;
  for (double n : r.layer_porosity) lo = std::min(lo, n), hi = std::max(hi, n);
  j["layer_porosity_spread"] = hi - lo;
  j["band_porosity"] = r.band_porosity;
  j["coordination_number"] = r.coordination;
  j["measurement_region"] = {{"radius", r.region.radius},
                             {"z_lo", r.region.z_lo},
                             {"z_hi", r.region.z_hi},
                             {"method",
                              "exact sphere-region volumes (union of each body's "
                              "spheres, slice areas integrated over z)"}};
  nlohmann::ordered_json cal = nlohmann::ordered_json::array();
  for (const auto& p : r.calibration)
    cal.push_back({{"friction", p.friction},
                   {"porosity", p.porosity},
                   {"steps", p.steps},
                   {"stopped_by", p.stopped_by}});
  j["calibration"] = cal;
  nlohmann::ordered_json rounds = nlohmann::ordered_json::array();
  for (const auto& x : r.rounds)
    rounds.push_back({{"friction_compaction", x.friction},
                      {"porosity", x.porosity},
                      {"relative_density", x.relative_density}});
  j["rounds"] = rounds;
  j["timestep"] = r.world.options().timestep;
  j["density_scaling"] = r.density_scaling;
  nlohmann::ordered_json steps, seconds;
  for (const auto& [k, v] : r.steps) steps[k] = v;
  for (const auto& [k, v] : r.seconds) seconds[k] = v;
  j["steps"] = steps;
  j["seconds"] = seconds;
  return j;
}

nlohmann::ordered_json compression_report(const SpecimenRecipe& recipe,
                                          const dem::CompressionResult& r) {
  nlohmann::ordered_json j = report_head(recipe);
  j["method"] = "compression";
  j["porosity"] = r.porosity;
  j["target_porosity"] = r.target_porosity;
  j["friction_compression"] = recipe.compression_friction;
  j["friction"] = recipe.friction;
  if (recipe.cuboid)
    j["container"] = {{"shape", "cuboid"},
                      {"size", {r.hi.x() - r.lo.x(), r.hi.y() - r.lo.y(), r.hi.z() - r.lo.z()}},
                      {"lo", {r.lo.x(), r.lo.y(), r.lo.z()}},
                      {"hi", {r.hi.x(), r.hi.y(), r.hi.z()}}};
  else if (recipe.segment)
    j["container"] = {{"shape", "segment"},
                      {"diameter", 2 * r.radius},
                      {"height", r.height},
                      {"angle_deg", recipe.segment_angle_deg}};
  else
    j["container"] = {{"shape", "cylinder"}, {"diameter", 2 * r.radius}, {"height", r.height}};
  j["density"] = {{"rock", recipe.rock_density}, {"soil", recipe.soil_density}};
  j["contact"] = contact_json(recipe);
  j["height"] = r.height;
  add_counts(j, r.world);
  j["coordination_number"] = r.coordination;
  j["mean_stress"] = r.mean_stress;
  j["gravity"] = false;
  j["timestep"] = r.timestep;
  j["steps"] = {{"compression", r.compression_steps}, {"relaxation", r.relax_steps}};
  j["relaxed_by"] = r.relaxed_by;
  if (!r.zones.empty()) {
    const dem::ZoneLayout& layout = recipe.zones;
    const char* coordinate = layout.coordinate == dem::ZoneCoordinate::radial  ? "radial"
                             : layout.coordinate == dem::ZoneCoordinate::depth ? "depth"
                                                                               : "spherical";
    nlohmann::ordered_json zones = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < r.zones.size(); ++k) {
      const dem::ZoneResult& z = r.zones[k];
      const dem::ZoneRegion& region = layout.regions[k];
      nlohmann::ordered_json e;
      e["zone"] = k;
      e["kind"] = region.mixed ? "mixed" : "uniform";
      e["inner"] = z.inner;
      e["outer"] = z.outer;
      if (region.mixed) {
        e["scale_small"] = dem::small_scale(layout, int(k));
        e["scale_large"] = dem::large_scale(layout, int(k));
        e["small_volume_fraction"] = {region.small_fraction, region.small_fraction_outer};
      } else {
        e["scale"] = region.scale;
      }
      e["volume"] = z.volume;
      e["target_porosity"] = z.target_porosity;
      // NaN (no region left away from the walls) is written as null.
      e["porosity"] = std::isfinite(z.porosity) ? nlohmann::ordered_json(z.porosity)
                                                : nlohmann::ordered_json(nullptr);
      e["porosity_margin"] = z.margin;
      e["solid_goal"] = z.solid_goal;
      e["solid_drawn"] = z.solid_drawn;
      e["count"] = z.count;
      e["left_zone"] = z.left_zone;
      e["migrated"] = z.migrated;
      e["mis_zoned"] = z.mis_zoned;
      zones.push_back(std::move(e));
    }
    j["zones"] = {{"coordinate", coordinate},
                  {"origin", {layout.origin.x(), layout.origin.y(), layout.origin.z()}},
                  {"wall_excess_diameters", dem::CompressionSpec().wall_excess},
                  {"left_zone", r.left_zone},
                  {"migrated", r.migrated},
                  {"migrated_fraction", double(r.migrated) / double(r.world.bodies().size())},
                  {"mis_zoned", r.mis_zoned},
                  {"mis_zoned_fraction", double(r.mis_zoned) / double(r.world.bodies().size())},
                  {"regions", std::move(zones)}};
    if (!recipe.zone_warnings.empty()) j["zones"]["warnings"] = recipe.zone_warnings;
  }
  return j;
}

}  // namespace clumpkit
