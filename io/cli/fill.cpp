// `clumpkit fill MESH -o CLUMP.csv`: greedy maximal-inscribed-sphere clump of one mesh.
#include "geom/fill/fill.h"
#include "geom/errors.h"
#include "geom/fill/fidelity.h"
#include "io/cli/common.h"
#include "io/clump_io.h"
#include "io/clump_vtp.h"
#include "io/mesh_io.h"
#include "io/report.h"
#include "io/views.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace clumpkit::cli {

nlohmann::ordered_json fidelity_json(const Fidelity& f) {
  nlohmann::ordered_json j;
  j["spheres"] = f.spheres;
  j["mesh_volume"] = f.mesh_volume;
  j["mesh_volume_method"] = f.mesh_volume_method;
  j["clump_volume"] = f.clump_volume;
  j["clump_volume_method"] = f.clump_volume_method;
  j["covered_fraction"] = f.covered_fraction;
  j["overshoot_fraction"] = f.overshoot_fraction;
  j["surface_mean_distance"] = f.surface_mean_distance;
  j["surface_max_distance"] = f.surface_max_distance;
  j["centroid_offset"] = f.centroid_offset;
  j["inertia_error"] = f.inertia_error;
  j["overshoot_depth_max"] = f.overshoot_depth_max;
  return j;
}

