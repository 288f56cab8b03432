// The export job: a specimen directory into an engine's files and runnable deck.
#pragma once

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
  LammpsDeck lammps;  ///< lammps only: a test after the settle, tiling
};

/// Exports the specimen directory `source` (specimen.csv, report.json and manifest.json of
/// `clumpkit specimen`) in `format` into `out_dir` (written in DIR.partial and renamed at the
/// end, the rule of job.h), with a manifest.json naming the source. Formats: "lammps"
/// (io/export/lammps.h). Throws InvalidInput for an unknown format, a format not available
/// yet, or a source that is not a specimen directory (naming it), before anything is written.
ExportResult run_export(const std::string& format, const std::string& source,
                        const std::string& out_dir, const ExportOptions& options = {});

}  // namespace clumpkit
