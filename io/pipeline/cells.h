// The job of `clumpkit cells`: a convex parent mesh cut into Voronoi cells with bonds on their
// shared faces, written as cells.vtp, cells.csv, bonds.csv, bond_points.csv, report.json and
// manifest.json.
#pragma once

#include "geom/cells/cell_bonds.h"
#include "geom/cells/voronoi_cells.h"
#include "geom/shapes/distribution.h"
#include "io/formats/mesh_io.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>

namespace clumpkit {

/// What the cells job reads and writes. Lengths in the mesh's units.
struct CellsJobOptions {
  std::string mesh;  ///< the convex parent (STL, OBJ, PLY)
  std::string out;   ///< output directory (written as OUT.partial, then renamed)
  CellOptions cells;
  std::uint64_t seed = 1;  ///< seeds from stream 0, strength factors from stream 1
  /// Factor on each bond's strengths (default_strength_factor(): normal 1 ± 0.125 in
  /// [0.75, 1.25]).
  Distribution strength = default_strength_factor();
  MeshReadOptions read;
};

/// Reads the parent, cuts it (voronoi_cells), bonds the shared faces (cell_bonds) and writes the
/// directory. Returns the report (also report.json): cells, bonds, bond_points, parent_volume,
/// cells_volume, volume_error (relative), cell_volume_cv, cell_diameter (mean volume-equivalent),
/// faces_per_cell, lloyd, seed, seconds. Nothing is written before the cells are made: a
/// refused parent (not convex, not closed) or bad options leave no OUT and no OUT.partial. Throws
/// InvalidInput naming the file, what read_mesh throws, IoError.
nlohmann::ordered_json run_cells_job(const CellsJobOptions& options,
                                     const std::function<void(const std::string&)>& note);

}  // namespace clumpkit
