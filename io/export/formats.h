// The export formats: one table that the export job dispatches on and the command line lists
// and describes, so a new engine is one row.
#pragma once

#include "io/export/export_source.h"
#include "io/export/lammps.h"

#include <string>
#include <vector>

namespace clumpkit {

/// One engine's export.
struct ExportFormat {
  const char* name;   ///< the FORMAT argument of `clumpkit export`
  const char* files;  ///< what it writes, for --help
  /// Writes the engine's files for `bodies` (from `source`) into `dir`; returns their paths.
  std::vector<std::string> (*write)(const ExportSource& source,
                                    const std::vector<SpecimenBody>& bodies, const std::string& dir,
                                    const LammpsDeck& deck);
  /// The command line that runs the written deck from its directory.
  std::string (*run)();
};

/// Every format, in the order --help lists them: lammps, liggghts, yade, pfc, vtk.
const std::vector<ExportFormat>& export_formats();

/// The format called `name`, or nullptr.
const ExportFormat* find_export_format(const std::string& name);

/// The names joined for a message: "lammps, liggghts, yade, pfc, vtk" (`last` before the final
/// name instead of ", " when given, e.g. " or ").
std::string export_format_names(const std::string& last = ", ");

}  // namespace clumpkit
