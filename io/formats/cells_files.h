// The files of a Voronoi-cell tessellation: cells.vtp for ParaView, cells.csv (mass properties),
// bonds.csv and bond_points.csv (the shared faces and their integration points).
#pragma once

#include "geom/cells/cell_bonds.h"
#include "geom/cells/voronoi_cells.h"

#include <string>
#include <vector>

namespace clumpkit {

/// Every face of every cell as a polygon, each cell with its own copy of its vertices. Cell data
/// "cell" (the cell's index), "neighbour" (the cell across the face, −1 on the parent's surface)
/// and "strength_factor" (the bond's across a shared face, 0 on the surface). In ParaView: colour
/// by "cell"; Threshold on "neighbour" ≥ 0 shows the internal faces. Atomic write; throws IoError
/// naming the path.
void write_cells_vtp(const std::string& path, const Tessellation& cells,
                     const std::vector<CellBond>& bonds);

/// cells.csv: `cell,volume,x,y,z,Ixx,Iyy,Izz,Ixy,Ixz,Iyz,faces,neighbours` — volume, centroid and
/// inertia about the centroid at unit density in the parent's frame and units (the six
/// components of the tensor), the face count and the number of bonded neighbours. Atomic write.
void write_cells_csv(const std::string& path, const Tessellation& cells,
                     const std::vector<CellBond>& bonds);

/// bonds.csv: `bond,a,b,area,x,y,z,nx,ny,nz,strength_factor,points` (face centroid, unit normal
/// from a to b, integration point count); bond_points.csv: `bond,x,y,z,area`. Atomic writes.
void write_bonds_csv(const std::string& bonds_path, const std::string& points_path,
                     const std::vector<CellBond>& bonds);

}  // namespace clumpkit
