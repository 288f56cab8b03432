// `clumpkit volume CLUMP.csv`: volume, area, centroid and inertia of a union of spheres by
// several methods (exact power diagram, inclusion–exclusion, analytic and pixel slicing, voxels).
#include "io/pipeline/volume.h"
#include "geom/format.h"
#include "io/base/units.h"
#include "io/cli/common.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

void register_volume(CLI::App& app) {
  struct Opts {
    std::string clump, method = "exact", rule = "touch", png, length_unit;
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
  add_max_memory_option(c, o->max_memory_gib,
                        "a method estimated to need more than this many GiB, before computing "
                        "anything");
  c->add_flag("--json", o->json, "Print one JSON object keyed by method on stdout");
  auto* unit = add_length_unit_option(
      c, o->length_unit,
      "The clump file's length unit, e.g. mm: only labels the output (default: the unit its "
      "header names, else L, the file's unit)");
  c->callback([o, unit] {
    VolumeJobOptions job;
    if (unit->count() > 0) job.length_unit = o->length_unit;
    job.clump = o->clump;
    job.method = o->method;
    job.slices = o->slices;
    job.pixel = o->pixel;
    job.rule = o->rule;
    job.png = o->png;
    job.voxel = o->voxel;
    job.max_bytes = max_memory_bytes(o->max_memory_gib);
    const VolumeJobResult r = run_volume_job(job);
    const nlohmann::ordered_json& out = r.methods;
    if (o->json) {
      nlohmann::ordered_json with_units = out;
      add_units(with_units, r.length);
      std::cout << with_units.dump(2) << "\n";
      return;
    }
    std::printf("%s: %zu spheres\n", o->clump.c_str(), r.spheres);
    for (const auto& [method, j] : out.items()) {
      std::printf("  %-20s volume %s %s", method.c_str(),
                  format_number(j["volume"].get<double>()).c_str(), r.length.pow(3).c_str());
      if (j.contains("area"))
        std::printf("  area %s %s", format_number(j["area"].get<double>()).c_str(),
                    r.length.pow(2).c_str());
      if (j.contains("centroid"))
        std::printf("  centroid (%s, %s, %s) %s",
                    format_number(j["centroid"][0].get<double>()).c_str(),
                    format_number(j["centroid"][1].get<double>()).c_str(),
                    format_number(j["centroid"][2].get<double>()).c_str(), r.length.symbol.c_str());
      std::printf("  %.4f s\n", j["seconds"].get<double>());
    }
  });
}

}  // namespace clumpkit::cli
