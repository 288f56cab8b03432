#include "io/pipeline/fill.h"

#include "geom/errors.h"
#include "geom/format.h"
#include "geom/mesh/mesh_index.h"
#include "io/formats/clump_io.h"
#include "io/formats/clump_vtp.h"
#include "io/formats/mesh_io.h"
#include "io/pipeline/output_dir.h"
#include "io/pipeline/repair.h"
#include "io/reports/views.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <utility>

namespace clumpkit {

nlohmann::ordered_json fidelity_json(const Fidelity& f) {
  nlohmann::ordered_json j;
  for_each_fidelity_field([&](const char* name, auto member) { j[name] = f.*member; });
  return j;
}

nlohmann::ordered_json refine_json(const FillResult& r, const Fidelity& before,
                                   const Fidelity& after) {
  nlohmann::ordered_json j;
  j["sweeps"] = r.refine_sweeps;
  j["moves"] = r.refine_moves;
  j["budget_steps"] = r.grow_steps;  // radius steps that spent the rest of the overshoot budget
  j["covered_fraction_before"] = before.covered_fraction;
  j["covered_fraction_after"] = after.covered_fraction;
  j["overshoot_fraction_before"] = before.overshoot_fraction;
  j["overshoot_fraction_after"] = after.overshoot_fraction;
  return j;
}

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string inside_outside(const FillOptions& fo) {
  return fo.field.vote_sign ? "Embree ray-parity voting (mesh not watertight)"
                            : "ray parity along the grid rows (watertight mesh)";
}

// The clump CSV, and the ParaView file and picture when asked for.
void write_fill_outputs(const FillJobOptions& options, const Mesh& mesh, const Clump& clump,
                        const Fidelity& f) {
  write_clump(options.out, clump,
              "clumpkit fill " + options.mesh + "\nspheres " +
                  std::to_string(clump.spheres.size()) + ", covered fraction " +
                  format_number(f.covered_fraction),
              options.length.symbol);
  if (!options.vtp.empty()) write_clump_vtp(options.vtp, mesh, clump);
  if (!options.png.empty())
    write_particle_png(options.png, mesh, clump,
                       std::filesystem::path(options.mesh).filename().string() + ": " +
                           std::to_string(f.spheres) + " spheres, coverage " +
                           format_fixed(f.covered_fraction, 3) + ", overshoot " +
                           format_fixed(f.overshoot_fraction, 4) + " of the volume",
                       450, false);
}

}  // namespace

