// `clumpkit volume CLUMP.csv`: volume, area, centroid and inertia of a union of spheres by
// several methods (exact power diagram, inclusion–exclusion, analytic and pixel slicing, voxels).
#include "geom/errors.h"
#include "geom/volume/inclusion_exclusion.h"
#include "geom/volume/pixel_slicing.h"
#include "geom/volume/slicing.h"
#include "geom/volume/union_of_balls.h"
#include "geom/volume/voxel_volume.h"
#include "io/cli/common.h"
#include "io/clump_io.h"
#include "io/png.h"
#include "io/report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

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

void register_volume(CLI::App& app) {
  struct Opts {
    std::string clump, method = "exact", rule = "touch", png;
    int slices = 100;
    double pixel = 0.0, voxel = 0.0;
    double max_memory_gib = 0;  // 0: half of this machine's memory
    bool json = false;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "volume",
      "Volume of a clump (CSV x,y,z,r; units of the file). Methods: exact (power diagram: volume, "
      "area, centroid, inertia about the centroid at unit density), inclusion-exclusion (volume, "
      "area over the alpha-0 dual complex), analytic-slice (exact slice areas, Gauss-Legendre in "
      "z), "
      "pixel-slice (Jin et al. 2017 §3: rasterised slices), voxel (OpenVDB level set), or all.");
  c->add_option("CLUMP", o->clump, "Clump CSV (x,y,z,r)")->required();
  c->add_option("--method", o->method,
                "exact|inclusion-exclusion|analytic-slice|pixel-slice|voxel|all")
      ->capture_default_str();
  c->add_option("--slices", o->slices,
                "pixel-slice: slices across the smallest sphere (paper: 100)")
      ->capture_default_str();
  c->add_option("--pixel", o->pixel, "pixel-slice: pixel size (default: the slice spacing)");
  c->add_option("--rule", o->rule,
                "pixel-slice: pixel counted if its centre is inside (centre) or if "
                "the circle touches it (touch, the paper's bias)")
      ->capture_default_str();
  c->add_option("--png", o->png, "pixel-slice: write slice images into this directory");
  c->add_option("--voxel", o->voxel, "voxel: voxel size (default: smallest radius / 10)");
  c->add_option("--max-memory", o->max_memory_gib,
                "Refuse, before computing anything, a method estimated to need more than this "
                "many GiB (default: half of this machine's memory)");
  c->add_flag("--json", o->json, "Print one JSON object keyed by method on stdout");
  c->callback([o] {
    const std::vector<std::string> known = {
        "exact", "inclusion-exclusion", "analytic-slice", "pixel-slice", "voxel", "all"};
    if (std::find(known.begin(), known.end(), o->method) == known.end())
      throw InvalidInput(
          "--method: unknown method '" + o->method +
          "' (known: exact, inclusion-exclusion, analytic-slice, pixel-slice, voxel, all)");
    if (o->rule != "centre" && o->rule != "center" && o->rule != "touch")
      throw InvalidInput("--rule: expected centre or touch, got '" + o->rule + "'");
    const double budget = max_memory_bytes(o->max_memory_gib);
    const Clump clump = read_clump(o->clump);
    auto want = [&](const char* m) { return o->method == m || o->method == "all"; };
    PixelSliceOptions po;
    po.slices_across_smallest = o->slices;
    po.pixel = o->pixel;
    po.rule = o->rule == "touch" ? PixelRule::Touch : PixelRule::Centre;
    double h = o->voxel;
    if (h <= 0) {
      double rmin = clump.spheres[0].radius;
      for (const auto& s : clump.spheres) rmin = std::min(rmin, s.radius);
      h = rmin / 10.0;
    }
    // Every method asked for is checked before the first one runs, so a refusal costs nothing.
    auto check = [&](const char* method, double need, const std::string& advice) {
      if (!(need <= budget))
        throw InvalidInput("volume --method " + std::string(method) + " on " + o->clump +
                           " would need an estimated " + format_number(need / 1073741824.0, 3) +
                           " GiB, more than --max-memory " +
                           format_number(budget / 1073741824.0, 3) + " GiB: " + advice);
    };
    if (want("exact") || want("analytic-slice") || want("inclusion-exclusion"))
      check(o->method == "all" ? "exact" : o->method.c_str(), union_bytes_estimate(clump),
            "split the clump");
    if (want("pixel-slice"))
      check("pixel-slice", pixel_slice_bytes_estimate(clump, po),
            "use fewer --slices or a larger --pixel");
    if (want("voxel"))
      check("voxel", voxel_volume_bytes_estimate(clump, h), "use a larger --voxel");
    nlohmann::ordered_json out;
    if (want("exact")) {
      const double t0 = now();
      const UnionProperties u = union_properties(clump);
      auto j = mass_json(u.mass);
      j["area"] = u.area;
      j["hidden_spheres"] = u.hidden;
      j["seconds"] = now() - t0;
      out["exact"] = j;
    }
    if (want("inclusion-exclusion")) {
      const double t0 = now();
      const UnionMeasure u = union_measure_inclusion_exclusion(clump);
      out["inclusion_exclusion"] = {
          {"volume", u.volume}, {"area", u.area}, {"seconds", now() - t0}};
    }
    if (want("analytic-slice")) {
      const double t0 = now();
      auto j = mass_json(union_properties_by_slicing(clump));
      j["seconds"] = now() - t0;
      out["analytic_slice"] = j;
    }
    if (want("pixel-slice")) {
      const double t0 = now();
      if (!o->png.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(o->png, ec);
        if (ec) throw IoError(o->png + ": cannot create directory: " + ec.message());
        po.on_slice = [&](int k, int w, int h, const std::uint8_t* px) {
          // Filled region black on white, as in Jin et al. 2017 Fig. 7.
          std::vector<std::uint8_t> inv(px, px + std::size_t(w) * h);
          for (auto& v : inv) v = 255 - v;
          char name[32];
          std::snprintf(name, sizeof name, "slice_%04d.png", k);
          write_png((std::filesystem::path(o->png) / name).string(), w, h, 1, inv.data());
        };
      }
      const PixelSliceResult p = pixel_slice_volume(clump, po);
      out["pixel_slice"] = {{"volume", p.volume}, {"slices", p.slices}, {"spacing", p.spacing},
                            {"pixel", p.pixel},   {"rule", o->rule},    {"seconds", now() - t0}};
    }
    if (want("voxel")) {
      const double t0 = now();
      const VoxelVolumeResult v = voxel_volume(clump, h);
      out["voxel"] = {{"volume", v.volume_levelset},
                      {"volume_voxel_count", v.volume_count},
                      {"voxel", v.voxel},
                      {"seconds", now() - t0}};
    }
    if (o->json) {
      std::cout << out.dump(2) << "\n";
      return;
    }
    std::printf("%s: %zu spheres\n", o->clump.c_str(), clump.spheres.size());
    for (const auto& [method, j] : out.items()) {
      std::printf("  %-20s volume %s", method.c_str(),
                  format_number(j["volume"].get<double>()).c_str());
      if (j.contains("area"))
        std::printf("  area %s", format_number(j["area"].get<double>()).c_str());
      if (j.contains("centroid"))
        std::printf("  centroid (%s, %s, %s)",
                    format_number(j["centroid"][0].get<double>()).c_str(),
                    format_number(j["centroid"][1].get<double>()).c_str(),
                    format_number(j["centroid"][2].get<double>()).c_str());
      std::printf("  %.4f s\n", j["seconds"].get<double>());
    }
  });
}

}  // namespace clumpkit::cli
