// Clump libraries: shapes + sphere fill + fidelity for every particle of a recipe, resumable.
#pragma once

#include "geom/mesh/repair.h"
#include "io/pipeline/shapes.h"
#include "io/recipes/recipe.h"

#include <string>
#include <vector>

namespace clumpkit {

struct LibraryOptions {
  /// Also write particles/NNNNN.png (four shaded views, io/reports/views.h) and contact_sheet.png.
  bool png = false;
  bool vtp = false;  ///< also write particles/NNNNN.vtp (mesh and spheres for ParaView)
  /// Memory the particles being filled at once may share (bytes, 0: no limit): each fill gets
  /// this divided by the worker threads, and one whose estimate exceeds its share is refused
  /// before allocating (the finished particles stay for a resume).
  double max_memory_bytes = 0;
  /// Repair the files of mesh fractions in memory before their fill (io/pipeline/repair.h), so a
  /// folder of raw scans becomes a library in one command; each record's `repair` says what it
  /// did.
  bool repair = false;
  RepairOptions repair_options;
};

struct LibraryResult {
  std::size_t particles = 0;
  std::size_t resumed = 0;  ///< particles found finished from an earlier run and kept
  /// Records of an earlier run refused (unreadable, or failing their checksum) and redone.
  std::vector<std::string> redone;
  std::string out_dir;
};

/// Builds DIR/particles/NNNNN.{stl,csv,json[,png][,vtp]}, then DIR/library.csv (parameters,
/// descriptors and fidelity per particle), DIR/recipe.toml (the recipe), DIR/manifest.json and
/// with `png` DIR/contact_sheet.png. Pictures are made from the written files after the last
/// fill, each only if missing, so a resumed run (or one that adds --png) makes what it lacks.
/// Work goes to DIR.partial, renamed to DIR at the end (the rule of job.h: an existing DIR is
/// replaced only when it is a clumpkit output). Particle i uses the random stream (seed, i) and
/// is written atomically, its .json last, so a run killed or interrupted (Interrupted, told to
/// the interrupter as stage "library") and restarted with the same recipe keeps the finished
/// particles of DIR.partial and ends byte-identical to an uninterrupted run, for any thread
/// count; a DIR.partial of another recipe is discarded. Each NNNNN.json carries a "checksum"
/// (FNV-1a 64 of the record's compact JSON without it); a record that fails it is redone and
/// named in `redone`. Fill settings come from the recipe's
/// [fill] table (defaults otherwise). Every number says its SI unit (docs/units.md): the CSV
/// header cells, and the "units" map of each record and of the manifest.
LibraryResult run_library(const ShapeRecipe& recipe, const std::string& out_dir,
                          const LibraryOptions& options, const Interrupter& interrupter = {});

}  // namespace clumpkit
