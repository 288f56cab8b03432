// The files of a Voronoi-cell tessellation: cells.vtp for ParaView, cells.csv (mass properties),
// bonds.csv and bond_points.csv (the shared faces and their integration points).
#pragma once

#include "geom/cells/cell_bonds.h"
#include "geom/cells/voronoi_cells.h"
#include "geom/mesh/mesh.h"

#include <Eigen/Geometry>

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

/// Where a cell went: its body's pose as the test began and as it ended.
struct CellPose {
  Vec3 position = Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// NNNNN.cells.json of a crushing run: the cells before and after, as a page draws them.
/// {"cells": [{"v": [x, y, z, …] (vertices where the cells were made), "f": [[i, j, k, …], …]
/// (faces, counter-clockwise from outside), "p0": body position before, "p1": after, "q": the
/// rotation from before to after (w, x, y, z), "fragment": the cell's fragment at the end, from
/// 1}, …]}: a vertex went to q·(v − p0) + p1. Six significant digits (a picture, not a state).
/// Atomic write.
void write_cell_motion(const std::string& path, const Tessellation& cells,
                       const std::vector<CellPose>& before, const std::vector<CellPose>& after,
                       const std::vector<int>& fragment);

}  // namespace clumpkit
