#include "io/formats/cells_files.h"

#include "geom/format.h"
#include "io/base/atomic_file.h"
#include "io/base/units.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <ostream>

namespace clumpkit {

namespace {

std::string num(double v) {
  return format_number(v);
}

}  // namespace

void write_cells_vtp(const std::string& path, const Tessellation& t,
                     const std::vector<CellBond>& bonds) {
  std::map<std::pair<int, int>, double> factor;
  for (const CellBond& b : bonds) factor[{b.a, b.b}] = b.strength_factor;
  write_file_atomically(path, [&](std::ostream& o) {
    std::size_t points = 0, polys = 0;
    for (const Cell& c : t.cells) {
      points += c.vertices.size();
      polys += c.faces.size();
    }
    o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<PolyData>\n<Piece NumberOfPoints=\""
      << points << "\" NumberOfPolys=\"" << polys
      << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const Cell& c : t.cells)
      for (const Vec3& p : c.vertices)
        o << num(p.x()) << " " << num(p.y()) << " " << num(p.z()) << "\n";
    o << "</DataArray>\n</Points>\n<CellData Scalars=\"cell\">\n"
      << "<DataArray type=\"Int32\" Name=\"cell\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < t.cells.size(); ++i)
      for (std::size_t f = 0; f < t.cells[i].faces.size(); ++f) o << i << "\n";
    o << "</DataArray>\n<DataArray type=\"Int32\" Name=\"neighbour\" format=\"ascii\">\n";
    for (const Cell& c : t.cells)
      for (const CellFace& f : c.faces) o << f.neighbour << "\n";
    o << "</DataArray>\n<DataArray type=\"Float64\" Name=\"strength_factor\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < t.cells.size(); ++i)
      for (const CellFace& f : t.cells[i].faces) {
        const int a = std::min<int>(i, f.neighbour), b = std::max<int>(i, f.neighbour);
        const auto it = f.neighbour >= 0 ? factor.find({a, b}) : factor.end();
        o << (it == factor.end() ? std::string("0") : num(it->second)) << "\n";
      }
    o << "</DataArray>\n</CellData>\n<Polys>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    std::size_t base = 0;
    for (const Cell& c : t.cells) {
      for (const CellFace& f : c.faces) {
        for (std::size_t k = 0; k < f.vertices.size(); ++k)
          o << (k ? " " : "") << base + f.vertices[k];
        o << "\n";
      }
      base += c.vertices.size();
    }
    o << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    std::size_t end = 0;
    for (const Cell& c : t.cells)
      for (const CellFace& f : c.faces) o << (end += f.vertices.size()) << "\n";
    o << "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  });
}

void write_cells_csv(const std::string& path, const Tessellation& t,
                     const std::vector<CellBond>& bonds) {
  std::vector<int> bonded(t.cells.size(), 0);
  for (const CellBond& b : bonds) ++bonded[b.a], ++bonded[b.b];
  write_file_atomically(path, [&](std::ostream& o) {
    o << csv_header("cells", "cell,volume,x,y,z,Ixx,Iyy,Izz,Ixy,Ixz,Iyz,faces,neighbours",
                    si_length())
      << "\n";
    for (std::size_t i = 0; i < t.cells.size(); ++i) {
      const MassProperties& m = t.cells[i].mass;
      const Mat3& j = m.inertia;
      o << i << "," << num(m.volume) << "," << num(m.centroid.x()) << "," << num(m.centroid.y())
        << "," << num(m.centroid.z()) << "," << num(j(0, 0)) << "," << num(j(1, 1)) << ","
        << num(j(2, 2)) << "," << num(j(0, 1)) << "," << num(j(0, 2)) << "," << num(j(1, 2)) << ","
        << t.cells[i].faces.size() << "," << bonded[i] << "\n";
    }
  });
}

void write_bonds_csv(const std::string& bonds_path, const std::string& points_path,
                     const std::vector<CellBond>& bonds) {
  write_file_atomically(bonds_path, [&](std::ostream& o) {
    o << csv_header("bonds", "bond,a,b,area,x,y,z,nx,ny,nz,strength_factor,points", si_length())
      << "\n";
    for (std::size_t k = 0; k < bonds.size(); ++k) {
      const CellBond& b = bonds[k];
      o << k << "," << b.a << "," << b.b << "," << num(b.area) << "," << num(b.centroid.x()) << ","
        << num(b.centroid.y()) << "," << num(b.centroid.z()) << "," << num(b.normal.x()) << ","
        << num(b.normal.y()) << "," << num(b.normal.z()) << "," << num(b.strength_factor) << ","
        << b.points.size() << "\n";
    }
  });
  write_file_atomically(points_path, [&](std::ostream& o) {
    o << csv_header("bond_points", "bond,x,y,z,area", si_length()) << "\n";
    for (std::size_t k = 0; k < bonds.size(); ++k)
      for (const FacePoint& p : bonds[k].points)
        o << k << "," << num(p.position.x()) << "," << num(p.position.y()) << ","
          << num(p.position.z()) << "," << num(p.area) << "\n";
  });
}

namespace {

nlohmann::json vec_json(const Vec3& v) {
  return {round_significant(v.x(), 6), round_significant(v.y(), 6), round_significant(v.z(), 6)};
}

}  // namespace

void write_cell_motion(const std::string& path, const Tessellation& t,
                       const std::vector<CellPose>& before, const std::vector<CellPose>& after,
                       const std::vector<int>& fragment) {
  nlohmann::json cells = nlohmann::json::array();
  for (std::size_t k = 0; k < t.cells.size(); ++k) {
    const Cell& c = t.cells[k];
    nlohmann::json v = nlohmann::json::array(), f = nlohmann::json::array();
    for (const Vec3& x : c.vertices)
      for (int i = 0; i < 3; ++i) v.push_back(round_significant(x[i], 6));
    for (const CellFace& face : c.faces) f.push_back(face.vertices);
    const Eigen::Quaterniond q = after[k].orientation * before[k].orientation.conjugate();
    cells.push_back({{"v", v},
                     {"f", f},
                     {"p0", vec_json(before[k].position)},
                     {"p1", vec_json(after[k].position)},
                     {"q", {q.w(), q.x(), q.y(), q.z()}},
                     {"fragment", fragment[k]}});
  }
  nlohmann::ordered_json doc = {{"cells", cells}};
  add_units(doc, si_length());
  write_file_atomically(path, [&](std::ostream& o) { o << doc.dump(); });
}

}  // namespace clumpkit
