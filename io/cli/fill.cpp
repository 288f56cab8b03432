// `clumpkit fill MESH -o CLUMP.csv`: maximal-inscribed-sphere clump of one mesh, greedy then
// refined.
#include "io/pipeline/fill.h"
#include "geom/errors.h"
#include "geom/format.h"
#include "io/base/units.h"
#include "io/cli/common.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

namespace {

// The printed report of `clumpkit fill` (without --json); lengths in `length`.
void print_fill_report(const FillJobResult& r, const std::string& out, const LengthUnit& length) {
  const nlohmann::ordered_json& j = r.report;
  const Fidelity& f = r.fidelity;
  const auto& phase = j["seconds_by_phase"];
  std::printf(
      "wrote %s: %d spheres (stopped by %s), covered %.4f, overshoot %.4f, surface gap "
      "mean %s %s max %s %s, %.3f s (read %.3f, index %.3f, field %.3f, fill %.3f, fidelity "
      "%.3f)\n",
      out.c_str(), f.spheres, r.fill.stopped_by.c_str(), f.covered_fraction, f.overshoot_fraction,
      format_number(f.surface_mean_distance).c_str(), length.symbol.c_str(),
      format_number(f.surface_max_distance).c_str(), length.symbol.c_str(),
      j["seconds"].get<double>(), phase["read"].get<double>(), phase["index"].get<double>(),
      phase["field"].get<double>(), phase["fill"].get<double>(), phase["fidelity"].get<double>());
  const auto& res = j["resolution"];
  if (res.contains("covered_change"))
    std::printf("at twice the voxels (voxel %s %s): covered %.4f, a change of %+.4f\n",
                format_number(res["finer_voxel"].get<double>()).c_str(), length.symbol.c_str(),
                res["covered_fraction_finer"].get<double>(), res["covered_change"].get<double>());
  if (r.fill.refine_sweeps > 0 || r.fill.grow_steps > 0)
    std::printf(
        "refined in %d sweeps (%d moves), %d steps of growth within the overshoot budget: "
        "covered %.4f -> %.4f, overshoot %.4f -> %.4f\n",
        r.fill.refine_sweeps, r.fill.refine_moves, r.fill.grow_steps,
        r.greedy_fidelity.covered_fraction, f.covered_fraction,
        r.greedy_fidelity.overshoot_fraction, f.overshoot_fraction);
}

}  // namespace

void register_fill(CLI::App& app) {
  struct Opts {
    std::string mesh, out, png, vtp, wrap, length_unit = "L";
    FillOptions fill;
    RepairOptions repair;
    int spheres = -1;
    double max_memory_gib = 0;  // 0: half of this machine's memory
    bool json = false, allow_open = false, check_resolution = false, repair_first = false;
    MeshReadOptions read;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "fill",
      "Clump of overlapping spheres inscribed in a closed mesh (units of the mesh): the largest "
      "inscribed sphere, then repeatedly the medial sphere covering the most uncovered volume "
      "(Zhang & Zhou 2015 §2.3), then each sphere moved where it covers more of what the others "
      "leave (Wang et al. 2006). Writes x,y,z,r CSV and prints a fidelity report.");
  c->add_option("MESH", o->mesh, "Closed mesh (STL, OBJ, PLY)")->required();
  c->add_option("-o,--output", o->out, "Clump CSV to write")->required();
  c->add_option("--spheres", o->spheres, "Sphere budget, at least 1 (default 50 if no --coverage)");
  c->add_option("--coverage", o->fill.coverage,
                "Stop at this covered fraction of the volume, in (0, 1]");
  c->add_option("--min-radius", o->fill.min_radius,
                "Smallest sphere radius R_lim (Jin et al. 2017)")
      ->capture_default_str();
  auto* voxels =
      c->add_option("--voxels", o->fill.field.voxels,
                    "Voxels across the smallest principal extent (default 40, finer where the "
                    "sphere budget needs smaller spheres, coarser for platy or elongated shapes: "
                    "at most 1e6 voxels unless this is given)")
          ->capture_default_str();
  auto* voxel_size = c->add_option("--voxel-size", o->fill.field.voxel_size,
                                   "Explicit voxel size (overrides --voxels)");
  c->add_option("--max-overshoot", o->fill.max_overshoot,
                "Largest volume the clump may put outside the mesh, as a fraction of the mesh's "
                "volume; every fill meets it (spheres reach past the surface at point contacts "
                "only while it holds). 0 keeps every sphere inside")
      ->capture_default_str();
  c->add_option("--refine-iterations", o->fill.refine_iterations,
                "Sweeps of the refinement after the greedy pass: each sphere moved, within the "
                "overshoot contract, to cover more of what the others leave; stops early once a "
                "sweep gains under 0.02 % of the volume. 0: the greedy clump as it is")
      ->capture_default_str();
  c->add_flag("--check-resolution", o->check_resolution,
              "Also fill on a grid of twice the voxels and report the change of coverage "
              "(about three times the work); the clump written is the first one");
  add_max_memory_option(c, o->max_memory_gib,
                        "a fill estimated to need more than this many GiB, before allocating");
  c->add_flag("--allow-open", o->allow_open,
              "Accept a mesh that is not watertight: inside/outside by Embree ray-parity voting "
              "(the report says so; volumes are then approximate, and the overshoot is measured "
              "against the voted inside; `clumpkit repair` closes the mesh instead)");
  c->add_flag("--repair", o->repair_first,
              "Repair the mesh in memory first, as `clumpkit repair` does (holes closed, "
              "crossings mended, a wrap as the last resort; --wrap and the other repair options "
              "below), so a raw scan fills in one command; the report's `repair` says what it "
              "did");
  add_repair_options(c, o->repair, o->wrap);
  c->add_option("--png", o->png,
                "Also write this picture (900 px: front, side, top and oblique views, the spheres "
                "lit and coloured under the translucent mesh, caps outside it red)");
  c->add_option("--vtp", o->vtp,
                "Also write mesh and spheres for ParaView here (Glyph: Sphere, Scale Array "
                "diameter, Scale Factor 1)");
  c->add_flag("--json", o->json, "Print the fidelity report as JSON on stdout");
  add_weld_option(c, o->read.weld_tolerance);
  add_length_unit_option(c, o->length_unit);
  c->callback([o, voxels, voxel_size] {
    const LengthUnit length = length_unit(o->length_unit);
    if (o->spheres == 0 || o->spheres < -1)
      throw InvalidInput("--spheres must be at least 1, got " + std::to_string(o->spheres));
    o->fill.spheres = std::max(0, o->spheres);
    // The default resolution has a budget; a resolution asked for is what it says.
    o->fill.field.max_voxels = voxels->count() > 0 ? 0.0 : kDefaultMaxVoxels;
    o->fill.voxels_from_count = voxels->count() == 0 && voxel_size->count() == 0;
    o->fill.field.max_bytes = max_memory_bytes(o->max_memory_gib);
    FillJobOptions job;
    job.mesh = o->mesh;
    job.out = o->out;
    job.png = o->png;
    job.vtp = o->vtp;
    job.fill = o->fill;
    job.allow_open = o->allow_open;
    job.check_resolution = o->check_resolution;
    job.read = o->read;
    job.repair = o->repair_first;
    job.repair_options = repair_options_from(o->repair, o->wrap);
    job.length = length;
    const FillJobResult r = run_fill_job(job, note, warning);
    if (o->json)
      std::cout << r.report.dump(2) << "\n";
    else
      print_fill_report(r, o->out, length);
  });
}

}  // namespace clumpkit::cli
