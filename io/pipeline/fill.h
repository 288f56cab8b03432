// The job of `clumpkit fill`: one mesh read, filled with a clump of spheres, its fidelity
// assessed, and the clump written (with a picture and a ParaView file when asked).
#pragma once

#include "geom/fill/fidelity.h"
#include "geom/fill/fill.h"
#include "geom/mesh/repair.h"
#include "io/base/units.h"
#include "io/formats/mesh_io.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace clumpkit {

/// What the fill job reads and writes. Lengths in the mesh's units.
struct FillJobOptions {
  std::string mesh;  ///< closed mesh (STL, OBJ, PLY)
  std::string out;   ///< clump CSV to write
  std::string png;   ///< four-view picture to write ("": none)
  std::string vtp;   ///< mesh and spheres for ParaView ("": none)
  FillOptions fill;  ///< the stop rules, the field and the overshoot contract
  /// Accept a mesh that is not watertight: inside/outside by Embree ray-parity voting.
  bool allow_open = false;
  /// Fill again on a grid of twice the voxels and report the change of coverage (the report's
  /// `resolution`), so the user sees whether the grid was fine enough; the clump written is the
  /// first one.
  bool check_resolution = false;
  MeshReadOptions read;  ///< welding on reading
  /// Repair the mesh in memory first (io/pipeline/repair.h: the chain of `clumpkit repair`), so a
  /// raw scan fills in one command; the report's `repair` says what it did.
  bool repair = false;
  RepairOptions repair_options;
  /// The mesh's length unit, which labels the clump's header and the report's "units" ("L":
  /// unnamed); the numbers are the same whatever it is.
  LengthUnit length;
};

/// What the fill job did.
struct FillJobResult {
  FillResult fill;
  Fidelity fidelity, greedy_fidelity;
  /// The report of `fill --json`: the fidelity, inside_outside, voxel, candidates, stopped_by,
  /// max_overshoot, refine (sweeps, moves, covered_fraction and overshoot_fraction before and
  /// after), resolution (voxel, smallest_sphere_voxels; with check_resolution the finer voxel, its
  /// covered_fraction and the change), seconds, seconds_by_phase (read, index, field, fill,
  /// fidelity), triangles; with FillJobOptions::repair also `repair` (repair_json); last the
  /// "units" of every number (add_units, lengths in FillJobOptions::length).
  nlohmann::ordered_json report;
};

/// The fill and fidelity of a mesh that read_mesh or validate_solid accepted (with
/// options.field.vote_sign: one that read_mesh_raw read), made as the fill job makes them:
/// index, field, fill, assessment, and the overshoot contract of run_fill_job below. `name`
/// stands for the mesh in messages; the interrupter is the fill's (geom/fill/fill.h).
struct SolidFill {
  FillResult fill;
  Fidelity fidelity;
  /// The greedy pass's clump assessed the same way, when a refinement moved any sphere (else
  /// equal to `fidelity`).
  Fidelity greedy_fidelity;
  double seconds_index = 0, seconds_field = 0, seconds_fill = 0, seconds_fidelity = 0;
};
SolidFill fill_solid(const Mesh& mesh, FillOptions options, const std::string& name,
                     const std::function<void(const std::string&)>& note,
                     const Interrupter& interrupter = {});

/// Reads the mesh, fills it (geom/fill/fill.h), assesses the clump (geom/fill/fidelity.h) and
/// writes the outputs. Every output's folder is checked, and no output may be the input or
/// another output, before the work starts, so a refusal leaves nothing behind. `note` hears
/// what the user should know about the input (a re-oriented mesh, ray voting), `warn` a sphere
/// budget that was not reached. The overshoot contract holds for every report: a clump whose
/// measured overshoot exceeds max_overshoot (possible only where the report's inside test is not
/// the fill's: a mesh read with allow_open) is filled again with a smaller budget, at most twice,
/// else refused. Throws InvalidInput for bad options, a mesh no sphere fits, a contract that
/// cannot be met, and what read_mesh throws.
FillJobResult run_fill_job(const FillJobOptions& options,
                           const std::function<void(const std::string&)>& note,
                           const std::function<void(const std::string&)>& warn);

/// The fidelity record as JSON (the keys of Fidelity).
nlohmann::ordered_json fidelity_json(const Fidelity& f);

/// What the refinement did, as JSON: sweeps, moves, and the covered and overshoot fractions of
/// the greedy clump (before) and the refined one (after).
nlohmann::ordered_json refine_json(const FillResult& r, const Fidelity& before,
                                   const Fidelity& after);

}  // namespace clumpkit
