#include "io/pipeline/volume.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/volume/inclusion_exclusion.h"
#include "geom/volume/pixel_slicing.h"
#include "geom/volume/slicing.h"
#include "geom/volume/union_of_balls.h"
#include "geom/volume/voxel_volume.h"
#include "io/formats/clump_io.h"
#include "io/formats/png.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

namespace clumpkit {

namespace {
double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
nlohmann::ordered_json mass_json(const MassProperties& m) {
  nlohmann::ordered_json j;
  j["volume"] = m.volume;
  j["centroid"] = {m.centroid.x(), m.centroid.y(), m.centroid.z()};
  j["inertia"] = nlohmann::ordered_json::array();
  for (int r = 0; r < 3; ++r)
    j["inertia"].push_back({m.inertia(r, 0), m.inertia(r, 1), m.inertia(r, 2)});
  return j;
}
}  // namespace

VolumeJobResult run_volume_job(const VolumeJobOptions& options) {
  check_volume_options(options);
  VolumeJobResult result;
  const std::string file_unit = read_clump_length_unit(options.clump);
  if (!options.length_unit.empty()) {
    result.length = length_unit(options.length_unit);
    // "L" is a file's own unit, unnamed: naming it is what --length-unit is for.
    if (!file_unit.empty() && file_unit != "L" && file_unit != result.length.symbol)
      throw InvalidInput("--length-unit " + options.length_unit + ": " + options.clump +
                         " says its lengths are in " + file_unit);
  } else if (!file_unit.empty()) {
    result.length = LengthUnit{file_unit};
  }
  const Clump clump = read_clump(options.clump);
  result.spheres = clump.spheres.size();
  result.methods = measure_volume(clump, options, options.clump);
  return result;
}

void check_volume_options(const VolumeJobOptions& options) {
  const std::vector<std::string> known = {
      "exact", "inclusion-exclusion", "analytic-slice", "pixel-slice", "voxel", "all"};
  if (std::find(known.begin(), known.end(), options.method) == known.end())
    throw InvalidInput(
        "--method: unknown method '" + options.method +
        "' (known: exact, inclusion-exclusion, analytic-slice, pixel-slice, voxel, all)");
  if (options.rule != "centre" && options.rule != "center" && options.rule != "touch")
    throw InvalidInput("--rule: expected centre or touch, got '" + options.rule + "'");
}

nlohmann::ordered_json measure_volume(const Clump& clump, const VolumeJobOptions& options,
                                      const std::string& name, const Interrupter& interrupter) {
  check_volume_options(options);
  validate(clump);
  const double budget = options.max_bytes;
  auto want = [&](const char* m) { return options.method == m || options.method == "all"; };
  PixelSliceOptions po;
  po.slices_across_smallest = options.slices;
  po.pixel = options.pixel;
  po.rule = options.rule == "touch" ? PixelRule::Touch : PixelRule::Centre;
  double h = options.voxel;
  if (h <= 0) {
    double rmin = clump.spheres[0].radius;
    for (const auto& s : clump.spheres) rmin = std::min(rmin, s.radius);
    h = rmin / 10.0;
  }
  // Every method asked for is checked before the first one runs, so a refusal costs nothing.
  auto check = [&](const char* method, double need, const std::string& advice) {
    if (!(need <= budget))
      throw InvalidInput("volume --method " + std::string(method) + " on " + name +
                         " would need an estimated " + format_number(need / 1073741824.0, 3) +
                         " GiB, more than --max-memory " + format_number(budget / 1073741824.0, 3) +
                         " GiB: " + advice);
  };
  if (want("exact")) check("exact", union_bytes_estimate(clump), "split the clump");
  for (const char* whole : {"analytic-slice", "inclusion-exclusion"})
    if (want(whole)) check(whole, whole_triangulation_bytes_estimate(clump), "split the clump");
  if (want("pixel-slice"))
    check("pixel-slice", pixel_slice_bytes_estimate(clump, po),
          "use fewer --slices or a larger --pixel");
  if (want("voxel")) check("voxel", voxel_volume_bytes_estimate(clump, h), "use a larger --voxel");
  nlohmann::ordered_json out;
  if (want("exact")) {
    const double t0 = now();
    const UnionProperties u = union_properties(clump, interrupter);
    auto j = mass_json(u.mass);
    j["area"] = u.area;
    j["hidden_spheres"] = u.hidden;
    j["seconds"] = now() - t0;
    out["exact"] = j;
  }
  if (want("inclusion-exclusion")) {
    const double t0 = now();
    const UnionMeasure u = union_measure_inclusion_exclusion(clump);
    out["inclusion_exclusion"] = {{"volume", u.volume}, {"area", u.area}, {"seconds", now() - t0}};
  }
  if (want("analytic-slice")) {
    const double t0 = now();
    auto j = mass_json(union_properties_by_slicing(clump));
    j["seconds"] = now() - t0;
    out["analytic_slice"] = j;
  }
  if (want("pixel-slice")) {
    const double t0 = now();
    if (!options.png.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(options.png, ec);
      if (ec) throw IoError(options.png + ": cannot create directory: " + ec.message());
      po.on_slice = [&](int k, int w, int h, const std::uint8_t* px) {
        // Filled region black on white, as in Jin et al. 2017 Fig. 7.
        std::vector<std::uint8_t> inv(px, px + std::size_t(w) * h);
        for (auto& v : inv) v = 255 - v;
        char name[32];
        std::snprintf(name, sizeof name, "slice_%04d.png", k);
        write_png((std::filesystem::path(options.png) / name).string(), w, h, 1, inv.data());
      };
    }
    const PixelSliceResult p = pixel_slice_volume(clump, po);
    out["pixel_slice"] = {{"volume", p.volume}, {"slices", p.slices},   {"spacing", p.spacing},
                          {"pixel", p.pixel},   {"rule", options.rule}, {"seconds", now() - t0}};
  }
  if (want("voxel")) {
    const double t0 = now();
    const VoxelVolumeResult v = voxel_volume(clump, h);
    out["voxel"] = {{"volume", v.volume_levelset},
                    {"volume_voxel_count", v.volume_count},
                    {"voxel", v.voxel},
                    {"seconds", now() - t0}};
  }
  return out;
}

}  // namespace clumpkit