SolidFill fill_solid(const Mesh& mesh, FillOptions fo, const std::string& name,
                     const std::function<void(const std::string&)>& note,
                     const Interrupter& interrupter) {
  validate(fo);
  // Phase times, so a user sees what grows with the triangle count (indexing) apart from what
  // should not (field, fill).
  SolidFill out;
  auto t = std::chrono::steady_clock::now();
  const MeshIndex index(mesh);
  out.seconds_index = seconds_since(t);
  t = std::chrono::steady_clock::now();
  const DistanceField field = make_distance_field(index, fill_field_options(mesh, fo));
  out.seconds_field = seconds_since(t);
  // The contract holds by construction on a watertight mesh (the fill's ledger keeps 10 % in
  // hand); where the report's measure disagrees with the fill's (a mesh that is not watertight:
  // voting against the field's sign), the fill runs again with a budget scaled down by the
  // miss, twice at most, and a clump that still breaks the contract is refused: no report shows
  // an overshoot above max_overshoot with exit 0.
  // volumes_only: the volumes alone (assess_volumes), for the greedy clump's "before".
  auto assess = [&](const Clump& clump, bool volumes_only) {
    if (volumes_only)
      return fo.field.vote_sign ? assess_volumes(mesh, clump, out.fill.voxel)
                                : assess_volumes(index, clump, out.fill.voxel);
    return fo.field.vote_sign ? assess_fidelity(mesh, clump, out.fill.voxel)
                              : assess_fidelity(index, clump, out.fill.voxel);
  };
  const double contract = fo.max_overshoot;
  int smaller = 0;  // fills again with a smaller budget
  while (true) {
    t = std::chrono::steady_clock::now();
    out.fill = fill(index, field, fo, interrupter);
    out.seconds_fill += seconds_since(t);
    if (out.fill.clump.spheres.empty())
      throw InvalidInput(name + ": no sphere fits with --min-radius " +
                         format_number(fo.min_radius));
    t = std::chrono::steady_clock::now();
    out.fidelity = assess(out.fill.clump, false);
    out.seconds_fidelity += seconds_since(t);
    const double measured = out.fidelity.overshoot_fraction;
    if (!(measured > contract)) break;
    const std::string over = "the clump put " + format_number(measured, 3) +
                             " of the volume outside the mesh (" + inside_outside(fo) +
                             "), over --max-overshoot " + format_number(contract);
    // The growth pass fills the ledger to 0.9 of the budget, where the report's rows, one voxel
    // apart, can read over it although the ledger holds (thin caps on faces that lie along the
    // voxel lattice, as a box's: tests/bench/RESULTS.md). The clump without that pass is tried
    // first, before any smaller budget.
    if (fo.spend_budget && fo.max_overshoot > 0) {
      fo.spend_budget = false;
      note(over + "; filled again without spending the rest of the budget");
      continue;
    }
    if (smaller == 2 || fo.max_overshoot == 0)
      throw InvalidInput(name + ": the clump puts " + format_number(measured, 3) +
                         " of the volume outside the mesh, over --max-overshoot " +
                         format_number(contract) + " (" + inside_outside(fo) +
                         "); close the mesh (clumpkit repair) or allow more");
    fo.max_overshoot *= 0.5 * contract / measured;
    ++smaller;
    note(over + "; filled again with a smaller budget");
  }
  // The greedy clump of the fill kept, its volumes assessed the same way (the report's "before":
  // covered and overshoot only).
  t = std::chrono::steady_clock::now();
  if (out.fill.refine_moves > 0 || out.fill.grow_steps > 0)
    out.greedy_fidelity = assess(out.fill.greedy, true);
  else
    out.greedy_fidelity = out.fidelity;
  out.seconds_fidelity += seconds_since(t);
  return out;
}

