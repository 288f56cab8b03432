// The import job: an engine's run of an exported deck back into a specimen directory, measured
// as clumpkit measures its own specimens.
#pragma once

#include <string>
#include <vector>

namespace clumpkit {

struct ImportResult {
  std::string engine;
  std::size_t bodies = 0, lost = 0;  ///< bodies imported, bodies the engine lost
  double porosity = 0, relative_density = 0, source_relative_density = 0, height = 0;
  double fit_residual = 0;         ///< largest sphere–atom distance of the rigid fits (m)
  std::vector<std::string> files;  ///< paths written (under the output directory)
};

/// Reads the final dump of `run_dir` (a run of `clumpkit export lammps` of `specimen_dir`) and
/// writes into `out_dir` (DIR.partial, renamed at the end: the rule of job.h) specimen.csv,
/// specimen.vtp, bodies_map.csv (imported id → the source specimen's id), slices/, report.json
/// (porosity, relative density with the source's calibration extremes, height, per-layer and
/// per-band porosity and coordination number of the same central region, the source's relative
/// density, bodies lost, the fit residual, and the container, densities and contact law, so the
/// result exports again) and manifest.json; with the deck's oedometer.csv also a copy of it and
/// oedometer.png. A run of the CPT deck (its cpt.csv, `clumpkit export lammps --test cpt`) is
/// read as `clumpkit test cpt` reports a push instead: curve.csv and curve.png, report.json with
/// the steps, final depth, qc_max and the second half's mean qc and fs (and the source's
/// container, densities and contact law), beside the final state's specimen.csv, specimen.vtp and
/// bodies_map.csv. Engines: "lammps". Throws InvalidInput naming the file for bad input before
/// anything is written.
ImportResult run_import(const std::string& engine, const std::string& run_dir,
                        const std::string& specimen_dir, const std::string& out_dir);

}  // namespace clumpkit
