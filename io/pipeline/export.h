// The export job: a specimen, a clump library or one clump into an engine's files and deck.
#pragma once

#include "io/export/export_source.h"
#include "io/export/lammps.h"

#include <string>
#include <vector>

namespace clumpkit {

struct ExportResult {
  std::string format;
  std::size_t bodies = 0, spheres = 0;
  std::vector<std::string> files;  ///< paths written (under the output directory)
  std::string run;                 ///< the command line that runs the deck, from that directory
};

/// What `clumpkit export` may add to the engine's files.
struct ExportOptions {
  LammpsDeck lammps;             ///< lammps only: a test after the settle, tiling
  TemplateSourceOptions source;  ///< a library or clump CSV: density, length unit, mass
  /// lammps, a specimen: the test recipe of a cone penetration test (its [probe] and [test]
  /// friction; `clumpkit test cpt`'s), exported as the CPT deck (io/export/lammps_cpt.h).
  std::string cpt_recipe;
};

/// Exports `source` (a specimen directory, a library directory or one clump CSV:
/// read_export_source) in `format` into `out_dir` (written in DIR.partial and renamed at the
/// end, the rule of job.h), with a manifest.json naming the source. Formats: export_formats()
/// (io/export/formats.h: lammps, liggghts, yade, pfc, vtk); a library or clump CSV also gets LAMMPS
/// molecule templates (io/export/lammps_molecules.h). Throws InvalidInput for an unknown format,
/// a bad option or a bad source (naming it), before anything is written.
ExportResult run_export(const std::string& format, const std::string& source,
                        const std::string& out_dir, const ExportOptions& options = {});

}  // namespace clumpkit