FillJobResult run_fill_job(const FillJobOptions& options,
                           const std::function<void(const std::string&)>& note,
                           const std::function<void(const std::string&)>& warn) {
  const auto t0 = std::chrono::steady_clock::now();
  FillOptions fo = options.fill;
  validate(fo);
  check_not_input(options.out, "--output", options.mesh);
  // Every output's folder must exist before the work, so a failure leaves no partial output.
  for (const auto& [option, path] :
       {std::pair<const char*, const std::string&>{"--output", options.out},
        {"--png", options.png},
        {"--vtp", options.vtp}}) {
    if (path.empty()) continue;
    if (std::string(option) != "--output") {
      check_not_input(path, option, options.mesh);
      if (path == options.out || (!options.png.empty() && options.png == options.vtp))
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
  nlohmann::ordered_json repaired;
  if (options.repair) {
    RepairedMesh m = read_repaired_mesh(options.mesh, options.read, options.repair_options);
    mesh = std::move(m.mesh);
    repaired = repair_json(m.repair, m.read, options.repair_options);
    for (const std::string& w : m.repair.warnings) warn(options.mesh + ": " + w);
    note(options.mesh + ": repaired (" + std::to_string(m.repair.holes) + " holes closed, " +
         std::to_string(m.repair.crossings_within + m.repair.crossings_between) +
         " crossing pairs" +
         (m.repair.mended_by.empty() ? "" : ", mended by " + m.repair.mended_by) +
         (m.repair.wrapped ? ", wrapped" : "") + "); volume " +
         format_number(m.repair.volume_after, 6) + " " + options.length.pow(3));
    validate_solid(mesh, options.mesh, &report);
  } else {
    try {
      mesh = read_mesh(options.mesh, &report, options.read);
    } catch (const InvalidInput& e) {
      if (!options.allow_open) throw;
      // Welded as a closed one would be; still throws for unreadable files.
      mesh = read_mesh_raw(options.mesh, options.read, &report);
      if (mesh.triangles.empty()) throw;
      fo.field.vote_sign = true;
      note(std::string(e.what()) + "; deciding inside/outside by ray-parity voting");
    }
  }
  for (const std::string& line : mesh_read_notes(options.mesh, report)) note(line);
  const double t_read = seconds_since(t0);
  SolidFill solid = fill_solid(mesh, fo, options.mesh, note);
  FillJobResult out;
  out.fill = std::move(solid.fill);
  out.fidelity = solid.fidelity;
  out.greedy_fidelity = solid.greedy_fidelity;
  const FillResult& r = out.fill;
  const Fidelity& f = out.fidelity;
  if (fo.spheres > 0 && static_cast<int>(r.clump.spheres.size()) < fo.spheres)
    warn("the budget of " + std::to_string(fo.spheres) + " spheres was not reached: " +
         std::to_string(r.clump.spheres.size()) + " placed, stopped by " + r.stopped_by +
         (r.stopped_by == "candidates" ? " (no medial candidate left adds coverage)" : ""));
  write_fill_outputs(options, mesh, r.clump, f);
  nlohmann::ordered_json& j = out.report = fidelity_json(f);
  j["inside_outside"] = inside_outside(fo);
  j["voxel"] = r.voxel;
  j["candidates"] = r.candidates;
  j["stopped_by"] = r.stopped_by;
  j["max_overshoot"] = fo.max_overshoot;
  j["refine"] = refine_json(r, out.greedy_fidelity, f);
  // How fine the grid was: the smallest sphere in voxels, and, when asked, the coverage of a
  // fill on twice the voxels (the same options otherwise).
  nlohmann::ordered_json res;
  double smallest = r.clump.spheres.front().radius;
  for (const Sphere& s : r.clump.spheres) smallest = std::min(smallest, s.radius);
  res["voxel"] = r.voxel;
  res["smallest_sphere_voxels"] = smallest / r.voxel;
  if (smallest < 3.0 * r.voxel)
    warn("the smallest sphere's radius spans " + format_number(smallest / r.voxel, 2) +
         " voxels: the grid counts such spheres coarsely; --check-resolution shows what a finer "
         "grid changes, --voxels sets one");
  if (options.check_resolution) {
    FillOptions finer = fo;
    finer.field.voxel_size = r.voxel / std::cbrt(2.0);
    finer.field.max_voxels = 0.0;
    finer.voxels_from_count = false;
    const auto t = std::chrono::steady_clock::now();
    const SolidFill check = fill_solid(mesh, finer, options.mesh, [](const std::string&) {});
    res["finer_voxel"] = check.fill.voxel;
    res["covered_fraction_finer"] = check.fidelity.covered_fraction;
    res["covered_change"] = check.fidelity.covered_fraction - f.covered_fraction;
    res["seconds"] = seconds_since(t);
  }
  j["resolution"] = res;
  if (options.repair) j["repair"] = repaired;
  j["seconds"] = seconds_since(t0);
  nlohmann::ordered_json phases;
  phases["read"] = t_read;  // reading, welding and checking the mesh
  phases["index"] = solid.seconds_index;
  phases["field"] = solid.seconds_field;
  phases["fill"] = solid.seconds_fill;
  phases["fidelity"] = solid.seconds_fidelity;
  j["seconds_by_phase"] = phases;
  j["triangles"] = mesh.triangles.size();
  add_units(j, options.length);
  return out;
}

}  // namespace clumpkit
