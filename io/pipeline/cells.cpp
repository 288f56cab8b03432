#include "io/pipeline/cells.h"

#include "geom/cells/cell_bonds.h"
#include "geom/errors.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"
#include "io/formats/cells_files.h"
#include "io/pipeline/manifest.h"
#include "io/pipeline/output_dir.h"

#include <chrono>
#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;

namespace clumpkit {

nlohmann::ordered_json run_cells_job(const CellsJobOptions& o,
                                     const std::function<void(const std::string&)>& note) {
  const auto start = std::chrono::steady_clock::now();
  validate(o.cells);
  validate(o.strength, "strength factor");
  check_output_directory(o.out);
  check_output_spares(o.out, o.mesh, "the mesh");
  MeshReadReport read;
  const Mesh parent = read_mesh(o.mesh, &read, o.read);
  for (const std::string& line : mesh_read_notes(o.mesh, read)) note(line);
  Tessellation t;
  std::vector<CellBond> bonds;
  try {
    Rng seeds = Rng::stream(o.seed, 0);
    t = voronoi_cells(parent, o.cells, seeds);
    Rng factors = Rng::stream(o.seed, 1);
    bonds = cell_bonds(t, o.strength, factors);
  } catch (const InvalidInput& e) {
    throw InvalidInput(o.mesh + ": " + e.what());
  }

  double sum = 0, sum2 = 0, diameter = 0;
  std::size_t faces = 0, points = 0;
  for (const Cell& c : t.cells) {
    sum += c.mass.volume;
    sum2 += c.mass.volume * c.mass.volume;
    diameter += std::cbrt(6.0 * c.mass.volume / M_PI);
    faces += c.faces.size();
  }
  for (const CellBond& b : bonds) points += b.points.size();
  const double n = static_cast<double>(t.cells.size()), mean = sum / n;
  nlohmann::ordered_json r;
  r["mesh"] = o.mesh;
  r["cells"] = t.cells.size();
  r["bonds"] = bonds.size();
  r["bond_points"] = points;
  r["parent_volume"] = t.parent_volume;
  r["cells_volume"] = sum;
  r["volume_error"] = (sum - t.parent_volume) / t.parent_volume;
  r["cell_volume_cv"] = std::sqrt(std::max(0.0, sum2 / n - mean * mean)) / mean;
  r["cell_diameter"] = diameter / n;
  r["faces_per_cell"] = static_cast<double>(faces) / n;
  r["lloyd"] = o.cells.lloyd;
  r["strength_factor"] = describe(o.strength);
  r["seed"] = o.seed;

  write_staged(o.out, [&](const std::string& staging) {
    const fs::path dir = staging;
    write_cells_vtp((dir / "cells.vtp").string(), t, bonds);
    write_cells_csv((dir / "cells.csv").string(), t, bonds);
    write_bonds_csv((dir / "bonds.csv").string(), (dir / "bond_points.csv").string(), bonds);
    r["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::ordered_json report = r;
    report.erase("seconds");  // report.json is the same bytes for the same command
    add_units(report, si_length());
    write_file_atomically((dir / "report.json").string(),
                          [&](std::ostream& f) { f << report.dump(2) << "\n"; });
    nlohmann::ordered_json m = manifest_head("cells", "", "", o.seed);
    m["mesh"] = fs::absolute(o.mesh).lexically_normal().string();
    if (o.cells.count > 0)
      m["count"] = o.cells.count;
    else
      m["cell_size"] = o.cells.cell_size;
    m["lloyd"] = o.cells.lloyd;
    m["strength_factor"] = describe(o.strength);
    m["files"] = {"cells.vtp", "cells.csv", "bonds.csv", "bond_points.csv", "report.json"};
    add_units(m, si_length());
    write_file_atomically((dir / "manifest.json").string(),
                          [&](std::ostream& f) { f << m.dump(2) << "\n"; });
  });
  add_units(r, si_length());
  return r;
}

}  // namespace clumpkit