void register_fill(CLI::App& app) {
  struct Opts {
    std::string mesh, out, png, vtp;
    FillOptions fill;
    int spheres = -1;
    double max_memory_gib = 0;  // 0: half of this machine's memory
    bool json = false, allow_open = false;
  };
  auto o = std::make_shared<Opts>();
  auto* c = app.add_subcommand(
      "fill",
      "Clump of overlapping spheres inscribed in a closed mesh (units of the mesh): the largest "
      "inscribed sphere, then repeatedly the medial sphere covering the most uncovered volume "
      "(Zhang & Zhou 2015 §2.3). Writes x,y,z,r CSV and prints a fidelity report.");
  c->add_option("MESH", o->mesh, "Closed mesh (STL, OBJ, PLY)")->required();
  c->add_option("-o,--output", o->out, "Clump CSV to write")->required();
  c->add_option("--spheres", o->spheres, "Sphere budget, at least 1 (default 50 if no --coverage)");
  c->add_option("--coverage", o->fill.coverage,
                "Stop at this covered fraction of the volume, in (0, 1]");
  c->add_option("--min-radius", o->fill.min_radius,
                "Smallest sphere radius R_lim (Jin et al. 2017)")
      ->capture_default_str();
  c->add_option("--voxels", o->fill.field.voxels, "Voxels across the smallest principal extent")
      ->capture_default_str();
  c->add_option("--voxel-size", o->fill.field.voxel_size,
                "Explicit voxel size (overrides --voxels)");
  c->add_option("--max-overshoot", o->fill.max_overshoot,
                "Largest volume the clump may put outside the mesh, as a fraction of the mesh's "
                "volume; every fill meets it (spheres reach past the surface at point contacts "
                "only while it holds). 0 keeps every sphere inside")
      ->capture_default_str();
  c->add_option("--max-memory", o->max_memory_gib,
                "Refuse, before allocating, a fill estimated to need more than this many GiB "
                "(default: half of this machine's memory)");
  c->add_flag("--allow-open", o->allow_open,
              "Accept a mesh that is not watertight: inside/outside by Embree ray-parity voting "
              "(the report says so; volumes are then approximate)");
  c->add_option("--png", o->png,
                "Also write this picture (900 px: front, side, top and oblique views, the spheres "
                "lit and coloured under the translucent mesh, caps outside it red)");
  c->add_option("--vtp", o->vtp,
                "Also write mesh and spheres for ParaView here (Glyph: Sphere, Scale Array "
                "diameter, Scale Factor 1)");
  c->add_flag("--json", o->json, "Print the fidelity report as JSON on stdout");
  c->callback([o] {
    const auto t0 = std::chrono::steady_clock::now();
    if (o->spheres == 0 || o->spheres < -1)
      throw InvalidInput("--spheres must be at least 1, got " + std::to_string(o->spheres));
    o->fill.spheres = std::max(0, o->spheres);
    o->fill.field.max_bytes = max_memory_bytes(o->max_memory_gib);
    validate(o->fill);
    check_not_input(o->out, "--output", o->mesh);
    // Every output's folder must exist before the work, so a failure leaves no partial output.
    for (const auto& [option, path] :
         {std::pair<const char*, const std::string&>{"--output", o->out},
          {"--png", o->png},
          {"--vtp", o->vtp}}) {
      if (path.empty()) continue;
      if (std::string(option) != "--output") {
        check_not_input(path, option, o->mesh);
        if (path == o->out || (!o->png.empty() && o->png == o->vtp))
          throw InvalidInput(std::string(option) + " " + path +
                             ": names another output of this run; choose distinct files");
      }
      const auto dir = std::filesystem::path(path).parent_path();
      if (!dir.empty() && !std::filesystem::is_directory(dir))
        throw InvalidInput(std::string(option) + " " + path + ": folder " + dir.string() +
                           " does not exist");
    }
    MeshReadReport report;
    Mesh mesh;
    std::string inside_outside = "ray parity along the grid rows (watertight mesh)";
    try {
      mesh = read_mesh(o->mesh, &report);
    } catch (const InvalidInput& e) {
      if (!o->allow_open) throw;
      mesh = read_mesh_raw(o->mesh);  // still throws for unreadable files
      if (mesh.triangles.empty()) throw;
      o->fill.field.vote_sign = true;
      inside_outside = "Embree ray-parity voting (mesh not watertight)";
      note(std::string(e.what()) + "; deciding inside/outside by ray-parity voting");
    }
    if (report.reoriented) note(o->mesh + ": triangles were not consistently outward; re-oriented");
    // Phase times, so a user sees what grows with the triangle count (reading, indexing) apart
    // from what should not (field, fill).
    auto since = [](std::chrono::steady_clock::time_point t) {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    const double t_read = since(t0);
    auto t = std::chrono::steady_clock::now();
    const MeshIndex index(mesh);
    const double t_index = since(t);
    t = std::chrono::steady_clock::now();
    const DistanceField field = make_distance_field(index, o->fill.field);
    const double t_field = since(t);
    t = std::chrono::steady_clock::now();
    const FillResult r = fill(index, field, o->fill);
    const double t_fill = since(t);
    if (r.clump.spheres.empty())
      throw InvalidInput(o->mesh + ": no sphere fits with --min-radius " +
                         format_number(o->fill.min_radius));
    if (o->spheres > 0 && static_cast<int>(r.clump.spheres.size()) < o->spheres)
      warning("the budget of " + std::to_string(o->spheres) + " spheres was not reached: " +
              std::to_string(r.clump.spheres.size()) + " placed, stopped by " + r.stopped_by +
              (r.stopped_by == "candidates" ? " (no medial candidate left adds coverage)" : ""));
    t = std::chrono::steady_clock::now();
    const Fidelity f = o->fill.field.vote_sign ? assess_fidelity(mesh, r.clump, r.voxel)
                                               : assess_fidelity(index, r.clump, r.voxel);
    const double t_fidelity = since(t);
    write_clump(o->out, r.clump,
                "clumpkit fill " + o->mesh + "\nspheres " + std::to_string(r.clump.spheres.size()) +
                    ", covered fraction " + format_number(f.covered_fraction));
    if (!o->vtp.empty()) write_clump_vtp(o->vtp, mesh, r.clump);
    if (!o->png.empty())
      write_particle_png(o->png, mesh, r.clump,
                         std::filesystem::path(o->mesh).filename().string() + ": " +
                             std::to_string(f.spheres) + " spheres, coverage " +
                             format_fixed(f.covered_fraction, 3) + ", overshoot " +
                             format_fixed(f.overshoot_fraction, 4) + " of the volume",
                         450, false);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    nlohmann::ordered_json j = fidelity_json(f);
    j["inside_outside"] = inside_outside;
    j["voxel"] = r.voxel;
    j["candidates"] = r.candidates;
    j["stopped_by"] = r.stopped_by;
    j["max_overshoot"] = o->fill.max_overshoot;
    j["seconds"] = seconds;
    nlohmann::ordered_json phases;
    phases["read"] = t_read;  // reading, welding and checking the mesh
    phases["index"] = t_index;
    phases["field"] = t_field;
    phases["fill"] = t_fill;
    phases["fidelity"] = t_fidelity;
    j["seconds_by_phase"] = phases;
    j["triangles"] = mesh.triangles.size();
    if (o->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::printf(
          "wrote %s: %d spheres (stopped by %s), covered %.4f, overshoot %.4f, surface gap "
          "mean %s max %s, %.3f s (read %.3f, index %.3f, field %.3f, fill %.3f, fidelity "
          "%.3f)\n",
          o->out.c_str(), f.spheres, r.stopped_by.c_str(), f.covered_fraction, f.overshoot_fraction,
          format_number(f.surface_mean_distance).c_str(),
          format_number(f.surface_max_distance).c_str(), seconds, t_read, t_index, t_field, t_fill,
          t_fidelity);
    }
  });
}

}  // namespace clumpkit::cli
